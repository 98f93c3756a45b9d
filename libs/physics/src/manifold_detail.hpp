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

// A manifold in A's local frame, before the move to world space: only the fields the pair
// routines compute. Only the first `count` points are written: nothing is zeroed.
struct LocalManifold {
    Vec2 normal;    // from A to B, A's frame
    Vec2 points[2]; // midway between the surfaces, A's frame
    float separations[2];
    std::uint16_t ids[2];
    int count;
};

// Moves a manifold computed in A's local frame to world space: `point` becomes the world
// point, the anchors are relative to each transform's origin along world axes (ManifoldPoint).
// Built as one aggregate so that no zeroing of the whole Manifold precedes the writes.
inline ManifoldPoint toWorldPoint(Vec2 local, float separation, std::uint16_t id,
                                  const Transform& xfA, Vec2 shift) {
    const Vec2 anchorA = rotate(xfA.q, local);
    return ManifoldPoint{
        anchorA + xfA.p, anchorA, anchorA + shift, separation, 0.0f, 0.0f, id, false};
}

inline Manifold localToWorld(const LocalManifold& m, const Transform& xfA, const Transform& xfB) {
    if (m.count == 0) {
        // The rest of `m` is unwritten: rotating its stale normal read garbage, sometimes
        // denormal floats, which cost microcode assists.
        return Manifold{};
    }
    const Vec2 shift = xfA.p - xfB.p;
    return Manifold{rotate(xfA.q, m.normal),
                    {toWorldPoint(m.points[0], m.separations[0], m.ids[0], xfA, shift),
                     m.count > 1 ? toWorldPoint(m.points[1], m.separations[1], m.ids[1], xfA, shift)
                                 : ManifoldPoint{}},
                    m.count};
}

// One point in A's frame: the usual result of the round-shape routines.
inline Manifold singlePointToWorld(Vec2 localNormal, Vec2 localPoint, float separation,
                                   std::uint16_t id, const Transform& xfA, const Transform& xfB) {
    return Manifold{rotate(xfA.q, localNormal),
                    {toWorldPoint(localPoint, separation, id, xfA, xfA.p - xfB.p), ManifoldPoint{}},
                    1};
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
