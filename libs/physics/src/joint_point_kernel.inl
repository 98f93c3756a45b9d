// SPDX-License-Identifier: MIT
// The passes of plain hinges N at a time, for one lane width. Included by joint_point.cpp once
// per width, inside a namespace that defines N, F, I, E2D_WIDE_FN and wide_lanes.hpp's helpers
// (splat, select, lanesOf, loadRows, storeRows). Each lane does warmStartRevolute()'s and
// solveRevolute()'s products and sums in the same order, so its results are the scalar
// joint's bits.

using Hinges = PointJointLanes<N>;

E2D_WIDE_FN F lanes(const float (&x)[N]) {
    F v;
    std::memcpy(&v, x, sizeof v);
    return v;
}

// Both sides of the N hinges, lane by lane: velocities (vx, vy, w, flags), motions (dpx, dpy,
// qc, qs) and the anchors' offsets rotated by the motions, rotate(deltaRotation, anchor) =
// {c x - s y, s x + c y}. Values only (no address taken), so they live in registers.
struct HingeSides {
    F avx, avy, aw, aflags, adpx, adpy, aqc, aqs;
    F bvx, bvy, bw, bflags, bdpx, bdpy, bqc, bqs;
    F rAx, rAy, rBx, rBy;
};

// Where the lanes' bodies are read from and their velocities written to (lanesOf()).
struct HingeBodies {
    BodyState sink;
    const BodyState* inA[N];
    const BodyState* inB[N];
    BodyState* outA[N];
    BodyState* outB[N];
};

E2D_WIDE_FN __attribute__((always_inline)) HingeSides gather(const Hinges& q,
                                                             const HingeBodies& at) {
    HingeSides s;
    loadRows(at.inA, 0, s.avx, s.avy, s.aw, s.aflags);
    loadRows(at.inB, 0, s.bvx, s.bvy, s.bw, s.bflags);
    loadRows(at.inA, 16, s.adpx, s.adpy, s.aqc, s.aqs);
    loadRows(at.inB, 16, s.bdpx, s.bdpy, s.bqc, s.bqs);
    const F aAx = lanes(q.anchorAx);
    const F aAy = lanes(q.anchorAy);
    const F aBx = lanes(q.anchorBx);
    const F aBy = lanes(q.anchorBy);
    s.rAx = s.aqc * aAx - s.aqs * aAy;
    s.rAy = s.aqs * aAx + s.aqc * aAy;
    s.rBx = s.bqc * aBx - s.bqs * aBy;
    s.rBy = s.bqs * aBx + s.bqc * aBy;
    return s;
}

// applyPointImpulse(j, a, b, rA, rB, p, 0): A gets -p, B gets +p; then the velocities go back
// (A's lanes first, then B's: the lanes' bodies are distinct, so the order does not matter).
E2D_WIDE_FN __attribute__((always_inline)) void applyAndScatter(const Hinges& q, HingeSides s,
                                                                HingeBodies& at, F px, F py) {
    const F zero = splat(0.0f);
    s.avx = s.avx - lanes(q.invMassAx) * px;
    s.avy = s.avy - lanes(q.invMassAy) * py;
    s.aw = s.aw - lanes(q.invInertiaA) * ((s.rAx * py - s.rAy * px) + zero);
    s.bvx = s.bvx + lanes(q.invMassBx) * px;
    s.bvy = s.bvy + lanes(q.invMassBy) * py;
    s.bw = s.bw + lanes(q.invInertiaB) * ((s.rBx * py - s.rBy * px) + zero);
    storeRows(s.avx, s.avy, s.aw, s.aflags, at.outA);
    storeRows(s.bvx, s.bvy, s.bw, s.bflags, at.outB);
}

E2D_WIDE_FN __attribute__((always_inline)) void
bodiesOf(const Hinges& q, std::span<BodyState> states, HingeBodies& at) {
    lanesOf(q.indexA, states, at.sink, at.inA, at.outA);
    lanesOf(q.indexB, states, at.sink, at.inB, at.outB);
}

E2D_WIDE_FN void warmStartHinges(Hinges& q, std::span<BodyState> states) {
    HingeBodies at;
    bodiesOf(q, states, at);
    applyAndScatter(q, gather(q, at), at, lanes(q.impulseX), lanes(q.impulseY));
}

E2D_WIDE_FN void solveHinges(Hinges& q, std::span<BodyState> states, const Softness& soft) {
    HingeBodies at;
    bodiesOf(q, states, at);
    const HingeSides s = gather(q, at);
    // d = (dpB - dpA) + deltaCenter + (rB - rA)
    const F dx = ((s.bdpx - s.adpx) + lanes(q.deltaCenterX)) + (s.rBx - s.rAx);
    const F dy = ((s.bdpy - s.adpy) + lanes(q.deltaCenterY)) + (s.rBy - s.rAy);
    // Cdot = (vB + cross(wB, rB)) - (vA + cross(wA, rA)); cross(w, r) = {-w r.y, w r.x}
    const F cdx = (s.bvx + (-s.bw) * s.rBy) - (s.avx + (-s.aw) * s.rAy);
    const F cdy = (s.bvy + s.bw * s.rBx) - (s.avy + s.aw * s.rAx);
    // pointMatrix()
    const F iA = lanes(q.invInertiaA);
    const F iB = lanes(q.invInertiaB);
    const F k11 =
        ((lanes(q.invMassAx) + lanes(q.invMassBx)) + (iA * s.rAy) * s.rAy) + (iB * s.rBy) * s.rBy;
    const F k12 = ((-iA) * s.rAx) * s.rAy - (iB * s.rBx) * s.rBy;
    const F k22 =
        ((lanes(q.invMassAy) + lanes(q.invMassBy)) + (iA * s.rAx) * s.rAx) + (iB * s.rBx) * s.rBx;
    // rhs = Cdot + biasRate * d; solve22(): det inverted where it is not zero (and no lane
    // divides by zero)
    const F bias = splat(soft.biasRate);
    const F bx = cdx + bias * dx;
    const F by = cdy + bias * dy;
    F det = k11 * k22 - k12 * k12;
    const I nonzero = det != splat(0.0f);
    const F one = splat(1.0f);
    det = select(nonzero, one / select(nonzero, det, one), det);
    const F sx = det * (k22 * bx - k12 * by);
    const F sy = det * (k11 * by - k12 * bx);
    // impulse = -massScale * K^-1 rhs - impulseScale * accumulated
    const F massScale = splat(-soft.massScale);
    const F impulseScale = splat(soft.impulseScale);
    const F accX = lanes(q.impulseX);
    const F accY = lanes(q.impulseY);
    const F px = massScale * sx - impulseScale * accX;
    const F py = massScale * sy - impulseScale * accY;
    const F sumX = accX + px;
    const F sumY = accY + py;
    std::memcpy(q.impulseX, &sumX, sizeof sumX);
    std::memcpy(q.impulseY, &sumY, sizeof sumY);
    applyAndScatter(q, s, at, px, py);
}
