// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

namespace e2d::physics {

/// How a body moves. Static bodies never move and cost nothing per step; kinematic bodies move
/// by their velocity only; dynamic bodies respond to forces and contacts.
enum class BodyType : std::uint8_t { Static = 0, Kinematic = 1, Dynamic = 2 };
inline constexpr int kBodyTypeCount = 3;

/// Collision filtering. Two shapes may touch when each one's category matches the other's mask,
/// as with core::Mask (a bit set: two masks match when they share a bit). A non-zero
/// `group` overrides the masks: same positive group always collides, same negative never does.
struct Filter {
    std::uint64_t categoryBits = 1;             ///< what this shape is, default bit 0
    std::uint64_t maskBits = ~std::uint64_t{0}; ///< what it may touch, default everything
    std::int32_t group = 0;                     ///< default 0: masks decide
};

/// Whether shapes with these filters may touch.
constexpr bool shouldCollide(const Filter& a, const Filter& b) {
    if (a.group == b.group && a.group != 0) {
        return a.group > 0;
    }
    return (a.maskBits & b.categoryBits) != 0 && (a.categoryBits & b.maskBits) != 0;
}

} // namespace e2d::physics
