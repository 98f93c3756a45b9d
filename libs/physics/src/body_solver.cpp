// SPDX-License-Identifier: MIT
#include "body_solver.hpp"

#include <e2d/physics/constants.hpp>

#include <algorithm>
#include <cmath>

namespace e2d::physics::detail {

void integrateVelocities(std::span<const BodySim> sims, std::span<BodyState> states, Vec2 gravity,
                         float h, float maxLinearSpeed) {
    float maxSpeedSquared = maxLinearSpeed * maxLinearSpeed;
    for (std::size_t i = 0; i < sims.size(); ++i) {
        const BodySim& sim = sims[i];
        BodyState& state = states[i];
        // Implicit damping: stable for any damping coefficient and step.
        float linearDamping = 1.0f / (1.0f + h * sim.linearDamping);
        float angularDamping = 1.0f / (1.0f + h * sim.angularDamping);
        // Gravity acts on each axis that can move (a kinematic body has none).
        Vec2 g = sim.gravityScale * gravity;
        Vec2 accel{sim.invMass.x > 0.0f ? g.x + sim.invMass.x * sim.force.x : 0.0f,
                   sim.invMass.y > 0.0f ? g.y + sim.invMass.y * sim.force.y : 0.0f};
        Vec2 v = h * accel + linearDamping * state.linearVelocity;
        float w = h * sim.invInertia * sim.torque + angularDamping * state.angularVelocity;
        float speedSquared = dot(v, v);
        if (speedSquared > maxSpeedSquared) {
            v *= maxLinearSpeed / std::sqrt(speedSquared);
        }
        state.linearVelocity = v;
        state.angularVelocity = w;
    }
}

void integratePositions(std::span<BodyState> states, float h) {
    for (BodyState& state : states) {
        state.deltaRotation = integrateRotation(state.deltaRotation, h * state.angularVelocity);
        state.deltaPosition += h * state.linearVelocity;
    }
}

ContactSoftness makeContactSoftness(const SolverDef& def, float dt) {
    float h = dt / static_cast<float>(def.subSteps);
    float hertz = std::min(def.contactHertz, 0.25f / h);
    return {makeSoftness(hertz, def.contactDampingRatio, h),
            makeSoftness(2.0f * hertz, def.contactDampingRatio, h)};
}

void solveSoftStep(const SolverStep& step) {
    const SolverDef& def = *step.def;
    float h = step.dt / static_cast<float>(def.subSteps);
    float invH = 1.0f / h;
    if (step.wide != nullptr) {
        WideContacts& wide = *step.wide;
        // The same passes as below; a backward sweep is the levels in reverse.
        for (int i = 0; i < def.subSteps; ++i) {
            integrateVelocities(step.sims, step.states, step.gravity, h, def.maxLinearSpeed);
            bool backward = (i % 2) == 1;
            warmStartWide(wide, step.states);
            solveWide(wide, step.states, invH, true, def.contactPushMaxSpeed, backward);
            integratePositions(step.states, h);
            for (int r = 0; r <= def.relaxIterations; ++r) {
                solveWide(wide, step.states, invH, false, def.contactPushMaxSpeed, backward);
            }
        }
        storeWide(wide, step.constraints, step.levelOrder, step.levelStart);
        applyRestitution(step.constraints, step.states, def.restitutionThreshold, h);
        return;
    }
    for (int i = 0; i < def.subSteps; ++i) {
        integrateVelocities(step.sims, step.states, step.gravity, h, def.maxLinearSpeed);
        // Odd sub-steps sweep the constraints backwards: alternating directions cancels the
        // order bias of Gauss-Seidel, which otherwise drifts piles sideways.
        bool backward = (i % 2) == 1;
        warmStartContacts(step.constraints, step.states);
        solveContacts(step.constraints, step.states, invH, true, def.contactPushMaxSpeed,
                      backward);
        integratePositions(step.states, h);
        for (int r = 0; r <= def.relaxIterations; ++r) {
            solveContacts(step.constraints, step.states, invH, false, def.contactPushMaxSpeed,
                          backward);
        }
    }
    applyRestitution(step.constraints, step.states, def.restitutionThreshold, h);
}

void solveClassic(const SolverStep& step) {
    const SolverDef& def = *step.def;
    float invDt = 1.0f / step.dt;
    integrateVelocities(step.sims, step.states, step.gravity, step.dt, def.maxLinearSpeed);
    prepareClassic(step.constraints, def.restitutionThreshold);
    warmStartContacts(step.constraints, step.states);
    for (int i = 0; i < def.velocityIterations; ++i) {
        solveVelocitiesClassic(step.constraints, step.states, invDt);
    }
    applyRestitution(step.constraints, step.states, def.restitutionThreshold, step.dt);
    integratePositions(step.states, step.dt);
    for (int i = 0; i < def.positionIterations; ++i) {
        // Box2D 2.4's stopping rule: done once nothing overlaps by more than 3 slops.
        if (solvePositionsClassic(step.constraints, step.states) >= -3.0f * kLinearSlop) {
            break;
        }
    }
}

void finalizePositions(std::span<BodySim> sims, std::span<const BodyState> states) {
    for (std::size_t i = 0; i < sims.size(); ++i) {
        BodySim& sim = sims[i];
        const BodyState& state = states[i];
        sim.center = sim.center0 + state.deltaPosition;
        Rot q = mulRot(state.deltaRotation, sim.rotation0);
        float mag = std::sqrt(q.c * q.c + q.s * q.s);
        if (mag > 0.0f) {
            q = {q.c / mag, q.s / mag};
        }
        sim.transform.q = q;
        sim.transform.p = sim.center - rotate(q, sim.localCenter);
    }
}

} // namespace e2d::physics::detail
