// SPDX-License-Identifier: MIT
// Mouse joint: a soft spring of capped force pulling a point of B to a world target.
#include "joint_solver.hpp"

namespace e2d::physics::detail {

void warmStartMouse(Joint& j, BodyState& /*a*/, BodyState& b) {
    Vec2 rB = rotate(b.deltaRotation, j.anchorB);
    b.linearVelocity += j.invMassB * j.linearImpulse;
    b.angularVelocity += j.invInertiaB * cross(rB, j.linearImpulse);
}

void solveMouse(Joint& j, BodyState& /*a*/, BodyState& b, const JointStep& step, bool /*useBias*/) {
    // A spring, not a rigid part: it pulls in every pass.
    Vec2 rB = rotate(b.deltaRotation, j.anchorB);
    Vec2 C = j.deltaCenter + b.deltaPosition + rB;
    Vec2 Cdot = b.linearVelocity + cross(b.angularVelocity, rB);
    const Softness& soft = j.springSoftness;
    Vec2 impulse =
        -soft.massScale * solve22(pointMatrix(j, Vec2{0.0f, 0.0f}, rB), Cdot + soft.biasRate * C) -
        soft.impulseScale * j.linearImpulse;
    Vec2 old = j.linearImpulse;
    j.linearImpulse += impulse;
    float maxImpulse = j.maxMotorForce * step.h;
    if (lengthSquared(j.linearImpulse) > maxImpulse * maxImpulse) {
        j.linearImpulse = maxImpulse * normalize(j.linearImpulse);
    }
    impulse = j.linearImpulse - old;
    b.linearVelocity += j.invMassB * impulse;
    b.angularVelocity += j.invInertiaB * cross(rB, impulse);
}

} // namespace e2d::physics::detail
