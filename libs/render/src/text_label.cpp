// SPDX-License-Identifier: MIT
#include <e2d/render/text_label.hpp>

#include <e2d/core/error_text.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>

#include "world_pose.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace e2d::render {

namespace {
constexpr const char* kCtor = "render::TextLabel";

void checkStyle(const char* function, const TextStyle& style) {
    if (!std::isfinite(style.lineSpacing) || style.lineSpacing <= 0.0f) {
        core::throwError(function, "style.lineSpacing must be > 0 and finite, got " +
                                       core::formatNumber(style.lineSpacing));
    }
}
} // namespace

TextLabel::TextLabel(const TextLabelDef& def) : def_(def) {
    if (def.pixelSize < 1 || def.pixelSize > 1024) {
        core::throwError(kCtor,
                         "pixelSize must be in [1, 1024], got " + std::to_string(def.pixelSize));
    }
    if (!core::isFinite(def.scale) || def.scale.x <= 0.0f || def.scale.y <= 0.0f) {
        core::throwError(kCtor,
                         "scale must be > 0 and finite, got " + core::formatVector(def.scale));
    }
    core::requireFinite(kCtor, "zOffset", def.zOffset);
    checkStyle(kCtor, def.style);
}

void TextLabel::setStyle(const TextStyle& style) {
    checkStyle("render::TextLabel::setStyle()", style);
    def_.style = style;
}

TextLabel::~TextLabel() { detach(); }

void TextLabel::onInitialize() {
    system_ = &scene()->system<RenderSystem>();
    font_ = system_->text().font(def_.fontPath, def_.pixelSize);
    system_->addHook(*this);
}

void TextLabel::onTerminate() { detach(); }

void TextLabel::detach() noexcept {
    if (system_ != nullptr) {
        system_->removeHook(*this);
    }
    system_ = nullptr;
    font_ = nullptr;
}

void TextLabel::beforeRender(Renderer&) {
    if (system_ == nullptr || font_ == nullptr || !def_.visible || def_.text.empty()) {
        return;
    }
    const detail::WorldPose pose = detail::worldPose(*gameObject());
    TextDraw where;
    where.position = pose.position;
    where.z = pose.z + def_.zOffset;
    where.rotation = pose.rotation;
    // Text is never mirrored: the object's scale magnitudes multiply the label's.
    where.scale = def_.scale * glm::abs(pose.scale);
    where.color = def_.color;
    where.hud = def_.hud;
    if (where.scale.x <= 0.0f || where.scale.y <= 0.0f) {
        return; // an object scaled to nothing shows no text
    }
    layout_ = system_->text().draw(*font_, def_.text, def_.style, where);
}

} // namespace e2d::render
