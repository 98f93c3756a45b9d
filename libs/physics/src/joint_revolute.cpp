// SPDX-License-Identifier: MIT
// Revolute joint: a shared point, with an angular spring, motor and limits.
#include "joint_solver.hpp"

namespace e2d::physics::detail {

void warmStartRevolute(Joint& j, BodyState& a, BodyState& b) {
    const JointFrame f = currentFrame(j, a, b);
    const float axial = j.springImpulse + j.motorImpulse + j.lowerImpulse - j.upperImpulse;
    applyPointImpulse(j, a, b, f.rA, f.rB, j.linearImpulse, axial);
}

namespace {

// The point and the nearer limit as one 3x3 block (rigid rows): a door swung into its stop
// and held by its hinge loses its speed in both at once, where one row after the other hands
// the door's momentum back and forth and leaves a rebound. The limit stays one-sided: if the
// block would pull, the point is solved alone with the limit's impulse at zero.
void solveRevolutePointAndLimit(Joint& j, BodyState& a, BodyState& b, const JointStep& step,
                                bool useBias) {
    const float angle = currentAngle(j, a, b);
    const bool lowerSide = angle - j.lower <= j.upper - angle;
    const float side = lowerSide ? 1.0f : -1.0f;
    const float C = lowerSide ? angle - j.lower : j.upper - angle; // >= 0 allowed
    // The far side cannot act this sub-step.
    (lowerSide ? j.upperImpulse : j.lowerImpulse) = 0.0f;
    float& limitImpulse = lowerSide ? j.lowerImpulse : j.upperImpulse;
    const JointFrame f = currentFrame(j, a, b);
    const Softness soft = rigidSoftness(step, useBias);
    const Mat22 k = pointMatrix(j, f.rA, f.rB);
    const float iA = j.invInertiaA;
    const float iB = j.invInertiaB;
    const float k13 = side * (-iA * f.rA.y - iB * f.rB.y);
    const float k23 = side * (iA * f.rA.x + iB * f.rB.x);
    const float k33 = iA + iB;
    const Vec2 pointRhs = relativeVelocity(a, b, f.rA, f.rB) + soft.biasRate * f.d;
    const float limitBias = C > 0.0f ? C * step.invH : soft.biasRate * C;
    const float limitRhs = side * (b.angularVelocity - a.angularVelocity) + limitBias;
    // K x = -rhs, by Cramer's rule on the symmetric 3x3.
    const float c11 = k.k22 * k33 - k23 * k23;
    const float c12 = k13 * k23 - k.k12 * k33;
    const float c13 = k.k12 * k23 - k13 * k.k22;
    float det = k.k11 * c11 + k.k12 * c12 + k13 * c13;
    Vec2 point{0.0f, 0.0f};
    float limit = 0.0f;
    if (det != 0.0f) {
        det = 1.0f / det;
        const float c22 = k.k11 * k33 - k13 * k13;
        const float c23 = k.k12 * k13 - k.k11 * k23;
        const float c33 = k.k11 * k.k22 - k.k12 * k.k12;
        const Vec2 r{-pointRhs.x, -pointRhs.y};
        const float r3 = -limitRhs;
        point = {det * (c11 * r.x + c12 * r.y + c13 * r3),
                 det * (c12 * r.x + c22 * r.y + c23 * r3)};
        limit = det * (c13 * r.x + c23 * r.y + c33 * r3);
    }
    if (limitImpulse + limit < 0.0f) {
        // The stop would pull: release it and solve the point with what is left.
        limit = -limitImpulse;
        point = solve22(k, Vec2{-pointRhs.x - k13 * limit, -pointRhs.y - k23 * limit});
    }
    limitImpulse += limit;
    j.linearImpulse += point;
    applyPointImpulse(j, a, b, f.rA, f.rB, point, side * limit);
}

} // namespace

void solveRevolute(Joint& j, BodyState& a, BodyState& b, const JointStep& step, bool useBias) {
    auto turn = [&](float impulse) {
        a.angularVelocity -= j.invInertiaA * impulse;
        b.angularVelocity += j.invInertiaB * impulse;
    };
    auto Cdot = [&] { return b.angularVelocity - a.angularVelocity; };
    if (j.enableSpring && j.hertz > 0.0f) {
        turn(solveSoftRow(j.springImpulse, j.axialMass, currentAngle(j, a, b), Cdot(),
                          j.springSoftness));
    }
    if (j.enableMotor) {
        turn(solveMotorRow(j.motorImpulse, j.axialMass, j.motorSpeed, Cdot(),
                           j.maxMotorForce * step.h));
    }
    if (j.enableLimit && step.blockLimit && j.lower < j.upper) {
        solveRevolutePointAndLimit(j, a, b, step, useBias);
        return;
    }
    if (j.enableLimit) {
        const float angle = currentAngle(j, a, b);
        turn(solveLimitRow(j.lowerImpulse, j.axialMass, angle - j.lower, Cdot(), step, useBias));
        turn(-solveLimitRow(j.upperImpulse, j.axialMass, j.upper - angle, -Cdot(), step, useBias));
    }
    const JointFrame f = currentFrame(j, a, b);
    const Softness soft = rigidSoftness(step, useBias);
    Vec2 Cdot2 = relativeVelocity(a, b, f.rA, f.rB);
    Vec2 impulse =
        -soft.massScale * solve22(pointMatrix(j, f.rA, f.rB), Cdot2 + soft.biasRate * f.d) -
        soft.impulseScale * j.linearImpulse;
    j.linearImpulse += impulse;
    applyPointImpulse(j, a, b, f.rA, f.rB, impulse);
}

} // namespace e2d::physics::detail
