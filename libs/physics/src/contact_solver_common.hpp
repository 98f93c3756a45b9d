// SPDX-License-Identifier: MIT
#pragma once

#include "contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <span>

// Small inline pieces the soft-step (contact_solver.cpp) and classic
// (contact_solver_classic.cpp) contact solvers share, so both run the same friction.
namespace e2d::physics::detail {

// Component-wise product: per-axis inverse mass times an impulse.
inline Vec2 scale(Vec2 invMass, Vec2 p) { return {invMass.x * p.x, invMass.y * p.y}; }

// What the rounding of the lever arms adds to an effective mass (see kLeverRounding2).
inline float leverRounding(Vec2 rA, Vec2 rB, const ContactConstraint& c) {
    return kLeverRounding2 * (c.invInertiaA * dot(rA, rA) + c.invInertiaB * dot(rB, rB));
}

// The least K along `axis` may be (see kMaxContactGain).
inline float lockedAxisFloor(Vec2 axis, const ContactConstraint& c) {
    const float ax = std::abs(axis.x);
    const float ay = std::abs(axis.y);
    const float a = std::max(c.invMassA.x * ax, c.invMassA.y * ay);
    const float b = std::max(c.invMassB.x * ax, c.invMassB.y * ay);
    return std::max(a, b) * (1.0f / kMaxContactGain);
}

// 1 / K along `axis` at one point (K: how a unit impulse along it changes the point's velocity
// along it); 0 where K is not positive.
inline float effectiveMass(Vec2 axis, Vec2 rA, Vec2 rB, const ContactConstraint& c) {
    float rnA = cross(rA, axis);
    float rnB = cross(rB, axis);
    float k = c.invMassA.x * axis.x * axis.x + c.invMassA.y * axis.y * axis.y +
              c.invMassB.x * axis.x * axis.x + c.invMassB.y * axis.y * axis.y +
              c.invInertiaA * rnA * rnA + c.invInertiaB * rnB * rnB;
    k += leverRounding(rA, rB, c);
    k = std::max(k, lockedAxisFloor(axis, c));
    return k > 0.0f ? 1.0f / k : 0.0f;
}

// Sets blockK, blockInvK, blockInvDet and blockSolve for a 2-point manifold (blockSolve false
// for any other). K says how each point's normal impulse changes both points' normal velocities. Its condition
// number, estimated as k11^2 / det K, must stay below kMaxBlockConditionNumber: above it the two
// rows are (nearly) the same constraint, e.g. a body that cannot rotate, and the block would be
// ill-conditioned. det K must not underflow either (kMinBlockDeterminant).
inline void prepareBlock(ContactConstraint& c) {
    c.blockSolve = false;
    if (c.pointCount != 2) {
        return;
    }
    Vec2 n = c.normal;
    Vec2 nn{n.x * n.x, n.y * n.y};
    float linear = dot(c.invMassA + c.invMassB, nn);
    float rn1A = cross(c.points[0].anchorA, n);
    float rn1B = cross(c.points[0].anchorB, n);
    float rn2A = cross(c.points[1].anchorA, n);
    float rn2B = cross(c.points[1].anchorB, n);
    float k11 = linear + c.invInertiaA * rn1A * rn1A + c.invInertiaB * rn1B * rn1B;
    float k22 = linear + c.invInertiaA * rn2A * rn2A + c.invInertiaB * rn2B * rn2B;
    k11 += leverRounding(c.points[0].anchorA, c.points[0].anchorB, c);
    k22 += leverRounding(c.points[1].anchorA, c.points[1].anchorB, c);
    float k12 = linear + c.invInertiaA * rn1A * rn2A + c.invInertiaB * rn1B * rn2B;
    float det = k11 * k22 - k12 * k12;
    // Where lockedAxisFloor() binds, K's rows are no guide to the velocities: one at a time.
    const float least = lockedAxisFloor(n, c);
    if (k11 * k11 < kMaxBlockConditionNumber * det && det >= kMinBlockDeterminant && k11 >= least &&
        k22 >= least) {
        c.blockSolve = true;
        c.blockK = {k11, k12, k22};
        float invDet = 1.0f / det;
        c.blockInvK = {invDet * k22, -invDet * k12, invDet * k11};
        c.blockInvDet = invDet;
    }
}

// Both normal impulses of a 2-point manifold at once: the linear complementarity problem
// vn = K x + b, x >= 0, vn >= 0, x . vn = 0 in terms of the accumulated impulses x (vn here is
// the normal velocity above its target). With two points it has four cases (both, only the
// first, only the second, or no point pushing); the first whose solution is feasible goes to
// `x` and true is returned. When none is feasible (round-off), false, and `x` is left alone.
inline bool solveBlock(const ContactConstraint& c, Vec2 accumulated, Vec2 vn, Vec2& x) {
    // Both push: vn = 0, reached from the accumulated impulses by -K^-1 vn (the common case of a
    // resting pile, so it comes first and alone).
    const BlockMatrix& inv = c.blockInvK;
    Vec2 both{accumulated.x - (inv.a11 * vn.x + inv.a12 * vn.y),
              accumulated.y - (inv.a12 * vn.x + inv.a22 * vn.y)};
    if (both.x >= 0.0f && both.y >= 0.0f) {
        x = both;
        return true;
    }
    // b: the velocities above target with no accumulated impulse at all.
    const BlockMatrix& k = c.blockK;
    Vec2 b{vn.x - (k.a11 * accumulated.x + k.a12 * accumulated.y),
           vn.y - (k.a12 * accumulated.x + k.a22 * accumulated.y)};
    // Only the first pushes: vn1 = 0, x2 = 0, vn2 >= 0 (normalMass = 1 / k11: no division).
    float x1 = -b.x * c.points[0].normalMass;
    if (x1 >= 0.0f && k.a12 * x1 + b.y >= 0.0f) {
        x = {x1, 0.0f};
        return true;
    }
    // Only the second pushes.
    float x2 = -b.y * c.points[1].normalMass;
    if (x2 >= 0.0f && k.a12 * x2 + b.x >= 0.0f) {
        x = {0.0f, x2};
        return true;
    }
    // Neither pushes: both separate on their own.
    if (b.x >= 0.0f && b.y >= 0.0f) {
        x = {0.0f, 0.0f};
        return true;
    }
    return false;
}

// Stores a 2-point manifold's new accumulated normal impulses `x` (they were `old`) and applies
// the change to the bodies' velocities. The order of the sums is the wide kernel's too.
inline void applyBlock(ContactConstraint& c, Vec2 old, Vec2 x, Vec2& vA, float& wA, Vec2& vB,
                       float& wB) {
    ContactConstraintPoint& cp1 = c.points[0];
    ContactConstraintPoint& cp2 = c.points[1];
    Vec2 d = x - old;
    cp1.normalImpulse = x.x;
    cp2.normalImpulse = x.y;
    cp1.maxNormalImpulse = std::max(cp1.maxNormalImpulse, d.x);
    cp2.maxNormalImpulse = std::max(cp2.maxNormalImpulse, d.y);
    Vec2 p1 = d.x * c.normal;
    Vec2 p2 = d.y * c.normal;
    vA -= scale(c.invMassA, p1 + p2);
    wA -= c.invInertiaA * (cross(cp1.anchorA, p1) + cross(cp2.anchorA, p2));
    vB += scale(c.invMassB, p1 + p2);
    wB += c.invInertiaB * (cross(cp1.anchorB, p1) + cross(cp2.anchorB, p2));
}

// A static body has no state; its constraints read and write this zero one instead. Writes
// are harmless: a static side has zero inverse mass, so nothing is ever added to it.
struct StatePair {
    BodyState* a;
    BodyState* b;
};

inline StatePair statesOf(const ContactConstraint& c, std::span<BodyState> states,
                          BodyState& dummyA, BodyState& dummyB) {
    BodyState* a = c.indexA >= 0 ? &states[static_cast<std::size_t>(c.indexA)] : &dummyA;
    BodyState* b = c.indexB >= 0 ? &states[static_cast<std::size_t>(c.indexB)] : &dummyB;
    return {a, b};
}

// Coulomb friction at each point of `c`, each clamped by its own accumulated normal impulse.
// Shared by the soft step and the classic solver; the velocities are updated in place.
inline void solveFriction(ContactConstraint& c, Vec2 tangent, Vec2& vA, float& wA, Vec2& vB,
                          float& wB) {
    const Vec2 mA = c.invMassA;
    const Vec2 mB = c.invMassB;
    const float iA = c.invInertiaA;
    const float iB = c.invInertiaB;
    for (int i = 0; i < c.pointCount; ++i) {
        ContactConstraintPoint& cp = c.points[i];
        Vec2 rA = cp.anchorA;
        Vec2 rB = cp.anchorB;
        Vec2 dv = (vB + cross(wB, rB)) - (vA + cross(wA, rA));
        float impulse = -cp.tangentMass * dot(dv, tangent);
        float maxFriction = c.friction * cp.normalImpulse;
        float newImpulse = std::clamp(cp.tangentImpulse + impulse, -maxFriction, maxFriction);
        impulse = newImpulse - cp.tangentImpulse;
        cp.tangentImpulse = newImpulse;
        Vec2 p = impulse * tangent;
        vA -= scale(mA, p);
        wA -= iA * cross(rA, p);
        vB += scale(mB, p);
        wB += iB * cross(rB, p);
    }
}

} // namespace e2d::physics::detail
