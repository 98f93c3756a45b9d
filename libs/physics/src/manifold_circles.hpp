// SPDX-License-Identifier: MIT
#pragma once

// collideCircles() inline, for the narrow phase's loop over contacts (contact.cpp): the call,
// and the registers that loop spilled around it, were about 20 instructions a circle pair, as
// much as the routine itself for a pair that does not touch (most of a ball pit's contacts).
// manifold_round.cpp defines collideCircles() with it.
#include <e2d/physics/manifold.hpp>

#include <bit>
#include <cfloat>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

#if defined(__SSE2__)
#include "sse_lanes.hpp"

#include <emmintrin.h>
#endif

namespace e2d::physics::detail {

// Both circles centred on their bodies (centres +0, as most are): the centres need no rotation.
// Compared as bits, so a centre of -0 takes the general path (which it matches but for signed
// zeros). Both collideCircles paths test this, so they stay bit-identical.
inline bool bothCentred(const Circle& a, const Circle& b) {
    return (std::bit_cast<std::uint64_t>(a.center) | std::bit_cast<std::uint64_t>(b.center)) == 0;
}

#if defined(__SSE2__)

namespace sse {

// Lanes of v in the order `Imm` (_MM_SHUFFLE) names: one pshufd where shufps of a register
// with itself needs a copy first.
template <int Imm>
inline __m128 permute(__m128 v) {
    return _mm_castsi128_ps(_mm_shuffle_epi32(_mm_castps_si128(v), Imm));
}

} // namespace sse

// The SSE2 circle pair builds the Manifold's bytes in registers: these are the offsets it
// writes (normal and first point's world point, the two anchors, the separation and the
// zeros after it, the second point, the count).
static_assert(offsetof(Manifold, normal) == 0 && offsetof(Manifold, points) == 8);
static_assert(offsetof(ManifoldPoint, point) == 0 && offsetof(ManifoldPoint, anchorA) == 8 &&
              offsetof(ManifoldPoint, anchorB) == 16 && offsetof(ManifoldPoint, separation) == 24 &&
              offsetof(ManifoldPoint, normalImpulse) == 28 && sizeof(ManifoldPoint) == 40);
static_assert(offsetof(Manifold, pointCount) == 88 && sizeof(Manifold) == 92);
static_assert(std::is_trivially_copyable_v<Manifold>);

// The first half of collideCirclesSse2(): the centres relative to A's origin along world axes
// and the radii's sum, enough to tell whether the pair is within a margin. The narrow phase
// asks that first with the largest margin it can use (contact.cpp), before it works out the
// pair's own.
struct CircleGapSse2 {
    __m128 tA;     // pA.x pA.y cA sA
    __m128 tB;     // pB.x pB.y cB sB
    __m128 cA;     // lanes 0-1: A's centre (lanes 2-3 hold finite leftovers, not read)
    __m128 d;      // lanes 0-1: B's centre - A's centre
    __m128 distSq; // lane 0: |d|^2
    __m128 radius; // lane 0: the radii's sum; the upper lanes zero (the separation is stored
                   // from it)

    // Whether the circles are farther apart than `margin`, where collideCircles() finds no
    // point. For margins m1 <= m2 (>= 0), beyond(m2) implies beyond(m1): sums and squares of
    // non-negative floats round monotonically.
    [[nodiscard]] bool beyond(float margin) const {
        const float limit = _mm_cvtss_f32(radius) + margin;
        return _mm_cvtss_f32(distSq) > limit * limit;
    }
};

[[gnu::always_inline]] inline CircleGapSse2 circleGapSse2(const Circle& a, const Transform& xfA,
                                                          const Circle& b, const Transform& xfB) {
    // collideCircles()'s scalar routine (manifold_round.cpp) two lanes at a time: both centres
    // rotated in one register (centred circles skip it, as there). Each lane does the scalar
    // code's products and sums in its order (a - b as a + -b, which is exact), so the Manifold
    // is bit-identical to it (manifold_round_scalar_test).
    CircleGapSse2 g;
    g.tA = _mm_loadu_ps(&xfA.p.x);
    g.tB = _mm_loadu_ps(&xfB.p.x);
    g.cA = _mm_setzero_ps();
    __m128 cB = _mm_sub_ps(g.tB, g.tA);
    if (!bothCentred(a, b)) {
        const __m128 centres = _mm_loadh_pi(
            _mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(&a.center.x))),
            reinterpret_cast<const __m64*>(&b.center.x)); // a.x a.y b.x b.y
        const __m128 cosSin = _mm_shuffle_ps(g.tA, g.tB, _MM_SHUFFLE(3, 2, 3, 2));
        // Lanes 0-1 rotate(qA, a.center), lanes 2-3 rotate(qB, b.center).
        g.cA = _mm_add_ps(_mm_mul_ps(cosSin, sse::permute<_MM_SHUFFLE(2, 2, 0, 0)>(centres)),
                          _mm_xor_ps(_mm_mul_ps(sse::permute<_MM_SHUFFLE(2, 3, 0, 1)>(cosSin),
                                                sse::permute<_MM_SHUFFLE(3, 3, 1, 1)>(centres)),
                                     _mm_setr_ps(-0.0f, 0.0f, -0.0f, 0.0f)));
        cB = _mm_add_ps(sse::permute<_MM_SHUFFLE(3, 2, 3, 2)>(g.cA), cB);
    }
    g.d = _mm_sub_ps(cB, g.cA);
    const __m128 dd = _mm_mul_ps(g.d, g.d);
    g.distSq = _mm_add_ss(dd, sse::splat<1>(dd));
    // The radii loaded as vectors (upper lanes zero). (Sums written b + a where the scalar code
    // has a + b: the same value, and a.radius is then read from memory by the addition instead
    // of kept in a register.)
    g.radius = _mm_add_ss(_mm_load_ss(&b.radius), _mm_load_ss(&a.radius));
    return g;
}

// The second half: the manifold of circles within the margin (!gap.beyond(margin)), written
// over `out` (all its bytes); `a` is the pair's first circle. The normal is divided in one
// instruction, and the result stored as 16-byte blocks instead of one store per field.
[[gnu::always_inline]] inline void storeCircleManifoldSse2(const CircleGapSse2& gap,
                                                           const Circle& a, Manifold& out) {
    const __m128 dist = _mm_sqrt_ss(gap.distSq);
    __m128 normal;
    if (_mm_cvtss_f32(dist) > FLT_EPSILON) [[likely]] {
        normal = _mm_div_ps(gap.d, sse::splat<0>(dist));
    } else {
        // Concentric: A's x axis, as collideCircles() has it.
        normal = sse::permute<_MM_SHUFFLE(3, 2, 3, 2)>(gap.tA);
    }
    const __m128 separation = _mm_sub_ss(dist, gap.radius);
    const __m128 anchorA = _mm_add_ps(
        gap.cA, _mm_mul_ps(sse::splat<0>(_mm_add_ss(_mm_mul_ss(_mm_set_ss(0.5f), separation),
                                                    _mm_load_ss(&a.radius))),
                           normal));
    // Lanes 0-1 the world point (anchorA + pA), lanes 2-3 anchorB (anchorA + (pA - pB)).
    const __m128 pointAnchorB = _mm_add_ps(_mm_movelh_ps(anchorA, anchorA),
                                           _mm_movelh_ps(gap.tA, _mm_sub_ps(gap.tA, gap.tB)));
    auto* bytes = reinterpret_cast<unsigned char*>(&out);
    const __m128 zero = _mm_setzero_ps();
    const __m128 blocks[3] = {_mm_movelh_ps(normal, pointAnchorB),
                              _mm_shuffle_ps(anchorA, pointAnchorB, _MM_SHUFFLE(3, 2, 1, 0)),
                              _mm_move_ss(zero, separation)};
    std::memcpy(bytes, &blocks[0], 16);
    std::memcpy(bytes + 16, &blocks[1], 16);
    std::memcpy(bytes + 32, &blocks[2], 16);
    std::memcpy(bytes + 48, &zero, 16);
    std::memcpy(bytes + 64, &zero, 16);
    // The second point's last 8 bytes and the count.
    constexpr std::int32_t tail[3] = {0, 0, 1};
    std::memcpy(bytes + 80, tail, sizeof tail);
}

// Manifold{} (all zero bytes) written over `out` as 16-byte blocks: assigned, it is built on the
// stack and copied, and a memset of its 92 bytes is a rep stos of a dozen steps.
[[gnu::always_inline]] inline void storeNoManifoldSse2(Manifold& out) {
    auto* bytes = reinterpret_cast<unsigned char*>(&out);
    const __m128 zero = _mm_setzero_ps();
    for (std::size_t offset = 0; offset < 80; offset += 16) {
        std::memcpy(bytes + offset, &zero, 16);
    }
    std::memcpy(bytes + sizeof(Manifold) - 16, &zero, 16); // the last 12, overlapping
}

[[gnu::always_inline]] inline Manifold collideCirclesSse2(const Circle& a, const Transform& xfA,
                                                          const Circle& b, const Transform& xfB,
                                                          float margin) {
    const CircleGapSse2 gap = circleGapSse2(a, xfA, b, xfB);
    Manifold m;
    if (!gap.beyond(margin)) {
        storeCircleManifoldSse2(gap, a, m);
    }
    return m;
}

#endif

} // namespace e2d::physics::detail
