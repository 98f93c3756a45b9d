// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/engine/frame_profile.hpp>
#include <e2d/render/render_system.hpp>

#include <cstdint>
#include <string>

namespace e2d::engine::detail {

/// The frame profile drawn by the engine in the top-left corner of the view: camera-space (HUD)
/// text over a translucent backdrop, nearest of everything drawn. Its text is the mean of each
/// phase over the frames since it last changed, refreshed every kRefreshFrames frames.
///
/// A RenderHook of the game's RenderSystem (added once; it survives scene changes). The font is
/// looked up every frame, as a scene change drops fonts.
class ProfileOverlay final : public render::RenderHook {
public:
    static constexpr int kRefreshFrames = 15;
    /// Font pixels. The text is drawn one font pixel per screen pixel.
    static constexpr int kPixelSize = 14;
    /// Text colour, opaque; the backdrop is black at 60 % opacity.
    static constexpr render::Color kColor{255, 230, 90, 255};

    /// `system` and `profile` must outlive the overlay. `depth`: the renderer's depth range
    /// (the overlay is drawn at its nearest z).
    ProfileOverlay(render::RenderSystem& system, const FrameProfile& profile, float depth) noexcept
        : system_(system), profile_(profile), depth_(depth) {}

    void setVisible(bool visible) noexcept { visible_ = visible; }
    [[nodiscard]] bool visible() const noexcept { return visible_; }
    /// The text shown (empty before the first frame drawn with the overlay on).
    [[nodiscard]] const std::string& text() const noexcept { return text_; }

    void beforeRender(render::Renderer& renderer) override;

private:
    void refresh();

    render::RenderSystem& system_;
    const FrameProfile& profile_;
    float depth_;
    bool visible_ = false;
    std::string text_;
    FrameProfile since_; // the profile when the text last changed
};

} // namespace e2d::engine::detail
