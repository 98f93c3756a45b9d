// SPDX-License-Identifier: MIT
// Motor joint: drives B towards a pose in A's frame with a capped force and torque.
#include "joint_solver.hpp"

namespace e2d::physics::detail {

void warmStartMotor(Joint& j, BodyState& a, BodyState& b) {
    const JointFrame f = currentFrame(j, a, b);
    applyPointImpulse(j, a, b, f.rA, f.rB, j.linearImpulse, j.angularImpulse);
}

void solveMotor(Joint& j, BodyState& a, BodyState& b, const JointStep& step, bool /*useBias*/) {
    // The correction is the motor's purpose, not a position error to relax away: it acts in
    // every pass.
    const float rate = j.correctionFactor * step.invH;
    {
        float C = currentAngle(j, a, b);
        float Cdot = b.angularVelocity - a.angularVelocity;
        float impulse = -j.angularMass * (Cdot + rate * C);
        float maxImpulse = j.maxTorque * step.h;
        float old = j.angularImpulse;
        j.angularImpulse = std::clamp(old + impulse, -maxImpulse, maxImpulse);
        impulse = j.angularImpulse - old;
        a.angularVelocity -= j.invInertiaA * impulse;
        b.angularVelocity += j.invInertiaB * impulse;
    }
    const JointFrame f = currentFrame(j, a, b);
    Vec2 Cdot = relativeVelocity(a, b, f.rA, f.rB);
    Vec2 impulse = -solve22(pointMatrix(j, f.rA, f.rB), Cdot + rate * f.d);
    Vec2 old = j.linearImpulse;
    j.linearImpulse += impulse;
    float maxImpulse = j.maxMotorForce * step.h;
    if (lengthSquared(j.linearImpulse) > maxImpulse * maxImpulse) {
        j.linearImpulse = maxImpulse * normalize(j.linearImpulse);
    }
    applyPointImpulse(j, a, b, f.rA, f.rB, j.linearImpulse - old);
}

} // namespace e2d::physics::detail
