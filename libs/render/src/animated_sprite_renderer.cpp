// SPDX-License-Identifier: MIT
#include <e2d/render/animated_sprite_renderer.hpp>

#include <e2d/core/error_text.hpp>

#include <string>

namespace e2d::render {

namespace {

constexpr const char* kCtor = "render::AnimatedSpriteRenderer";

const std::vector<AnimationFrame>& checkedFrames(const AnimatedSpriteRendererDef& def) {
    if (def.frames.empty()) {
        core::throwError(kCtor, "frames must not be empty");
    }
    for (std::size_t i = 0; i < def.frames.size(); ++i) {
        const Rect& r = def.frames[i].uv;
        if (!core::isFinite(r.min) || !core::isFinite(r.size) || r.min.x < 0.0f || r.min.y < 0.0f ||
            r.size.x < 0.0f || r.size.y < 0.0f || r.max().x > 1.0f || r.max().y > 1.0f) {
            core::throwError(kCtor,
                             "frames[" + std::to_string(i) + "].uv must lie in [0, 1], got min " +
                                 core::formatVector(r.min) + " size " + core::formatVector(r.size));
        }
        const glm::vec2 size = def.frames[i].size;
        if (!core::isFinite(size) || size.x < 0.0f || size.y < 0.0f) {
            core::throwError(kCtor, "frames[" + std::to_string(i) +
                                        "].size must be >= 0 and finite, got " +
                                        core::formatVector(size));
        }
    }
    return def.frames;
}

AnimationDef timing(const AnimatedSpriteRendererDef& def) {
    AnimationDef a = def.animation;
    a.frameCount = static_cast<int>(checkedFrames(def).size());
    return a;
}

SpriteRendererDef firstLook(const AnimatedSpriteRendererDef& def) {
    checkedFrames(def); // its messages come first: the sprite's size may come from a frame
    SpriteRendererDef s = def.sprite;
    const int start = def.animation.startFrame;
    if (start >= 0 && static_cast<std::size_t>(start) < def.frames.size()) {
        const AnimationFrame& frame = def.frames[static_cast<std::size_t>(start)];
        s.uv = frame.uv;
        s.uvRotated = frame.rotated;
        if (s.size == glm::vec2(0.0f)) {
            s.size = frame.size;
        }
    }
    return s;
}

} // namespace

std::vector<AnimationFrame> animationUvs(const SpriteSheet& sheet, std::string_view baseName) {
    const std::vector<int> indices = sheet.animationFrames(baseName);
    if (indices.empty()) {
        core::throwError("render::animationUvs()", "sheet '" + sheet.name() +
                                                       "' has no frames named '" +
                                                       std::string(baseName) + "<number>'");
    }
    std::vector<AnimationFrame> frames;
    frames.reserve(indices.size());
    for (int index : indices) {
        const SpriteFrame& frame = sheet.frames()[static_cast<std::size_t>(index)];
        frames.push_back(AnimationFrame{frame.uv, frame.rotated, glm::vec2(frame.size())});
    }
    return frames;
}

AnimatedSpriteRenderer::AnimatedSpriteRenderer(const AnimatedSpriteRendererDef& def)
    : SpriteRenderer(firstLook(def)), frames_(checkedFrames(def)), animation_(timing(def)),
      frameSized_(def.sprite.size == glm::vec2(0.0f)) {
    shown_ = animation_.frame();
}

void AnimatedSpriteRenderer::update(double dt) {
    animation_.update(dt);
    if (animation_.frame() != shown_) {
        shown_ = animation_.frame();
        const AnimationFrame& frame = frames_[static_cast<std::size_t>(shown_)];
        setUv(frame.uv, frame.rotated);
        if (frameSized_) {
            setSize(frame.size);
        }
    }
}

} // namespace e2d::render
