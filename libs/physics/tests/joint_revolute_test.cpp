// SPDX-License-Identifier: MIT
// Revolute joints: a pendulum's small-angle period, limits, motor, spring, reaction force.
#include "joint_test_util.hpp"

#include <cmath>
#include <vector>

namespace e2d::physics::test {
namespace {

class RevoluteJoint : public JointModes {};

// A disc of radius r on a massless arm of length L from a static pivot: a physical pendulum,
// T = 2 pi sqrt(I_pivot / (m g L)), I_pivot = m r^2 / 2 + m L^2.
TEST_P(RevoluteJoint, SmallAnglePendulumPeriodMatchesTheory) {
    World world(worldDef());
    const float L = 1.0f;
    const float theta0 = 0.05f;
    BodyId pivot = addStatic(world, {0.0f, 2.0f});
    BodyId bob = addDisc(world, {L * std::sin(theta0), 2.0f - L * std::cos(theta0)}, 0.05f, 100.0f);
    RevoluteJointDef def;
    def.bodyA = pivot;
    def.bodyB = bob;
    def.localAnchorA = {0.0f, 0.0f};
    def.localAnchorB = world.transform(bob).p - Vec2{0.0f, 2.0f};
    def.localAnchorB = -def.localAnchorB; // the pivot seen from the bob (bob not rotated)
    world.createJoint(def);

    MassData md = world.massData(bob);
    const float iPivot = md.rotationalInertia + md.mass * L * L;
    const double expected = 2.0 * kPi * std::sqrt(iPivot / (md.mass * 10.0f * L));

    // Times of downward zero crossings of x (interpolated), over 5 periods.
    std::vector<double> crossings;
    float lastX = world.transform(bob).p.x;
    for (int i = 1; i < 60 * 12 && crossings.size() < 6; ++i) {
        world.step(kJointStep);
        float x = world.transform(bob).p.x;
        if (lastX > 0.0f && x <= 0.0f) {
            double frac = lastX / (lastX - x);
            crossings.push_back((i - 1 + frac) * kJointStep);
        }
        lastX = x;
    }
    ASSERT_EQ(crossings.size(), 6u);
    const double period = (crossings.back() - crossings.front()) / 5.0;
    EXPECT_NEAR(period, expected, 0.015 * expected) << "expected " << expected;
    // The bob stays on its circle.
    EXPECT_NEAR(length(world.transform(bob).p - Vec2{0.0f, 2.0f}), L, 0.005f);
}

// A hanging mass: the joint holds its weight, m g upward on B.
TEST_P(RevoluteJoint, ReactionForceOfAHangingMassIsItsWeight) {
    World world(worldDef());
    BodyId pivot = addStatic(world, {0.0f, 5.0f});
    BodyId box = addPlank(world, {0.0f, 4.0f}, 0.2f, 0.2f, 2.0f);
    RevoluteJointDef def;
    def.bodyA = pivot;
    def.bodyB = box;
    def.localAnchorB = {0.0f, 1.0f};
    JointId joint = world.createJoint(def);
    EXPECT_EQ(world.jointReactionForce(joint), Vec2(0.0f, 0.0f));
    run(world, 1.0f);
    const float weight = world.massData(box).mass * 10.0f;
    Vec2 force = world.jointReactionForce(joint);
    EXPECT_NEAR(force.x, 0.0f, 0.01f * weight);
    EXPECT_NEAR(force.y, weight, 0.01f * weight);
    EXPECT_NEAR(world.jointReactionTorque(joint), 0.0f, 1e-3f);
}

// A bar hinged at its end starts horizontal; the limit stops it 0.25 rad below horizontal.
TEST_P(RevoluteJoint, LimitHoldsAHeavyBar) {
    World world(worldDef());
    BodyId wall = addStatic(world);
    BodyId bar = addPlank(world, {1.0f, 0.0f}, 1.0f, 0.1f, 5.0f);
    RevoluteJointDef def;
    def.bodyA = wall;
    def.bodyB = bar;
    def.localAnchorB = {-1.0f, 0.0f};
    def.enableLimit = true;
    def.lowerAngle = -0.25f;
    def.upperAngle = 0.25f;
    JointId joint = world.createJoint(def);
    float lowest = 0.0f;
    for (int i = 0; i < 120; ++i) {
        world.step(kJointStep);
        lowest = std::min(lowest, world.jointValue(joint));
    }
    EXPECT_GT(lowest, -0.25f - 0.02f);
    EXPECT_NEAR(world.jointValue(joint), -0.25f, 0.01f);
    EXPECT_NEAR(world.transform(bar).q.angle(), -0.25f, 0.01f);
    // The limit carries the bar's moment m g (L / 2) about the hinge.
    const float moment = world.massData(bar).mass * 10.0f * 1.0f * std::cos(0.25f);
    EXPECT_NEAR(world.jointReactionTorque(joint), moment, 0.03f * moment);
}

TEST_P(RevoluteJoint, MotorReachesItsSpeedAndItsTorqueLimits) {
    World world(worldDef({0.0f, 0.0f}));
    BodyId ground = addStatic(world);
    BodyId wheel = addDisc(world, {0.0f, 0.0f}, 0.5f);
    RevoluteJointDef def;
    def.bodyA = ground;
    def.bodyB = wheel;
    def.enableMotor = true;
    def.motorSpeed = 3.0f;
    def.maxMotorTorque = 1000.0f;
    JointId joint = world.createJoint(def);
    run(world, 0.5f);
    EXPECT_NEAR(world.angularVelocity(wheel), 3.0f, 0.01f);
    // A weak motor: angular acceleration = torque / inertia.
    world.setAngularVelocity(wheel, 0.0f);
    world.setJointMaxMotorForce(joint, 0.1f);
    world.setJointMotorSpeed(joint, 100.0f);
    run(world, 1.0f);
    const float expected = 0.1f / world.massData(wheel).rotationalInertia * 1.0f;
    EXPECT_NEAR(world.angularVelocity(wheel), expected, 0.02f * expected);
    EXPECT_NEAR(world.jointReactionTorque(joint), 0.1f, 1e-4f);
}

// An angular spring of f hertz on a disc hinged at its centre oscillates at f.
TEST_P(RevoluteJoint, SpringOscillatesAtItsFrequency) {
    World world(worldDef({0.0f, 0.0f}));
    BodyId ground = addStatic(world);
    BodyId disc = addDisc(world, {0.0f, 0.0f}, 0.5f);
    RevoluteJointDef def;
    def.bodyA = ground;
    def.bodyB = disc;
    def.enableSpring = true;
    def.hertz = 1.0f;
    JointId joint = world.createJoint(def);
    world.setAngularVelocity(disc, 1.0f);
    std::vector<double> crossings;
    float last = world.jointValue(joint);
    for (int i = 1; i < 60 * 5; ++i) {
        world.step(kJointStep);
        float a = world.jointValue(joint);
        if (last < 0.0f && a >= 0.0f) {
            crossings.push_back((i - 1 + last / (last - a)) * kJointStep);
        }
        last = a;
    }
    ASSERT_GE(crossings.size(), 4u);
    const double period = (crossings[3] - crossings[0]) / 3.0;
    EXPECT_NEAR(period, 1.0, 0.02);
}

// A disc hinged at its centre to the ground (no gravity), spinning at `speed` rad/s.
struct SpinningDisc {
    BodyId disc;
    JointId joint;
};
SpinningDisc addSpinningDisc(World& world, float speed) {
    BodyId ground = addStatic(world);
    BodyId disc = addDisc(world, {0.0f, 0.0f}, 0.5f);
    RevoluteJointDef def;
    def.bodyA = ground;
    def.bodyB = disc;
    JointId joint = world.createJoint(def);
    world.setAngularVelocity(disc, speed);
    return {disc, joint};
}

// A joint angle is followed through whole turns.
TEST_P(RevoluteJoint, AngleCountsWholeTurns) {
    World world(worldDef({0.0f, 0.0f}));
    const JointId joint = addSpinningDisc(world, 2.0f * kPi).joint;
    run(world, 2.0f);
    EXPECT_NEAR(world.jointValue(joint), 4.0f * kPi, 0.05f);
}

// A plain hinge follows its angle only every so many degrees; a limit switched on after
// whole turns at several speeds (a few degrees a step, and over 45 degrees a step, where it is
// followed every step) must see the angle through all of them: the disc runs on to the upper
// limit, a turn and a half further, and stops there.
TEST_P(RevoluteJoint, ALimitSwitchedOnAfterWholeTurnsSeesThem) {
    for (const float speed : {1.0f * kPi, 6.0f * kPi, 20.0f * kPi}) {
        SCOPED_TRACE(speed);
        World world(worldDef({0.0f, 0.0f}));
        const auto [disc, joint] = addSpinningDisc(world, speed);
        // The disc's turn, followed step by step here (the integration turns a body by a
        // little less than w h per sub-step).
        float turned = 0.0f;
        for (int i = 0; i < 37; ++i) {
            const Rot before = world.transform(disc).q;
            world.step(kJointStep);
            turned += invMulRot(before, world.transform(disc).q).angle();
        }
        ASSERT_GT(turned, 0.7f * speed * 37.0f / 60.0f);
        ASSERT_NEAR(world.jointValue(joint), turned, 1e-3f * turned);
        world.setJointLimits(joint, -1.0f, turned + 3.0f * kPi);
        world.enableJointLimit(joint, true);
        run(world, 4.0f);
        EXPECT_NEAR(world.jointValue(joint), turned + 3.0f * kPi, 0.05f);
        EXPECT_NEAR(world.angularVelocity(disc), 0.0f, 0.05f);
    }
}

// The soft step's rigid joint rows are springs of SolverDef::jointHertz: a 5 kg ball hung
// from a 0.05 kg link stretches their joint by about its load / (m (2 pi hertz)^2), m the
// pair's reduced mass, so doubling the stiffness divides the stretch by four.
TEST(RevoluteJointSoftness, JointHertzSetsTheStretchUnderLoad) {
    auto stretchAt = [](float hertz) {
        WorldDef def;
        def.gravity = {0.0f, -10.0f};
        def.solver.subSteps = 8;
        def.solver.jointHertz = hertz;
        def.solver.jointSolver = JointSolver::Soft; // the rows are rigid in the other models
        World world(def);
        BodyId top = addStatic(world, {0.0f, 0.0f});
        BodyId link = addDisc(world, {0.0f, -0.5f}, 0.05f);
        world.setMassData(link, {0.05f, {0.0f, 0.0f}, 1.0e-4f});
        BodyId ball = addDisc(world, {0.0f, -1.0f}, 0.2f);
        world.setMassData(ball, {5.0f, {0.0f, 0.0f}, 0.1f});
        RevoluteJointDef upper;
        upper.bodyA = top;
        upper.bodyB = link;
        upper.localAnchorB = {0.0f, 0.5f};
        world.createJoint(upper);
        RevoluteJointDef lower;
        lower.bodyA = link;
        lower.bodyB = ball;
        lower.localAnchorA = {0.0f, -0.5f};
        world.createJoint(lower);
        run(world, 3.0f);
        // The lower joint's gap: the link's bottom to the ball's centre.
        const Vec2 linkEnd = transformPoint(world.transform(link), {0.0f, -0.5f});
        return length(world.transform(ball).p - linkEnd);
    };
    const float reduced = 0.05f * 5.0f / 5.05f;
    for (const float hertz : {60.0f, 120.0f}) {
        const float omega = 2.0f * kPi * hertz;
        const float expected = 5.0f * 10.0f / (reduced * omega * omega);
        EXPECT_NEAR(stretchAt(hertz), expected, 0.05f * expected) << hertz << " Hz";
    }
    EXPECT_GT(stretchAt(60.0f), 3.0f * stretchAt(120.0f));
}

E2D_JOINT_MODES(RevoluteJoint);

} // namespace
} // namespace e2d::physics::test
