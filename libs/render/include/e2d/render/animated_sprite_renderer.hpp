// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/render/animation.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/sprite_sheet.hpp>

#include <string_view>
#include <vector>

namespace e2d::render {

/// One frame of an animation: where its image lies in the texture.
struct AnimationFrame {
    /// UV rectangle, as SpriteDef::uv (fractions, top-left origin, inside [0, 1]). Default empty.
    Rect uv{};
    /// The image is stored turned 90 degrees clockwise in `uv` (SpriteFrame::rotated, shown
    /// upright as SpriteDef::uvRotated). Default false.
    bool rotated = false;
    /// Upright size of the frame, pixels (SpriteFrame::size()), used as the sprite's size while
    /// the sprite's own size is (0, 0); (0, 0): the texture's size times the `uv` extent. A
    /// frame that carries its size keeps it when the sheet's image failed to load and the 64 x
    /// 64 placeholder is drawn instead. Default (0, 0).
    glm::vec2 size{0.0f, 0.0f};
};

/// How an AnimatedSpriteRenderer starts.
struct AnimatedSpriteRendererDef {
    /// The sprite (texture, size, pivot, tint, ...); its `uv` and `uvRotated` are replaced by
    /// the current frame's, and so is its size while it is (0, 0).
    SpriteRendererDef sprite{};
    /// The frames in playing order, at least one. Default none.
    std::vector<AnimationFrame> frames{};
    /// Timing; its `frameCount` is ignored (the number of `frames` is used). Default: 0.1 s per
    /// frame, from frame 0, looping, speed 1.
    AnimationDef animation{};
};

/// The frames of the animation `baseName` of `sheet` (SpriteSheet::animationFrames(), natural
/// numeric order) with their UV rectangles, rotation and size, for AnimatedSpriteRendererDef::frames.
/// Frames stored rotated are shown upright. Throws core::Error naming the sheet and base name
/// when there is no such frame.
[[nodiscard]] std::vector<AnimationFrame> animationUvs(const SpriteSheet& sheet,
                                                       std::string_view baseName);

/// A SpriteRenderer whose UV rectangle plays a frame-by-frame Animation: every update(dt) of the
/// scene advances the animation by dt and shows its frame.
class AnimatedSpriteRenderer : public SpriteRenderer {
public:
    /// Throws core::Error naming an invalid field: no frames, a frame outside [0, 1], or an
    /// invalid animation ("render::AnimatedSpriteRenderer: frames must not be empty").
    explicit AnimatedSpriteRenderer(const AnimatedSpriteRendererDef& def);

    [[nodiscard]] Animation& animation() noexcept { return animation_; }
    [[nodiscard]] const Animation& animation() const noexcept { return animation_; }
    [[nodiscard]] const std::vector<AnimationFrame>& frames() const noexcept { return frames_; }

    void update(double dt) override;

private:
    std::vector<AnimationFrame> frames_;
    Animation animation_;
    int shown_ = -1;
    // The def's size was (0, 0): every frame shows at its own size.
    bool frameSized_ = false;
};

} // namespace e2d::render
