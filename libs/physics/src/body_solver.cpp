// SPDX-License-Identifier: MIT
#include "body_solver.hpp"

#include <algorithm>
#include <cmath>

namespace e2d::physics::detail {

namespace {

// Largest rotation of one integration step, radians (Box2D 2.4's value): 94 rad/s at 60 Hz,
// 377 rad/s with 4 sub-steps.
constexpr float kMaxRotation = 0.5f * 3.14159265f;

// The speeds integrateVelocities() and clampVelocity() allow for a step of h seconds.
struct SpeedCaps {
    float linear;
    float angular;
};

inline SpeedCaps speedCaps(float maxLinearSpeed, float h) {
    // The rotation integrator is only right for small angles, and a huge one overflows it
    // into a zero (not unit) rotation that no finiteness check would catch.
    return {maxLinearSpeed, kMaxRotation / h};
}

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

} // namespace

void clampVelocity(Vec2& v, float& w, float maxLinearSpeed, float h) {
    clampVelocity(v, w, speedCaps(maxLinearSpeed, h));
}

namespace {

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

inline void integrateVelocity(const BodySim& sim, BodyState& state, SpeedCaps caps) {
    Vec2 v = sim.velocityStep + sim.linearDampingFactor * state.linearVelocity;
    float w = sim.angularVelocityStep + sim.angularDampingFactor * state.angularVelocity;
    clampVelocity(v, w, caps);
    if (!isFinite(v) || !isFinite(w) || (state.flags & kNonFinite) != 0) {
        // Absurd input (a force or gravity scale near the float limit) overflowed: the
        // body stays still for the rest of the step, so the contact solver spreads nothing
        // to what it touches, and the world disables and reports it afterwards.
        state.flags |= kNonFinite;
        v = {0.0f, 0.0f};
        w = 0.0f;
    }
    state.linearVelocity = v;
    state.angularVelocity = w;
}

// The speeds are capped again first: the constraints solved since integrateVelocity() can
// give a body any speed (a 2e-8 kg body next to a 1e6 kg and a 6e9 kg one took 4e7 m/s from
// the classic velocity iterations and left the coordinate range in one step, the fuzzer's
// tiny-body-out-of-range). Box2D 2.4 caps the translation at this point too.
inline void integratePosition(BodyState& state, float h, SpeedCaps caps) {
    clampVelocity(state.linearVelocity, state.angularVelocity, caps);
    state.deltaRotation = integrateRotation(state.deltaRotation, h * state.angularVelocity);
    state.deltaPosition += h * state.linearVelocity;
}

} // namespace

void prepareIntegration(std::span<BodySim> sims, Vec2 gravity, float h) {
    for (BodySim& sim : sims) {
        prepareIntegration(sim, gravity, h);
    }
}

void prepareIntegration(std::span<BodySim> sims, std::span<const int> indices, Vec2 gravity,
                        float h) {
    for (int i : indices) {
        prepareIntegration(sims[static_cast<std::size_t>(i)], gravity, h);
    }
}

void integrateVelocities(std::span<const BodySim> sims, std::span<BodyState> states, float h,
                         float maxLinearSpeed) {
    const SpeedCaps caps = speedCaps(maxLinearSpeed, h);
    for (std::size_t i = 0; i < sims.size(); ++i) {
        integrateVelocity(sims[i], states[i], caps);
    }
}

void integrateVelocities(std::span<BodySim> sims, std::span<BodyState> states, Vec2 gravity,
                         float h, float maxLinearSpeed) {
    prepareIntegration(sims, gravity, h);
    integrateVelocities(std::span<const BodySim>(sims), states, h, maxLinearSpeed);
}

void integrateVelocities(std::span<const BodySim> sims, std::span<BodyState> states,
                         std::span<const int> indices, float h, float maxLinearSpeed) {
    const SpeedCaps caps = speedCaps(maxLinearSpeed, h);
    for (int i : indices) {
        const auto k = static_cast<std::size_t>(i);
        integrateVelocity(sims[k], states[k], caps);
    }
}

void integratePositions(std::span<BodyState> states, float h, float maxLinearSpeed) {
    const SpeedCaps caps = speedCaps(maxLinearSpeed, h);
    for (BodyState& state : states) {
        integratePosition(state, h, caps);
    }
}

void integratePositions(std::span<BodyState> states, std::span<const int> indices, float h,
                        float maxLinearSpeed) {
    const SpeedCaps caps = speedCaps(maxLinearSpeed, h);
    for (int i : indices) {
        integratePosition(states[static_cast<std::size_t>(i)], h, caps);
    }
}

ContactSoftness makeContactSoftness(const SolverDef& def, float dt) {
    float h = dt / static_cast<float>(def.subSteps);
    float hertz = std::min(def.contactHertz, 0.25f / h);
    return {makeSoftness(hertz, def.contactDampingRatio, h),
            makeSoftness(2.0f * hertz, def.contactDampingRatio, h)};
}

namespace {

// The joint passes over `order`; a step without joints (order empty) has no groups.
void warmStartJointsOf(const SolverStep& step, std::span<const int> order) {
    if (!order.empty()) {
        warmStartJoints(step.joints, *step.pointJoints, order, step.states);
    }
}
void solveJointsOf(const SolverStep& step, std::span<const int> order, bool useBias) {
    if (!order.empty()) {
        solveJoints(step.joints, *step.pointJoints, order, step.states, step.jointStep, useBias);
    }
}

} // namespace

void solveSoftStep(const SolverStep& step) {
    const SolverDef& def = *step.def;
    float h = step.dt / static_cast<float>(def.subSteps);
    float invH = 1.0f / h;
    const int relaxIterations = def.relaxIterations + step.extraRelaxIterations;
    prepareIntegration(step.sims, step.gravity, h);
    for (int i = 0; i < def.subSteps; ++i) {
        integrateVelocities(step.sims, step.states, h, def.maxLinearSpeed);
        // Gauss-Seidel's order biases the result, so every group of four sub-steps runs all
        // four orders. Odd sub-steps sweep the constraints backwards, which cancels the
        // sideways drift of piles. Sub-steps 2 and 3 also solve each constraint's two points
        // in reverse: the point solved second gets more impulse (the first one's push tilts
        // the bodies against it), a torque of one sign every sub-step otherwise, which leans
        // tall stacks and toppled a column pushed out of a 25 % overlap. Reversing the points
        // together with the constraints (on odd sub-steps) cancels the torque but not its
        // coupling with the sweep direction: base-70 pyramids then drift 5x more.
        bool backward = (i % 2) == 1;
        bool reversePoints = ((i / 2) % 2) == 1;
        // Joints go before the contacts in each pass (Box2D v3's order): the contacts, solved
        // last, win where the two disagree.
        warmStartJointsOf(step, step.jointOrder);
        warmStartContacts(step.constraints, step.states);
        for (int r = 0; r <= step.extraSolveIterations; ++r) {
            if (r == 0) { // the extra sweeps are the contacts' (SolverStep)
                solveJointsOf(step, step.jointOrder, true);
            }
            solveContacts(step.constraints, step.states, invH, true, def.contactPushMaxSpeed,
                          backward, reversePoints);
        }
        integratePositions(step.states, h, def.maxLinearSpeed);
        // The relax passes sweep the other way: the sweep direction's bias then cancels within
        // each sub-step, not only over two. Relaxed in the same direction, a five-level house of
        // cards (0.002 x 0.4 m cards) swayed 3-5 mm to one side as its contacts took the load,
        // and each swing slipped the top pair a little at its apex until it fell.
        for (int r = 0; r <= relaxIterations; ++r) {
            if (r <= def.relaxIterations) {
                solveJointsOf(step, step.jointOrder, false);
            }
            solveContacts(step.constraints, step.states, invH, false, def.contactPushMaxSpeed,
                          !backward, reversePoints);
        }
    }
    applyRestitution(step.constraints, step.states, def.restitutionThreshold, h);
}

void solveSoftStepBlock(const SolverStep& step, WideContacts& wide, int firstLevel, int endLevel,
                        std::span<const int> bodies, std::span<const WideRestitution> restitution,
                        std::span<const int> blockJoints) {
    struct Passes {
        const SolverStep& step;
        WideContacts& wide;
        int firstLevel;
        int endLevel;
        std::span<const int> bodies;
        std::span<const WideRestitution> restituted;
        std::span<const int> joints;
        float h;

        void integrateVelocities(int subStep) {
            if (subStep == 0) {
                prepareIntegration(step.sims, bodies, step.gravity, h);
            }
            detail::integrateVelocities(step.sims, step.states, bodies, h,
                                        step.def->maxLinearSpeed);
        }
        void warmStart() {
            warmStartJointsOf(step, joints);
            warmStartWide(wide, firstLevel, endLevel, step.states);
        }
        void solve(bool useBias, bool backward, bool reversePoints, bool withJoints) {
            if (withJoints) {
                solveJointsOf(step, joints, useBias);
            }
            solveWide(wide, firstLevel, endLevel, step.states, 1.0f / h, useBias,
                      step.def->contactPushMaxSpeed, backward, reversePoints);
        }
        void integratePositions() {
            detail::integratePositions(step.states, bodies, h, step.def->maxLinearSpeed);
        }
        void restitution() {
            applyRestitutionWide(wide, restituted, step.states, step.def->restitutionThreshold, h);
        }
    };
    Passes passes{
        step,   wide,        firstLevel,  endLevel,
        bodies, restitution, blockJoints, step.dt / static_cast<float>(step.def->subSteps)};
    forEachSoftStepPass(step, passes);
}

void solveClassic(const SolverStep& step) {
    const SolverDef& def = *step.def;
    float invDt = 1.0f / step.dt;
    integrateVelocities(step.sims, step.states, step.gravity, step.dt, def.maxLinearSpeed);
    prepareClassic(step.constraints, step.states, def.restitutionThreshold);
    warmStartJointsOf(step, step.jointOrder);
    warmStartContacts(step.constraints, step.states);
    for (int i = 0; i < def.velocityIterations; ++i) {
        // Box2D 2.4's recipe: velocities only here (a limit not reached yet still stops the
        // bodies at it), position errors in the position iterations below.
        solveJointsOf(step, step.jointOrder, false);
        solveVelocitiesClassic(step.constraints, step.states, invDt);
    }
    applyRestitution(step.constraints, step.states, def.restitutionThreshold, step.dt);
    integratePositions(step.states, step.dt, def.maxLinearSpeed);
    for (int i = 0; i < def.positionIterations; ++i) {
        // Box2D 2.4's stopping rule: done once nothing overlaps by more than 3 times the
        // allowed penetration (3 slops by default).
        const float allowed = def.classicAllowedPenetration;
        const bool contactsDone = solvePositionsClassic(step.constraints, step.states, allowed,
                                                        def.classicPositionBias) >= -3.0f * allowed;
        const bool jointsDone = solveJointPositions(step.joints, step.jointOrder, step.states);
        if (contactsDone && jointsDone) {
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
        // The next step starts from the centre the float transform gives; what it misses of
        // center0 + deltaPosition is kept. Near each other (the usual case far away, where it
        // matters) the two centres subtract exactly.
        const Vec2 next = transformPoint(sim.transform, sim.localCenter);
        sim.positionResidual = state.deltaPosition - (next - sim.center0);
    }
}

} // namespace e2d::physics::detail
