// SPDX-License-Identifier: MIT
#include "contact_solver_wide.hpp"

#include <bit>
#include <cstddef>
#include <cstring>

namespace e2d::physics::detail {

namespace {

// mask ? a : b, lane by lane (mask lanes are all ones or all zeros).
inline Float4 select(Int4 mask, Float4 a, Float4 b) {
    return std::bit_cast<Float4>((mask & std::bit_cast<Int4>(a)) | (~mask & std::bit_cast<Int4>(b)));
}
// std::max and std::min, lane by lane, with their exact semantics (first argument on ties).
inline Float4 maxOf(Float4 a, Float4 b) { return select(a < b, b, a); }
inline Float4 splat(float x) { return Float4{x, x, x, x}; }

// A static side (index -1) reads a resting state and writes nothing.
const BodyState kStaticState{};

struct WideBody {
    Float4 vx, vy, w, flags;
    Float4 dpx, dpy, qc, qs;
};

inline void lanesOf(const int index[kLanes], std::span<BodyState> states,
                    const BodyState* (&out)[kLanes]) {
    for (int i = 0; i < kLanes; ++i) {
        out[i] = index[i] >= 0 ? &states[static_cast<std::size_t>(index[i])] : &kStaticState;
    }
}

// BodyState is two 16-byte rows, {vx, vy, w, flags} and {dpx, dpy, qc, qs}: a lane's row is one
// load, and four rows transpose into four lane vectors (and back) with shuffles only, which
// move bits unchanged (flags included).
static_assert(sizeof(BodyState) == 32, "BodyState must stay two 16-byte rows");
static_assert(offsetof(BodyState, linearVelocity) == 0 && offsetof(BodyState, angularVelocity) == 8 &&
                  offsetof(BodyState, deltaPosition) == 16 && offsetof(BodyState, deltaRotation) == 24,
              "BodyState rows out of order");

inline Float4 loadRow(const BodyState* s, std::size_t offset) {
    Float4 row;
    std::memcpy(&row, reinterpret_cast<const unsigned char*>(s) + offset, sizeof row);
    return row;
}

inline void transpose(Float4 r0, Float4 r1, Float4 r2, Float4 r3, Float4& c0, Float4& c1,
                      Float4& c2, Float4& c3) {
    Float4 t0 = __builtin_shufflevector(r0, r1, 0, 4, 1, 5);
    Float4 t1 = __builtin_shufflevector(r2, r3, 0, 4, 1, 5);
    Float4 t2 = __builtin_shufflevector(r0, r1, 2, 6, 3, 7);
    Float4 t3 = __builtin_shufflevector(r2, r3, 2, 6, 3, 7);
    c0 = __builtin_shufflevector(t0, t1, 0, 1, 4, 5);
    c1 = __builtin_shufflevector(t0, t1, 2, 3, 6, 7);
    c2 = __builtin_shufflevector(t2, t3, 0, 1, 4, 5);
    c3 = __builtin_shufflevector(t2, t3, 2, 3, 6, 7);
}

inline WideBody gatherVelocities(const BodyState* const (&s)[kLanes]) {
    WideBody b;
    transpose(loadRow(s[0], 0), loadRow(s[1], 0), loadRow(s[2], 0), loadRow(s[3], 0), b.vx, b.vy,
              b.w, b.flags);
    return b;
}

inline void gatherDeltas(WideBody& b, const BodyState* const (&s)[kLanes]) {
    transpose(loadRow(s[0], 16), loadRow(s[1], 16), loadRow(s[2], 16), loadRow(s[3], 16), b.dpx,
              b.dpy, b.qc, b.qs);
}

inline void scatterVelocities(const WideBody& b, const int index[kLanes],
                              std::span<BodyState> states) {
    Float4 rows[kLanes];
    transpose(b.vx, b.vy, b.w, b.flags, rows[0], rows[1], rows[2], rows[3]);
    for (int i = 0; i < kLanes; ++i) {
        if (index[i] >= 0) {
            // BodyState is trivially copyable: its first row takes the lane whole.
            std::memcpy(reinterpret_cast<unsigned char*>(&states[static_cast<std::size_t>(index[i])]),
                        &rows[i], sizeof rows[i]);
        }
    }
}

void warmStartOne(const WideConstraint& c, std::span<BodyState> states) {
    const BodyState* sa[kLanes];
    const BodyState* sb[kLanes];
    lanesOf(c.indexA, states, sa);
    lanesOf(c.indexB, states, sb);
    WideBody a = gatherVelocities(sa);
    WideBody b = gatherVelocities(sb);
    const Float4 nx = c.normalX;
    const Float4 ny = c.normalY;
    const Float4 tx = ny;
    const Float4 ty = -nx;
    for (const WidePoint& cp : c.points) {
        Float4 px = cp.normalImpulse * nx + cp.tangentImpulse * tx;
        Float4 py = cp.normalImpulse * ny + cp.tangentImpulse * ty;
        a.w = a.w - c.invInertiaA * (cp.anchorAx * py - cp.anchorAy * px);
        a.vx = a.vx - c.invMassAx * px;
        a.vy = a.vy - c.invMassAy * py;
        b.w = b.w + c.invInertiaB * (cp.anchorBx * py - cp.anchorBy * px);
        b.vx = b.vx + c.invMassBx * px;
        b.vy = b.vy + c.invMassBy * py;
    }
    scatterVelocities(a, c.indexA, states);
    scatterVelocities(b, c.indexB, states);
}

template <bool kReversePoints>
void solveOne(WideConstraint& c, std::span<BodyState> states, float invH, bool useBias,
              float pushMaxSpeed) {
    const BodyState* sa[kLanes];
    const BodyState* sb[kLanes];
    lanesOf(c.indexA, states, sa);
    lanesOf(c.indexB, states, sb);
    WideBody a = gatherVelocities(sa);
    WideBody b = gatherVelocities(sb);
    gatherDeltas(a, sa);
    gatherDeltas(b, sb);
    const Float4 nx = c.normalX;
    const Float4 ny = c.normalY;
    const Float4 tx = ny;
    const Float4 ty = -nx;
    const Float4 zero = splat(0.0f);
    const Float4 one = splat(1.0f);
    const Float4 vInvH = splat(invH);

    // Reversed, a one-point lane meets its empty second point first: zero normal mass, no
    // impulse, the same result as the scalar pass that skips it.
    for (int j = 0; j < 2; ++j) {
        WidePoint& cp = c.points[kReversePoints ? 1 - j : j];
        Float4 prAx = a.qc * cp.anchorAx - a.qs * cp.anchorAy;
        Float4 prAy = a.qs * cp.anchorAx + a.qc * cp.anchorAy;
        Float4 prBx = b.qc * cp.anchorBx - b.qs * cp.anchorBy;
        Float4 prBy = b.qs * cp.anchorBx + b.qc * cp.anchorBy;
        Float4 dx = (b.dpx - a.dpx) + (prBx - prAx);
        Float4 dy = (b.dpy - a.dpy) + (prBy - prAy);
        Float4 s = (dx * nx + dy * ny) + cp.baseSeparation;

        Int4 speculative = s > zero;
        Float4 bias;
        Float4 massScale;
        Float4 impulseScale;
        if (useBias) {
            bias = select(speculative, s * vInvH, maxOf(c.biasRate * s, splat(-pushMaxSpeed)));
            massScale = select(speculative, one, c.massScale);
            impulseScale = select(speculative, zero, c.impulseScale);
        } else {
            bias = select(speculative, s * vInvH, zero);
            massScale = one;
            impulseScale = zero;
        }

        Float4 dvx = (b.vx + (-b.w) * cp.anchorBy) - (a.vx + (-a.w) * cp.anchorAy);
        Float4 dvy = (b.vy + b.w * cp.anchorBx) - (a.vy + a.w * cp.anchorAx);
        Float4 vn = dvx * nx + dvy * ny;

        Int4 impact = ~cp.impactSeen & (vn + maxOf(s, zero) * vInvH < zero);
        // Rare once a pile has settled: skip the stores (and the division) when no lane hits.
        if ((impact[0] | impact[1] | impact[2] | impact[3]) != 0) {
            cp.impactSeen |= impact;
            cp.relativeVelocity = select(impact, vn, cp.relativeVelocity);
            cp.impactGap = select(impact, useBias ? s + vn / vInvH : s, cp.impactGap);
        }

        Float4 impulse = (-cp.normalMass) * massScale * (vn + bias) - impulseScale * cp.normalImpulse;
        Float4 newImpulse = maxOf(cp.normalImpulse + impulse, zero);
        impulse = newImpulse - cp.normalImpulse;
        cp.normalImpulse = newImpulse;
        cp.maxNormalImpulse = maxOf(cp.maxNormalImpulse, impulse);
        Float4 px = impulse * nx;
        Float4 py = impulse * ny;
        a.vx = a.vx - c.invMassAx * px;
        a.vy = a.vy - c.invMassAy * py;
        a.w = a.w - c.invInertiaA * (cp.anchorAx * py - cp.anchorAy * px);
        b.vx = b.vx + c.invMassBx * px;
        b.vy = b.vy + c.invMassBy * py;
        b.w = b.w + c.invInertiaB * (cp.anchorBx * py - cp.anchorBy * px);
    }

    // Friction, as solveFriction() does it.
    for (WidePoint& cp : c.points) {
        Float4 dvx = (b.vx + (-b.w) * cp.anchorBy) - (a.vx + (-a.w) * cp.anchorAy);
        Float4 dvy = (b.vy + b.w * cp.anchorBx) - (a.vy + a.w * cp.anchorAx);
        Float4 impulse = -cp.tangentMass * (dvx * tx + dvy * ty);
        Float4 maxFriction = c.friction * cp.normalImpulse;
        // std::clamp(v, lo, hi): v < lo ? lo : (hi < v ? hi : v)
        Float4 v = cp.tangentImpulse + impulse;
        Float4 lo = -maxFriction;
        Float4 newImpulse = select(v < lo, lo, select(maxFriction < v, maxFriction, v));
        impulse = newImpulse - cp.tangentImpulse;
        cp.tangentImpulse = newImpulse;
        Float4 px = impulse * tx;
        Float4 py = impulse * ty;
        a.vx = a.vx - c.invMassAx * px;
        a.vy = a.vy - c.invMassAy * py;
        a.w = a.w - c.invInertiaA * (cp.anchorAx * py - cp.anchorAy * px);
        b.vx = b.vx + c.invMassBx * px;
        b.vy = b.vy + c.invMassBy * py;
        b.w = b.w + c.invInertiaB * (cp.anchorBx * py - cp.anchorBy * px);
    }

    scatterVelocities(a, c.indexA, states);
    scatterVelocities(b, c.indexB, states);
}

// The constraints of a level lie scattered over the whole array (a level takes a few from
// every island): fetch the ones a few lanes ahead while this one is copied.
constexpr int kPrefetchAhead = 16;

inline void prefetchConstraint(std::span<const ContactConstraint> constraints,
                               std::span<const int> levelOrder, int slot) {
    if (slot < static_cast<int>(levelOrder.size())) {
        const auto* p = reinterpret_cast<const char*>(
            &constraints[static_cast<std::size_t>(levelOrder[static_cast<std::size_t>(slot)])]);
        for (std::size_t offset = 0; offset < sizeof(ContactConstraint); offset += 64) {
            __builtin_prefetch(p + offset);
        }
    }
}

} // namespace

void layoutWide(WideContacts& wide, std::span<const int> levelStart) {
    const std::size_t levelCount = levelStart.empty() ? 0 : levelStart.size() - 1;
    wide.levelStart.assign(levelCount + 1, 0);
    int groups = 0;
    for (std::size_t k = 0; k < levelCount; ++k) {
        wide.levelStart[k] = groups;
        groups += (levelStart[k + 1] - levelStart[k] + kLanes - 1) / kLanes;
    }
    wide.levelStart[levelCount] = groups;
    wide.constraints.resize(static_cast<std::size_t>(groups));
    // The lanes past a level's last constraint stay empty: no bodies, no mass, so every impulse
    // they compute is zero.
    for (std::size_t k = 0; k < levelCount; ++k) {
        const int count = levelStart[k + 1] - levelStart[k];
        if (count % kLanes == 0) {
            continue;
        }
        WideConstraint& w = wide.constraints[static_cast<std::size_t>(wide.levelStart[k + 1] - 1)];
        for (int lane = count % kLanes; lane < kLanes; ++lane) {
            packWideLane(w, lane, ContactConstraint{});
        }
    }
}

void packWideLane(WideConstraint& w, int lane, const ContactConstraint& c) {
    w.indexA[lane] = c.indexA;
    w.indexB[lane] = c.indexB;
    w.normalX[lane] = c.normal.x;
    w.normalY[lane] = c.normal.y;
    w.invMassAx[lane] = c.invMassA.x;
    w.invMassAy[lane] = c.invMassA.y;
    w.invMassBx[lane] = c.invMassB.x;
    w.invMassBy[lane] = c.invMassB.y;
    w.invInertiaA[lane] = c.invInertiaA;
    w.invInertiaB[lane] = c.invInertiaB;
    w.friction[lane] = c.friction;
    w.biasRate[lane] = c.softness.biasRate;
    w.massScale[lane] = c.softness.massScale;
    w.impulseScale[lane] = c.softness.impulseScale;
    for (int i = 0; i < 2; ++i) {
        // A missing second point has no mass: its impulses stay zero.
        const ContactConstraintPoint cp = i < c.pointCount ? c.points[i] : ContactConstraintPoint{};
        WidePoint& wp = w.points[i];
        wp.anchorAx[lane] = cp.anchorA.x;
        wp.anchorAy[lane] = cp.anchorA.y;
        wp.anchorBx[lane] = cp.anchorB.x;
        wp.anchorBy[lane] = cp.anchorB.y;
        wp.baseSeparation[lane] = cp.baseSeparation;
        wp.relativeVelocity[lane] = cp.relativeVelocity;
        wp.normalImpulse[lane] = cp.normalImpulse;
        wp.tangentImpulse[lane] = cp.tangentImpulse;
        wp.maxNormalImpulse[lane] = cp.maxNormalImpulse;
        wp.normalMass[lane] = cp.normalMass;
        wp.tangentMass[lane] = cp.tangentMass;
        wp.impactGap[lane] = cp.impactGap;
        wp.impactSeen[lane] = cp.impactSeen ? -1 : 0;
    }
}

void prepareWide(WideContacts& wide, std::span<const ContactConstraint> constraints,
                 std::span<const int> levelOrder, std::span<const int> levelStart) {
    layoutWide(wide, levelStart);
    const std::size_t levelCount = levelStart.empty() ? 0 : levelStart.size() - 1;
    for (std::size_t k = 0; k < levelCount; ++k) {
        for (int slot = levelStart[k]; slot < levelStart[k + 1]; ++slot) {
            prefetchConstraint(constraints, levelOrder, slot + kPrefetchAhead);
            const int at = slot - levelStart[k];
            packWideLane(wide.constraints[static_cast<std::size_t>(wide.levelStart[k] + at / kLanes)],
                         at % kLanes,
                         constraints[static_cast<std::size_t>(levelOrder[static_cast<std::size_t>(slot)])]);
        }
    }
}

void storeWide(const WideContacts& wide, std::span<ContactConstraint> constraints,
               std::span<const int> levelOrder, std::span<const int> levelStart) {
    const std::size_t levelCount = levelStart.empty() ? 0 : levelStart.size() - 1;
    for (std::size_t k = 0; k < levelCount; ++k) {
        const int end = levelStart[k + 1];
        int g = wide.levelStart[k];
        for (int first = levelStart[k]; first < end; first += kLanes, ++g) {
            const WideConstraint& w = wide.constraints[static_cast<std::size_t>(g)];
            for (int lane = 0; lane < kLanes && first + lane < end; ++lane) {
                prefetchConstraint(constraints, levelOrder, first + lane + kPrefetchAhead);
                ContactConstraint& c =
                    constraints[static_cast<std::size_t>(levelOrder[static_cast<std::size_t>(first + lane)])];
                for (int i = 0; i < c.pointCount; ++i) {
                    ContactConstraintPoint& cp = c.points[i];
                    const WidePoint& wp = w.points[i];
                    cp.relativeVelocity = wp.relativeVelocity[lane];
                    cp.normalImpulse = wp.normalImpulse[lane];
                    cp.tangentImpulse = wp.tangentImpulse[lane];
                    cp.maxNormalImpulse = wp.maxNormalImpulse[lane];
                    cp.impactGap = wp.impactGap[lane];
                    cp.impactSeen = wp.impactSeen[lane] != 0;
                }
            }
        }
    }
}

void warmStartWide(const WideContacts& wide, std::span<BodyState> states) {
    for (const WideConstraint& c : wide.constraints) {
        warmStartOne(c, states);
    }
}

namespace {

template <bool kReversePoints>
void solveWideInOrder(WideContacts& wide, std::span<BodyState> states, float invH, bool useBias,
                      float pushMaxSpeed, bool backward) {
    if (!backward) {
        for (WideConstraint& c : wide.constraints) {
            solveOne<kReversePoints>(c, states, invH, useBias, pushMaxSpeed);
        }
        return;
    }
    // Within a level the order does not matter; backward only reverses the levels.
    const std::size_t levelCount = wide.levelStart.empty() ? 0 : wide.levelStart.size() - 1;
    for (std::size_t k = levelCount; k-- > 0;) {
        for (int g = wide.levelStart[k]; g < wide.levelStart[k + 1]; ++g) {
            solveOne<kReversePoints>(wide.constraints[static_cast<std::size_t>(g)], states, invH,
                                     useBias, pushMaxSpeed);
        }
    }
}

} // namespace

void solveWide(WideContacts& wide, std::span<BodyState> states, float invH, bool useBias,
               float pushMaxSpeed, bool backward, bool reversePoints) {
    if (reversePoints) {
        solveWideInOrder<true>(wide, states, invH, useBias, pushMaxSpeed, backward);
    } else {
        solveWideInOrder<false>(wide, states, invH, useBias, pushMaxSpeed, backward);
    }
}

} // namespace e2d::physics::detail
