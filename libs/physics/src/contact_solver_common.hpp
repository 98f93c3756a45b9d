// SPDX-License-Identifier: MIT
#pragma once

#include "contact_solver.hpp"

#include <algorithm>
#include <span>

// Small inline pieces the soft-step (contact_solver.cpp) and classic
// (contact_solver_classic.cpp) contact solvers share, so both run the same friction.
namespace e2d::physics::detail {

// Component-wise product: per-axis inverse mass times an impulse.
inline Vec2 scale(Vec2 invMass, Vec2 p) { return {invMass.x * p.x, invMass.y * p.y}; }

inline float effectiveMass(Vec2 axis, Vec2 rA, Vec2 rB, const ContactConstraint& c) {
    float rnA = cross(rA, axis);
    float rnB = cross(rB, axis);
    float k = c.invMassA.x * axis.x * axis.x + c.invMassA.y * axis.y * axis.y +
              c.invMassB.x * axis.x * axis.x + c.invMassB.y * axis.y * axis.y +
              c.invInertiaA * rnA * rnA + c.invInertiaB * rnB * rnB;
    return k > 0.0f ? 1.0f / k : 0.0f;
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
