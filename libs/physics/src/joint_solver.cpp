// SPDX-License-Identifier: MIT
// The joints' step: prepare, the passes in order, and the reaction each joint reports.
#include "joint_solver.hpp"

#include <e2d/physics/constants.hpp>

#include <algorithm>

namespace e2d::physics::detail {

namespace {

inline float inverseOrZero(float k) { return k > 0.0f ? 1.0f / k : 0.0f; }

// Axial effective mass at the step start of a joint whose B anchor slides along axisA.
float slideMass(const Joint& j) {
    Vec2 d = j.deltaCenter + j.anchorB - j.anchorA;
    float a1 = cross(d + j.anchorA, j.axisA);
    float a2 = cross(j.anchorB, j.axisA);
    return inverseOrZero(axisMass(j.invMassA, j.axisA) + axisMass(j.invMassB, j.axisA) +
                         j.invInertiaA * a1 * a1 + j.invInertiaB * a2 * a2);
}

Softness springOf(float hertz, float dampingRatio, float h) {
    return hertz > 0.0f ? makeSoftness(hertz, dampingRatio, h) : Softness{0.0f, 1.0f, 0.0f};
}

} // namespace

JointStep makeJointStep(const SolverDef& def, float h, JointDirectScratch* direct) {
    JointStep step{h, 1.0f / h, makeSoftness(def.jointHertz, def.jointDampingRatio, h)};
    // The soft step's rigid models: rigid rows (their position errors are the position passes'),
    // a revolute joint's point and limit as one block.
    const JointSolver model = def.jointSolver;
    if (model != JointSolver::Soft && def.mode == SolverMode::SoftStep) {
        step.jointSoftness = Softness{0.0f, 1.0f, 0.0f};
        step.blockLimit = true;
    }
    if (model == JointSolver::Direct && def.mode == SolverMode::SoftStep) {
        step.direct = direct;
    }
    return step;
}

void prepareJoint(Joint& j, const JointBodyView& a, const JointBodyView& b, const JointStep& step) {
    j.indexA = a.stateIndex;
    j.indexB = b.stateIndex;
    j.invMassA = a.invMass;
    j.invMassB = b.invMass;
    j.invInertiaA = a.invInertia;
    j.invInertiaB = b.invInertia;
    j.anchorA = rotate(a.q, j.localAnchorA - a.localCenter);
    j.anchorB = rotate(b.q, j.localAnchorB - b.localCenter);
    j.deltaCenter = b.center - a.center;
    j.axisA = rotate(a.q, j.localAxisA);
    const float angularK = a.invInertia + b.invInertia;
    j.angularMass = inverseOrZero(angularK);
    // The joint angle at the step start (a revolute joint's is followed through whole turns
    // below, from the same relative angle). A plain hinge reads no angle: while it has turned
    // less than kAngleFollowCos from where its angle was last followed, the angle waits (no
    // atan2f).
    const Rot rotation = invMulRot(a.q, b.q);
    const bool follow =
        !isPointJoint(j) ||
        rotation.c * j.angleRotation.c + rotation.s * j.angleRotation.s < kAngleFollowCos;
    const float relative = follow ? wrapAngle(rotation.angle() - j.referenceAngle) : j.angle;
    j.angle0 = relative;
    if (!j.enableMotor) {
        j.motorImpulse = 0.0f;
    }
    if (!j.enableLimit) {
        j.lowerImpulse = 0.0f;
        j.upperImpulse = 0.0f;
    }
    switch (j.type) {
    case JointType::Distance: {
        Vec2 d = j.deltaCenter + j.anchorB - j.anchorA;
        Vec2 axis = normalize(d);
        float crA = cross(j.anchorA, axis);
        float crB = cross(j.anchorB, axis);
        j.axialMass = inverseOrZero(axisMass(a.invMass, axis) + axisMass(b.invMass, axis) +
                                    a.invInertia * crA * crA + b.invInertia * crB * crB);
        j.springSoftness = springOf(j.hertz, j.dampingRatio, step.h);
        if (!j.enableSpring && !j.enableLimit) {
            j.motorImpulse = 0.0f; // rigid: no motor
        }
        break;
    }
    case JointType::Motor:
        break;
    case JointType::Mouse:
        // Body A is a reference only: the joint acts on B alone.
        j.indexA = -1;
        j.invMassA = {0.0f, 0.0f};
        j.invInertiaA = 0.0f;
        j.deltaCenter = b.center - j.target;
        j.anchorA = {0.0f, 0.0f};
        j.springSoftness = springOf(j.hertz, j.dampingRatio, step.h);
        break;
    case JointType::Prismatic:
    case JointType::Wheel:
        j.axialMass = slideMass(j);
        j.springSoftness = springOf(j.hertz, j.dampingRatio, step.h);
        if (!j.enableSpring) {
            j.springImpulse = 0.0f;
        }
        break;
    case JointType::Revolute: {
        // Followed through whole turns: the turn since it was last followed is below half a
        // turn.
        if (follow) {
            j.angle += wrapAngle(relative - j.angle);
            j.angleRotation = rotation;
        }
        j.angle0 = j.angle;
        j.axialMass = j.angularMass;
        j.springSoftness = springOf(j.hertz, j.dampingRatio, step.h);
        if (!j.enableSpring) {
            j.springImpulse = 0.0f;
        }
        break;
    }
    case JointType::Weld:
        j.springSoftness = springOf(j.hertz, j.dampingRatio, step.h);
        j.angularSoftness = springOf(j.angularHertz, j.angularDampingRatio, step.h);
        break;
    }
}

namespace {

template <typename F>
inline void withStates(Joint& j, std::span<BodyState> states, F&& f) {
    BodyState fixedA{};
    BodyState fixedB{};
    BodyState& a = j.indexA < 0 ? fixedA : states[static_cast<std::size_t>(j.indexA)];
    BodyState& b = j.indexB < 0 ? fixedB : states[static_cast<std::size_t>(j.indexB)];
    f(a, b);
}

} // namespace

void warmStartJoint(Joint& j, std::span<BodyState> states) {
    withStates(j, states, [&](BodyState& a, BodyState& b) {
        switch (j.type) {
        case JointType::Distance:
            warmStartDistance(j, a, b);
            break;
        case JointType::Motor:
            warmStartMotor(j, a, b);
            break;
        case JointType::Mouse:
            warmStartMouse(j, a, b);
            break;
        case JointType::Prismatic:
            warmStartPrismatic(j, a, b);
            break;
        case JointType::Revolute:
            warmStartRevolute(j, a, b);
            break;
        case JointType::Weld:
            warmStartWeld(j, a, b);
            break;
        case JointType::Wheel:
            warmStartWheel(j, a, b);
            break;
        }
    });
}

void solveJoint(Joint& j, std::span<BodyState> states, const JointStep& step, bool useBias) {
    withStates(j, states, [&](BodyState& a, BodyState& b) {
        switch (j.type) {
        case JointType::Distance:
            solveDistance(j, a, b, step, useBias);
            break;
        case JointType::Motor:
            solveMotor(j, a, b, step, useBias);
            break;
        case JointType::Mouse:
            solveMouse(j, a, b, step, useBias);
            break;
        case JointType::Prismatic:
            solvePrismatic(j, a, b, step, useBias);
            break;
        case JointType::Revolute:
            solveRevolute(j, a, b, step, useBias);
            break;
        case JointType::Weld:
            solveWeld(j, a, b, step, useBias);
            break;
        case JointType::Wheel:
            solveWheel(j, a, b, step, useBias);
            break;
        }
    });
}

void storeJointReaction(Joint& j, std::span<const BodyState> states, float invH) {
    BodyState fixedA{};
    BodyState fixedB{};
    const BodyState& a = j.indexA < 0 ? fixedA : states[static_cast<std::size_t>(j.indexA)];
    const BodyState& b = j.indexB < 0 ? fixedB : states[static_cast<std::size_t>(j.indexB)];
    const JointFrame f = currentFrame(j, a, b);
    const Vec2 axis = rotate(a.deltaRotation, j.axisA);
    const Vec2 perp = leftPerp(axis);
    const float axial = j.springImpulse + j.motorImpulse + j.lowerImpulse - j.upperImpulse;
    Vec2 force{0.0f, 0.0f};
    float torque = 0.0f;
    switch (j.type) {
    case JointType::Distance:
        force =
            (j.springImpulse + j.motorImpulse + j.lowerImpulse - j.upperImpulse) * normalize(f.d);
        break;
    case JointType::Motor:
    case JointType::Weld:
        force = j.linearImpulse;
        torque = j.angularImpulse;
        break;
    case JointType::Mouse:
        force = j.linearImpulse;
        break;
    case JointType::Prismatic:
        force = j.linearImpulse.x * perp + axial * axis;
        torque = j.linearImpulse.y;
        break;
    case JointType::Revolute:
        force = j.linearImpulse;
        torque = axial;
        break;
    case JointType::Wheel:
        force = j.perpImpulse * perp + (j.springImpulse + j.lowerImpulse - j.upperImpulse) * axis;
        torque = j.motorImpulse;
        break;
    }
    j.reactionForce = invH * force;
    j.reactionTorque = invH * torque;
}

void warmStartJoints(std::span<Joint> joints, PointJointGroups& groups, std::span<const int> order,
                     std::span<BodyState> states) {
    for (int k : order) {
        if (k >= 0) {
            warmStartJoint(joints[static_cast<std::size_t>(k)], states);
        } else if ((~k & 1) != 0) {
            warmStartPointOctet(groups.octets[static_cast<std::size_t>(~k >> 1)], states);
        } else {
            warmStartPointQuad(groups.quads[static_cast<std::size_t>(~k >> 1)], states);
        }
    }
}

void solveJoints(std::span<Joint> joints, PointJointGroups& groups, std::span<const int> order,
                 std::span<BodyState> states, const JointStep& step, bool useBias) {
    const Softness soft = rigidSoftness(step, useBias);
    for (int k : order) {
        if (k >= 0) {
            solveJoint(joints[static_cast<std::size_t>(k)], states, step, useBias);
        } else if ((~k & 1) != 0) {
            solvePointOctet(groups.octets[static_cast<std::size_t>(~k >> 1)], states, soft);
        } else {
            solvePointQuad(groups.quads[static_cast<std::size_t>(~k >> 1)], states, soft);
        }
    }
    if (step.direct != nullptr) {
        solveJointsDirect(joints, order, states, step, useBias, *step.direct); // no groups then
    }
}

} // namespace e2d::physics::detail
