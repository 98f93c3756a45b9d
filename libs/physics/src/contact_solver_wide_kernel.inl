// SPDX-License-Identifier: MIT
// The wide contact passes for one lane width. Included by contact_solver_wide.cpp once per
// width, inside a namespace that defines: N (lanes), F and I (float and mask vectors),
// E2D_WIDE_FN (the function attributes: the instruction set of that width) and
// wide_lanes.hpp's helpers of that width (splat, select, maxOf, anyLane, allLanes, bodiesAt,
// transposeRows, loadRows and storeRows). One text for every width, so they cannot drift apart.
//
// A pass over a group keeps few lane vectors live, so that they stay in registers: the
// velocities of both sides and the points' separations, which it computes once from the motion
// rows (positions do not change during a velocity pass). A group whose lanes have one point
// each (no lane has a second: every pile of circles) takes passes without the second point.

#define E2D_WIDE_INLINE E2D_WIDE_FN __attribute__((always_inline))

using Constraint = WideConstraintT<N>;
using Point = WidePointT<N>;
using Impact = WideImpactT<N>;

// Every lane, lane k in bit k.
constexpr int kAllLaneBits = (1 << N) - 1;

// Where a group's lanes read and write their bodies: the addresses prepareGroup() recorded,
// static sides and empty lanes at the group's pad (in `im`), reset here before the lanes are
// read when a lane uses it. One 32-byte store (the member-wise assignment takes four stores
// and a load).
E2D_WIDE_INLINE void resetPad(const Constraint& c, const Impact& im) {
    if (c.padLanes == 0) {
        return;
    }
    const BodyState resting{};
    Float8 rows;
    static_assert(sizeof rows == sizeof resting);
    std::memcpy(&rows, &resting, sizeof rows);
    std::memcpy(reinterpret_cast<unsigned char*>(&im.pad), &rows, sizeof rows);
}

// The same object, which the compiler can no longer tell is `x`: what is read through it is
// read from memory again (a memory operand, no instruction of its own) instead of kept in a
// register or a stack slot since an earlier read. Changes no result.
template <class T>
E2D_WIDE_INLINE T& reread(T& x) {
    T* p = &x;
    asm("" : "+r"(p));
    return *p;
}

// One side's velocity rows as lane vectors; flags ride along unchanged, to be stored back.
struct Velocities {
    F vx, vy, w, flags;
};

E2D_WIDE_INLINE Velocities velocitiesOf(BodyState* const (&at)[N]) {
    Velocities v;
    loadRows(at, 0, v.vx, v.vy, v.w, v.flags);
    return v;
}

E2D_WIDE_INLINE void storeVelocities(const Velocities& v, BodyState* const (&at)[N]) {
    storeRows(v.vx, v.vy, v.w, v.flags, at);
}

// The separation of the first kPoints points now (currentSeparation()).
template <int kPoints>
E2D_WIDE_INLINE void separationsOf(const Constraint& c, F (&s)[2]) {
    F adpx, adpy, aqc, aqs, bdpx, bdpy, bqc, bqs;
    loadRows(c.bodyA, 16, adpx, adpy, aqc, aqs);
    loadRows(c.bodyB, 16, bdpx, bdpy, bqc, bqs);
    const F ddx = bdpx - adpx;
    const F ddy = bdpy - adpy;
#pragma GCC unroll 2
    for (int j = 0; j < kPoints; ++j) {
        const Point& cp = c.points[j];
        F prAx = aqc * cp.anchorAx - aqs * cp.anchorAy;
        F prAy = aqs * cp.anchorAx + aqc * cp.anchorAy;
        F prBx = bqc * cp.anchorBx - bqs * cp.anchorBy;
        F prBy = bqs * cp.anchorBx + bqc * cp.anchorBy;
        F dx = ddx + (prBx - prAx);
        F dy = ddy + (prBy - prAy);
        s[j] = (dx * c.normalX + dy * c.normalY) + cp.baseSeparation;
    }
}

template <int kPoints>
E2D_WIDE_INLINE void warmStartGroup(const Constraint& c, const Impact& im) {
    resetPad(c, im);
    Velocities a = velocitiesOf(c.bodyA);
    Velocities b = velocitiesOf(c.bodyB);
    const F nx = c.normalX;
    const F ny = c.normalY;
    const F tx = ny;
    const F ty = -nx;
#pragma GCC unroll 2
    for (int j = 0; j < kPoints; ++j) {
        const Point& cp = c.points[j];
        F px = cp.normalImpulse * nx + cp.tangentImpulse * tx;
        F py = cp.normalImpulse * ny + cp.tangentImpulse * ty;
        a.w = a.w - c.invInertiaA * (cp.anchorAx * py - cp.anchorAy * px);
        a.vx = a.vx - c.invMassAx * px;
        a.vy = a.vy - c.invMassAy * py;
        b.w = b.w + c.invInertiaB * (cp.anchorBx * py - cp.anchorBy * px);
        b.vx = b.vx + c.invMassBx * px;
        b.vy = b.vy + c.invMassBy * py;
    }
    storeVelocities(a, c.bodyA);
    storeVelocities(b, c.bodyB);
}

E2D_WIDE_FN F normalVelocityOf(const Point& cp, const Constraint& c, const Velocities& a,
                               const Velocities& b) {
    F dvx = (b.vx + (-b.w) * cp.anchorBy) - (a.vx + (-a.w) * cp.anchorAy);
    F dvy = (b.vy + b.w * cp.anchorBx) - (a.vy + a.w * cp.anchorAx);
    return dvx * c.normalX + dvy * c.normalY;
}

// A softness in every lane, or each lane's own. Only the biased passes read it.
struct LaneSoftness {
    F biasRate, massScale, impulseScale;
};

E2D_WIDE_FN LaneSoftness splatSoftness(const Softness& s) {
    return {splat(s.biasRate), splat(s.massScale), splat(s.impulseScale)};
}

// The lanes' softness: `rigid` lanes take vsStatic's, the others dynamic's.
E2D_WIDE_FN LaneSoftness softnessOf(I rigid, const LaneSoftness& dynamic,
                                    const LaneSoftness& vsStatic) {
    return {select(rigid, vsStatic.biasRate, dynamic.biasRate),
            select(rigid, vsStatic.massScale, dynamic.massScale),
            select(rigid, vsStatic.impulseScale, dynamic.impulseScale)};
}

// What a pass needs beyond the groups: the sub-step's 1/h and push-out speed cap, and the two
// softnesses the groups' lanes pick from (WideContacts::dynamic and vsStatic).
struct PassInput {
    F invH;
    float pushMaxSpeed;
    LaneSoftness dynamic;
    LaneSoftness vsStatic;
};

// A point's bias, mass scale and impulse scale, as targetOf() in contact_solver.cpp picks them.
struct Target {
    F bias, massScale, impulseScale;
};

E2D_WIDE_FN Target targetOf(const LaneSoftness& soft, F s, F invH, bool useBias,
                            float pushMaxSpeed) {
    const F zero = splat(0.0f);
    const F one = splat(1.0f);
    I speculative = s > zero;
    if (useBias) {
        return {select(speculative, s * invH, maxOf(soft.biasRate * s, splat(-pushMaxSpeed))),
                select(speculative, one, soft.massScale),
                select(speculative, zero, soft.impulseScale)};
    }
    return {select(speculative, s * invH, zero), one, zero};
}

// noteImpact() on point j's lanes of `lanes` (its bookkeeping in `im`).
E2D_WIDE_FN void noteImpact(Constraint& c, Impact& im, int j, I lanes, F vn, F s, F invH,
                            bool useBias) {
    // Points touching when the step began start seen: in a resting pile, all of them (and
    // `im` is not read).
    if (c.unseenLanes[j] == 0) {
        return;
    }
    I impact = lanes & ~im.impactSeen[j] & (vn + maxOf(s, splat(0.0f)) * invH < splat(0.0f));
    // Rare once a pile has settled: skip the stores (and the division) when no lane hits.
    if (anyLane(impact)) {
        im.impactSeen[j] |= impact;
        im.relativeVelocity[j] = select(impact, vn, im.relativeVelocity[j]);
        im.impactGap[j] = select(impact, useBias ? s + vn / invH : s, im.impactGap[j]);
        c.unseenLanes[j] = ~laneBits(im.impactSeen[j]) & kAllLaneBits;
    }
}

// `updated` on the lanes of `lanes`, `old` (bit for bit) on the others; kMasked false: every
// lane is in `lanes`.
template <bool kMasked>
E2D_WIDE_FN F keep(I lanes, F updated, F old) {
    if constexpr (kMasked) {
        return select(lanes, updated, old);
    } else {
        (void)lanes;
        (void)old;
        return updated;
    }
}

// The scalar pass's normal solve of point j (separation s), on the lanes of `lanes`.
template <bool kMasked, bool kReread = false>
E2D_WIDE_INLINE void solvePoint(Constraint& c, Impact& im, int j, F s, Velocities& a, Velocities& b,
                                I lanes, const LaneSoftness& soft, F invH, bool useBias,
                                float pushMaxSpeed) {
    Point& cp = c.points[j];
    Target t = targetOf(soft, s, invH, useBias, pushMaxSpeed);
    F vn = normalVelocityOf(cp, c, a, b);
    noteImpact(c, im, j, lanes, vn, s, invH, useBias);
    // As in solveBlock(), where it saves instructions (measured).
    Constraint& k = kReread ? reread(c) : c;
    Point& q = kReread ? reread(cp) : cp;
    const F nx = k.normalX;
    const F ny = k.normalY;
    F impulse = (-q.normalMass) * t.massScale * (vn + t.bias) - t.impulseScale * q.normalImpulse;
    F newImpulse = maxOf(q.normalImpulse + impulse, splat(0.0f));
    impulse = newImpulse - q.normalImpulse;
    q.normalImpulse = keep<kMasked>(lanes, newImpulse, q.normalImpulse);
    q.maxNormalImpulse =
        keep<kMasked>(lanes, maxOf(q.maxNormalImpulse, impulse), q.maxNormalImpulse);
    F px = impulse * nx;
    F py = impulse * ny;
    a.vx = keep<kMasked>(lanes, a.vx - k.invMassAx * px, a.vx);
    a.vy = keep<kMasked>(lanes, a.vy - k.invMassAy * py, a.vy);
    a.w = keep<kMasked>(lanes, a.w - k.invInertiaA * (q.anchorAx * py - q.anchorAy * px), a.w);
    b.vx = keep<kMasked>(lanes, b.vx + k.invMassBx * px, b.vx);
    b.vy = keep<kMasked>(lanes, b.vy + k.invMassBy * py, b.vy);
    b.w = keep<kMasked>(lanes, b.w + k.invInertiaB * (q.anchorBx * py - q.anchorBy * px), b.w);
}

// The scalar pass's block solve (solveBlock() on each point's soft right-hand side) on the
// lanes of `lanes`; s: the points' separations.
template <bool kMasked>
E2D_WIDE_INLINE void solveBlock(Constraint& c, Impact& im, const F (&s)[2], Velocities& a,
                                Velocities& b, I lanes, const LaneSoftness& soft, F invH,
                                bool useBias, float pushMaxSpeed) {
    const F zero = splat(0.0f);
    Point& cp1 = c.points[0];
    Point& cp2 = c.points[1];
    Target t1 = targetOf(soft, s[0], invH, useBias, pushMaxSpeed);
    Target t2 = targetOf(soft, s[1], invH, useBias, pushMaxSpeed);
    F vn1 = normalVelocityOf(cp1, c, a, b);
    F vn2 = normalVelocityOf(cp2, c, a, b);
    noteImpact(c, im, 0, lanes, vn1, s[0], invH, useBias);
    noteImpact(c, im, 1, lanes, vn2, s[1], invH, useBias);
    // Read again from memory what follows reads of `c` (a memory operand each) rather than
    // keep what the velocities and separations loaded: the anchors and the normal otherwise
    // sit in stack slots (a store each).
    Constraint& k = reread(c);
    Point& k1 = k.points[0];
    Point& k2 = k.points[1];
    const F acc1 = k1.normalImpulse;
    const F acc2 = k2.normalImpulse;
    // K's inverse, as prepareBlock() works it out (K = identity gives the identity).
    const F inv11 = k.invDet * k.k22;
    const F inv12 = -k.invDet * k.k12;
    const F inv22 = k.invDet * k.k11;
    F r1 = t1.massScale * (vn1 + t1.bias) + t1.impulseScale * (k.k11 * acc1 + k.k12 * acc2);
    F r2 = t2.massScale * (vn2 + t2.bias) + t2.impulseScale * (k.k12 * acc1 + k.k22 * acc2);
    F x1 = acc1 - (inv11 * r1 + inv12 * r2);
    F x2 = acc2 - (inv12 * r1 + inv22 * r2);
    I okBoth = (x1 >= zero) & (x2 >= zero);
    // A resting pile has both points pushing in every lane: the other cases are rare.
    if (!allLanes(okBoth | ~lanes)) {
        F b1 = r1 - (k.k11 * acc1 + k.k12 * acc2);
        F b2 = r2 - (k.k12 * acc1 + k.k22 * acc2);
        F first = -b1 * k1.normalMass;
        I okFirst = (first >= zero) & (k.k12 * first + b2 >= zero);
        F second = -b2 * k2.normalMass;
        I okSecond = (second >= zero) & (k.k12 * second + b1 >= zero);
        I okNone = (b1 >= zero) & (b2 >= zero);
        // The first feasible case wins; none feasible keeps the impulses.
        x1 = select(okBoth, x1, select(okFirst, first, select(okSecond | okNone, zero, acc1)));
        x2 = select(okBoth, x2,
                    select(okFirst, zero, select(okSecond, second, select(okNone, zero, acc2))));
    }
    F d1 = x1 - acc1;
    F d2 = x2 - acc2;
    k1.normalImpulse = keep<kMasked>(lanes, x1, acc1);
    k2.normalImpulse = keep<kMasked>(lanes, x2, acc2);
    k1.maxNormalImpulse = keep<kMasked>(lanes, maxOf(k1.maxNormalImpulse, d1), k1.maxNormalImpulse);
    k2.maxNormalImpulse = keep<kMasked>(lanes, maxOf(k2.maxNormalImpulse, d2), k2.maxNormalImpulse);
    F p1x = d1 * k.normalX;
    F p1y = d1 * k.normalY;
    F p2x = d2 * k.normalX;
    F p2y = d2 * k.normalY;
    a.vx = keep<kMasked>(lanes, a.vx - k.invMassAx * (p1x + p2x), a.vx);
    a.vy = keep<kMasked>(lanes, a.vy - k.invMassAy * (p1y + p2y), a.vy);
    a.w = keep<kMasked>(lanes,
                        a.w - k.invInertiaA * ((k1.anchorAx * p1y - k1.anchorAy * p1x) +
                                               (k2.anchorAx * p2y - k2.anchorAy * p2x)),
                        a.w);
    b.vx = keep<kMasked>(lanes, b.vx + k.invMassBx * (p1x + p2x), b.vx);
    b.vy = keep<kMasked>(lanes, b.vy + k.invMassBy * (p1y + p2y), b.vy);
    b.w = keep<kMasked>(lanes,
                        b.w + k.invInertiaB * ((k1.anchorBx * p1y - k1.anchorBy * p1x) +
                                               (k2.anchorBx * p2y - k2.anchorBy * p2x)),
                        b.w);
}

// Friction at point `cp`, as solveFriction() does it.
E2D_WIDE_INLINE void solveFrictionAt(Constraint& c, Point& cp, Velocities& a, Velocities& b) {
    const F tx = c.normalY;
    const F ty = -c.normalX;
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

// solveContacts() on one group, whose lanes have at most kPoints points.
// pass: the softnesses (invH and pushMaxSpeed come apart, in registers).
template <bool kReversePoints, int kPoints>
E2D_WIDE_INLINE void solveGroup(Constraint& c, Impact& im, F invH, bool useBias, float pushMaxSpeed,
                                const PassInput& pass) {
    resetPad(c, im);
    F s[2];
    if (c.separationsKnown != 0) {
        if (useBias) {
            c.separationsKnown = 0;
        }
#pragma GCC unroll 2
        for (int j = 0; j < kPoints; ++j) {
            s[j] = c.separation[j];
        }
    } else {
        separationsOf<kPoints>(c, s);
        if (!useBias) {
#pragma GCC unroll 2
            for (int j = 0; j < kPoints; ++j) {
                c.separation[j] = s[j];
            }
            c.separationsKnown = 1;
        }
    }
    Velocities a = velocitiesOf(c.bodyA);
    Velocities b = velocitiesOf(c.bodyB);
    const I all = ~I{};
    // The relax passes use no softness (folded away). Most groups have no rigid lane: they
    // read the pass's, from memory as a group's own fields are read (kept in registers through
    // the solve, three more vectors spill others).
    LaneSoftness mixed;
    if (useBias && c.rigidLanes != 0) {
        mixed = softnessOf(laneMaskOf(c.rigidLanes), pass.dynamic, pass.vsStatic);
    }
    const LaneSoftness& soft = !useBias || c.rigidLanes == 0 ? pass.dynamic : reread(mixed);
    if constexpr (kPoints == 1) {
        solvePoint<false, true>(c, im, 0, s[0], a, b, all, soft, invH, useBias, pushMaxSpeed);
    } else {
        // Lanes of well-conditioned 2-point manifolds take the block solve, the others go point
        // by point; a group is usually all one kind (a pile of boxes). Reversed, a one-point
        // lane meets its empty second point first: zero normal mass, no impulse, the same
        // result as the scalar pass that skips it.
        const int blockLanes = c.blockLanes;
        const int first = kReversePoints ? 1 : 0;
        if (blockLanes == kAllLaneBits) {
            solveBlock<false>(c, im, s, a, b, all, soft, invH, useBias, pushMaxSpeed);
        } else if (blockLanes == 0) {
            solvePoint<false>(c, im, first, s[first], a, b, all, soft, invH, useBias, pushMaxSpeed);
            solvePoint<false>(c, im, 1 - first, s[1 - first], a, b, all, soft, invH, useBias,
                              pushMaxSpeed);
        } else {
            const I block = laneMaskOf(blockLanes);
            solvePoint<true>(c, im, first, s[first], a, b, ~block, soft, invH, useBias,
                             pushMaxSpeed);
            solvePoint<true>(c, im, 1 - first, s[1 - first], a, b, ~block, soft, invH, useBias,
                             pushMaxSpeed);
            solveBlock<true>(c, im, s, a, b, block, soft, invH, useBias, pushMaxSpeed);
        }
    }
    if constexpr (kPoints == 2) {
        // Two points' constants do not fit in the registers with the velocities: without this,
        // the compiler keeps what it loaded from `c` for the separations and the normal solve
        // in stack slots for friction too (a store each); past this point (memory may have
        // changed, to the compiler) friction reads them from `c` again. An instruction
        // barrier only: it changes no result. With one point it costs more than it saves, and
        // so does one before the normal solve (measured with callgrind).
        asm volatile("" ::: "memory");
    }
#pragma GCC unroll 2
    for (int j = 0; j < kPoints; ++j) {
        solveFrictionAt(c, c.points[j], a, b);
    }
    storeVelocities(a, c.bodyA);
    storeVelocities(b, c.bodyB);
}

// levelStart: the group boundaries of the levels to run (absolute indices into constraints);
// impacts: the groups' side data (their pads), at the groups' indices.
E2D_WIDE_FN void warmStartAll(std::span<const Constraint> constraints,
                              std::span<const Impact> impacts, std::span<const int> levelStart) {
    if (levelStart.size() < 2) {
        return;
    }
    for (int g = levelStart.front(); g < levelStart.back(); ++g) {
        const Constraint& c = constraints[static_cast<std::size_t>(g)];
        const Impact& im = impacts[static_cast<std::size_t>(g)];
        if (c.twoPointLanes != 0) {
            warmStartGroup<2>(c, im);
        } else {
            warmStartGroup<1>(c, im);
        }
    }
}

// kUseBias a constant: each pass runs one kind (solve or relax), and the relax pass's targets
// (mass scale one, impulse scale zero) then fold into the code instead of being selected.
// impacts: the groups' impact bookkeeping, at the groups' indices.
template <bool kReversePoints, bool kUseBias>
E2D_WIDE_FN void solveGroups(std::span<Constraint> constraints, std::span<Impact> impacts,
                             int first, int end, const PassInput& pass) {
    const F invH = pass.invH;
    for (int g = first; g < end; ++g) {
        Constraint& c = constraints[static_cast<std::size_t>(g)];
        Impact& im = impacts[static_cast<std::size_t>(g)];
        if (c.twoPointLanes != 0) {
            solveGroup<kReversePoints, 2>(c, im, invH, kUseBias, pass.pushMaxSpeed, pass);
        } else {
            solveGroup<kReversePoints, 1>(c, im, invH, kUseBias, pass.pushMaxSpeed, pass);
        }
    }
}

template <bool kReversePoints, bool kUseBias>
E2D_WIDE_FN void solveLevels(std::span<Constraint> constraints, std::span<Impact> impacts,
                             std::span<const int> levelStart, const PassInput& pass,
                             bool backward) {
    if (!backward) {
        solveGroups<kReversePoints, kUseBias>(constraints, impacts, levelStart.front(),
                                              levelStart.back(), pass);
        return;
    }
    // Within a level the order does not matter; backward only reverses the levels.
    for (std::size_t k = levelStart.size() - 1; k-- > 0;) {
        solveGroups<kReversePoints, kUseBias>(constraints, impacts, levelStart[k],
                                              levelStart[k + 1], pass);
    }
}

// dynamic, vsStatic: the softnesses the groups' lanes pick from (WideContacts).
template <bool kReversePoints>
E2D_WIDE_FN void solveAll(std::span<Constraint> constraints, std::span<Impact> impacts,
                          std::span<const int> levelStart, float invH, bool useBias,
                          float pushMaxSpeed, bool backward, const Softness& dynamic,
                          const Softness& vsStatic) {
    if (levelStart.size() < 2) {
        return;
    }
    const PassInput pass{splat(invH), pushMaxSpeed, splatSoftness(dynamic),
                         splatSoftness(vsStatic)};
    if (useBias) {
        solveLevels<kReversePoints, true>(constraints, impacts, levelStart, pass, backward);
    } else {
        solveLevels<kReversePoints, false>(constraints, impacts, levelStart, pass, backward);
    }
}

// The lanes of `c` (its impact bookkeeping in `im`) that may hit (WideLaneHit), lane k in bit k.
E2D_WIDE_FN int hitLanes(const Constraint& c, const Impact& im, float threshold) {
    I mayHit = I{};
    for (int j = 0; j < 2; ++j) {
        mayHit |= (c.points[j].maxNormalImpulse > splat(0.0f)) &
                  (-im.relativeVelocity[j] > splat(threshold));
    }
    return laneBits(mayHit);
}

#undef E2D_WIDE_INLINE

// --- Prepare: prepareContact(), prepareBlock() and packLane() on every lane at once ---

using Gather = WideGatherT<N>;

E2D_WIDE_FN F vectorOf(const float (&x)[N]) {
    F v;
    std::memcpy(&v, x, sizeof v);
    return v;
}

// The manifold rows prepareGroup() reads: {normal, -, -}, and per point {anchorA, anchorB} and
// {separation, normalImpulse, tangentImpulse, -} (the last float is the id's bytes, not used).
static_assert(offsetof(Manifold, normal) == 0 && sizeof(ManifoldPoint) == 40 &&
                  offsetof(ManifoldPoint, anchorB) == offsetof(ManifoldPoint, anchorA) + 8 &&
                  offsetof(ManifoldPoint, normalImpulse) ==
                      offsetof(ManifoldPoint, separation) + 4 &&
                  offsetof(ManifoldPoint, tangentImpulse) ==
                      offsetof(ManifoldPoint, separation) + 8 &&
                  offsetof(ManifoldPoint, separation) + 16 <= sizeof(ManifoldPoint) &&
                  sizeof(Manifold::pointCount) == 4 && offsetof(Manifold, pointCount) >= 12,
              "prepareGroup() reads Manifold rows of four floats");

// leverRounding().
E2D_WIDE_FN F leverRoundingOf(const Constraint& c, F rAx, F rAy, F rBx, F rBy) {
    return splat(kLeverRounding2) *
           (c.invInertiaA * (rAx * rAx + rAy * rAy) + c.invInertiaB * (rBx * rBx + rBy * rBy));
}

// lockedAxisFloor() along (ax, ay).
E2D_WIDE_FN F lockedAxisFloorOf(const Constraint& c, F ax, F ay) {
    // |ax| and |ay| (a -0 where std::abs() gives +0 changes no maximum below).
    const F absX = maxOf(ax, -ax);
    const F absY = maxOf(ay, -ay);
    const F a = maxOf(c.invMassAx * absX, c.invMassAy * absY);
    const F b = maxOf(c.invMassBx * absX, c.invMassBy * absY);
    return maxOf(a, b) * splat(1.0f / kMaxContactGain);
}

// effectiveMass() along (ax, ay); 0 where the sum is not positive. `locked`: whether any lane
// has a side locked along one axis (lockedAxisFloor() binds on no other lane).
E2D_WIDE_FN F effectiveMassOf(const Constraint& c, F ax, F ay, F rAx, F rAy, F rBx, F rBy,
                              bool locked) {
    F rnA = rAx * ay - rAy * ax;
    F rnB = rBx * ay - rBy * ax;
    F k = c.invMassAx * ax * ax + c.invMassAy * ay * ay + c.invMassBx * ax * ax +
          c.invMassBy * ay * ay + c.invInertiaA * rnA * rnA + c.invInertiaB * rnB * rnB;
    k = k + leverRoundingOf(c, rAx, rAy, rBx, rBy);
    if (locked) {
        k = maxOf(k, lockedAxisFloorOf(c, ax, ay));
    }
    const F zero = splat(0.0f);
    I positive = k > zero;
    // The divisor is 1 where it is not used: no division by zero, even in discarded lanes.
    return select(positive, splat(1.0f) / select(positive, k, splat(1.0f)), zero);
}

// `states`: the array the group's bodies are in; `im`: the group's side data; dynamic and
// vsStatic: the softnesses its lanes pick from (WideContacts). Returns the lanes
// isPushedApart() holds pushed apart (prepareWideGroup()).
E2D_WIDE_FN int prepareGroup(const Gather& in, Constraint& c, Impact& im, BodyState* states,
                             const Softness& dynamic, const Softness& vsStatic) {
    const F zero = splat(0.0f);
    const F one = splat(1.0f);
    bodiesAt(in.indexA, states, &im.pad, c.bodyA);
    bodiesAt(in.indexB, states, &im.pad, c.bodyB);
    int padLanes = 0;
    for (int lane = 0; lane < N; ++lane) {
        padLanes |= (in.indexA[lane] < 0 || in.indexB[lane] < 0) ? 1 << lane : 0;
    }
    c.padLanes = padLanes;
    // Static sides and empty lanes read the pad: at rest, as ContactBodyView{} is.
    resetPad(c, im);
    F unused0, unused1, unused2, countBits;
    // The row that ends with the point count (its bits ride through the shuffles unchanged):
    // a few loads and shuffles where a lane at a time took a load, a load and a store.
    loadRows(in.manifold, offsetof(Manifold, pointCount) + sizeof(int) - 16, unused0, unused1,
             unused2, countBits);
    I count;
    std::memcpy(&count, &countBits, sizeof count);
    F nx, ny;
    loadRows(in.manifold, offsetof(Manifold, normal), nx, ny, unused0, unused1);
    c.normalX = nx;
    c.normalY = ny;
    F oAx, oAy, oBx, oBy;
    loadRows(in.offsetA, 0, oAx, oAy, unused0, unused1);
    loadRows(in.offsetB, 0, oBx, oBy, unused0, unused1);
    loadRows(in.massA, 0, c.invMassAx, c.invMassAy, c.invInertiaA, unused0);
    loadRows(in.massB, 0, c.invMassBx, c.invMassBy, c.invInertiaB, unused0);
    F vAx, vAy, wA, vBx, vBy, wB;
    loadRows(c.bodyA, 0, vAx, vAy, wA, unused0);
    loadRows(c.bodyB, 0, vBx, vBy, wB, unused0);
    c.friction = vectorOf(in.friction);
    // The world's choice of softness: vsStatic against a rigid side (empty lanes are rigid; no
    // impulse comes of theirs). isDeepPushedApart() below reads an empty lane's as
    // Softness{}, as ContactConstraint{} holds it.
    const I rigid = ((c.invMassAx == zero) & (c.invMassAy == zero) & (c.invInertiaA == zero)) |
                    ((c.invMassBx == zero) & (c.invMassBy == zero) & (c.invInertiaB == zero));
    const I empty = count == 0;
    c.rigidLanes = laneBits(rigid);
    // A side free on both axes has the same inverse mass on each.
    const bool locked = anyLane((c.invMassAx != c.invMassAy) | (c.invMassBx != c.invMassBy));
    const LaneSoftness picked = softnessOf(rigid, splatSoftness(dynamic), splatSoftness(vsStatic));
    const LaneSoftness soft{select(empty, splat(Softness{}.biasRate), picked.biasRate),
                            select(empty, splat(Softness{}.massScale), picked.massScale),
                            select(empty, splat(Softness{}.impulseScale), picked.impulseScale)};
    // Per point, isPushedApart()'s first test and what its second reads.
    I deep = I{};
    F depth[2];
    const F tx = ny;
    const F ty = -nx;
#pragma GCC unroll 2
    for (int i = 0; i < 2; ++i) {
        Point& cp = c.points[i];
        // A missing point (or an empty lane) packs as ContactConstraintPoint{}: all zero. What
        // the manifold holds there is read but never kept.
        const I present = count > i;
        if (i == 1 && !anyLane(present)) {
            // No lane has a second point (a pile of circles): all zero, what the lines below
            // give such a point, without reading it.
            cp = Point{};
            im.relativeVelocity[i] = zero;
            im.impactGap[i] = zero;
            im.impactSeen[i] = I{};
            c.unseenLanes[i] = kAllLaneBits;
            depth[i] = zero;
            continue;
        }
        const std::size_t at = offsetof(Manifold, points) + sizeof(ManifoldPoint) * i;
        F anchorAx, anchorAy, anchorBx, anchorBy, separation, normalImpulse, tangentImpulse;
        loadRows(in.manifold, at + offsetof(ManifoldPoint, anchorA), anchorAx, anchorAy, anchorBx,
                 anchorBy);
        loadRows(in.manifold, at + offsetof(ManifoldPoint, separation), separation, normalImpulse,
                 tangentImpulse, unused0);
        // isPushedApart()'s first test.
        deep |= present & (separation < splat(-kLinearSlop));
        depth[i] = select(present, -separation, zero);
        F rAx = anchorAx - oAx;
        F rAy = anchorAy - oAy;
        F rBx = anchorBx - oBx;
        F rBy = anchorBy - oBy;
        cp.anchorAx = select(present, rAx, zero);
        cp.anchorAy = select(present, rAy, zero);
        cp.anchorBx = select(present, rBx, zero);
        cp.anchorBy = select(present, rBy, zero);
        cp.baseSeparation =
            select(present, separation - ((rBx - rAx) * nx + (rBy - rAy) * ny), zero);
        cp.normalImpulse = select(present, normalImpulse, zero);
        cp.tangentImpulse = select(present, tangentImpulse, zero);
        cp.maxNormalImpulse = zero;
        cp.normalMass =
            select(present, effectiveMassOf(c, nx, ny, rAx, rAy, rBx, rBy, locked), zero);
        cp.tangentMass =
            select(present, effectiveMassOf(c, tx, ty, rAx, rAy, rBx, rBy, locked), zero);
        F vrAx = vAx + (-wA) * rAy;
        F vrAy = vAy + wA * rAx;
        F vrBx = vBx + (-wB) * rBy;
        F vrBy = vBy + wB * rBx;
        im.relativeVelocity[i] = select(present, nx * (vrBx - vrAx) + ny * (vrBy - vrAy), zero);
        const I seen = present & (separation <= splat(kTouchingSeparation));
        im.impactSeen[i] = seen;
        im.impactGap[i] = select(seen, separation, zero);
        c.unseenLanes[i] = ~laneBits(seen) & kAllLaneBits;
    }

    // prepareBlock(), on the anchors just packed.
    const Point& p1 = c.points[0];
    const Point& p2 = c.points[1];
    F linear = (c.invMassAx + c.invMassBx) * (nx * nx) + (c.invMassAy + c.invMassBy) * (ny * ny);
    F rn1A = p1.anchorAx * ny - p1.anchorAy * nx;
    F rn1B = p1.anchorBx * ny - p1.anchorBy * nx;
    F rn2A = p2.anchorAx * ny - p2.anchorAy * nx;
    F rn2B = p2.anchorBx * ny - p2.anchorBy * nx;
    F k11 = linear + c.invInertiaA * rn1A * rn1A + c.invInertiaB * rn1B * rn1B;
    F k22 = linear + c.invInertiaA * rn2A * rn2A + c.invInertiaB * rn2B * rn2B;
    F k12 = linear + c.invInertiaA * rn1A * rn2A + c.invInertiaB * rn1B * rn2B;
    // isDeepPushedApart(): K's rows (before the rounding term; K21 rounds apart from K12) times
    // the stored impulses, against the overlaps.
    {
        const I two = count == 2;
        const F k21 = linear + c.invInertiaA * rn2A * rn1A + c.invInertiaB * rn2B * rn1B;
        const F stiffness = soft.massScale * soft.biasRate;
        const I stiff = stiffness > zero;
        const F restPerImpulse =
            splat(kPushOutRestMargin) * soft.impulseScale / select(stiff, stiffness, one);
        const F lambda1 = p1.normalImpulse;
        const F lambda2 = p2.normalImpulse;
        F load1 = zero + k11 * lambda1;
        F load2 = zero + k21 * lambda1;
        load1 = select(two, load1 + k12 * lambda2, load1);
        load2 = select(two, load2 + k22 * lambda2, load2);
        const I beyond1 = depth[0] > splat(kLinearSlop) + restPerImpulse * maxOf(load1, zero);
        const I beyond2 =
            two & (depth[1] > splat(kLinearSlop) + restPerImpulse * maxOf(load2, zero));
        deep &= stiff & (beyond1 | beyond2);
    }
    k11 = k11 + leverRoundingOf(c, p1.anchorAx, p1.anchorAy, p1.anchorBx, p1.anchorBy);
    k22 = k22 + leverRoundingOf(c, p2.anchorAx, p2.anchorAy, p2.anchorBx, p2.anchorBy);
    F det = k11 * k22 - k12 * k12;
    I block = (count == 2) & (k11 * k11 < splat(kMaxBlockConditionNumber) * det) &
              (det >= splat(kMinBlockDeterminant));
    if (locked) {
        const F least = lockedAxisFloorOf(c, nx, ny);
        block &= (k11 >= least) & (k22 >= least);
    }
    F invDet = one / select(block, det, one);
    // Other lanes hold K = identity; empty lanes count as block lanes (see WideConstraintT).
    c.k11 = select(block, k11, one);
    c.k12 = select(block, k12, zero);
    c.k22 = select(block, k22, one);
    c.invDet = invDet;
    c.blockLanes = laneBits(block | empty);
    c.twoPointLanes = laneBits(count == 2);
    c.separationsKnown = 0;
    return laneBits(deep);
}
