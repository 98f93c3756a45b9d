// SPDX-License-Identifier: MIT
// Wheel joint: B's anchor on a line fixed in A (suspension spring and limits along it), B free
// to turn (with a drive motor).
#include "joint_solver.hpp"

namespace e2d::physics::detail {

void warmStartWheel(Joint& j, BodyState& a, BodyState& b) {
    const SlideFrame s = currentSlide(j, a, b);
    const float axial = j.springImpulse + j.lowerImpulse - j.upperImpulse;
    applySlideImpulse(j, a, b, s.axis, axial, s.a1, s.a2, j.motorImpulse);
    applySlideImpulse(j, a, b, s.perp, j.perpImpulse, s.s1, s.s2);
}

void solveWheel(Joint& j, BodyState& a, BodyState& b, const JointStep& step, bool useBias) {
    if (j.enableMotor) {
        float impulse =
            solveMotorRow(j.motorImpulse, j.angularMass, j.motorSpeed,
                          b.angularVelocity - a.angularVelocity, j.maxMotorForce * step.h);
        a.angularVelocity -= j.invInertiaA * impulse;
        b.angularVelocity += j.invInertiaB * impulse;
    }
    const SlideFrame s = currentSlide(j, a, b);
    const float translation = dot(s.axis, s.f.d);
    auto Cdot = [&] { return slideVelocity(a, b, s.axis, s.a1, s.a2); };
    auto push = [&](float impulse) { applySlideImpulse(j, a, b, s.axis, impulse, s.a1, s.a2); };
    if (j.enableSpring && j.hertz > 0.0f) {
        push(solveSoftRow(j.springImpulse, j.axialMass, translation, Cdot(), j.springSoftness));
    }
    if (j.enableLimit) {
        push(solveLimitRow(j.lowerImpulse, j.axialMass, translation - j.lower, Cdot(), step,
                           useBias));
        push(-solveLimitRow(j.upperImpulse, j.axialMass, j.upper - translation, -Cdot(), step,
                            useBias));
    }
    // B's anchor stays on the line.
    const float k = axisMass(j.invMassA, s.perp) + axisMass(j.invMassB, s.perp) +
                    j.invInertiaA * s.s1 * s.s1 + j.invInertiaB * s.s2 * s.s2;
    const float perpMass = k > 0.0f ? 1.0f / k : 0.0f;
    float impulse =
        solveSoftRow(j.perpImpulse, perpMass, dot(s.perp, s.f.d),
                     slideVelocity(a, b, s.perp, s.s1, s.s2), rigidSoftness(step, useBias));
    applySlideImpulse(j, a, b, s.perp, impulse, s.s1, s.s2);
}

} // namespace e2d::physics::detail
