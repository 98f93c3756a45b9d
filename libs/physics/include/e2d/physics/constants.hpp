// SPDX-License-Identifier: MIT
#pragma once

/// Tuning constants shared by collision and dynamics. Lengths are in metres: e2d is tuned for
/// moving objects of 0.1 m to 10 m, like Box2D. Scale game units to metres at the boundary.
namespace e2d::physics {

/// The most vertices a convex polygon may have.
inline constexpr int kMaxPolygonVertices = 8;
/// Collision and constraint tolerance, metres. Points closer than this are welded by the hull.
inline constexpr float kLinearSlop = 0.005f;
/// Default margin within which not-yet-touching points are reported in a manifold, metres.
inline constexpr float kSpeculativeDistance = 4.0f * kLinearSlop;
/// How far the broad phase fattens a moving shape's box, metres.
inline constexpr float kAabbMargin = 0.1f;
/// Coordinates beyond this magnitude are rejected, metres.
inline constexpr float kHuge = 100000.0f;

} // namespace e2d::physics
