// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec2.hpp>

#include <cstdint>

/// Small value types shared by the render library's headers.
namespace e2d::render {

/// An 8-bit RGBA colour (straight, not premultiplied alpha). Default opaque white.
struct Color {
    std::uint8_t r = 255;
    std::uint8_t g = 255;
    std::uint8_t b = 255;
    std::uint8_t a = 255;

    friend constexpr bool operator==(Color, Color) = default;
};

/// An axis-aligned rectangle: `min` is its corner with the smallest coordinates, `size` its
/// extent (both components >= 0 for a valid rectangle). Units depend on where it is used.
struct Rect {
    glm::vec2 min{0.0f, 0.0f};
    glm::vec2 size{0.0f, 0.0f};

    [[nodiscard]] constexpr glm::vec2 max() const { return min + size; }
    friend constexpr bool operator==(const Rect&, const Rect&) = default;
};

/// The whole image as a UV rectangle: (0, 0) to (1, 1).
inline constexpr Rect kFullUv{{0.0f, 0.0f}, {1.0f, 1.0f}};

} // namespace e2d::render
