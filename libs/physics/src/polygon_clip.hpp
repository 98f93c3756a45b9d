// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/manifold.hpp>

namespace e2d::physics::detail {

/// Contact points of two polygons once the axis is known: the reference edge `edgeA` of `a`
/// and the incident edge `edgeB` of `b`, both polygons in the same frame (A's local frame).
/// `flip` swaps the roles (b holds the reference edge `edgeB`, a the incident edge `edgeA`).
/// Returns a manifold in that frame (normal from a to b); the caller transforms it to world.
/// Each point's `point` and `anchorA` hold its position in that frame (midway between the two
/// rounded surfaces); `anchorB` is left zero. Points with separation > margin are dropped.
/// Shared by SAT and GJK/EPA so both algorithms clip the same way.
Manifold clipPolygons(const Polygon& a, const Polygon& b, int edgeA, int edgeB, bool flip,
                      float margin);

} // namespace e2d::physics::detail
