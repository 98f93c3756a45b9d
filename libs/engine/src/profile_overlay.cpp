// SPDX-License-Identifier: MIT
#include "profile_overlay.hpp"

#include <e2d/render/camera.hpp>
#include <e2d/render/font.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/text_renderer.hpp>

#include <cstdio>

namespace e2d::engine::detail {

void ProfileOverlay::refresh() {
    const std::int64_t frames = profile_.frames - since_.frames;
    if (frames <= 0 && !text_.empty()) {
        return;
    }
    const double n = frames > 0 ? static_cast<double>(frames) : 1.0;
    const FrameTimes& now = profile_.sum;
    const FrameTimes& then = since_.sum;
    const auto mean = [n](double a, double b) { return (a - b) / n; };
    const double total = mean(now.total, then.total);
    char buffer[256];
    std::snprintf(buffer, sizeof buffer,
                  "frame %6.2f ms  %5.1f fps\n"
                  "update %.2f  fixed %.2f (physics %.2f)\n"
                  "render %.2f  audio %.2f  input %.2f",
                  total, total > 0.0 ? 1000.0 / total : 0.0, mean(now.update, then.update),
                  mean(now.fixedSteps, then.fixedSteps), mean(now.physics, then.physics),
                  mean(now.render, then.render), mean(now.audio, then.audio),
                  mean(now.input, then.input));
    text_ = buffer;
    since_ = profile_;
}

void ProfileOverlay::beforeRender(render::Renderer& renderer) {
    if (!visible_) {
        return;
    }
    if (text_.empty() || profile_.frames - since_.frames >= kRefreshFrames) {
        refresh();
    }
    render::Font* font = system_.text().font(render::kDefaultFontPath, kPixelSize);
    if (font == nullptr) {
        return;
    }
    // The top-left corner of what the screen shows, 6 px in, in camera (HUD) units.
    const render::Camera& camera = system_.activeCamera();
    const glm::vec2 unitsPerPixel = 1.0f / camera.pixelsPerUnit();
    const render::Rect region = camera.screenRegion();
    const glm::vec2 corner = camera.screenToCamera({region.min.x, region.max().y});
    render::TextDraw where;
    where.position = corner + glm::vec2{6.0f, -6.0f} * unitsPerPixel;
    where.z = depth_;
    where.scale = unitsPerPixel;
    where.color = kColor;
    where.hud = true;
    const render::TextLayout layout = system_.text().draw(*font, text_, render::TextStyle{}, where);
    // The backdrop: the text's bounds (font pixels from the anchor, y up) and 4 px around.
    render::Quad backdrop;
    backdrop.texture = renderer.whiteTexture();
    backdrop.position = where.position + (layout.bounds.min - glm::vec2{4.0f}) * unitsPerPixel;
    backdrop.size = (layout.bounds.max - layout.bounds.min + glm::vec2{8.0f}) * unitsPerPixel;
    backdrop.z = depth_ * 0.999f;
    backdrop.tint = {0, 0, 0, 153};
    backdrop.hud = true;
    renderer.submit(backdrop);
}

} // namespace e2d::engine::detail
