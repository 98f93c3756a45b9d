// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/manifold.hpp>

namespace e2d::physics::detail {

// Decisions every polygon manifold makes the same way, whichever algorithm found the axis
// (SAT in manifold_sat.cpp, GJK/EPA in manifold_gjk_epa.cpp), so that the two agree.
//
// B's face separation must beat A's by this much (metres) before B's face becomes the
// reference: nearly equal faces then do not flip-flop between steps and change the ids.
inline constexpr float kFlipTolerance = 0.1f * kLinearSlop;
// Cores whose face separation exceeds this (metres) are "separated": their closest features,
// not the face, decide the contact (the face separation only bounds the gap from below).
inline constexpr float kSeparatedCores = 0.1f * kLinearSlop;
// Separated closest points offset along the reference face by at most this (metres) make a
// face contact (clipped, up to two points); more, and it is a vertex contact with one point
// along the closest-point direction. Only rounding noise of exactly parallel edges should
// pass: an angle test instead lets a point just past the face's end through, and clipping it
// to the face overstates its separation by the offset times the incident edge's slope.
inline constexpr float kFaceOffset = 0.01f * kLinearSlop;

// Moves a manifold computed in A's local frame to world space. On entry each point's `point`
// holds its position in A's frame; on exit `point` is the world point and the anchors are
// relative to each transform's origin along world axes, as ManifoldPoint documents.
inline Manifold localToWorld(Manifold m, const Transform& xfA, const Transform& xfB) {
    m.normal = rotate(xfA.q, m.normal);
    Vec2 shift = xfA.p - xfB.p;
    for (int i = 0; i < m.pointCount; ++i) {
        ManifoldPoint& mp = m.points[i];
        mp.anchorA = rotate(xfA.q, mp.point);
        mp.anchorB = mp.anchorA + shift;
        mp.point = mp.anchorA + xfA.p;
    }
    return m;
}

// A manifold's A and B swapped: the normal flips, the anchors and the two halves of each
// feature id trade places, so ids keep the (feature of A, feature of B) layout.
inline Manifold swapped(Manifold m) {
    m.normal = -m.normal;
    for (int i = 0; i < m.pointCount; ++i) {
        ManifoldPoint& mp = m.points[i];
        Vec2 anchor = mp.anchorA;
        mp.anchorA = mp.anchorB;
        mp.anchorB = anchor;
        mp.id = static_cast<std::uint16_t>((mp.id >> 8) | ((mp.id & 0xFF) << 8));
    }
    return m;
}

} // namespace e2d::physics::detail
