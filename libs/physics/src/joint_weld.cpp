// SPDX-License-Identifier: MIT
// Weld joint: a shared point and a fixed relative angle, each rigid or a spring.
#include "joint_solver.hpp"

namespace e2d::physics::detail {

void warmStartWeld(Joint& j, BodyState& a, BodyState& b) {
    const JointFrame f = currentFrame(j, a, b);
    applyPointImpulse(j, a, b, f.rA, f.rB, j.linearImpulse, j.angularImpulse);
}

void solveWeld(Joint& j, BodyState& a, BodyState& b, const JointStep& step, bool useBias) {
    {
        const Softness soft =
            j.angularHertz > 0.0f ? j.angularSoftness : rigidSoftness(step, useBias);
        float impulse = solveSoftRow(j.angularImpulse, j.angularMass, currentAngle(j, a, b),
                                     b.angularVelocity - a.angularVelocity, soft);
        a.angularVelocity -= j.invInertiaA * impulse;
        b.angularVelocity += j.invInertiaB * impulse;
    }
    const JointFrame f = currentFrame(j, a, b);
    const Softness soft = j.hertz > 0.0f ? j.springSoftness : rigidSoftness(step, useBias);
    Vec2 Cdot = relativeVelocity(a, b, f.rA, f.rB);
    Vec2 impulse =
        -soft.massScale * solve22(pointMatrix(j, f.rA, f.rB), Cdot + soft.biasRate * f.d) -
        soft.impulseScale * j.linearImpulse;
    j.linearImpulse += impulse;
    applyPointImpulse(j, a, b, f.rA, f.rB, impulse);
}

} // namespace e2d::physics::detail
