// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/render/image.hpp>

#include <cstdint>
#include <filesystem>

namespace e2d::assetgen {

/// A straight-alpha RGBA colour, 0..255 per channel.
struct Colour {
    std::uint8_t r = 0;
    std::uint8_t g = 0;
    std::uint8_t b = 0;
    std::uint8_t a = 255;
    friend bool operator==(const Colour&, const Colour&) = default;
};

/// `c` with alpha `a` (0..255).
[[nodiscard]] constexpr Colour withAlpha(Colour c, std::uint8_t a) noexcept {
    return {c.r, c.g, c.b, a};
}
/// Linear mix of two colours, t in [0, 1] (0 gives `a`).
[[nodiscard]] Colour mix(Colour a, Colour b, double t) noexcept;

/// An RGBA8 picture to paint assets on, pixels, origin at the top-left, y down (the order of
/// render::Image and of image files). Shapes are antialiased over one pixel and blended
/// "source over" onto what is there. Coordinates are floats: pixel (x, y) covers
/// [x, x + 1) x [y, y + 1), so a circle centred on (8, 8) is centred in a 16 x 16 canvas.
class Canvas {
public:
    /// A `width` x `height` canvas filled with `background` (default transparent black).
    /// Throws core::Error if a size is not positive.
    Canvas(int width, int height, Colour background = {0, 0, 0, 0});

    [[nodiscard]] int width() const noexcept { return image_.width; }
    [[nodiscard]] int height() const noexcept { return image_.height; }
    /// The pixels, top row first.
    [[nodiscard]] const render::Image& image() const noexcept { return image_; }
    /// The colour of pixel (x, y). Throws core::Error outside the canvas.
    [[nodiscard]] Colour pixel(int x, int y) const;

    /// Replaces every pixel with `colour` (no blending).
    void fill(Colour colour);
    /// Blends a filled axis-aligned rectangle (top-left x, y; size w x h, pixels).
    void fillRect(float x, float y, float w, float h, Colour colour);
    /// Blends a filled disc of `radius` pixels around (cx, cy).
    void fillCircle(float cx, float cy, float radius, Colour colour);
    /// Blends a ring `thickness` pixels wide centred on the circle of `radius` around (cx, cy).
    void strokeCircle(float cx, float cy, float radius, float thickness, Colour colour);
    /// Blends a filled rectangle with corners rounded by `radius` pixels.
    void fillRoundedRect(float x, float y, float w, float h, float radius, Colour colour);
    /// Blends the outline (`thickness` pixels wide, inside the rectangle) of a rounded rect.
    void strokeRoundedRect(float x, float y, float w, float h, float radius, float thickness,
                           Colour colour);
    /// Blends a rectangle whose colour goes linearly from `from` to `to`: top to bottom when
    /// `vertical`, else left to right.
    void linearGradient(float x, float y, float w, float h, Colour from, Colour to,
                        bool vertical = true);
    /// Blends a disc whose colour goes from `centre` at (cx, cy) to `edge` at `radius`.
    void radialGradient(float cx, float cy, float radius, Colour centre, Colour edge);
    /// Blends a line segment `thickness` pixels wide with round caps.
    void line(float x0, float y0, float x1, float y1, float thickness, Colour colour);
    /// Blends a filled triangle (any winding).
    void fillTriangle(float x0, float y0, float x1, float y1, float x2, float y2, Colour colour);
    /// Copies `source` with its top-left at (x, y), replacing pixels (no blending); parts
    /// outside this canvas are cut off.
    void copyFrom(const Canvas& source, int x, int y);

    /// Writes the canvas as a PNG (render::writePng). Throws core::Error naming the file.
    void writePng(const std::filesystem::path& path) const;

private:
    render::Image image_;
};

} // namespace e2d::assetgen
