// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace e2d::render {

/// Which coordinates a debug shape is given in.
enum class DrawSpace : std::uint32_t {
    /// World units, through the renderer's camera (zoom, rotation, position).
    World = 0,
    /// Framebuffer pixels, origin at the bottom-left corner, y up; the camera is ignored.
    Screen = 1,
};

/// One line segment as the GPU reads it (one instance of a quad). 28 bytes.
struct DebugLine {
    glm::vec2 a{0.0f, 0.0f};
    glm::vec2 b{0.0f, 0.0f};
    /// Pixels, on screen whatever the space.
    float width = 1.0f;
    /// RGBA8, red in the lowest byte.
    std::uint32_t color = 0xFFFFFFFFu;
    DrawSpace space = DrawSpace::World;
};

/// One vertex of a filled triangle as the GPU reads it. 16 bytes.
struct DebugVertex {
    glm::vec2 position{0.0f, 0.0f};
    /// RGBA8, red in the lowest byte.
    std::uint32_t color = 0xFFFFFFFFu;
    DrawSpace space = DrawSpace::World;
};

/// Debug drawing: lines, rectangles, circles and polygons, outlined or filled, in world or
/// screen space, collected during a frame and drawn by the Renderer after the sprites (on top
/// of them, no depth test) in at most two draw calls: every line as one instanced quad each,
/// every filled shape as triangles of one buffer. The Renderer clears it after each frame.
///
/// Line widths are in screen pixels in both spaces (a debug line stays readable at any zoom);
/// segment ends are extended by half the width, so outlines have square corners. Colours are
/// RGBA in [0, 1] (clamped). Shapes with non-finite coordinates, widths or radii, widths <= 0
/// or radii < 0 are skipped: debug drawing never throws.
class Drawer {
public:
    /// A segment from `a` to `b`. Default width 1 px.
    void line(glm::vec2 a, glm::vec2 b, glm::vec4 color, float width = 1.0f,
              DrawSpace space = DrawSpace::World);
    /// The outline of the axis-aligned rectangle from `min` to `max`.
    void rect(glm::vec2 min, glm::vec2 max, glm::vec4 color, float width = 1.0f,
              DrawSpace space = DrawSpace::World);
    /// The axis-aligned rectangle from `min` to `max`, filled.
    void fillRect(glm::vec2 min, glm::vec2 max, glm::vec4 color,
                  DrawSpace space = DrawSpace::World);
    /// The outline of a circle. `segments` < 3 picks a count from the radius (16 to 128).
    void circle(glm::vec2 center, float radius, glm::vec4 color, float width = 1.0f,
                DrawSpace space = DrawSpace::World, int segments = 0);
    /// A filled circle (a fan of `segments` triangles; < 3 picks a count from the radius).
    void fillCircle(glm::vec2 center, float radius, glm::vec4 color,
                    DrawSpace space = DrawSpace::World, int segments = 0);
    /// The closed outline through `points` (2 points: one segment).
    void polygon(std::span<const glm::vec2> points, glm::vec4 color, float width = 1.0f,
                 DrawSpace space = DrawSpace::World);
    /// A filled simple polygon (convex or concave, either winding, no self-intersection),
    /// triangulated by ear clipping. Fewer than 3 points draw nothing.
    void fillPolygon(std::span<const glm::vec2> points, glm::vec4 color,
                     DrawSpace space = DrawSpace::World);

    /// Forgets everything drawn so far.
    void clear() noexcept;

    /// Lines collected so far, in call order (outlines add one line per edge).
    [[nodiscard]] std::span<const DebugLine> lines() const noexcept { return lines_; }
    /// Filled triangles so far, three vertices each, in call order.
    [[nodiscard]] std::span<const DebugVertex> triangles() const noexcept { return triangles_; }
    [[nodiscard]] bool empty() const noexcept { return lines_.empty() && triangles_.empty(); }

private:
    void triangle(glm::vec2 a, glm::vec2 b, glm::vec2 c, std::uint32_t color, DrawSpace space);

    std::vector<DebugLine> lines_;
    std::vector<DebugVertex> triangles_;
    std::vector<int> scratch_;
};

/// Packs an RGBA colour in [0, 1] (clamped) as RGBA8, red in the lowest byte.
[[nodiscard]] std::uint32_t packColor(glm::vec4 color) noexcept;

} // namespace e2d::render
