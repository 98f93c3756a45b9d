// SPDX-License-Identifier: MIT
// Uses the installed render library alone: a hidden window, a renderer, a red and a blue
// sprite and a line of text drawn, the frame read back and checked, a screenshot written and
// read back, the window closed.
#include <e2d/core/error.hpp>
#include <e2d/render/camera.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/text_renderer.hpp>
#include <e2d/render/window.hpp>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

namespace {

using namespace e2d::render;

Color pixel(const Image& image, int x, int yFromBottom) {
    const std::uint8_t* p = image.at(x, image.height - 1 - yFromBottom);
    return Color{p[0], p[1], p[2], p[3]};
}

int run() {
    WindowDef windowDef;
    windowDef.title = "e2d render consumer";
    windowDef.size = {160, 120};
    windowDef.visible = false;
    windowDef.vsync = false;
    Window window(windowDef);
    Renderer renderer(window);
    TextRenderer text(renderer);

    // One world unit per pixel, origin at the centre of the 160 x 120 framebuffer.
    CameraDef cameraDef;
    cameraDef.referenceSize = glm::vec2(window.framebufferSize());
    Camera camera(cameraDef);

    SpriteDef red;
    red.position = {-40.0f, 20.0f};
    red.size = {20.0f, 20.0f};
    red.tint = Color{255, 0, 0, 255};
    renderer.createSprite(red);
    SpriteDef blue = red;
    blue.position = {40.0f, 20.0f};
    blue.tint = Color{0, 0, 255, 255};
    renderer.createSprite(blue);

    Font* font = text.font(kDefaultFontPath, 24);
    if (font == nullptr) {
        std::fprintf(stderr, "consumer: no font (%s)\n", text.fontError(kDefaultFontPath).c_str());
        return 1;
    }
    TextStyle style;
    style.horizontal = HorizontalAlign::Center;
    style.vertical = VerticalAlign::Center;
    TextDraw where;
    where.position = {0.0f, -30.0f};
    const TextLayout layout = text.draw(*font, "e2d", style, where);

    renderer.render(camera);
    const Image frame = renderer.readPixels();
    const glm::ivec2 centre = window.framebufferSize() / 2;
    const Color r = pixel(frame, centre.x - 40, centre.y + 20);
    const Color b = pixel(frame, centre.x + 40, centre.y + 20);
    const Color gap = pixel(frame, centre.x, centre.y + 20);
    int ink = 0;
    for (int y = centre.y - 45; y < centre.y - 15; ++y) {
        for (int x = centre.x - 30; x < centre.x + 30; ++x) {
            ink += pixel(frame, x, y).r > 128 ? 1 : 0;
        }
    }

    const std::filesystem::path shot =
        std::filesystem::temp_directory_path() / "e2d_render_consumer.png";
    renderer.screenshot(shot);
    const bool shotWritten = std::filesystem::file_size(shot) > 0;
    const int drawCalls = renderer.stats().drawCalls;
    window.requestClose();
    window.pollEvents();

    if (r.r != 255 || r.g != 0 || r.b != 0 || b.b != 255 || b.r != 0 || gap.r != 0 || gap.b != 0 ||
        ink == 0 || layout.quads.size() != 3 || !shotWritten || !window.shouldClose()) {
        std::fprintf(
            stderr,
            "consumer: render did not work (red %d,%d,%d blue %d,%d,%d gap %d,%d,%d, %d ink "
            "pixels, %zu glyphs, screenshot %d)\n",
            r.r, r.g, r.b, b.r, b.g, b.b, gap.r, gap.g, gap.b, ink, layout.quads.size(),
            shotWritten ? 1 : 0);
        return 1;
    }
    std::printf(
        "consumer: render drew 2 sprites and %zu glyphs in %d draw calls on %s, %d ink pixels, "
        "screenshot %s\n",
        layout.quads.size(), drawCalls, window.context().renderer.c_str(), ink,
        shot.string().c_str());
    std::filesystem::remove(shot);
    return 0;
}

} // namespace

int main() {
    try {
        return run();
    } catch (const e2d::core::Error& e) {
        std::fprintf(stderr, "consumer: %s\n", e.what());
        return 1;
    }
}
