// SPDX-License-Identifier: MIT
// The wide contact passes for one lane width. Included by contact_solver_wide.cpp once per
// width, inside a namespace that defines: N (lanes), F and I (float and mask vectors),
// E2D_WIDE_FN (the function attributes: the instruction set of that width), splat, select,
// maxOf, anyLane, transposeRows, loadRows and storeRows. One text for every width, so they
// cannot drift apart.

using Constraint = WideConstraintT<N>;
using Point = WidePointT<N>;

struct WideBody {
    F vx, vy, w, flags;
    F dpx, dpy, qc, qs;
};

// Where each lane reads its body (a static side: a resting state) and writes it back (a
// static side: `sink`, never read). Unconditional stores cost less than a branch per lane.
E2D_WIDE_FN void lanesOf(const int (&index)[N], std::span<BodyState> states, BodyState& sink,
                         const BodyState* (&in)[N], BodyState* (&out)[N]) {
    for (int i = 0; i < N; ++i) {
        const bool moving = index[i] >= 0;
        BodyState* s = states.data() + (moving ? index[i] : 0);
        in[i] = moving ? s : &kStaticState;
        out[i] = moving ? s : &sink;
    }
}

E2D_WIDE_FN void scatterVelocities(const WideBody& b, BodyState* const (&out)[N]) {
    storeRows(b.vx, b.vy, b.w, b.flags, out);
}

E2D_WIDE_FN void warmStartOne(const Constraint& c, std::span<BodyState> states) {
    BodyState sink;
    const BodyState* sa[N];
    const BodyState* sb[N];
    BodyState* wa[N];
    BodyState* wb[N];
    lanesOf(c.indexA, states, sink, sa, wa);
    lanesOf(c.indexB, states, sink, sb, wb);
    WideBody a;
    WideBody b;
    loadRows(sa, 0, a.vx, a.vy, a.w, a.flags);
    loadRows(sb, 0, b.vx, b.vy, b.w, b.flags);
    const F nx = c.normalX;
    const F ny = c.normalY;
    const F tx = ny;
    const F ty = -nx;
    for (const Point& cp : c.points) {
        F px = cp.normalImpulse * nx + cp.tangentImpulse * tx;
        F py = cp.normalImpulse * ny + cp.tangentImpulse * ty;
        a.w = a.w - c.invInertiaA * (cp.anchorAx * py - cp.anchorAy * px);
        a.vx = a.vx - c.invMassAx * px;
        a.vy = a.vy - c.invMassAy * py;
        b.w = b.w + c.invInertiaB * (cp.anchorBx * py - cp.anchorBy * px);
        b.vx = b.vx + c.invMassBx * px;
        b.vy = b.vy + c.invMassBy * py;
    }
    scatterVelocities(a, wa);
    scatterVelocities(b, wb);
}

template <bool kReversePoints>
E2D_WIDE_FN void solveOne(Constraint& c, std::span<BodyState> states, float invH, bool useBias,
                          float pushMaxSpeed) {
    BodyState sink;
    const BodyState* sa[N];
    const BodyState* sb[N];
    BodyState* wa[N];
    BodyState* wb[N];
    lanesOf(c.indexA, states, sink, sa, wa);
    lanesOf(c.indexB, states, sink, sb, wb);
    WideBody a;
    WideBody b;
    loadRows(sa, 0, a.vx, a.vy, a.w, a.flags);
    loadRows(sb, 0, b.vx, b.vy, b.w, b.flags);
    loadRows(sa, 16, a.dpx, a.dpy, a.qc, a.qs);
    loadRows(sb, 16, b.dpx, b.dpy, b.qc, b.qs);
    const F nx = c.normalX;
    const F ny = c.normalY;
    const F tx = ny;
    const F ty = -nx;
    const F zero = splat(0.0f);
    const F one = splat(1.0f);
    const F vInvH = splat(invH);

    // Reversed, a one-point lane meets its empty second point first: zero normal mass, no
    // impulse, the same result as the scalar pass that skips it.
    for (int j = 0; j < 2; ++j) {
        Point& cp = c.points[kReversePoints ? 1 - j : j];
        F prAx = a.qc * cp.anchorAx - a.qs * cp.anchorAy;
        F prAy = a.qs * cp.anchorAx + a.qc * cp.anchorAy;
        F prBx = b.qc * cp.anchorBx - b.qs * cp.anchorBy;
        F prBy = b.qs * cp.anchorBx + b.qc * cp.anchorBy;
        F dx = (b.dpx - a.dpx) + (prBx - prAx);
        F dy = (b.dpy - a.dpy) + (prBy - prAy);
        F s = (dx * nx + dy * ny) + cp.baseSeparation;

        I speculative = s > zero;
        F bias;
        F massScale;
        F impulseScale;
        if (useBias) {
            bias = select(speculative, s * vInvH, maxOf(c.biasRate * s, splat(-pushMaxSpeed)));
            massScale = select(speculative, one, c.massScale);
            impulseScale = select(speculative, zero, c.impulseScale);
        } else {
            bias = select(speculative, s * vInvH, zero);
            massScale = one;
            impulseScale = zero;
        }

        F dvx = (b.vx + (-b.w) * cp.anchorBy) - (a.vx + (-a.w) * cp.anchorAy);
        F dvy = (b.vy + b.w * cp.anchorBx) - (a.vy + a.w * cp.anchorAx);
        F vn = dvx * nx + dvy * ny;

        I impact = ~cp.impactSeen & (vn + maxOf(s, zero) * vInvH < zero);
        // Rare once a pile has settled: skip the stores (and the division) when no lane hits.
        if (anyLane(impact)) {
            cp.impactSeen |= impact;
            cp.relativeVelocity = select(impact, vn, cp.relativeVelocity);
            cp.impactGap = select(impact, useBias ? s + vn / vInvH : s, cp.impactGap);
        }

        F impulse = (-cp.normalMass) * massScale * (vn + bias) - impulseScale * cp.normalImpulse;
        F newImpulse = maxOf(cp.normalImpulse + impulse, zero);
        impulse = newImpulse - cp.normalImpulse;
        cp.normalImpulse = newImpulse;
        cp.maxNormalImpulse = maxOf(cp.maxNormalImpulse, impulse);
        F px = impulse * nx;
        F py = impulse * ny;
        a.vx = a.vx - c.invMassAx * px;
        a.vy = a.vy - c.invMassAy * py;
        a.w = a.w - c.invInertiaA * (cp.anchorAx * py - cp.anchorAy * px);
        b.vx = b.vx + c.invMassBx * px;
        b.vy = b.vy + c.invMassBy * py;
        b.w = b.w + c.invInertiaB * (cp.anchorBx * py - cp.anchorBy * px);
    }

    // Friction, as solveFriction() does it.
    for (Point& cp : c.points) {
        F dvx = (b.vx + (-b.w) * cp.anchorBy) - (a.vx + (-a.w) * cp.anchorAy);
        F dvy = (b.vy + b.w * cp.anchorBx) - (a.vy + a.w * cp.anchorAx);
        F impulse = -cp.tangentMass * (dvx * tx + dvy * ty);
        F maxFriction = c.friction * cp.normalImpulse;
        // std::clamp(v, lo, hi): v < lo ? lo : (hi < v ? hi : v)
        F v = cp.tangentImpulse + impulse;
        F lo = -maxFriction;
        F newImpulse = select(v < lo, lo, select(maxFriction < v, maxFriction, v));
        impulse = newImpulse - cp.tangentImpulse;
        cp.tangentImpulse = newImpulse;
        F px = impulse * tx;
        F py = impulse * ty;
        a.vx = a.vx - c.invMassAx * px;
        a.vy = a.vy - c.invMassAy * py;
        a.w = a.w - c.invInertiaA * (cp.anchorAx * py - cp.anchorAy * px);
        b.vx = b.vx + c.invMassBx * px;
        b.vy = b.vy + c.invMassBy * py;
        b.w = b.w + c.invInertiaB * (cp.anchorBx * py - cp.anchorBy * px);
    }

    scatterVelocities(a, wa);
    scatterVelocities(b, wb);
}

// levelStart: the group boundaries of the levels to run (absolute indices into constraints).
E2D_WIDE_FN void warmStartAll(std::span<const Constraint> constraints, std::span<const int> levelStart,
                              std::span<BodyState> states) {
    if (levelStart.size() < 2) {
        return;
    }
    for (int g = levelStart.front(); g < levelStart.back(); ++g) {
        warmStartOne(constraints[static_cast<std::size_t>(g)], states);
    }
}

template <bool kReversePoints>
E2D_WIDE_FN void solveAll(std::span<Constraint> constraints, std::span<const int> levelStart,
                          std::span<BodyState> states, float invH, bool useBias,
                          float pushMaxSpeed, bool backward) {
    if (levelStart.size() < 2) {
        return;
    }
    if (!backward) {
        for (int g = levelStart.front(); g < levelStart.back(); ++g) {
            solveOne<kReversePoints>(constraints[static_cast<std::size_t>(g)], states, invH, useBias,
                                     pushMaxSpeed);
        }
        return;
    }
    // Within a level the order does not matter; backward only reverses the levels.
    const std::size_t levelCount = levelStart.size() - 1;
    for (std::size_t k = levelCount; k-- > 0;) {
        for (int g = levelStart[k]; g < levelStart[k + 1]; ++g) {
            solveOne<kReversePoints>(constraints[static_cast<std::size_t>(g)], states, invH,
                                     useBias, pushMaxSpeed);
        }
    }
}
