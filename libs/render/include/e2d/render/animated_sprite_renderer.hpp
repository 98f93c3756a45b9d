// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/render/animation.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/sprite_sheet.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace e2d::render {

/// How an AnimatedSpriteRenderer starts.
struct AnimatedSpriteRendererDef {
    /// TexturePacker JSON sheet (hash or array), read once per RenderSystem
    /// (RenderSystem::sheet()); its image is loaded through the Renderer's texture cache.
    /// A missing or broken sheet is logged once and the sprite shows the checker placeholder.
    std::filesystem::path sheetPath;
    /// The frames played: those named `animation` + a number (+ an extension), in numeric
    /// order (SpriteSheet::animationFrames), e.g. "run" plays run1.png, run2.png, ...
    std::string animation;
    /// Seconds per frame at speed 1, finite, > 0. Default 0.1.
    double frameDuration = 0.1;
    /// Default Loop.
    AnimationMode mode = AnimationMode::Loop;
    /// Frame shown first (clamped to the animation's frames). Default 0.
    int startFrame = 0;
    /// Playback speed, finite, >= 0. Default 1.
    double speed = 1.0;
    /// Everything else about the sprite (size (0, 0): the frame's size in pixels, pivot, tint,
    /// flips, parallax, HUD, z offset). Its texture, texturePath and uv are ignored: they come
    /// from the sheet. Frames are drawn at their stored size (trimming offsets are not applied).
    SpriteRendererDef sprite{};
};

/// A SpriteRenderer that plays a frame-by-frame animation from a sprite sheet: each update(dt)
/// advances a render::Animation and shows its frame.
class AnimatedSpriteRenderer : public SpriteRenderer {
public:
    /// Throws core::Error naming an invalid field (frameDuration, speed, or the sprite's).
    explicit AnimatedSpriteRenderer(const AnimatedSpriteRendererDef& def);

    /// The playing animation; nullopt until the component starts, or when the sheet could not
    /// be read or has no such frames.
    [[nodiscard]] const std::optional<Animation>& animation() const noexcept { return animation_; }
    /// Name of the animation playing.
    [[nodiscard]] const std::string& animationName() const noexcept { return name_; }
    /// Switches to the frames named `name` from its first frame (no change if it already plays
    /// them, unless `restart`). Unknown names are logged once and keep the current animation.
    void play(const std::string& name, bool restart = false);
    /// Changes the playback speed (finite, >= 0; core::Error otherwise).
    void setSpeed(double speed);

    void onInitialize() override;
    void update(double dt) override;

private:
    void showFrame();

    AnimatedSpriteRendererDef animDef_;
    const SpriteSheet* sheet_ = nullptr;
    std::string name_;
    std::vector<int> frames_;
    std::optional<Animation> animation_;
    int shown_ = -1;
};

} // namespace e2d::render
