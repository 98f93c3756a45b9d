// SPDX-License-Identifier: MIT
#pragma once

// Small SSE2 helpers the narrow-phase face searches share (manifold_sat.cpp,
// manifold_round.cpp): four faces or vertices to a register, x and y apart. Only for SSE2
// targets; the callers keep a scalar path with the same results.
#if defined(__SSE2__)

#include <emmintrin.h>

#include <cstdint>

namespace e2d::physics::detail::sse {

// Lane L of v in every lane (pshufd: one instruction, where shufps would need a copy first).
template <int L>
inline __m128 splat(__m128 v) {
    return _mm_castsi128_ps(_mm_shuffle_epi32(_mm_castps_si128(v), L * 0x55));
}

// kLaneMasks[used]: all ones in the lanes below `used`.
alignas(16) inline constexpr std::uint32_t kLaneMasks[4][4] = {
    {0, 0, 0, 0}, {~0u, 0, 0, 0}, {~0u, ~0u, 0, 0}, {~0u, ~0u, ~0u, 0}};

// Lanes at or past `used` (1..3) repeat lane 0 of v: a repeated vertex changes no minimum, and
// a repeated face ties with the real one and loses the tie to its lower index, so the first
// best item still wins.
inline __m128 padLanes(__m128 v, int used) {
    const __m128 keep =
        _mm_castsi128_ps(_mm_load_si128(reinterpret_cast<const __m128i*>(kLaneMasks[used])));
    return _mm_or_ps(_mm_and_ps(keep, v), _mm_andnot_ps(keep, splat<0>(v)));
}

} // namespace e2d::physics::detail::sse

#endif
