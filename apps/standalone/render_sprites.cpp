// SPDX-License-Identifier: MIT
// e2d::render alone: a Window, a Renderer and a Camera, no engine and no scene. A checkered
// tile made in memory, drawn as a floor of sprites, and a tinted square that turns. Closes
// with the window, or after --frames N; --screenshot FILE writes the last frame as a PNG.
// Links e2d::render only.
#include <e2d/render/camera.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/window.hpp>

#include <cstdint>
#include <string>

using namespace e2d::render;

int main(int argc, char** argv) {
    int frames = -1; // -1: until the window is closed
    std::string screenshot;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--frames") {
            frames = std::stoi(argv[i + 1]);
        } else if (flag == "--screenshot") {
            screenshot = argv[i + 1];
        }
    }

    // Initialisation: the window owns the OpenGL context, the renderer draws into it, the
    // camera says which part of the world is seen (here 640 x 360 units, one per pixel).
    Window window(WindowDef{.title = "e2d render sprites", .size = {640, 360}});
    Renderer renderer(window, RendererDef{.clearColor = {30, 30, 60, 255}});
    Camera camera(CameraDef{.referenceSize = {640.0f, 360.0f}});

    // A 2 x 2 checker, white and grey, made in memory (rows from the top, RGBA8).
    Image checker{2, 2, {}};
    for (const std::uint8_t v : {255, 128, 128, 255}) {
        checker.pixels.insert(checker.pixels.end(), {v, v, v, 255});
    }
    const TextureId tile = renderer.createTexture(checker, {.filter = TextureFilter::Nearest});
    for (int x = -4; x <= 4; ++x) { // a floor of nine 64-unit tiles along the bottom
        renderer.createSprite({.texture = tile,
                               .position = {64.0f * static_cast<float>(x), -140.0f},
                               .size = {64.0f, 64.0f}});
    }
    // No texture: a plain rectangle in its tint, in front of the floor (larger z is nearer).
    const SpriteId square = renderer.createSprite({.position = {0.0f, 30.0f},
                                                   .z = 1.0f,
                                                   .size = {120.0f, 120.0f},
                                                   .tint = {80, 200, 120, 255}});

    // The loop: window events, change what moves, draw, show.
    for (int frame = 0; frame != frames && !window.shouldClose(); ++frame) {
        window.pollEvents();
        renderer.setRotation(square, 0.02f * static_cast<float>(frame));
        renderer.render(camera); // one instanced draw per texture
        window.swapBuffers();
    }

    // Shutdown: read the last frame back if asked; the renderer, then the window, go away.
    if (!screenshot.empty()) {
        renderer.screenshot(screenshot);
    }
    return 0;
}
