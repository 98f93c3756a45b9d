// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/render/types.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

namespace e2d::render {

/// How the reference region (what the game was designed to show) is fitted to a screen of
/// another size. Outside the fitted region the screen is letterboxed
/// (black).
enum class ScreenFit {
    /// Stretch the reference region over the whole screen, distorting it if the aspect ratio
    /// differs. Never letterboxes.
    Expand,
    /// Scale uniformly so the reference width fills the screen width: the left and right edges
    /// stay at the screen's edges; top and bottom are cut off or letterboxed.
    WidthFit,
    /// Scale uniformly so the reference height fills the screen height: left and right are cut
    /// off or letterboxed.
    HeightFit,
    /// Whichever of WidthFit and HeightFit cuts nothing off: the whole reference region is
    /// visible, letterboxed on two sides.
    BestFit,
};

/// How a Camera starts. Camera's constructor validates every field.
struct CameraDef {
    /// World point at the centre of the view, world units, finite. Default (0, 0).
    glm::vec2 position{0.0f, 0.0f};
    /// Radians counter-clockwise, finite: the world appears rotated by -rotation. Default 0.
    float rotation = 0.0f;
    /// Magnification, > 0 and finite: 2 shows half as much of the world, twice as large.
    /// Default 1.
    float zoom = 1.0f;
    /// Size of the reference region, world units (at zoom 1 one world unit is one pixel of a
    /// screen of exactly this size), each > 0. Default 1280 x 720.
    glm::vec2 referenceSize{1280.0f, 720.0f};
    /// Default BestFit.
    ScreenFit fit = ScreenFit::BestFit;
};

/// A 2D orthographic camera and the conversions between its three spaces:
/// - world: world units, y up;
/// - camera: the HUD space. Origin at the centre of the view, axes along the screen's, units
///   are world units at zoom 1 (reference pixels); rotation and zoom do not apply to it;
/// - screen: framebuffer pixels, origin at the BOTTOM-LEFT of the screen, y up (OpenGL's
///   convention and glReadPixels'; GLFW's cursor position is y-down in screen coordinates,
///   convert with `y = height - y` times the window's content scale).
///
/// world -> camera: `zoom * R(-rotation) * (world - position)`;
/// camera -> screen: `screenSize / 2 + pixelsPerUnit() * camera`.
/// The screen size is set by the Renderer before each frame (so the camera refits on resize),
/// or by hand with setScreenSize().
class Camera {
public:
    /// Throws core::Error naming the invalid field ("render::Camera: zoom must be > 0, got 0").
    explicit Camera(const CameraDef& def = {});

    [[nodiscard]] glm::vec2 position() const noexcept { return def_.position; }
    void setPosition(glm::vec2 position);
    [[nodiscard]] float rotation() const noexcept { return def_.rotation; }
    void setRotation(float radians);
    [[nodiscard]] float zoom() const noexcept { return def_.zoom; }
    void setZoom(float zoom);
    [[nodiscard]] glm::vec2 referenceSize() const noexcept { return def_.referenceSize; }
    void setReferenceSize(glm::vec2 size);
    [[nodiscard]] ScreenFit fit() const noexcept { return def_.fit; }
    void setFit(ScreenFit fit);
    [[nodiscard]] const CameraDef& def() const noexcept { return def_; }

    /// Screen size in pixels, each >= 1. Default: the reference size rounded.
    [[nodiscard]] glm::ivec2 screenSize() const noexcept { return screen_; }
    void setScreenSize(glm::ivec2 pixels);

    /// Screen pixels per camera unit along x and y (equal unless Expand distorts).
    [[nodiscard]] glm::vec2 pixelsPerUnit() const noexcept;
    /// The part of the screen the reference region covers, clipped to the screen, pixels,
    /// bottom-left origin. Everything outside is letterboxed. Expand: the whole screen.
    [[nodiscard]] Rect screenRegion() const noexcept;
    /// Axis-aligned world bounds of what screenRegion() shows (for culling).
    [[nodiscard]] Rect visibleWorldBounds() const noexcept;

    [[nodiscard]] glm::vec2 worldToCamera(glm::vec2 world) const noexcept;
    [[nodiscard]] glm::vec2 cameraToWorld(glm::vec2 camera) const noexcept;
    [[nodiscard]] glm::vec2 cameraToScreen(glm::vec2 camera) const noexcept;
    [[nodiscard]] glm::vec2 screenToCamera(glm::vec2 screen) const noexcept;
    [[nodiscard]] glm::vec2 worldToScreen(glm::vec2 world) const noexcept;
    [[nodiscard]] glm::vec2 screenToWorld(glm::vec2 screen) const noexcept;

    /// World -> OpenGL clip space (x, y; z is left to the renderer).
    [[nodiscard]] glm::mat4 worldToClip() const noexcept;
    /// Camera (HUD) space -> clip space.
    [[nodiscard]] glm::mat4 cameraToClip() const noexcept;

private:
    CameraDef def_;
    glm::ivec2 screen_{1280, 720};
};

} // namespace e2d::render
