// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/solver_def.hpp>

#include "contact_solver.hpp"
#include "contact_solver_wide.hpp"
#include "joint_solver.hpp"
#include "solver_body.hpp"

#include <algorithm>
#include <cmath>
#include <span>

// The step's stages over the awake bodies' arrays and the contact constraints: the soft-step
// sub-step loop and the classic iterations. The world builds the arrays, this runs them.
namespace e2d::physics::detail {

struct SolverStep {
    std::span<BodySim> sims;
    std::span<BodyState> states; // same order as sims
    std::span<ContactConstraint> constraints;
    Vec2 gravity{0.0f, 0.0f};
    float dt = 0.0f;
    const SolverDef* def = nullptr;
    // The step's joints: jointOrder's entries in order (packJointPasses(): slots of joints or
    // groups of plain hinges in *pointJoints; solveSoftStepBlock() takes its block's order
    // instead), and the rigid parts' softness at the (sub-)step.
    std::span<Joint> joints{};
    std::span<const int> jointOrder{};
    JointStep jointStep{};
    PointJointGroups* pointJoints = nullptr; // set when there are joints
    // Soft step: biased solve sweeps per sub-step beyond the first, and relax sweeps on top of
    // def->relaxIterations (kPushOutSolveIterations and kPushOutRelaxIterations while shapes
    // are pushed apart, see World::Impl::solve()). They are the contacts' only: the joints are
    // solved and relaxed once per sub-step (plus def->relaxIterations) either way. A folding
    // 400-link chain pushed some self-overlap apart in about one step in seven, and solving
    // its joints in all 31 sweeps then doubled the chain's joint time, with no effect on any
    // joint scenario of the validation (ragdoll, car, bridge: the same joint gaps).
    int extraSolveIterations = 0;
    int extraRelaxIterations = 0;
};

// Largest rotation of one integration step, radians (Box2D 2.4's value): 94 rad/s at 60 Hz,
// 377 rad/s with 4 sub-steps.
inline constexpr float kMaxRotation = 0.5f * 3.14159265f;

/// The speeds integrateVelocities() and clampVelocity() allow for a step of h seconds: linear
/// in m/s, angular in rad/s.
struct SpeedCaps {
    float linear;
    float angular;
};

/// The caps of an integration step of h seconds (h > 0).
inline SpeedCaps speedCaps(float maxLinearSpeed, float h) {
    // The rotation integrator is only right for small angles, and a huge one overflows it
    // into a zero (not unit) rotation that no finiteness check would catch.
    return {maxLinearSpeed, kMaxRotation / h};
}

/// Clamps a body's speed to caps.linear and its angular speed to caps.angular (a quarter turn
/// per integration step, speedCaps()), as integrateVelocities() does. Inline: the world
/// clamps every awake body once a step, with the same caps.
inline void clampVelocity(Vec2& v, float& w, SpeedCaps caps) {
    float speedSquared = dot(v, v);
    if (speedSquared > caps.linear * caps.linear) {
        if (std::isinf(speedSquared)) {
            // Past about 1.8e19 m/s the square overflows, and scaling by cap / inf would stop
            // the body dead: bring the components to at most 1 first (still the same direction).
            v *= 1.0f / std::max(std::fabs(v.x), std::fabs(v.y));
            speedSquared = dot(v, v);
        }
        v *= caps.linear / std::sqrt(speedSquared);
    }
    w = std::clamp(w, -caps.angular, caps.angular);
}
// Implicit damping, 1 / (1 + h c): stable for any coefficient and step. Most bodies have
// none, and skipping the division then gives the same 1.
inline float dampingFactor(float h, float coefficient) {
    return coefficient == 0.0f ? 1.0f : 1.0f / (1.0f + h * coefficient);
}

/// Sets sim's velocityStep, angularVelocityStep and damping factors for integration steps of h
/// seconds: what integrateVelocities() adds and multiplies every sub-step, computed once.
/// Inline: the world prepares each awake body as it copies it in (World::Impl::solve()).
inline void prepareIntegration(BodySim& sim, Vec2 gravity, float h) {
    sim.linearDampingFactor = dampingFactor(h, sim.linearDamping);
    sim.angularDampingFactor = dampingFactor(h, sim.angularDamping);
    // Gravity acts on each axis that can move (a kinematic body has none).
    Vec2 g = sim.gravityScale * gravity;
    Vec2 accel{sim.invMass.x > 0.0f ? g.x + sim.invMass.x * sim.force.x : 0.0f,
               sim.invMass.y > 0.0f ? g.y + sim.invMass.y * sim.force.y : 0.0f};
    sim.velocityStep = h * accel;
    sim.angularVelocityStep = h * sim.invInertia * sim.torque;
}
// Sets each sim's velocityStep, angularVelocityStep and damping factors for integration steps
// of h seconds: what integrateVelocities() adds and multiplies every sub-step, computed once.
void prepareIntegration(std::span<BodySim> sims, Vec2 gravity, float h);
// Gravity, forces and damping over h seconds, as prepareIntegration() left them for that h;
// speeds clamped (clampVelocity()).
void integrateVelocities(std::span<const BodySim> sims, std::span<BodyState> states, float h,
                         float maxLinearSpeed);
// prepareIntegration() and integrateVelocities() in one: a single step of h seconds.
void integrateVelocities(std::span<BodySim> sims, std::span<BodyState> states, Vec2 gravity,
                         float h, float maxLinearSpeed);
// Accumulates each body's motion over h seconds into its deltaPosition/deltaRotation, its
// speeds capped first as integrateVelocities() caps them (the constraints may have raised
// them since): no body moves further than maxLinearSpeed * h.
void integratePositions(std::span<BodyState> states, float h, float maxLinearSpeed);
// The same for the bodies states[indices[i]] only.
void integrateVelocities(std::span<const BodySim> sims, std::span<BodyState> states,
                         std::span<const int> indices, float h, float maxLinearSpeed);
void integratePositions(std::span<BodyState> states, std::span<const int> indices, float h,
                        float maxLinearSpeed);
// The same for a block's bodies, `increasing` (indices in increasing order): read in place when
// they are one run of the arrays (a block holding every awake body, about a third of the
// indexed loops' instructions saved), through the indices otherwise.
void integrateBlockVelocities(std::span<const BodySim> sims, std::span<BodyState> states,
                              std::span<const int> increasing, float h, float maxLinearSpeed);
void integrateBlockPositions(std::span<BodyState> states, std::span<const int> increasing, float h,
                             float maxLinearSpeed);

// Runs the velocity and position stages of one step; positions end in the states' deltas.
void solveSoftStep(const SolverStep& step);
// The soft step of one block of islands on the wide solver: levels [firstLevel, endLevel) of
// `wide` (colours, ConstraintColors: the constraints of a level share no moving body, several
// constraints at a time), the BodyState indices `bodies` (every body those constraints touch, and no body
// another block's constraints touch), then restitution on `restitution` (the block's, in
// constraint order). Blocks share no body, so running one through all sub-steps before the
// next gives what running all of them sub-step by sub-step gives, and the block's
// constraints and bodies stay in cache meanwhile. step.constraints is not used; the joints
// solved are blockJoints (the block's: every joint between its bodies), before the contacts in
// each pass. The bodies come prepared (prepareIntegration() for sub-steps of
// step.dt / subSteps), as World::Impl::solve() copies them in.
void solveSoftStepBlock(const SolverStep& step, WideContacts& wide, int firstLevel, int endLevel,
                        std::span<const int> bodies, std::span<const WideRestitution> restitution,
                        std::span<const int> blockJoints = {});

// The passes of solveSoftStepBlock() in their order, as calls on `passes`:
// integrateVelocities(subStep), warmStart() (joints, then contacts), solve(useBias, backward,
// reversePoints, joints) (the contacts' levels, in reverse when backward, after the joints when
// `joints`), integratePositions(), and restitution() once at the end. solveSoftStepBlock() runs
// them on one worker; solveSoftStepStaged() (soft_step_stages.hpp) as stages on several.
template <class Passes>
void forEachSoftStepPass(const SolverStep& step, Passes& passes) {
    const SolverDef& def = *step.def;
    const int relaxIterations = def.relaxIterations + step.extraRelaxIterations;
    // The same passes and orders as solveSoftStep() (see there why).
    for (int i = 0; i < def.subSteps; ++i) {
        passes.integrateVelocities(i);
        const bool backward = (i % 2) == 1;
        const bool reversePoints = ((i / 2) % 2) == 1;
        passes.warmStart();
        for (int r = 0; r <= step.extraSolveIterations; ++r) {
            // The extra sweeps are the contacts' (SolverStep).
            passes.solve(true, backward, reversePoints, r == 0);
        }
        passes.integratePositions();
        for (int r = 0; r <= relaxIterations; ++r) {
            passes.solve(false, !backward, reversePoints, r <= def.relaxIterations);
        }
    }
    passes.restitution();
}
void solveClassic(const SolverStep& step);

// Continuous collision's slow-body rule (Box2D v3's, safety factor 0.5): a body whose centre
// moved by `centerMotion` while it turned by a rotation of sine `turnSine`, its shapes between
// minExtent and maxExtent from its centre, may have passed through a static shape only if it
// travelled half its smallest extent; below that its speculative contacts cover it.
inline bool movedFast(Vec2 centerMotion, float turnSine, float maxExtent, float minExtent) {
    return length(centerMotion) + std::abs(turnSine) * maxExtent >= 0.5f * minExtent;
}

// Moves each sim by its state's deltas (centre, rotation, origin) and sets its position residual
// (the part of center0 + deltaPosition the float centre cannot hold). A body that became
// non-finite is left so; the world checks and disables it. Flags the bodies that movedFast()
// kIsFast, here where their motion is at hand (the test was about 30 instructions a body in a
// pass of its own); returns whether any body is kIsFast or a bullet: whether continuous
// collision has a body to sweep.
bool finalizePositions(std::span<BodySim> sims, std::span<const BodyState> states);

// Contact softness at the sub-step rate: contactHertz capped at a quarter of the sub-step
// rate; against static bodies twice as stiff.
struct ContactSoftness {
    Softness dynamic;
    Softness vsStatic;
};
ContactSoftness makeContactSoftness(const SolverDef& def, float dt);

} // namespace e2d::physics::detail
