// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/render/animation.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/sprite_sheet.hpp>

#include <string_view>
#include <vector>

namespace e2d::render {

/// How an AnimatedSpriteRenderer starts (seed 2.4.2.8).
struct AnimatedSpriteRendererDef {
    /// The sprite (texture, size, pivot, tint, ...); its `uv` is replaced by the current frame's.
    SpriteRendererDef sprite{};
    /// The frames' UV rectangles in the texture, in playing order, at least one (each as
    /// SpriteDef::uv: fractions, top-left origin, inside [0, 1]). Default none.
    std::vector<Rect> frames;
    /// Timing; its `frameCount` is ignored (the number of `frames` is used). Default: 0.1 s per
    /// frame, from frame 0, looping, speed 1.
    AnimationDef animation{};
};

/// The UV rectangles of the animation `baseName` of `sheet` (SpriteSheet::animationFrames(),
/// natural numeric order), for AnimatedSpriteRendererDef::frames. Throws core::Error naming the
/// sheet and base name when there is no such frame, and naming the frame when one is stored
/// rotated (a rotated frame needs a rotated quad, which a sprite's UV rectangle cannot express).
[[nodiscard]] std::vector<Rect> animationUvs(const SpriteSheet& sheet, std::string_view baseName);

/// A SpriteRenderer whose UV rectangle plays a frame-by-frame Animation: every update(dt) of the
/// scene advances the animation by dt and shows its frame.
class AnimatedSpriteRenderer : public SpriteRenderer {
public:
    /// Throws core::Error naming an invalid field: no frames, a frame outside [0, 1], or an
    /// invalid animation ("render::AnimatedSpriteRenderer: frames must not be empty").
    explicit AnimatedSpriteRenderer(const AnimatedSpriteRendererDef& def);

    [[nodiscard]] Animation& animation() noexcept { return animation_; }
    [[nodiscard]] const Animation& animation() const noexcept { return animation_; }
    [[nodiscard]] const std::vector<Rect>& frames() const noexcept { return frames_; }

    void update(double dt) override;

private:
    std::vector<Rect> frames_;
    Animation animation_;
    int shown_ = -1;
};

} // namespace e2d::render
