// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/id.hpp>
#include <e2d/physics/math.hpp>

#include <cstdint>

/// What World queries (ray casts, overlap tests, shape casts) look for and what they return.
namespace e2d::physics {

/// Which shapes a query sees. A shape is seen when its Filter::categoryBits share a bit with
/// `maskBits` and its Filter::maskBits share a bit with `categoryBits`, like a core::Mask
/// match in both directions. Filter::group plays no part in queries.
struct QueryFilter {
    std::uint64_t categoryBits = 1;             ///< what the query is, default bit 0
    std::uint64_t maskBits = ~std::uint64_t{0}; ///< what it may see, default everything
    /// Whether sensor shapes are seen. Default false: sensors detect overlap, they are not
    /// solid, so rays pass through them and point/box queries skip them.
    bool includeSensors = false;
    /// Ray casts only. Default true: a ray reports only the points where it enters a shape.
    /// When false, the point where it leaves a solid shape is also reported ("back faces"),
    /// including the exit of a shape the ray starts inside. A segment, which
    /// has no inside, is hit once either way.
    bool ignoreBackFaces = true;
};

/// One ray or shape-cast hit, in world space.
struct RayResult {
    ShapeId shape;           ///< the shape hit
    Vec2 point{0.0f, 0.0f};  ///< where, metres
    Vec2 normal{0.0f, 0.0f}; ///< unit surface normal there, pointing out of the shape
    float fraction = 0.0f;   ///< point = origin + fraction * translation, in [0, 1]
    bool exit = false;       ///< true for a back-face hit: the ray leaves the shape here
};

} // namespace e2d::physics
