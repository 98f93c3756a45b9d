// SPDX-License-Identifier: MIT
// Distance joint: the anchors' distance held rigid, sprung, limited (a rope) or motor-driven.
#include "joint_solver.hpp"

#include <e2d/physics/constants.hpp>

namespace e2d::physics::detail {

void warmStartDistance(Joint& j, BodyState& a, BodyState& b) {
    const JointFrame f = currentFrame(j, a, b);
    const float axial = j.springImpulse + j.lowerImpulse - j.upperImpulse + j.motorImpulse;
    applyPointImpulse(j, a, b, f.rA, f.rB, axial * normalize(f.d));
}

void solveDistance(Joint& j, BodyState& a, BodyState& b, const JointStep& step, bool useBias) {
    const JointFrame f = currentFrame(j, a, b);
    const float length = physics::length(f.d);
    const Vec2 axis = normalize(f.d);
    auto Cdot = [&] { return dot(axis, relativeVelocity(a, b, f.rA, f.rB)); };
    if (!j.enableSpring && !j.enableLimit) {
        // A rigid rod.
        float impulse = solveSoftRow(j.springImpulse, j.axialMass, length - j.length, Cdot(),
                                     rigidSoftness(step, useBias));
        applyPointImpulse(j, a, b, f.rA, f.rB, impulse * axis);
        return;
    }
    if (j.enableSpring && j.hertz > 0.0f) {
        // A real spring: it acts while relaxing too.
        float impulse =
            solveSoftRow(j.springImpulse, j.axialMass, length - j.length, Cdot(), j.springSoftness);
        applyPointImpulse(j, a, b, f.rA, f.rB, impulse * axis);
    }
    if (j.enableMotor) {
        float impulse = solveMotorRow(j.motorImpulse, j.axialMass, j.motorSpeed, Cdot(),
                                      j.maxMotorForce * step.h);
        applyPointImpulse(j, a, b, f.rA, f.rB, impulse * axis);
    }
    if (j.enableLimit) {
        const float minLength = std::max(j.minLength, kLinearSlop);
        float lower =
            solveLimitRow(j.lowerImpulse, j.axialMass, length - minLength, Cdot(), step, useBias);
        applyPointImpulse(j, a, b, f.rA, f.rB, lower * axis);
        float upper = solveLimitRow(j.upperImpulse, j.axialMass, j.maxLength - length, -Cdot(),
                                    step, useBias);
        applyPointImpulse(j, a, b, f.rA, f.rB, -upper * axis);
    }
}

} // namespace e2d::physics::detail
