// SPDX-License-Identifier: MIT
#include <e2d/render/animated_sprite_renderer.hpp>

#include <e2d/core/log.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/render/render_system.hpp>

#include "error_format.hpp"

#include <algorithm>
#include <cmath>

namespace e2d::render {
namespace {

constexpr const char* kCtor = "render::AnimatedSpriteRenderer";

} // namespace

AnimatedSpriteRenderer::AnimatedSpriteRenderer(const AnimatedSpriteRendererDef& def)
    : SpriteRenderer(def.sprite), animDef_(def), name_(def.animation) {
    if (!std::isfinite(def.frameDuration) || def.frameDuration <= 0.0) {
        detail::fail(kCtor, "frameDuration must be > 0 and finite, got " +
                                detail::formatFloat(static_cast<float>(def.frameDuration)));
    }
    if (!std::isfinite(def.speed) || def.speed < 0.0) {
        detail::fail(kCtor, "speed must be >= 0 and finite, got " +
                                detail::formatFloat(static_cast<float>(def.speed)));
    }
}

void AnimatedSpriteRenderer::onInitialize() {
    RenderSystem& system = scene()->system<RenderSystem>();
    sheet_ = system.sheet(animDef_.sheetPath);
    SpriteRendererDef& sprite = mutableDef();
    sprite.texture = {};
    if (sheet_ == nullptr) {
        // The placeholder: the renderer draws its checker for a path it cannot load.
        sprite.texturePath = animDef_.sheetPath.string();
        sprite.uv = kFullUv;
    } else {
        sprite.texturePath = sheet_->imagePath().string();
        play(name_, true);
    }
    SpriteRenderer::onInitialize();
}

void AnimatedSpriteRenderer::play(const std::string& name, bool restart) {
    if (sheet_ == nullptr || (name == name_ && animation_ && !restart)) {
        return;
    }
    std::vector<int> frames = sheet_->animationFrames(name);
    if (frames.empty()) {
        if (core::Logger* log = scene() != nullptr ? scene()->logger() : nullptr) {
            log->error(std::string(kCtor) + ": sheet '" + sheet_->name() + "' has no frames named '" +
                       name + "<n>'");
        }
        if (!animation_) {
            // Nothing to play at all: show the whole sheet rather than nothing.
            setUv(kFullUv);
        }
        return;
    }
    name_ = name;
    frames_ = std::move(frames);
    AnimationDef def;
    def.frameCount = static_cast<int>(frames_.size());
    def.frameDuration = animDef_.frameDuration;
    def.mode = animDef_.mode;
    def.startFrame = std::clamp(animDef_.startFrame, 0, def.frameCount - 1);
    def.speed = animation_ ? animation_->def().speed : animDef_.speed;
    animation_.emplace(def);
    shown_ = -1;
    showFrame();
}

void AnimatedSpriteRenderer::setSpeed(double speed) {
    if (!std::isfinite(speed) || speed < 0.0) {
        detail::fail("render::AnimatedSpriteRenderer::setSpeed()",
                     "speed must be >= 0 and finite, got " + detail::formatFloat(static_cast<float>(speed)));
    }
    animDef_.speed = speed;
    if (animation_) {
        animation_->setSpeed(speed);
    }
}

void AnimatedSpriteRenderer::update(double dt) {
    if (animation_) {
        animation_->update(dt);
        showFrame();
    }
}

void AnimatedSpriteRenderer::showFrame() {
    const int frame = animation_->frame();
    if (frame == shown_) {
        return;
    }
    shown_ = frame;
    setUv(sheet_->frames()[static_cast<std::size_t>(frames_[static_cast<std::size_t>(frame)])].uv);
}

} // namespace e2d::render
