// SPDX-License-Identifier: MIT
#include "body_solver.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <type_traits>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace e2d::physics::detail {

namespace {

inline void integrateVelocity(const BodySim& sim, BodyState& state, SpeedCaps caps) {
    Vec2 v = sim.velocityStep + sim.linearDampingFactor * state.linearVelocity;
    float w = sim.angularVelocityStep + sim.angularDampingFactor * state.angularVelocity;
    clampVelocity(v, w, caps);
    if (!isFinite(v) || !isFinite(w) || (state.flags & kNonFinite) != 0) {
        // Absurd input (a force or gravity scale near the float limit) overflowed: the
        // body stays still for the rest of the step, so the contact solver spreads nothing
        // to what it touches, and the world disables and reports it afterwards.
        state.flags |= kNonFinite;
        v = {0.0f, 0.0f};
        w = 0.0f;
    }
    state.linearVelocity = v;
    state.angularVelocity = w;
}

// The speeds are capped again first: the constraints solved since integrateVelocity() can
// give a body any speed (a 2e-8 kg body next to a 1e6 kg and a 6e9 kg one took 4e7 m/s from
// the classic velocity iterations and left the coordinate range in one step, the fuzzer's
// tiny-body-out-of-range). Box2D 2.4 caps the translation at this point too.
inline void integratePosition(BodyState& state, float h, SpeedCaps caps) {
    clampVelocity(state.linearVelocity, state.angularVelocity, caps);
    state.deltaRotation = integrateRotation(state.deltaRotation, h * state.angularVelocity);
    state.deltaPosition += h * state.linearVelocity;
}

// Flags sims[i] kIsFast for each bit i of `lanes` (a lane mask of finalizePositions4/8()).
inline void flagFast(BodySim* sims, int lanes) {
    for (auto bits = static_cast<unsigned>(lanes); bits != 0; bits &= bits - 1) {
        sims[std::countr_zero(bits)].flags |= kIsFast;
    }
}

// Body k of a loop over a block's bodies: indices[k], the indices in increasing order.
struct IncreasingIndex {
    std::span<const int> indices;
    std::size_t operator()(std::size_t k) const { return static_cast<std::size_t>(indices[k]); }
};

#if defined(__SSE2__)

// Four bodies a register. Each lane runs integrateVelocity()'s or integratePosition()'s
// operations on its body, in their order (no FMA on the SSE2 baseline), so the results are bit
// for bit theirs. A group of four in which any body needs a rare path (a speed over the cap, a
// non-finite value, a rotation that does not normalise) is left to the scalar functions whole:
// nothing is stored before that is known. Bodies are independent here, so the grouping changes
// nothing. A body a sub-step costs about a quarter of the scalar loop's instructions, most of
// them the transposes.
static_assert(offsetof(BodyState, angularVelocity) == 8 && offsetof(BodyState, flags) == 12 &&
                  offsetof(BodyState, deltaPosition) == 16 &&
                  offsetof(BodyState, deltaRotation) == 24 && sizeof(Rot) == 8,
              "the lanes load a BodyState as two rows: v w flags, deltaPosition deltaRotation");
static_assert(offsetof(BodySim, angularVelocityStep) == offsetof(BodySim, velocityStep) + 8 &&
                  offsetof(BodySim, linearDampingFactor) == offsetof(BodySim, velocityStep) + 12,
              "the lanes load velocityStep, angularVelocityStep, linearDampingFactor as one row");

struct WideCaps {
    __m128 linearSquared;
    __m128 angularLow;
    __m128 angularHigh;
};

inline WideCaps wideCaps(SpeedCaps caps) {
    return {_mm_set1_ps(caps.linear * caps.linear), _mm_set1_ps(-caps.angular),
            _mm_set1_ps(caps.angular)};
}

// Lanes whose speed is over the cap (clampVelocity() would scale them).
inline __m128 overSpeedCap(__m128 vx, __m128 vy, const WideCaps& caps) {
    return _mm_cmpgt_ps(_mm_add_ps(_mm_mul_ps(vx, vx), _mm_mul_ps(vy, vy)), caps.linearSquared);
}

// std::clamp(w, -cap, cap): max(lo, w) keeps w when it is NaN, as the comparisons do.
inline __m128 clampAngular(__m128 w, const WideCaps& caps) {
    return _mm_min_ps(caps.angularHigh, _mm_max_ps(caps.angularLow, w));
}

inline float* row(BodyState& state) { return &state.linearVelocity.x; }

// integrateVelocity() on states[at[0..3]]; false (and nothing written) when a lane needs the
// scalar path.
[[gnu::always_inline]] inline bool integrateVelocity4(std::span<const BodySim> sims,
                                                      std::span<BodyState> states,
                                                      const std::size_t (&at)[4],
                                                      const WideCaps& caps) {
    __m128 vx = _mm_loadu_ps(row(states[at[0]]));
    __m128 vy = _mm_loadu_ps(row(states[at[1]]));
    __m128 w = _mm_loadu_ps(row(states[at[2]]));
    __m128 flags = _mm_loadu_ps(row(states[at[3]]));
    _MM_TRANSPOSE4_PS(vx, vy, w, flags);
    __m128 stepX = _mm_loadu_ps(&sims[at[0]].velocityStep.x);
    __m128 stepY = _mm_loadu_ps(&sims[at[1]].velocityStep.x);
    __m128 stepW = _mm_loadu_ps(&sims[at[2]].velocityStep.x);
    __m128 linearDamping = _mm_loadu_ps(&sims[at[3]].velocityStep.x);
    _MM_TRANSPOSE4_PS(stepX, stepY, stepW, linearDamping);
    const __m128 angularDamping =
        _mm_setr_ps(sims[at[0]].angularDampingFactor, sims[at[1]].angularDampingFactor,
                    sims[at[2]].angularDampingFactor, sims[at[3]].angularDampingFactor);
    vx = _mm_add_ps(stepX, _mm_mul_ps(linearDamping, vx));
    vy = _mm_add_ps(stepY, _mm_mul_ps(linearDamping, vy));
    w = clampAngular(_mm_add_ps(stepW, _mm_mul_ps(angularDamping, w)), caps);
    // Finite: |x| <= FLT_MAX, false for infinities and NaN.
    const __m128 absMask = _mm_castsi128_ps(_mm_set1_epi32(0x7FFFFFFF));
    const __m128 largest = _mm_set1_ps(3.40282347e38f);
    const __m128 finite = _mm_and_ps(_mm_and_ps(_mm_cmple_ps(_mm_and_ps(vx, absMask), largest),
                                                _mm_cmple_ps(_mm_and_ps(vy, absMask), largest)),
                                     _mm_cmple_ps(_mm_and_ps(w, absMask), largest));
    const __m128i heldStill = _mm_and_si128(_mm_castps_si128(flags), _mm_set1_epi32(kNonFinite));
    const __m128 rare =
        _mm_or_ps(_mm_or_ps(overSpeedCap(vx, vy, caps), _mm_cmpeq_ps(finite, _mm_setzero_ps())),
                  _mm_castsi128_ps(_mm_cmpgt_epi32(heldStill, _mm_setzero_si128())));
    if (_mm_movemask_ps(rare) != 0) {
        return false;
    }
    _MM_TRANSPOSE4_PS(vx, vy, w, flags);
    _mm_storeu_ps(row(states[at[0]]), vx);
    _mm_storeu_ps(row(states[at[1]]), vy);
    _mm_storeu_ps(row(states[at[2]]), w);
    _mm_storeu_ps(row(states[at[3]]), flags);
    return true;
}

// integratePosition() on states[at[0..3]]; false (and nothing written) when a lane needs the
// scalar path.
[[gnu::always_inline]] inline bool integratePosition4(std::span<BodyState> states,
                                                      const std::size_t (&at)[4], __m128 h,
                                                      const WideCaps& caps) {
    float* rows[4] = {row(states[at[0]]), row(states[at[1]]), row(states[at[2]]),
                      row(states[at[3]])};
    __m128 vx = _mm_loadu_ps(rows[0]);
    __m128 vy = _mm_loadu_ps(rows[1]);
    __m128 w = _mm_loadu_ps(rows[2]);
    __m128 flags = _mm_loadu_ps(rows[3]);
    _MM_TRANSPOSE4_PS(vx, vy, w, flags);
    __m128 px = _mm_loadu_ps(rows[0] + 4);
    __m128 py = _mm_loadu_ps(rows[1] + 4);
    __m128 qc = _mm_loadu_ps(rows[2] + 4);
    __m128 qs = _mm_loadu_ps(rows[3] + 4);
    _MM_TRANSPOSE4_PS(px, py, qc, qs);
    w = clampAngular(w, caps);
    // integrateRotation()
    const __m128 da = _mm_mul_ps(h, w);
    const __m128 c = _mm_sub_ps(qc, _mm_mul_ps(da, qs));
    const __m128 s = _mm_add_ps(qs, _mm_mul_ps(da, qc));
    const __m128 mag = _mm_sqrt_ps(_mm_add_ps(_mm_mul_ps(c, c), _mm_mul_ps(s, s)));
    const __m128 normalises =
        _mm_and_ps(_mm_cmpgt_ps(mag, _mm_setzero_ps()), _mm_cmplt_ps(mag, _mm_set1_ps(INFINITY)));
    if (_mm_movemask_ps(normalises) != 0xF || _mm_movemask_ps(overSpeedCap(vx, vy, caps)) != 0) {
        return false;
    }
    const __m128 inv = _mm_div_ps(_mm_set1_ps(1.0f), mag);
    qc = _mm_mul_ps(c, inv);
    qs = _mm_mul_ps(s, inv);
    px = _mm_add_ps(px, _mm_mul_ps(h, vx));
    py = _mm_add_ps(py, _mm_mul_ps(h, vy));
    _MM_TRANSPOSE4_PS(vx, vy, w, flags);
    _MM_TRANSPOSE4_PS(px, py, qc, qs);
    _mm_storeu_ps(rows[0], vx);
    _mm_storeu_ps(rows[1], vy);
    _mm_storeu_ps(rows[2], w);
    _mm_storeu_ps(rows[3], flags);
    _mm_storeu_ps(rows[0] + 4, px);
    _mm_storeu_ps(rows[1] + 4, py);
    _mm_storeu_ps(rows[2] + 4, qc);
    _mm_storeu_ps(rows[3] + 4, qs);
    return true;
}

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define E2D_BODY_AVX2 1

// The same lanes eight bodies a register, on AVX2 machines (checked at run time; the build's
// baseline is SSE2). A 256-bit register holds bodies 0-3 in its low half and 4-7 in its high
// half, each half transposed as the four-lane code transposes its register: half the
// transposes and arithmetic instructions per body. AVX2 brings no FMA, so every lane still
// rounds as the scalar code does. It mirrors the four-lane functions above line for line (change
// both together; BodySolver.* compares each with the scalar code): one kernel written over
// wide_lanes.hpp for both widths was measured at +63 k instructions a falling_circles_1000 step.
namespace avx2 {

// _MM_TRANSPOSE4_PS in each 128-bit half.
#define E2D_TRANSPOSE4X2_PS(r0, r1, r2, r3)                                                        \
    do {                                                                                           \
        const __m256 t0 = _mm256_unpacklo_ps(r0, r1);                                              \
        const __m256 t1 = _mm256_unpacklo_ps(r2, r3);                                              \
        const __m256 t2 = _mm256_unpackhi_ps(r0, r1);                                              \
        const __m256 t3 = _mm256_unpackhi_ps(r2, r3);                                              \
        r0 = _mm256_shuffle_ps(t0, t1, _MM_SHUFFLE(1, 0, 1, 0));                                   \
        r1 = _mm256_shuffle_ps(t0, t1, _MM_SHUFFLE(3, 2, 3, 2));                                   \
        r2 = _mm256_shuffle_ps(t2, t3, _MM_SHUFFLE(1, 0, 1, 0));                                   \
        r3 = _mm256_shuffle_ps(t2, t3, _MM_SHUFFLE(3, 2, 3, 2));                                   \
    } while (false)

// Rows lo (low half) and hi (high half), four floats each.
[[gnu::always_inline]] __attribute__((target("avx2"))) inline __m256 load2(const float* lo,
                                                                           const float* hi) {
    return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(lo)), _mm_loadu_ps(hi), 1);
}
[[gnu::always_inline]] __attribute__((target("avx2"))) inline void store2(float* lo, float* hi,
                                                                          __m256 v) {
    _mm_storeu_ps(lo, _mm256_castps256_ps128(v));
    _mm_storeu_ps(hi, _mm256_extractf128_ps(v, 1));
}

struct Caps {
    __m256 linearSquared;
    __m256 angularLow;
    __m256 angularHigh;
};

[[gnu::always_inline]] __attribute__((target("avx2"))) inline Caps caps8(SpeedCaps caps) {
    return {_mm256_set1_ps(caps.linear * caps.linear), _mm256_set1_ps(-caps.angular),
            _mm256_set1_ps(caps.angular)};
}

// overSpeedCap(), clampAngular() and the finiteness test of the four-lane code.
[[gnu::always_inline]] __attribute__((target("avx2"))) inline __m256
overSpeedCap(__m256 vx, __m256 vy, const Caps& caps) {
    return _mm256_cmp_ps(_mm256_add_ps(_mm256_mul_ps(vx, vx), _mm256_mul_ps(vy, vy)),
                         caps.linearSquared, _CMP_GT_OS);
}
[[gnu::always_inline]] __attribute__((target("avx2"))) inline __m256
clampAngular(__m256 w, const Caps& caps) {
    return _mm256_min_ps(caps.angularHigh, _mm256_max_ps(caps.angularLow, w));
}
[[gnu::always_inline]] __attribute__((target("avx2"))) inline __m256 isFinite(__m256 v) {
    const __m256 absMask = _mm256_castsi256_ps(_mm256_set1_epi32(0x7FFFFFFF));
    return _mm256_cmp_ps(_mm256_and_ps(v, absMask), _mm256_set1_ps(3.40282347e38f), _CMP_LE_OS);
}

// integrateVelocity4() for bodies at[0..7].
[[gnu::always_inline]] __attribute__((target("avx2"))) inline bool
integrateVelocity8(std::span<const BodySim> sims, std::span<BodyState> states,
                   const std::size_t (&at)[8], const Caps& caps) {
    __m256 vx = load2(row(states[at[0]]), row(states[at[4]]));
    __m256 vy = load2(row(states[at[1]]), row(states[at[5]]));
    __m256 w = load2(row(states[at[2]]), row(states[at[6]]));
    __m256 flags = load2(row(states[at[3]]), row(states[at[7]]));
    E2D_TRANSPOSE4X2_PS(vx, vy, w, flags);
    __m256 stepX = load2(&sims[at[0]].velocityStep.x, &sims[at[4]].velocityStep.x);
    __m256 stepY = load2(&sims[at[1]].velocityStep.x, &sims[at[5]].velocityStep.x);
    __m256 stepW = load2(&sims[at[2]].velocityStep.x, &sims[at[6]].velocityStep.x);
    __m256 linearDamping = load2(&sims[at[3]].velocityStep.x, &sims[at[7]].velocityStep.x);
    E2D_TRANSPOSE4X2_PS(stepX, stepY, stepW, linearDamping);
    const __m256 angularDamping =
        _mm256_setr_ps(sims[at[0]].angularDampingFactor, sims[at[1]].angularDampingFactor,
                       sims[at[2]].angularDampingFactor, sims[at[3]].angularDampingFactor,
                       sims[at[4]].angularDampingFactor, sims[at[5]].angularDampingFactor,
                       sims[at[6]].angularDampingFactor, sims[at[7]].angularDampingFactor);
    vx = _mm256_add_ps(stepX, _mm256_mul_ps(linearDamping, vx));
    vy = _mm256_add_ps(stepY, _mm256_mul_ps(linearDamping, vy));
    w = clampAngular(_mm256_add_ps(stepW, _mm256_mul_ps(angularDamping, w)), caps);
    const __m256 finite = _mm256_and_ps(_mm256_and_ps(isFinite(vx), isFinite(vy)), isFinite(w));
    const __m256i heldStill =
        _mm256_and_si256(_mm256_castps_si256(flags), _mm256_set1_epi32(kNonFinite));
    const __m256 rare =
        _mm256_or_ps(_mm256_or_ps(overSpeedCap(vx, vy, caps),
                                  _mm256_cmp_ps(finite, _mm256_setzero_ps(), _CMP_EQ_OQ)),
                     _mm256_castsi256_ps(_mm256_cmpgt_epi32(heldStill, _mm256_setzero_si256())));
    if (_mm256_movemask_ps(rare) != 0) {
        return false;
    }
    E2D_TRANSPOSE4X2_PS(vx, vy, w, flags);
    store2(row(states[at[0]]), row(states[at[4]]), vx);
    store2(row(states[at[1]]), row(states[at[5]]), vy);
    store2(row(states[at[2]]), row(states[at[6]]), w);
    store2(row(states[at[3]]), row(states[at[7]]), flags);
    return true;
}

// integratePosition4() for bodies at[0..7].
[[gnu::always_inline]] __attribute__((target("avx2"))) inline bool
integratePosition8(std::span<BodyState> states, const std::size_t (&at)[8], __m256 h,
                   const Caps& caps) {
    float* const rows[8] = {row(states[at[0]]), row(states[at[1]]), row(states[at[2]]),
                            row(states[at[3]]), row(states[at[4]]), row(states[at[5]]),
                            row(states[at[6]]), row(states[at[7]])};
    __m256 vx = load2(rows[0], rows[4]);
    __m256 vy = load2(rows[1], rows[5]);
    __m256 w = load2(rows[2], rows[6]);
    __m256 flags = load2(rows[3], rows[7]);
    E2D_TRANSPOSE4X2_PS(vx, vy, w, flags);
    __m256 px = load2(rows[0] + 4, rows[4] + 4);
    __m256 py = load2(rows[1] + 4, rows[5] + 4);
    __m256 qc = load2(rows[2] + 4, rows[6] + 4);
    __m256 qs = load2(rows[3] + 4, rows[7] + 4);
    E2D_TRANSPOSE4X2_PS(px, py, qc, qs);
    w = clampAngular(w, caps);
    const __m256 da = _mm256_mul_ps(h, w);
    const __m256 c = _mm256_sub_ps(qc, _mm256_mul_ps(da, qs));
    const __m256 s = _mm256_add_ps(qs, _mm256_mul_ps(da, qc));
    const __m256 mag = _mm256_sqrt_ps(_mm256_add_ps(_mm256_mul_ps(c, c), _mm256_mul_ps(s, s)));
    const __m256 normalises =
        _mm256_and_ps(_mm256_cmp_ps(mag, _mm256_setzero_ps(), _CMP_GT_OS),
                      _mm256_cmp_ps(mag, _mm256_set1_ps(INFINITY), _CMP_LT_OS));
    if (_mm256_movemask_ps(normalises) != 0xFF ||
        _mm256_movemask_ps(overSpeedCap(vx, vy, caps)) != 0) {
        return false;
    }
    const __m256 inv = _mm256_div_ps(_mm256_set1_ps(1.0f), mag);
    qc = _mm256_mul_ps(c, inv);
    qs = _mm256_mul_ps(s, inv);
    px = _mm256_add_ps(px, _mm256_mul_ps(h, vx));
    py = _mm256_add_ps(py, _mm256_mul_ps(h, vy));
    E2D_TRANSPOSE4X2_PS(vx, vy, w, flags);
    E2D_TRANSPOSE4X2_PS(px, py, qc, qs);
    store2(rows[0], rows[4], vx);
    store2(rows[1], rows[5], vy);
    store2(rows[2], rows[6], w);
    store2(rows[3], rows[7], flags);
    store2(rows[0] + 4, rows[4] + 4, px);
    store2(rows[1] + 4, rows[5] + 4, py);
    store2(rows[2] + 4, rows[6] + 4, qc);
    store2(rows[3] + 4, rows[7] + 4, qs);
    return true;
}

// finalizePositions4() for sims[0..7] and states[0..7].
__attribute__((target("avx2"))) bool finalizePositions8(BodySim* sims, const BodyState* states) {
    __m256 c0x = load2(&sims[0].center0.x, &sims[4].center0.x);
    __m256 c0y = load2(&sims[1].center0.x, &sims[5].center0.x);
    __m256 r0c = load2(&sims[2].center0.x, &sims[6].center0.x);
    __m256 r0s = load2(&sims[3].center0.x, &sims[7].center0.x);
    E2D_TRANSPOSE4X2_PS(c0x, c0y, r0c, r0s);
    __m256 dpx = load2(&states[0].deltaPosition.x, &states[4].deltaPosition.x);
    __m256 dpy = load2(&states[1].deltaPosition.x, &states[5].deltaPosition.x);
    __m256 drc = load2(&states[2].deltaPosition.x, &states[6].deltaPosition.x);
    __m256 drs = load2(&states[3].deltaPosition.x, &states[7].deltaPosition.x);
    E2D_TRANSPOSE4X2_PS(dpx, dpy, drc, drs);
    // localCenter (x, y) of bodies 0 1 2 3 (low halves) and 4 5 6 7 (high), as two rows.
    auto pair = [&](int a) {
        return _mm_loadh_pi(_mm_castsi128_ps(_mm_loadl_epi64(
                                reinterpret_cast<const __m128i*>(&sims[a].localCenter))),
                            reinterpret_cast<const __m64*>(&sims[a + 1].localCenter));
    };
    const __m256 lc01 = _mm256_insertf128_ps(_mm256_castps128_ps256(pair(0)), pair(4), 1);
    const __m256 lc23 = _mm256_insertf128_ps(_mm256_castps128_ps256(pair(2)), pair(6), 1);
    const __m256 lcx = _mm256_shuffle_ps(lc01, lc23, _MM_SHUFFLE(2, 0, 2, 0));
    const __m256 lcy = _mm256_shuffle_ps(lc01, lc23, _MM_SHUFFLE(3, 1, 3, 1));

    __m256 cx = _mm256_add_ps(c0x, dpx);
    __m256 cy = _mm256_add_ps(c0y, dpy);
    __m256 qc = _mm256_sub_ps(_mm256_mul_ps(drc, r0c), _mm256_mul_ps(drs, r0s));
    __m256 qs = _mm256_add_ps(_mm256_mul_ps(drs, r0c), _mm256_mul_ps(drc, r0s));
    const __m256 mag = _mm256_sqrt_ps(_mm256_add_ps(_mm256_mul_ps(qc, qc), _mm256_mul_ps(qs, qs)));
    const __m256 positive = _mm256_cmp_ps(mag, _mm256_setzero_ps(), _CMP_GT_OS);
    qc = _mm256_or_ps(_mm256_and_ps(positive, _mm256_div_ps(qc, mag)),
                      _mm256_andnot_ps(positive, qc));
    qs = _mm256_or_ps(_mm256_and_ps(positive, _mm256_div_ps(qs, mag)),
                      _mm256_andnot_ps(positive, qs));
    // rotate(q, localCenter)
    const __m256 rx = _mm256_sub_ps(_mm256_mul_ps(qc, lcx), _mm256_mul_ps(qs, lcy));
    const __m256 ry = _mm256_add_ps(_mm256_mul_ps(qs, lcx), _mm256_mul_ps(qc, lcy));
    __m256 px = _mm256_sub_ps(cx, rx);
    __m256 py = _mm256_sub_ps(cy, ry);
    __m256 residualX = _mm256_sub_ps(dpx, _mm256_sub_ps(_mm256_add_ps(rx, px), c0x));
    __m256 residualY = _mm256_sub_ps(dpy, _mm256_sub_ps(_mm256_add_ps(ry, py), c0y));

    // movedFast(), and the bullets: rows maxExtent, minExtent, bodyIndex, flags.
    __m256 maxExtent = load2(&sims[0].maxExtent, &sims[4].maxExtent);
    __m256 minExtent = load2(&sims[1].maxExtent, &sims[5].maxExtent);
    __m256 bodyIndex = load2(&sims[2].maxExtent, &sims[6].maxExtent);
    __m256 flags = load2(&sims[3].maxExtent, &sims[7].maxExtent);
    E2D_TRANSPOSE4X2_PS(maxExtent, minExtent, bodyIndex, flags);
    const __m256 dx = _mm256_sub_ps(cx, c0x);
    const __m256 dy = _mm256_sub_ps(cy, c0y);
    const __m256 turn = _mm256_and_ps(drs, _mm256_castsi256_ps(_mm256_set1_epi32(0x7FFFFFFF)));
    const __m256 travel =
        _mm256_add_ps(_mm256_sqrt_ps(_mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy))),
                      _mm256_mul_ps(turn, maxExtent));
    const int fast = _mm256_movemask_ps(
        _mm256_cmp_ps(travel, _mm256_mul_ps(_mm256_set1_ps(0.5f), minExtent), _CMP_GE_OQ));
    const __m256i bullet = _mm256_set1_epi32(kIsBullet);
    const int bullets = _mm256_movemask_ps(_mm256_castsi256_ps(
        _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_castps_si256(flags), bullet), bullet)));
    flagFast(sims, fast);
    E2D_TRANSPOSE4X2_PS(px, py, qc, qs);
    store2(&sims[0].transform.p.x, &sims[4].transform.p.x, px);
    store2(&sims[1].transform.p.x, &sims[5].transform.p.x, py);
    store2(&sims[2].transform.p.x, &sims[6].transform.p.x, qc);
    store2(&sims[3].transform.p.x, &sims[7].transform.p.x, qs);
    E2D_TRANSPOSE4X2_PS(cx, cy, residualX, residualY); // rows: centre x y, residual x y
    const __m256 rows[4] = {cx, cy, residualX, residualY};
    for (int k = 0; k < 4; ++k) {
        const __m128 halves[2] = {_mm256_castps256_ps128(rows[k]),
                                  _mm256_extractf128_ps(rows[k], 1)};
        for (int half = 0; half < 2; ++half) {
            BodySim& sim = sims[k + 4 * half];
            _mm_storel_pi(reinterpret_cast<__m64*>(&sim.center), halves[half]);
            _mm_storeh_pi(reinterpret_cast<__m64*>(&sim.positionResidual), halves[half]);
        }
    }
    return (fast | bullets) != 0;
}

#undef E2D_TRANSPOSE4X2_PS

// Whether bodies index(k) .. index(k + 7) of a loop are consecutive, index(k) + 0 .. 7: so where
// the indices are in increasing order (IncreasingIndex) and these eight span eight places. Such
// a group is given as a base and constant offsets, which saves about a third of an indexed
// group's instructions (a block's islands are mostly runs of the arrays).
template <class Index>
[[gnu::always_inline]] inline bool consecutive8(Index index, std::size_t k) {
    if constexpr (std::is_same_v<Index, IncreasingIndex>) {
        return index(k + 7) == index(k) + 7;
    }
    return false;
}

// integrateVelocity8(), or the scalar function on each body when one is on a rare path.
[[gnu::always_inline]] __attribute__((target("avx2"))) inline void
integrateVelocities8(std::span<const BodySim> sims, std::span<BodyState> states,
                     const std::size_t (&at)[8], const Caps& wide, SpeedCaps caps) {
    if (!integrateVelocity8(sims, states, at, wide)) {
        for (std::size_t i : at) {
            integrateVelocity(sims[i], states[i], caps);
        }
    }
}
[[gnu::always_inline]] __attribute__((target("avx2"))) inline void
integratePositions8(std::span<BodyState> states, const std::size_t (&at)[8], __m256 wideH,
                    const Caps& wide, float h, SpeedCaps caps) {
    if (!integratePosition8(states, at, wideH, wide)) {
        for (std::size_t i : at) {
            integratePosition(states[i], h, caps);
        }
    }
}

// The groups of eight of the first `count` bodies; returns how many bodies it did (a multiple
// of eight). A group with a body on a rare path goes to the scalar functions whole, as in the
// four-lane loops.
template <class Index>
__attribute__((target("avx2"))) std::size_t
integrateVelocities(std::span<const BodySim> sims, std::span<BodyState> states, std::size_t count,
                    Index index, SpeedCaps caps) {
    const Caps wide = caps8(caps);
    std::size_t k = 0;
    for (; k + 8 <= count; k += 8) {
        if (consecutive8(index, k)) {
            const std::size_t i = index(k);
            const std::size_t at[8] = {i, i + 1, i + 2, i + 3, i + 4, i + 5, i + 6, i + 7};
            integrateVelocities8(sims, states, at, wide, caps);
            continue;
        }
        const std::size_t at[8] = {index(k),     index(k + 1), index(k + 2), index(k + 3),
                                   index(k + 4), index(k + 5), index(k + 6), index(k + 7)};
        integrateVelocities8(sims, states, at, wide, caps);
    }
    return k;
}

template <class Index>
__attribute__((target("avx2"))) std::size_t integratePositions(std::span<BodyState> states,
                                                               std::size_t count, Index index,
                                                               float h, SpeedCaps caps) {
    const Caps wide = caps8(caps);
    const __m256 wideH = _mm256_set1_ps(h);
    std::size_t k = 0;
    for (; k + 8 <= count; k += 8) {
        if (consecutive8(index, k)) {
            const std::size_t i = index(k);
            const std::size_t at[8] = {i, i + 1, i + 2, i + 3, i + 4, i + 5, i + 6, i + 7};
            integratePositions8(states, at, wideH, wide, h, caps);
            continue;
        }
        const std::size_t at[8] = {index(k),     index(k + 1), index(k + 2), index(k + 3),
                                   index(k + 4), index(k + 5), index(k + 6), index(k + 7)};
        integratePositions8(states, at, wideH, wide, h, caps);
    }
    return k;
}

} // namespace avx2

#endif

#endif

// The loops over `count` bodies, body k being states[index(k)] (and sims[index(k)]).
template <class Index>
void integrateVelocitiesOf(std::span<const BodySim> sims, std::span<BodyState> states,
                           std::size_t count, Index index, SpeedCaps caps) {
    std::size_t k = 0;
#if defined(__SSE2__)
#if defined(E2D_BODY_AVX2)
    if (__builtin_cpu_supports("avx2")) {
        k = avx2::integrateVelocities(sims, states, count, index, caps);
    }
#endif
    const WideCaps wide = wideCaps(caps);
    for (; k + 4 <= count; k += 4) {
        const std::size_t at[4] = {index(k), index(k + 1), index(k + 2), index(k + 3)};
        if (!integrateVelocity4(sims, states, at, wide)) {
            for (std::size_t i : at) {
                integrateVelocity(sims[i], states[i], caps);
            }
        }
    }
#endif
    for (; k < count; ++k) {
        const std::size_t i = index(k);
        integrateVelocity(sims[i], states[i], caps);
    }
}

template <class Index>
void integratePositionsOf(std::span<BodyState> states, std::size_t count, Index index, float h,
                          SpeedCaps caps) {
    std::size_t k = 0;
#if defined(__SSE2__)
#if defined(E2D_BODY_AVX2)
    if (__builtin_cpu_supports("avx2")) {
        k = avx2::integratePositions(states, count, index, h, caps);
    }
#endif
    const WideCaps wide = wideCaps(caps);
    const __m128 wideH = _mm_set1_ps(h);
    for (; k + 4 <= count; k += 4) {
        const std::size_t at[4] = {index(k), index(k + 1), index(k + 2), index(k + 3)};
        if (!integratePosition4(states, at, wideH, wide)) {
            for (std::size_t i : at) {
                integratePosition(states[i], h, caps);
            }
        }
    }
#endif
    for (; k < count; ++k) {
        integratePosition(states[index(k)], h, caps);
    }
}

} // namespace

void prepareIntegration(std::span<BodySim> sims, Vec2 gravity, float h) {
    for (BodySim& sim : sims) {
        prepareIntegration(sim, gravity, h);
    }
}

void integrateVelocities(std::span<const BodySim> sims, std::span<BodyState> states, float h,
                         float maxLinearSpeed) {
    integrateVelocitiesOf(
        sims, states, sims.size(), [](std::size_t k) { return k; }, speedCaps(maxLinearSpeed, h));
}

void integrateVelocities(std::span<BodySim> sims, std::span<BodyState> states, Vec2 gravity,
                         float h, float maxLinearSpeed) {
    prepareIntegration(sims, gravity, h);
    integrateVelocities(std::span<const BodySim>(sims), states, h, maxLinearSpeed);
}

void integrateVelocities(std::span<const BodySim> sims, std::span<BodyState> states,
                         std::span<const int> indices, float h, float maxLinearSpeed) {
    integrateVelocitiesOf(
        sims, states, indices.size(),
        [indices](std::size_t k) { return static_cast<std::size_t>(indices[k]); },
        speedCaps(maxLinearSpeed, h));
}

void integratePositions(std::span<BodyState> states, float h, float maxLinearSpeed) {
    integratePositionsOf(
        states, states.size(), [](std::size_t k) { return k; }, h, speedCaps(maxLinearSpeed, h));
}

void integratePositions(std::span<BodyState> states, std::span<const int> indices, float h,
                        float maxLinearSpeed) {
    integratePositionsOf(
        states, indices.size(),
        [indices](std::size_t k) { return static_cast<std::size_t>(indices[k]); }, h,
        speedCaps(maxLinearSpeed, h));
}

namespace {

// `increasing` (indices in increasing order) as one run of the arrays: its first index and
// length, or a length of 0 when it is not one (a gap between its first and last).
struct BodyRun {
    std::size_t start = 0;
    std::size_t length = 0;
};
BodyRun runOf(std::span<const int> increasing) {
    if (increasing.empty() ||
        static_cast<std::size_t>(increasing.back() - increasing.front()) != increasing.size() - 1) {
        return {};
    }
    return {static_cast<std::size_t>(increasing.front()), increasing.size()};
}

} // namespace

void integrateBlockVelocities(std::span<const BodySim> sims, std::span<BodyState> states,
                              std::span<const int> increasing, float h, float maxLinearSpeed) {
    if (const BodyRun run = runOf(increasing); run.length != 0) {
        integrateVelocities(sims.subspan(run.start, run.length),
                            states.subspan(run.start, run.length), h, maxLinearSpeed);
        return;
    }
    integrateVelocitiesOf(sims, states, increasing.size(), IncreasingIndex{increasing},
                          speedCaps(maxLinearSpeed, h));
}

void integrateBlockPositions(std::span<BodyState> states, std::span<const int> increasing, float h,
                             float maxLinearSpeed) {
    if (const BodyRun run = runOf(increasing); run.length != 0) {
        integratePositions(states.subspan(run.start, run.length), h, maxLinearSpeed);
        return;
    }
    integratePositionsOf(states, increasing.size(), IncreasingIndex{increasing}, h,
                         speedCaps(maxLinearSpeed, h));
}

ContactSoftness makeContactSoftness(const SolverDef& def, float dt) {
    float h = dt / static_cast<float>(def.subSteps);
    float hertz = std::min(def.contactHertz, 0.25f / h);
    return {makeSoftness(hertz, def.contactDampingRatio, h),
            makeSoftness(2.0f * hertz, def.contactDampingRatio, h)};
}

namespace {

// The joint passes over `order`; a step without joints (order empty) has no groups.
void warmStartJointsOf(const SolverStep& step, std::span<const int> order) {
    if (!order.empty()) {
        warmStartJoints(step.joints, *step.pointJoints, order, step.states);
    }
}
void solveJointsOf(const SolverStep& step, std::span<const int> order, bool useBias) {
    if (!order.empty()) {
        solveJoints(step.joints, *step.pointJoints, order, step.states, step.jointStep, useBias);
    }
}

} // namespace

void solveSoftStep(const SolverStep& step) {
    const SolverDef& def = *step.def;
    float h = step.dt / static_cast<float>(def.subSteps);
    float invH = 1.0f / h;
    const int relaxIterations = def.relaxIterations + step.extraRelaxIterations;
    prepareIntegration(step.sims, step.gravity, h);
    for (int i = 0; i < def.subSteps; ++i) {
        integrateVelocities(step.sims, step.states, h, def.maxLinearSpeed);
        // Gauss-Seidel's order biases the result, so every group of four sub-steps runs all
        // four orders. Odd sub-steps sweep the constraints backwards, which cancels the
        // sideways drift of piles. Sub-steps 2 and 3 also solve each constraint's two points
        // in reverse: the point solved second gets more impulse (the first one's push tilts
        // the bodies against it), a torque of one sign every sub-step otherwise, which leans
        // tall stacks and toppled a column pushed out of a 25 % overlap. Reversing the points
        // together with the constraints (on odd sub-steps) cancels the torque but not its
        // coupling with the sweep direction: base-70 pyramids then drift 5x more.
        bool backward = (i % 2) == 1;
        bool reversePoints = ((i / 2) % 2) == 1;
        // Joints go before the contacts in each pass (Box2D v3's order): the contacts, solved
        // last, win where the two disagree.
        warmStartJointsOf(step, step.jointOrder);
        warmStartContacts(step.constraints, step.states);
        for (int r = 0; r <= step.extraSolveIterations; ++r) {
            if (r == 0) { // the extra sweeps are the contacts' (SolverStep)
                solveJointsOf(step, step.jointOrder, true);
            }
            solveContacts(step.constraints, step.states, invH, true, def.contactPushMaxSpeed,
                          backward, reversePoints);
        }
        integratePositions(step.states, h, def.maxLinearSpeed);
        // The relax passes sweep the other way: the sweep direction's bias then cancels within
        // each sub-step, not only over two. Relaxed in the same direction, a five-level house of
        // cards (0.002 x 0.4 m cards) swayed 3-5 mm to one side as its contacts took the load,
        // and each swing slipped the top pair a little at its apex until it fell.
        for (int r = 0; r <= relaxIterations; ++r) {
            if (r <= def.relaxIterations) {
                solveJointsOf(step, step.jointOrder, false);
            }
            solveContacts(step.constraints, step.states, invH, false, def.contactPushMaxSpeed,
                          !backward, reversePoints);
        }
    }
    applyRestitution(step.constraints, step.states, def.restitutionThreshold, h);
}

void solveSoftStepBlock(const SolverStep& step, WideContacts& wide, int firstLevel, int endLevel,
                        std::span<const int> bodies, std::span<const WideRestitution> restitution,
                        std::span<const int> blockJoints) {
    struct Passes {
        const SolverStep& step;
        WideContacts& wide;
        int firstLevel;
        int endLevel;
        std::span<const int> bodies;
        std::span<const WideRestitution> restituted;
        std::span<const int> joints;
        float h;

        void integrateVelocities(int /*subStep*/) {
            integrateBlockVelocities(step.sims, step.states, bodies, h, step.def->maxLinearSpeed);
        }
        void warmStart() {
            warmStartJointsOf(step, joints);
            warmStartWide(wide, firstLevel, endLevel);
        }
        void solve(bool useBias, bool backward, bool reversePoints, bool withJoints) {
            if (withJoints) {
                solveJointsOf(step, joints, useBias);
            }
            solveWide(wide, firstLevel, endLevel, 1.0f / h, useBias, step.def->contactPushMaxSpeed,
                      backward, reversePoints);
        }
        void integratePositions() {
            integrateBlockPositions(step.states, bodies, h, step.def->maxLinearSpeed);
        }
        void restitution() {
            applyRestitutionWide(wide, restituted, step.states, step.def->restitutionThreshold, h);
        }
    };
    Passes passes{
        step,   wide,        firstLevel,  endLevel,
        bodies, restitution, blockJoints, step.dt / static_cast<float>(step.def->subSteps)};
    forEachSoftStepPass(step, passes);
}

void solveClassic(const SolverStep& step) {
    const SolverDef& def = *step.def;
    float invDt = 1.0f / step.dt;
    integrateVelocities(step.sims, step.states, step.gravity, step.dt, def.maxLinearSpeed);
    prepareClassic(step.constraints, step.states, def.restitutionThreshold);
    warmStartJointsOf(step, step.jointOrder);
    warmStartContacts(step.constraints, step.states);
    for (int i = 0; i < def.velocityIterations; ++i) {
        // Box2D 2.4's recipe: velocities only here (a limit not reached yet still stops the
        // bodies at it), position errors in the position iterations below.
        solveJointsOf(step, step.jointOrder, false);
        solveVelocitiesClassic(step.constraints, step.states, invDt);
    }
    applyRestitution(step.constraints, step.states, def.restitutionThreshold, step.dt);
    integratePositions(step.states, step.dt, def.maxLinearSpeed);
    for (int i = 0; i < def.positionIterations; ++i) {
        // Box2D 2.4's stopping rule: done once nothing overlaps by more than 3 times the
        // allowed penetration (3 slops by default).
        const float allowed = def.classicAllowedPenetration;
        const bool contactsDone = solvePositionsClassic(step.constraints, step.states, allowed,
                                                        def.classicPositionBias) >= -3.0f * allowed;
        const bool jointsDone = solveJointPositions(step.joints, step.jointOrder, step.states);
        if (contactsDone && jointsDone) {
            break;
        }
    }
}

namespace {

inline bool finalizePosition(BodySim& sim, const BodyState& state) {
    sim.center = sim.center0 + state.deltaPosition;
    Rot q = mulRot(state.deltaRotation, sim.rotation0);
    float mag = std::sqrt(q.c * q.c + q.s * q.s);
    if (mag > 0.0f) {
        q = {q.c / mag, q.s / mag};
    }
    sim.transform.q = q;
    sim.transform.p = sim.center - rotate(q, sim.localCenter);
    // The next step starts from the centre the float transform gives; what it misses of
    // center0 + deltaPosition is kept. Near each other (the usual case far away, where it
    // matters) the two centres subtract exactly.
    const Vec2 next = transformPoint(sim.transform, sim.localCenter);
    sim.positionResidual = state.deltaPosition - (next - sim.center0);
    if (movedFast(sim.center - sim.center0, state.deltaRotation.s, sim.maxExtent, sim.minExtent)) {
        sim.flags |= kIsFast;
    }
    return (sim.flags & (kIsFast | kIsBullet)) != 0;
}

#if defined(__SSE2__)

static_assert(offsetof(BodySim, transform) == 0 && offsetof(BodySim, center) == 16 &&
                  offsetof(BodySim, rotation0) == offsetof(BodySim, center0) + 8 &&
                  offsetof(BodySim, positionResidual) % 4 == 0,
              "finalizePositions4() loads center0 and rotation0 as one row and stores the "
              "transform as one");

// finalizePosition() on sims[i..i+3] and states[i..i+3], each lane doing its operations in its
// order (no FMA on the SSE2 baseline; the normalisation divides every lane and keeps the
// quotient where mag > 0), so the results are bit for bit its own. About a third of its
// instructions a body.
inline bool finalizePositions4(BodySim* sims, const BodyState* states) {
    __m128 c0x = _mm_loadu_ps(&sims[0].center0.x);
    __m128 c0y = _mm_loadu_ps(&sims[1].center0.x);
    __m128 r0c = _mm_loadu_ps(&sims[2].center0.x);
    __m128 r0s = _mm_loadu_ps(&sims[3].center0.x);
    _MM_TRANSPOSE4_PS(c0x, c0y, r0c, r0s);
    __m128 dpx = _mm_loadu_ps(&states[0].deltaPosition.x);
    __m128 dpy = _mm_loadu_ps(&states[1].deltaPosition.x);
    __m128 drc = _mm_loadu_ps(&states[2].deltaPosition.x);
    __m128 drs = _mm_loadu_ps(&states[3].deltaPosition.x);
    _MM_TRANSPOSE4_PS(dpx, dpy, drc, drs);
    // localCenter (x, y) of bodies 0 1 2 3, as two rows.
    const __m128 lc01 = _mm_loadh_pi(
        _mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(&sims[0].localCenter))),
        reinterpret_cast<const __m64*>(&sims[1].localCenter));
    const __m128 lc23 = _mm_loadh_pi(
        _mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(&sims[2].localCenter))),
        reinterpret_cast<const __m64*>(&sims[3].localCenter));
    const __m128 lcx = _mm_shuffle_ps(lc01, lc23, _MM_SHUFFLE(2, 0, 2, 0));
    const __m128 lcy = _mm_shuffle_ps(lc01, lc23, _MM_SHUFFLE(3, 1, 3, 1));

    __m128 cx = _mm_add_ps(c0x, dpx);
    __m128 cy = _mm_add_ps(c0y, dpy);
    __m128 qc = _mm_sub_ps(_mm_mul_ps(drc, r0c), _mm_mul_ps(drs, r0s));
    __m128 qs = _mm_add_ps(_mm_mul_ps(drs, r0c), _mm_mul_ps(drc, r0s));
    const __m128 mag = _mm_sqrt_ps(_mm_add_ps(_mm_mul_ps(qc, qc), _mm_mul_ps(qs, qs)));
    const __m128 positive = _mm_cmpgt_ps(mag, _mm_setzero_ps());
    qc = _mm_or_ps(_mm_and_ps(positive, _mm_div_ps(qc, mag)), _mm_andnot_ps(positive, qc));
    qs = _mm_or_ps(_mm_and_ps(positive, _mm_div_ps(qs, mag)), _mm_andnot_ps(positive, qs));
    // rotate(q, localCenter)
    const __m128 rx = _mm_sub_ps(_mm_mul_ps(qc, lcx), _mm_mul_ps(qs, lcy));
    const __m128 ry = _mm_add_ps(_mm_mul_ps(qs, lcx), _mm_mul_ps(qc, lcy));
    __m128 px = _mm_sub_ps(cx, rx);
    __m128 py = _mm_sub_ps(cy, ry);
    __m128 residualX = _mm_sub_ps(dpx, _mm_sub_ps(_mm_add_ps(rx, px), c0x));
    __m128 residualY = _mm_sub_ps(dpy, _mm_sub_ps(_mm_add_ps(ry, py), c0y));

    // movedFast(), and the bullets: rows maxExtent, minExtent, bodyIndex, flags.
    __m128 maxExtent = _mm_loadu_ps(&sims[0].maxExtent);
    __m128 minExtent = _mm_loadu_ps(&sims[1].maxExtent);
    __m128 bodyIndex = _mm_loadu_ps(&sims[2].maxExtent);
    __m128 flags = _mm_loadu_ps(&sims[3].maxExtent);
    _MM_TRANSPOSE4_PS(maxExtent, minExtent, bodyIndex, flags);
    const __m128 dx = _mm_sub_ps(cx, c0x);
    const __m128 dy = _mm_sub_ps(cy, c0y);
    const __m128 turn = _mm_and_ps(drs, _mm_castsi128_ps(_mm_set1_epi32(0x7FFFFFFF)));
    const __m128 travel =
        _mm_add_ps(_mm_sqrt_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy))),
                   _mm_mul_ps(turn, maxExtent));
    const int fast =
        _mm_movemask_ps(_mm_cmpge_ps(travel, _mm_mul_ps(_mm_set1_ps(0.5f), minExtent)));
    const __m128i bullet = _mm_set1_epi32(kIsBullet);
    const int bullets = _mm_movemask_ps(
        _mm_castsi128_ps(_mm_cmpeq_epi32(_mm_and_si128(_mm_castps_si128(flags), bullet), bullet)));
    flagFast(sims, fast);
    _MM_TRANSPOSE4_PS(px, py, qc, qs);
    _mm_storeu_ps(&sims[0].transform.p.x, px);
    _mm_storeu_ps(&sims[1].transform.p.x, py);
    _mm_storeu_ps(&sims[2].transform.p.x, qc);
    _mm_storeu_ps(&sims[3].transform.p.x, qs);
    _MM_TRANSPOSE4_PS(cx, cy, residualX, residualY); // rows: centre x y, residual x y
    const __m128 rows[4] = {cx, cy, residualX, residualY};
    for (int k = 0; k < 4; ++k) {
        _mm_storel_pi(reinterpret_cast<__m64*>(&sims[k].center), rows[k]);
        _mm_storeh_pi(reinterpret_cast<__m64*>(&sims[k].positionResidual), rows[k]);
    }
    return (fast | bullets) != 0;
}

#endif

} // namespace

bool finalizePositions(std::span<BodySim> sims, std::span<const BodyState> states) {
    bool sweeps = false;
    std::size_t i = 0;
#if defined(__SSE2__)
#if defined(E2D_BODY_AVX2)
    if (__builtin_cpu_supports("avx2")) {
        for (; i + 8 <= sims.size(); i += 8) {
            sweeps = avx2::finalizePositions8(&sims[i], &states[i]) || sweeps;
        }
    }
#endif
    for (; i + 4 <= sims.size(); i += 4) {
        sweeps = finalizePositions4(&sims[i], &states[i]) || sweeps;
    }
#endif
    for (; i < sims.size(); ++i) {
        sweeps = finalizePosition(sims[i], states[i]) || sweeps;
    }
    return sweeps;
}

} // namespace e2d::physics::detail
