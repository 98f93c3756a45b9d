// SPDX-License-Identifier: MIT
// Classic mode's position pass for joints: non-linear Gauss-Seidel on the rigid parts'
// position errors (Box2D 2.4's recipe), moving the states' deltaPosition and deltaRotation.
// Springs, motors, mouse and motor joints have no position error of their own.
#include "joint_solver.hpp"

#include <e2d/physics/constants.hpp>

#include <algorithm>
#include <cmath>

namespace e2d::physics::detail {

namespace {

// Moves the bodies by position impulse p at the anchors plus angular impulse l.
void shift(const Joint& j, BodyState& a, BodyState& b, Vec2 rA, Vec2 rB, Vec2 p, float l) {
    a.deltaPosition -= j.invMassA * p;
    a.deltaRotation = integrateRotation(a.deltaRotation, -j.invInertiaA * (cross(rA, p) + l));
    b.deltaPosition += j.invMassB * p;
    b.deltaRotation = integrateRotation(b.deltaRotation, j.invInertiaB * (cross(rB, p) + l));
}

void turn(const Joint& j, BodyState& a, BodyState& b, float l) {
    a.deltaRotation = integrateRotation(a.deltaRotation, -j.invInertiaA * l);
    b.deltaRotation = integrateRotation(b.deltaRotation, j.invInertiaB * l);
}

// The shared point of revolute and weld joints.
float fixPoint(const Joint& j, BodyState& a, BodyState& b) {
    const JointFrame f = currentFrame(j, a, b);
    Vec2 p = -solve22(pointMatrix(j, f.rA, f.rB), f.d);
    shift(j, a, b, f.rA, f.rB, p, 0.0f);
    return length(f.d);
}

// A prismatic or wheel joint's limit along the axis.
float fixSlideLimit(const Joint& j, BodyState& a, BodyState& b) {
    if (!j.enableLimit) {
        return 0.0f;
    }
    const SlideFrame s = currentSlide(j, a, b);
    const float C = pastLimit(dot(s.axis, s.f.d), j.lower, j.upper, kMaxLinearCorrection);
    const float k = axisMass(j.invMassA, s.axis) + axisMass(j.invMassB, s.axis) +
                    j.invInertiaA * s.a1 * s.a1 + j.invInertiaB * s.a2 * s.a2;
    if (C == 0.0f || k <= 0.0f) {
        return 0.0f;
    }
    const float impulse = -C / k;
    a.deltaPosition -= j.invMassA * (impulse * s.axis);
    a.deltaRotation = integrateRotation(a.deltaRotation, -j.invInertiaA * impulse * s.a1);
    b.deltaPosition += j.invMassB * (impulse * s.axis);
    b.deltaRotation = integrateRotation(b.deltaRotation, j.invInertiaB * impulse * s.a2);
    return std::abs(C);
}

JointErrors fixJoint(const Joint& j, BodyState& a, BodyState& b) {
    JointErrors e;
    switch (j.type) {
    case JointType::Motor:
    case JointType::Mouse:
        break;
    case JointType::Distance: {
        const JointFrame f = currentFrame(j, a, b);
        const float len = length(f.d);
        float C = 0.0f;
        if (!j.enableSpring && !j.enableLimit) {
            C = std::clamp(len - j.length, -kMaxLinearCorrection, kMaxLinearCorrection);
        } else if (j.enableLimit) {
            C = pastLimit(len, std::max(j.minLength, kLinearSlop), j.maxLength,
                          kMaxLinearCorrection);
        }
        if (C != 0.0f) {
            shift(j, a, b, f.rA, f.rB, (-j.axialMass * C) * normalize(f.d), 0.0f);
        }
        e.linear = std::abs(C);
        break;
    }
    case JointType::Revolute:
        if (j.enableLimit && j.axialMass > 0.0f) {
            const float C =
                pastLimit(currentAngle(j, a, b), j.lower, j.upper, kMaxAngularCorrection);
            turn(j, a, b, -j.axialMass * C);
            e.angular = std::abs(C);
        }
        e.linear = fixPoint(j, a, b);
        break;
    case JointType::Weld:
        if (j.angularHertz == 0.0f) {
            const float C = currentAngle(j, a, b);
            turn(j, a, b, -j.angularMass * C);
            e.angular = std::abs(C);
        }
        if (j.hertz == 0.0f) {
            e.linear = fixPoint(j, a, b);
        }
        break;
    case JointType::Prismatic: {
        e.linear = fixSlideLimit(j, a, b);
        const SlideFrame s = currentSlide(j, a, b);
        const float iA = j.invInertiaA;
        const float iB = j.invInertiaB;
        Mat22 k{axisMass(j.invMassA, s.perp) + axisMass(j.invMassB, s.perp) + iA * s.s1 * s.s1 +
                    iB * s.s2 * s.s2,
                iA * s.s1 + iB * s.s2, iA + iB};
        if (k.k22 == 0.0f) {
            k.k22 = 1.0f;
        }
        Vec2 C{dot(s.perp, s.f.d), currentAngle(j, a, b)};
        Vec2 impulse = -solve22(k, C);
        a.deltaPosition -= j.invMassA * (impulse.x * s.perp);
        a.deltaRotation = integrateRotation(a.deltaRotation, -iA * (impulse.x * s.s1 + impulse.y));
        b.deltaPosition += j.invMassB * (impulse.x * s.perp);
        b.deltaRotation = integrateRotation(b.deltaRotation, iB * (impulse.x * s.s2 + impulse.y));
        e.linear = std::max(e.linear, std::abs(C.x));
        e.angular = std::abs(C.y);
        break;
    }
    case JointType::Wheel: {
        e.linear = fixSlideLimit(j, a, b);
        const SlideFrame s = currentSlide(j, a, b);
        const float k = axisMass(j.invMassA, s.perp) + axisMass(j.invMassB, s.perp) +
                        j.invInertiaA * s.s1 * s.s1 + j.invInertiaB * s.s2 * s.s2;
        const float C = dot(s.perp, s.f.d);
        if (k > 0.0f) {
            const float impulse = -C / k;
            a.deltaPosition -= j.invMassA * (impulse * s.perp);
            a.deltaRotation = integrateRotation(a.deltaRotation, -j.invInertiaA * impulse * s.s1);
            b.deltaPosition += j.invMassB * (impulse * s.perp);
            b.deltaRotation = integrateRotation(b.deltaRotation, j.invInertiaB * impulse * s.s2);
        }
        e.linear = std::max(e.linear, std::abs(C));
        break;
    }
    }
    return e;
}

} // namespace

bool solveJointPositions(std::span<Joint> joints, std::span<const int> order,
                         std::span<BodyState> states) {
    JointErrors worst;
    for (int k : order) {
        Joint& j = joints[static_cast<std::size_t>(k)];
        BodyState fixedA{};
        BodyState fixedB{};
        BodyState& a = j.indexA < 0 ? fixedA : states[static_cast<std::size_t>(j.indexA)];
        BodyState& b = j.indexB < 0 ? fixedB : states[static_cast<std::size_t>(j.indexB)];
        JointErrors e = fixJoint(j, a, b);
        worst.linear = std::max(worst.linear, e.linear);
        worst.angular = std::max(worst.angular, e.angular);
    }
    return worst.linear <= kLinearSlop && worst.angular <= kAngularSlop;
}

} // namespace e2d::physics::detail
