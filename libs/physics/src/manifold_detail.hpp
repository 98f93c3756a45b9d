// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/manifold.hpp>

#include "sse_lanes.hpp"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

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
#if defined(__SSE2__)
    // The scalar code below, both points at once (x0 y0 x1 y1 in one register) and the result
    // stored as 16-byte blocks instead of field by field: about half the instructions. Each
    // lane does the scalar products and sums (c x - s y as c x + (-s) y, s x + c y as c y + s x,
    // both exact rewrites), so the Manifold is bit-identical to the scalar one.
    const __m128 xf = _mm_loadu_ps(&xfA.p.x); // p.x p.y c s
    const __m128 c = sse::splat<2>(xf);
    const __m128 signedS = _mm_xor_ps(sse::splat<3>(xf), _mm_setr_ps(-0.0f, 0.0f, -0.0f, 0.0f));
    const __m128 first = _mm_castpd_ps(_mm_load_sd(reinterpret_cast<const double*>(&m.points[0])));
    // A one-point manifold leaves points[1] unwritten: lane 0's point is rotated twice instead.
    const __m128 local = m.count > 1
                             ? _mm_loadh_pi(first, reinterpret_cast<const __m64*>(&m.points[1]))
                             : _mm_movelh_ps(first, first);
    auto rotateLanes = [&](__m128 v) {
        return _mm_add_ps(_mm_mul_ps(c, v),
                          _mm_mul_ps(signedS, _mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 3, 0, 1))));
    };
    const __m128 anchorA = rotateLanes(local);
    const __m128 pA = _mm_movelh_ps(xf, xf);
    const __m128 pB = _mm_castpd_ps(_mm_load1_pd(reinterpret_cast<const double*>(&xfB.p)));
    const __m128 world = _mm_add_ps(anchorA, pA);
    const __m128 anchorB = _mm_add_ps(anchorA, _mm_sub_ps(pA, pB));
    const __m128 normal = rotateLanes(
        _mm_castpd_ps(_mm_load_sd(reinterpret_cast<const double*>(&m.normal)))); // lanes 0-1
    // Separation, then the zero impulses, then the id with `persisted` (false) and padding.
    auto tail = [](float separation, std::uint16_t id) {
        return _mm_castsi128_ps(_mm_setr_epi32(std::bit_cast<std::int32_t>(separation), 0, 0,
                                               static_cast<std::int32_t>(id)));
    };
    static_assert(
        offsetof(Manifold, normal) == 0 && offsetof(Manifold, points) == 8 &&
        offsetof(ManifoldPoint, anchorA) == 8 && offsetof(ManifoldPoint, anchorB) == 16 &&
        offsetof(ManifoldPoint, separation) == 24 && offsetof(ManifoldPoint, normalImpulse) == 28 &&
        offsetof(ManifoldPoint, tangentImpulse) == 32 && offsetof(ManifoldPoint, id) == 36 &&
        offsetof(ManifoldPoint, persisted) == 38 && sizeof(ManifoldPoint) == 40 &&
        offsetof(Manifold, pointCount) == 88 && sizeof(Manifold) == 92);
    Manifold out;
    auto* bytes = reinterpret_cast<unsigned char*>(&out);
    auto store = [&](std::size_t offset, __m128 v) { std::memcpy(bytes + offset, &v, 16); };
    store(0, _mm_movelh_ps(normal, world));     // normal, points[0].point
    store(16, _mm_movelh_ps(anchorA, anchorB)); // points[0].anchorA, .anchorB
    store(32, tail(m.separations[0], m.ids[0]));
    std::int32_t last[3] = {0, 0, 1}; // points[1].tangentImpulse, id and flag, pointCount
    if (m.count > 1) {
        store(48, _mm_shuffle_ps(world, anchorA, _MM_SHUFFLE(3, 2, 3, 2)));
        // points[1].anchorB, separation and normalImpulse (0), then the rest from `last`.
        const __m128 t = tail(m.separations[1], m.ids[1]);
        store(64, _mm_shuffle_ps(anchorB, t, _MM_SHUFFLE(1, 0, 3, 2)));
        last[1] = static_cast<std::int32_t>(m.ids[1]);
        last[2] = 2;
    } else {
        store(48, _mm_setzero_ps());
        store(64, _mm_setzero_ps());
    }
    std::memcpy(bytes + 80, last, sizeof last);
    return out;
#else
    const Vec2 shift = xfA.p - xfB.p;
    return Manifold{rotate(xfA.q, m.normal),
                    {toWorldPoint(m.points[0], m.separations[0], m.ids[0], xfA, shift),
                     m.count > 1 ? toWorldPoint(m.points[1], m.separations[1], m.ids[1], xfA, shift)
                                 : ManifoldPoint{}},
                    m.count};
#endif
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
