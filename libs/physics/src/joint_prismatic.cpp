// SPDX-License-Identifier: MIT
// Prismatic joint: B slides along an axis fixed in A without turning relative to it, with a
// spring, a motor and limits along the axis.
#include "joint_solver.hpp"

namespace e2d::physics::detail {

void warmStartPrismatic(Joint& j, BodyState& a, BodyState& b) {
    const SlideFrame s = currentSlide(j, a, b);
    const float axial = j.springImpulse + j.motorImpulse + j.lowerImpulse - j.upperImpulse;
    applySlideImpulse(j, a, b, s.axis, axial, s.a1, s.a2);
    applySlideImpulse(j, a, b, s.perp, j.linearImpulse.x, s.s1, s.s2, j.linearImpulse.y);
}

void solvePrismatic(Joint& j, BodyState& a, BodyState& b, const JointStep& step, bool useBias) {
    const SlideFrame s = currentSlide(j, a, b);
    const float translation = dot(s.axis, s.f.d);
    auto Cdot = [&] { return slideVelocity(a, b, s.axis, s.a1, s.a2); };
    auto push = [&](float impulse) { applySlideImpulse(j, a, b, s.axis, impulse, s.a1, s.a2); };
    if (j.enableMotor) {
        push(solveMotorRow(j.motorImpulse, j.axialMass, j.motorSpeed, Cdot(),
                           j.maxMotorForce * step.h));
    }
    if (j.enableSpring && j.hertz > 0.0f) {
        push(solveSoftRow(j.springImpulse, j.axialMass, translation, Cdot(), j.springSoftness));
    }
    if (j.enableLimit) {
        push(solveLimitRow(j.lowerImpulse, j.axialMass, translation - j.lower, Cdot(), step,
                           useBias));
        push(-solveLimitRow(j.upperImpulse, j.axialMass, j.upper - translation, -Cdot(), step,
                            useBias));
    }
    // Sideways and angular together (2x2).
    const float iA = j.invInertiaA;
    const float iB = j.invInertiaB;
    Mat22 k{axisMass(j.invMassA, s.perp) + axisMass(j.invMassB, s.perp) + iA * s.s1 * s.s1 +
                iB * s.s2 * s.s2,
            iA * s.s1 + iB * s.s2, iA + iB};
    if (k.k22 == 0.0f) {
        k.k22 = 1.0f; // neither body turns: the angular row is idle
    }
    const Softness soft = rigidSoftness(step, useBias);
    Vec2 Cdot2{slideVelocity(a, b, s.perp, s.s1, s.s2), b.angularVelocity - a.angularVelocity};
    Vec2 C{dot(s.perp, s.f.d), currentAngle(j, a, b)};
    Vec2 impulse = -soft.massScale * solve22(k, Cdot2 + soft.biasRate * C) -
                   soft.impulseScale * j.linearImpulse;
    j.linearImpulse += impulse;
    applySlideImpulse(j, a, b, s.perp, impulse.x, s.s1, s.s2, impulse.y);
}

} // namespace e2d::physics::detail
