// SPDX-License-Identifier: MIT
// Revolute joint: a shared point, with an angular spring, motor and limits.
#include "joint_solver.hpp"

namespace e2d::physics::detail {

void warmStartRevolute(Joint& j, BodyState& a, BodyState& b) {
    const JointFrame f = currentFrame(j, a, b);
    const float axial = j.springImpulse + j.motorImpulse + j.lowerImpulse - j.upperImpulse;
    applyPointImpulse(j, a, b, f.rA, f.rB, j.linearImpulse, axial);
}

void solveRevolute(Joint& j, BodyState& a, BodyState& b, const JointStep& step, bool useBias) {
    auto turn = [&](float impulse) {
        a.angularVelocity -= j.invInertiaA * impulse;
        b.angularVelocity += j.invInertiaB * impulse;
    };
    auto Cdot = [&] { return b.angularVelocity - a.angularVelocity; };
    if (j.enableSpring && j.hertz > 0.0f) {
        turn(solveSoftRow(j.springImpulse, j.axialMass, currentAngle(j, a, b), Cdot(), j.springSoftness));
    }
    if (j.enableMotor) {
        turn(solveMotorRow(j.motorImpulse, j.axialMass, j.motorSpeed, Cdot(), j.maxMotorForce * step.h));
    }
    if (j.enableLimit) {
        const float angle = currentAngle(j, a, b);
        turn(solveLimitRow(j.lowerImpulse, j.axialMass, angle - j.lower, Cdot(), step, useBias));
        turn(-solveLimitRow(j.upperImpulse, j.axialMass, j.upper - angle, -Cdot(), step, useBias));
    }
    const JointFrame f = currentFrame(j, a, b);
    const Softness soft = rigidSoftness(step, useBias);
    Vec2 Cdot2 = relativeVelocity(a, b, f.rA, f.rB);
    Vec2 impulse = -soft.massScale * solve22(pointMatrix(j, f.rA, f.rB), Cdot2 + soft.biasRate * f.d) -
                   soft.impulseScale * j.linearImpulse;
    j.linearImpulse += impulse;
    applyPointImpulse(j, a, b, f.rA, f.rB, impulse);
}

} // namespace e2d::physics::detail
