// SPDX-License-Identifier: MIT
#pragma once

#include "solver_body.hpp"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

// Lane vectors for the passes that solve several constraints at a time (contacts, plain
// hinges): the vector types of four and eight lanes and, per width, splat, select, maxOf,
// anyLane, allLanes, laneBits, laneMaskOf, lanesOf and bodiesAt (where each lane reads and
// writes its body), transposeRows, and loadRows/storeRows, which gather BodyStates (or any
// rows of four floats, one per lane) into lane vectors and scatter BodyStates back with
// shuffles only. Four lanes everywhere (SSE2 on x86-64, NEON on ARM64, plain scalar code where
// the target has no SIMD); eight on x86-64 (AVX2, E2D_HAS_WIDE8), for code
// that checked the CPU at run time. No "fma" in the target: a fused multiply-add rounds once
// where the scalar code rounds twice, so every width gives the scalar results.
namespace e2d::physics::detail {

using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));
using Float8 = float __attribute__((vector_size(32)));
using Int8 = std::int32_t __attribute__((vector_size(32)));

template <int N>
struct WideLanes;
template <>
struct WideLanes<4> {
    using F = Float4;
    using I = Int4;
};
template <>
struct WideLanes<8> {
    using F = Float8;
    using I = Int8;
};

// A static side (index -1) reads a resting state and writes nothing.
inline const BodyState kStaticState{};

// Where each of N lanes reads its body (a static side: a resting state) and writes it back
// (a static side: `sink`, never read). Unconditional stores cost less than a branch per lane.
// Plain code for every width: it inlines into the AVX2 kernels as into the others.
template <int N>
__attribute__((always_inline)) inline void
lanesOf(const int (&index)[N], std::span<BodyState> states, BodyState& sink,
        const BodyState* (&in)[N], BodyState* (&out)[N]) {
    for (int i = 0; i < N; ++i) {
        const bool moving = index[i] >= 0;
        BodyState* s = states.data() + (moving ? index[i] : 0);
        in[i] = moving ? s : &kStaticState;
        out[i] = moving ? s : &sink;
    }
}

// Where each of N lanes reads and writes its body, one address for both: a static side (index
// -1) gets `pad`, a resting state of the caller's, reset before the lanes are read. All lanes
// are read before any is written, so a static side reads a resting state whatever the others
// write to the pad. Half the addresses of lanesOf(); the contact groups work them out once a
// step and keep them (WideConstraintT::bodyA and bodyB).
template <int N>
__attribute__((always_inline)) inline void bodiesAt(const int (&index)[N], BodyState* states,
                                                    BodyState* pad, BodyState* (&at)[N]) {
    for (int i = 0; i < N; ++i) {
        at[i] = index[i] >= 0 ? states + index[i] : pad;
    }
}

// BodyState is two 16-byte rows, {vx, vy, w, flags} and {dpx, dpy, qc, qs}: a lane's row is one
// load, and rows transpose into lane vectors (and back) with shuffles only, which move bits
// unchanged (flags included).
static_assert(sizeof(BodyState) == 32, "BodyState must stay two 16-byte rows");
static_assert(offsetof(BodyState, linearVelocity) == 0 &&
                  offsetof(BodyState, angularVelocity) == 8 &&
                  offsetof(BodyState, deltaPosition) == 16 &&
                  offsetof(BodyState, deltaRotation) == 24,
              "BodyState rows out of order");

// The 16 bytes `offset` bytes into *s (a BodyState row, or four floats of another object).
template <class T>
inline Float4 loadRow(const T* s, std::size_t offset) {
    Float4 row;
    std::memcpy(&row, reinterpret_cast<const unsigned char*>(s) + offset, sizeof row);
    return row;
}

inline void storeRow(BodyState& s, Float4 row) {
    // BodyState is trivially copyable: its first row takes the lane whole.
    std::memcpy(reinterpret_cast<unsigned char*>(&s), &row, sizeof row);
}

namespace lanes4 {

constexpr int N = 4;
using F = Float4;
using I = Int4;

inline F splat(float x) { return F{x, x, x, x}; }
// mask ? a : b, lane by lane (mask lanes are all ones or all zeros).
inline F select(I mask, F a, F b) {
    return std::bit_cast<F>((mask & std::bit_cast<I>(a)) | (~mask & std::bit_cast<I>(b)));
}
// std::max(a, b) lane by lane, with its exact semantics (a on ties and NaNs): MAXPS returns
// its second operand unless the first is greater, which is the same rule with the operands
// swapped.
inline F maxOf(F a, F b) {
#if defined(__x86_64__)
    return _mm_max_ps(b, a);
#else
    return select(a < b, b, a);
#endif
}
inline bool anyLane(I mask) {
#if defined(__x86_64__)
    return _mm_movemask_ps(std::bit_cast<__m128>(mask)) != 0;
#else
    return (mask[0] | mask[1] | mask[2] | mask[3]) != 0;
#endif
}
inline bool allLanes(I mask) {
#if defined(__x86_64__)
    return _mm_movemask_ps(std::bit_cast<__m128>(mask)) == 0xF;
#else
    return (mask[0] & mask[1] & mask[2] & mask[3]) == -1;
#endif
}
// One bit per lane, lane k in bit k.
inline int laneBits(I mask) {
#if defined(__x86_64__)
    return _mm_movemask_ps(std::bit_cast<__m128>(mask));
#else
    return (mask[0] & 1) | (mask[1] & 2) | (mask[2] & 4) | (mask[3] & 8);
#endif
}

// The mask whose lane k is all ones where bit k of `bits` is set (laneBits() undone).
inline I laneMaskOf(int bits) { return ((I{} + bits) & I{1, 2, 4, 8}) != I{}; }

inline void transposeRows(F r0, F r1, F r2, F r3, F& c0, F& c1, F& c2, F& c3) {
    F t0 = __builtin_shufflevector(r0, r1, 0, 4, 1, 5);
    F t1 = __builtin_shufflevector(r2, r3, 0, 4, 1, 5);
    F t2 = __builtin_shufflevector(r0, r1, 2, 6, 3, 7);
    F t3 = __builtin_shufflevector(r2, r3, 2, 6, 3, 7);
    c0 = __builtin_shufflevector(t0, t1, 0, 1, 4, 5);
    c1 = __builtin_shufflevector(t0, t1, 2, 3, 6, 7);
    c2 = __builtin_shufflevector(t2, t3, 0, 1, 4, 5);
    c3 = __builtin_shufflevector(t2, t3, 2, 3, 6, 7);
}

// Lane k's row (`offset` bytes into *s[k]) transposed: float j of it in lane k of c_j.
template <class T>
inline void loadRows(const T* const* s, std::size_t offset, F& c0, F& c1, F& c2, F& c3) {
    transposeRows(loadRow(s[0], offset), loadRow(s[1], offset), loadRow(s[2], offset),
                  loadRow(s[3], offset), c0, c1, c2, c3);
}

inline void storeRows(F c0, F c1, F c2, F c3, BodyState* const* out) {
    F r0, r1, r2, r3;
    transposeRows(c0, c1, c2, c3, r0, r1, r2, r3);
    storeRow(*out[0], r0);
    storeRow(*out[1], r1);
    storeRow(*out[2], r2);
    storeRow(*out[3], r3);
}

} // namespace lanes4

#if defined(__x86_64__)
#define E2D_HAS_WIDE8 1
#define E2D_AVX2_FN __attribute__((target("avx2"))) inline

namespace lanes8 {

constexpr int N = 8;
using F = Float8;
using I = Int8;

E2D_AVX2_FN F splat(float x) { return F{x, x, x, x, x, x, x, x}; }
E2D_AVX2_FN F select(I mask, F a, F b) { return _mm256_blendv_ps(b, a, (__m256)mask); }
E2D_AVX2_FN F maxOf(F a, F b) { return _mm256_max_ps(b, a); }
E2D_AVX2_FN bool anyLane(I mask) { return _mm256_movemask_ps((__m256)mask) != 0; }
E2D_AVX2_FN bool allLanes(I mask) { return _mm256_movemask_ps((__m256)mask) == 0xFF; }
E2D_AVX2_FN int laneBits(I mask) { return _mm256_movemask_ps((__m256)mask); }
E2D_AVX2_FN I laneMaskOf(int bits) {
    return ((I{} + bits) & I{1, 2, 4, 8, 16, 32, 64, 128}) != I{};
}

// Rows k and k + 4 share a vector (low and high half); the halves transpose independently.
E2D_AVX2_FN void transposeRows(F r0, F r1, F r2, F r3, F& c0, F& c1, F& c2, F& c3) {
    F t0 = __builtin_shufflevector(r0, r1, 0, 8, 1, 9, 4, 12, 5, 13);
    F t1 = __builtin_shufflevector(r2, r3, 0, 8, 1, 9, 4, 12, 5, 13);
    F t2 = __builtin_shufflevector(r0, r1, 2, 10, 3, 11, 6, 14, 7, 15);
    F t3 = __builtin_shufflevector(r2, r3, 2, 10, 3, 11, 6, 14, 7, 15);
    c0 = __builtin_shufflevector(t0, t1, 0, 1, 8, 9, 4, 5, 12, 13);
    c1 = __builtin_shufflevector(t0, t1, 2, 3, 10, 11, 6, 7, 14, 15);
    c2 = __builtin_shufflevector(t2, t3, 0, 1, 8, 9, 4, 5, 12, 13);
    c3 = __builtin_shufflevector(t2, t3, 2, 3, 10, 11, 6, 7, 14, 15);
}

// The high row goes in with one instruction that reads memory (VINSERTF128 m128): a
// shuffle of two loaded rows costs a load more.
template <class T>
E2D_AVX2_FN F joinRows(const T* low, const T* high, std::size_t offset) {
    return _mm256_insertf128_ps(_mm256_castps128_ps256(loadRow(low, offset)), loadRow(high, offset),
                                1);
}

template <class T>
E2D_AVX2_FN void loadRows(const T* const* s, std::size_t offset, F& c0, F& c1, F& c2, F& c3) {
    transposeRows(joinRows(s[0], s[4], offset), joinRows(s[1], s[5], offset),
                  joinRows(s[2], s[6], offset), joinRows(s[3], s[7], offset), c0, c1, c2, c3);
}

// Row k to lane k (low half) and lane k + 4 (high half): one store each.
E2D_AVX2_FN void splitRow(F row, BodyState* low, BodyState* high) {
    _mm_storeu_ps(reinterpret_cast<float*>(low), _mm256_castps256_ps128(row));
    _mm_storeu_ps(reinterpret_cast<float*>(high), _mm256_extractf128_ps(row, 1));
}

E2D_AVX2_FN void storeRows(F c0, F c1, F c2, F c3, BodyState* const* out) {
    F r0, r1, r2, r3;
    transposeRows(c0, c1, c2, c3, r0, r1, r2, r3);
    splitRow(r0, out[0], out[4]);
    splitRow(r1, out[1], out[5]);
    splitRow(r2, out[2], out[6]);
    splitRow(r3, out[3], out[7]);
}

} // namespace lanes8
#endif

} // namespace e2d::physics::detail
