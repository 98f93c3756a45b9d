// SPDX-License-Identifier: MIT
#include <e2d/render/text_label.hpp>

#include <e2d/core/scene.hpp>
#include <e2d/render/text_renderer.hpp>

#include "error_format.hpp"
#include "world_pose.hpp"

#include <cmath>

namespace e2d::render {
namespace {

constexpr const char* kCtor = "render::TextLabel";

void checkStyle(std::string_view function, const TextStyle& style) {
    if (!std::isfinite(style.lineSpacing) || style.lineSpacing <= 0.0f) {
        detail::fail(function, "lineSpacing must be > 0 and finite, got " +
                                   detail::formatFloat(style.lineSpacing));
    }
}

} // namespace

TextLabel::TextLabel(const TextLabelDef& def) : def_(def) {
    if (def.pixelSize < 1 || def.pixelSize > 1024) {
        detail::fail(kCtor, "pixelSize must be in [1, 1024], got " + std::to_string(def.pixelSize));
    }
    checkStyle(kCtor, def.style);
    detail::requireFinite(kCtor, "zOffset", def.zOffset);
}

TextLabel::~TextLabel() {
    if (system_ != nullptr) {
        system_->removeHook(*this);
    }
}

void TextLabel::setText(std::string text) {
    if (text != def_.text) {
        def_.text = std::move(text);
        dirty_ = true;
    }
}

void TextLabel::setStyle(const TextStyle& style) {
    checkStyle("render::TextLabel::setStyle()", style);
    def_.style = style;
    dirty_ = true;
}

void TextLabel::setAlignment(HorizontalAlign horizontal, VerticalAlign vertical) {
    def_.style.horizontal = horizontal;
    def_.style.vertical = vertical;
    dirty_ = true;
}

void TextLabel::onInitialize() {
    system_ = &scene()->system<RenderSystem>();
    system_->addHook(*this);
    dirty_ = true;
}

void TextLabel::onTerminate() {
    if (system_ != nullptr) {
        system_->removeHook(*this);
    }
    system_ = nullptr;
    font_ = nullptr;
}

void TextLabel::beforeRender(Renderer& renderer) {
    static_cast<void>(renderer);
    if (system_ == nullptr || !visible_) {
        return;
    }
    TextRenderer& text = system_->text();
    Font* font = text.font(def_.fontPath, def_.pixelSize);
    if (font == nullptr) {
        layout_ = {};
        return;
    }
    if (font != font_ || dirty_) {
        font_ = font;
        layout_ = layoutText(*font, def_.text, def_.style);
        dirty_ = false;
    }
    const detail::WorldPose pose = detail::worldPose(*gameObject());
    TextDraw where;
    where.position = pose.position;
    where.z = pose.z + def_.zOffset;
    where.rotation = pose.rotation;
    where.scale = pose.scale;
    where.color = def_.color;
    where.hud = def_.hud;
    text.submit(*font, layout_, where);
}

} // namespace e2d::render
