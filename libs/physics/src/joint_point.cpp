// SPDX-License-Identifier: MIT
// Plain hinges four at a time: packing them into quads, their warm start and solve (SSE2, with
// a scalar path for other targets), and their impulses back to the joints. Every lane does
// warmStartRevolute()'s and solveRevolute()'s products and sums in the same order (no FMA),
// so the results are the scalar joint's bits.
#include "joint_solver.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#include <xmmintrin.h>
#endif

#include <cstring>

namespace e2d::physics::detail {

void packJointPasses(std::span<const Joint> joints, std::span<const int> slots, std::span<const int> levels,
                     bool quadsAllowed, std::vector<PointJointQuad>& quads, std::vector<int>& entries) {
    const std::size_t n = slots.size();
    std::size_t first = 0;
    while (first < n) {
        std::size_t end = first + 1;
        while (end < n && levels[end] == levels[first]) {
            ++end;
        }
        // The level's plain hinges four to a quad, then its other joints. A lone hinge left
        // over (a chain's levels hold one joint each) is cheaper solved alone than in a quad
        // of padding.
        int points = 0;
        for (std::size_t k = first; k < end && quadsAllowed; ++k) {
            points += isPointJoint(joints[static_cast<std::size_t>(slots[k])]) ? 1 : 0;
        }
        const int packed = points % 4 == 1 ? points - 1 : points;
        int lane = 4;
        int taken = 0;
        for (std::size_t k = first; k < end && taken < packed; ++k) {
            const int s = slots[k];
            const Joint& j = joints[static_cast<std::size_t>(s)];
            if (!isPointJoint(j)) {
                continue;
            }
            ++taken;
            if (lane == 4) {
                entries.push_back(~static_cast<int>(quads.size()));
                quads.emplace_back();
                lane = 0;
            }
            PointJointQuad& q = quads.back();
            q.indexA[lane] = j.indexA;
            q.indexB[lane] = j.indexB;
            q.slot[lane] = s;
            q.invInertiaA[lane] = j.invInertiaA;
            q.invInertiaB[lane] = j.invInertiaB;
            q.invMassAx[lane] = j.invMassA.x;
            q.invMassAy[lane] = j.invMassA.y;
            q.invMassBx[lane] = j.invMassB.x;
            q.invMassBy[lane] = j.invMassB.y;
            q.anchorAx[lane] = j.anchorA.x;
            q.anchorAy[lane] = j.anchorA.y;
            q.anchorBx[lane] = j.anchorB.x;
            q.anchorBy[lane] = j.anchorB.y;
            q.deltaCenterX[lane] = j.deltaCenter.x;
            q.deltaCenterY[lane] = j.deltaCenter.y;
            q.impulseX[lane] = j.linearImpulse.x;
            q.impulseY[lane] = j.linearImpulse.y;
            ++lane;
        }
        int seen = 0;
        // A level of plain hinges only, all in quads (a joint grid's), has no other entries.
        const bool allPacked = quadsAllowed && static_cast<std::size_t>(packed) == end - first;
        for (std::size_t k = first; k < end && !allPacked; ++k) {
            const int s = slots[k];
            if (!quadsAllowed || !isPointJoint(joints[static_cast<std::size_t>(s)]) || seen++ >= packed) {
                entries.push_back(s);
            }
        }
        first = end;
    }
}

void storePointJointQuads(std::span<const PointJointQuad> quads, std::span<Joint> joints, float invH) {
    for (const PointJointQuad& q : quads) {
        for (int lane = 0; lane < 4; ++lane) {
            if (q.slot[lane] >= 0) {
                Joint& j = joints[static_cast<std::size_t>(q.slot[lane])];
                j.linearImpulse = {q.impulseX[lane], q.impulseY[lane]};
                // No frame needed: a revolute joint's force is its point impulse.
                j.reactionForce = invH * j.linearImpulse;
                // A plain hinge has no spring, motor or limit, and prepareJoint() zeroed their
                // impulses: no torque (and no read of the joint's second cache line).
                j.reactionTorque = 0.0f;
            }
        }
    }
}

#if defined(__SSE2__)

namespace {

// A fixed side (static, asleep, padding) reads as a default BodyState, as the scalar joint's.
const BodyState kFixedState{};

// A lane's body: where its state is read from and its velocities written to (a fixed side's
// go to a sink that is never read).
struct QuadBodies {
    const BodyState* readA[4];
    const BodyState* readB[4];
    float* writeA[4];
    float* writeB[4];
};

inline QuadBodies bodiesOf(const PointJointQuad& q, std::span<BodyState> states, float (&sink)[8][4]) {
    QuadBodies r;
    for (int lane = 0; lane < 4; ++lane) {
        const int ia = q.indexA[lane];
        const int ib = q.indexB[lane];
        BodyState* a = ia < 0 ? nullptr : &states[static_cast<std::size_t>(ia)];
        BodyState* b = ib < 0 ? nullptr : &states[static_cast<std::size_t>(ib)];
        r.readA[lane] = a != nullptr ? a : &kFixedState;
        r.readB[lane] = b != nullptr ? b : &kFixedState;
        r.writeA[lane] = a != nullptr ? reinterpret_cast<float*>(a) : sink[lane];
        r.writeB[lane] = b != nullptr ? reinterpret_cast<float*>(b) : sink[4 + lane];
    }
    return r;
}

// The four states' velocities (vx, vy, w, flags) and motions (dpx, dpy, qc, qs), lane by lane.
struct Lanes {
    __m128 vx, vy, w, flags, dpx, dpy, qc, qs;
};

static_assert(sizeof(BodyState) == 8 * sizeof(float), "BodyState is two registers of four floats");

inline Lanes load(const BodyState* const (&s)[4]) {
    Lanes l;
    l.vx = _mm_loadu_ps(reinterpret_cast<const float*>(s[0]));
    l.vy = _mm_loadu_ps(reinterpret_cast<const float*>(s[1]));
    l.w = _mm_loadu_ps(reinterpret_cast<const float*>(s[2]));
    l.flags = _mm_loadu_ps(reinterpret_cast<const float*>(s[3]));
    _MM_TRANSPOSE4_PS(l.vx, l.vy, l.w, l.flags);
    l.dpx = _mm_loadu_ps(reinterpret_cast<const float*>(s[0]) + 4);
    l.dpy = _mm_loadu_ps(reinterpret_cast<const float*>(s[1]) + 4);
    l.qc = _mm_loadu_ps(reinterpret_cast<const float*>(s[2]) + 4);
    l.qs = _mm_loadu_ps(reinterpret_cast<const float*>(s[3]) + 4);
    _MM_TRANSPOSE4_PS(l.dpx, l.dpy, l.qc, l.qs);
    return l;
}

// Writes the velocities back (the flags' bits unchanged: shuffles only).
inline void storeVelocities(float* const (&s)[4], __m128 vx, __m128 vy, __m128 w, __m128 flags) {
    _MM_TRANSPOSE4_PS(vx, vy, w, flags);
    _mm_storeu_ps(s[0], vx);
    _mm_storeu_ps(s[1], vy);
    _mm_storeu_ps(s[2], w);
    _mm_storeu_ps(s[3], flags);
}

struct Frame {
    __m128 rAx, rAy, rBx, rBy;
};

// rotate(deltaRotation, anchor) for both sides: {c x - s y, s x + c y}.
inline Frame frameOf(const PointJointQuad& q, const Lanes& a, const Lanes& b) {
    const __m128 aAx = _mm_load_ps(q.anchorAx);
    const __m128 aAy = _mm_load_ps(q.anchorAy);
    const __m128 aBx = _mm_load_ps(q.anchorBx);
    const __m128 aBy = _mm_load_ps(q.anchorBy);
    return {_mm_sub_ps(_mm_mul_ps(a.qc, aAx), _mm_mul_ps(a.qs, aAy)),
            _mm_add_ps(_mm_mul_ps(a.qs, aAx), _mm_mul_ps(a.qc, aAy)),
            _mm_sub_ps(_mm_mul_ps(b.qc, aBx), _mm_mul_ps(b.qs, aBy)),
            _mm_add_ps(_mm_mul_ps(b.qs, aBx), _mm_mul_ps(b.qc, aBy))};
}

// applyPointImpulse(j, a, b, rA, rB, p, 0): A gets -p, B gets +p.
inline void apply(const PointJointQuad& q, const Frame& f, Lanes& a, Lanes& b, __m128 px, __m128 py) {
    const __m128 zero = _mm_setzero_ps();
    a.vx = _mm_sub_ps(a.vx, _mm_mul_ps(_mm_load_ps(q.invMassAx), px));
    a.vy = _mm_sub_ps(a.vy, _mm_mul_ps(_mm_load_ps(q.invMassAy), py));
    const __m128 crossA = _mm_sub_ps(_mm_mul_ps(f.rAx, py), _mm_mul_ps(f.rAy, px));
    a.w = _mm_sub_ps(a.w, _mm_mul_ps(_mm_load_ps(q.invInertiaA), _mm_add_ps(crossA, zero)));
    b.vx = _mm_add_ps(b.vx, _mm_mul_ps(_mm_load_ps(q.invMassBx), px));
    b.vy = _mm_add_ps(b.vy, _mm_mul_ps(_mm_load_ps(q.invMassBy), py));
    const __m128 crossB = _mm_sub_ps(_mm_mul_ps(f.rBx, py), _mm_mul_ps(f.rBy, px));
    b.w = _mm_add_ps(b.w, _mm_mul_ps(_mm_load_ps(q.invInertiaB), _mm_add_ps(crossB, zero)));
}

// A's lanes first, then B's; the lanes' bodies are distinct, so the order of the stores does
// not matter.
inline void storeBoth(const QuadBodies& bodies, const Lanes& a, const Lanes& b) {
    storeVelocities(bodies.writeA, a.vx, a.vy, a.w, a.flags);
    storeVelocities(bodies.writeB, b.vx, b.vy, b.w, b.flags);
}

} // namespace

void warmStartPointQuad(PointJointQuad& q, std::span<BodyState> states) {
    float sink[8][4];
    const QuadBodies bodies = bodiesOf(q, states, sink);
    Lanes a = load(bodies.readA);
    Lanes b = load(bodies.readB);
    const Frame f = frameOf(q, a, b);
    apply(q, f, a, b, _mm_load_ps(q.impulseX), _mm_load_ps(q.impulseY));
    storeBoth(bodies, a, b);
}

void solvePointQuad(PointJointQuad& q, std::span<BodyState> states, const Softness& soft) {
    float sink[8][4];
    const QuadBodies bodies = bodiesOf(q, states, sink);
    Lanes a = load(bodies.readA);
    Lanes b = load(bodies.readB);
    const Frame f = frameOf(q, a, b);
    // d = (dpB - dpA) + deltaCenter + (rB - rA)
    const __m128 dx = _mm_add_ps(_mm_add_ps(_mm_sub_ps(b.dpx, a.dpx), _mm_load_ps(q.deltaCenterX)),
                                 _mm_sub_ps(f.rBx, f.rAx));
    const __m128 dy = _mm_add_ps(_mm_add_ps(_mm_sub_ps(b.dpy, a.dpy), _mm_load_ps(q.deltaCenterY)),
                                 _mm_sub_ps(f.rBy, f.rAy));
    // Cdot = (vB + cross(wB, rB)) - (vA + cross(wA, rA)); cross(w, r) = {-w r.y, w r.x}
    const __m128 sign = _mm_set1_ps(-0.0f);
    const __m128 cdx = _mm_sub_ps(_mm_add_ps(b.vx, _mm_mul_ps(_mm_xor_ps(b.w, sign), f.rBy)),
                                  _mm_add_ps(a.vx, _mm_mul_ps(_mm_xor_ps(a.w, sign), f.rAy)));
    const __m128 cdy = _mm_sub_ps(_mm_add_ps(b.vy, _mm_mul_ps(b.w, f.rBx)), _mm_add_ps(a.vy, _mm_mul_ps(a.w, f.rAx)));
    // pointMatrix()
    const __m128 iA = _mm_load_ps(q.invInertiaA);
    const __m128 iB = _mm_load_ps(q.invInertiaB);
    const __m128 k11 = _mm_add_ps(
        _mm_add_ps(_mm_add_ps(_mm_load_ps(q.invMassAx), _mm_load_ps(q.invMassBx)), _mm_mul_ps(_mm_mul_ps(iA, f.rAy), f.rAy)),
        _mm_mul_ps(_mm_mul_ps(iB, f.rBy), f.rBy));
    const __m128 k12 = _mm_sub_ps(_mm_mul_ps(_mm_mul_ps(_mm_xor_ps(iA, sign), f.rAx), f.rAy),
                                  _mm_mul_ps(_mm_mul_ps(iB, f.rBx), f.rBy));
    const __m128 k22 = _mm_add_ps(
        _mm_add_ps(_mm_add_ps(_mm_load_ps(q.invMassAy), _mm_load_ps(q.invMassBy)), _mm_mul_ps(_mm_mul_ps(iA, f.rAx), f.rAx)),
        _mm_mul_ps(_mm_mul_ps(iB, f.rBx), f.rBx));
    // rhs = Cdot + biasRate * d; solve22(): det inverted where it is not zero
    const __m128 bias = _mm_set1_ps(soft.biasRate);
    const __m128 bx = _mm_add_ps(cdx, _mm_mul_ps(bias, dx));
    const __m128 by = _mm_add_ps(cdy, _mm_mul_ps(bias, dy));
    __m128 det = _mm_sub_ps(_mm_mul_ps(k11, k22), _mm_mul_ps(k12, k12));
    const __m128 nonzero = _mm_cmpneq_ps(det, _mm_setzero_ps());
    const __m128 inverse = _mm_div_ps(_mm_set1_ps(1.0f), _mm_or_ps(_mm_and_ps(nonzero, det), _mm_andnot_ps(nonzero, _mm_set1_ps(1.0f))));
    det = _mm_or_ps(_mm_and_ps(nonzero, inverse), _mm_andnot_ps(nonzero, det));
    const __m128 sx = _mm_mul_ps(det, _mm_sub_ps(_mm_mul_ps(k22, bx), _mm_mul_ps(k12, by)));
    const __m128 sy = _mm_mul_ps(det, _mm_sub_ps(_mm_mul_ps(k11, by), _mm_mul_ps(k12, bx)));
    // impulse = -massScale * K^-1 rhs - impulseScale * accumulated
    const __m128 massScale = _mm_set1_ps(-soft.massScale);
    const __m128 impulseScale = _mm_set1_ps(soft.impulseScale);
    __m128 accX = _mm_load_ps(q.impulseX);
    __m128 accY = _mm_load_ps(q.impulseY);
    const __m128 px = _mm_sub_ps(_mm_mul_ps(massScale, sx), _mm_mul_ps(impulseScale, accX));
    const __m128 py = _mm_sub_ps(_mm_mul_ps(massScale, sy), _mm_mul_ps(impulseScale, accY));
    _mm_store_ps(q.impulseX, _mm_add_ps(accX, px));
    _mm_store_ps(q.impulseY, _mm_add_ps(accY, py));
    apply(q, f, a, b, px, py);
    storeBoth(bodies, a, b);
}

#else

namespace {

// One lane as the scalar joint: the revolute joint's point with this lane's fields.
Joint laneJoint(const PointJointQuad& q, int lane) {
    Joint j;
    j.type = JointType::Revolute;
    j.indexA = q.indexA[lane];
    j.indexB = q.indexB[lane];
    j.invInertiaA = q.invInertiaA[lane];
    j.invInertiaB = q.invInertiaB[lane];
    j.invMassA = {q.invMassAx[lane], q.invMassAy[lane]};
    j.invMassB = {q.invMassBx[lane], q.invMassBy[lane]};
    j.anchorA = {q.anchorAx[lane], q.anchorAy[lane]};
    j.anchorB = {q.anchorBx[lane], q.anchorBy[lane]};
    j.deltaCenter = {q.deltaCenterX[lane], q.deltaCenterY[lane]};
    j.linearImpulse = {q.impulseX[lane], q.impulseY[lane]};
    return j;
}

} // namespace

void warmStartPointQuad(PointJointQuad& q, std::span<BodyState> states) {
    for (int lane = 0; lane < 4; ++lane) {
        if (q.slot[lane] >= 0) {
            Joint j = laneJoint(q, lane);
            warmStartJoint(j, states);
        }
    }
}

void solvePointQuad(PointJointQuad& q, std::span<BodyState> states, const Softness& soft) {
    const JointStep step{0.0f, 0.0f, soft};
    for (int lane = 0; lane < 4; ++lane) {
        if (q.slot[lane] >= 0) {
            Joint j = laneJoint(q, lane);
            solveJoint(j, states, step, true);
            q.impulseX[lane] = j.linearImpulse.x;
            q.impulseY[lane] = j.linearImpulse.y;
        }
    }
}

#endif

} // namespace e2d::physics::detail
