// SPDX-License-Identifier: MIT
// Distance joints: rigid rod, spring frequency, rope (max length), motor.
#include "joint_test_util.hpp"

#include <cmath>
#include <vector>

namespace e2d::physics::test {
namespace {

class DistanceJoint : public JointModes {};

TEST_P(DistanceJoint, RigidRodKeepsItsLengthAndCarriesTheWeight) {
    World world(worldDef());
    BodyId anchor = addStatic(world, {0.0f, 5.0f});
    BodyId ball = addDisc(world, {1.5f, 5.0f}, 0.1f, 10.0f);
    DistanceJointDef def;
    def.bodyA = anchor;
    def.bodyB = ball;
    def.length = 1.5f;
    JointId joint = world.createJoint(def);
    float worst = 0.0f;
    for (int i = 0; i < 240; ++i) {
        world.step(kJointStep);
        worst = std::max(worst, std::abs(world.jointValue(joint) - 1.5f));
    }
    EXPECT_LT(worst, 0.01f);
    // Swung down and damped enough? No: check the force at the bottom once it hangs still.
    World still(worldDef());
    BodyId a2 = addStatic(still, {0.0f, 5.0f});
    BodyId b2 = addDisc(still, {0.0f, 3.5f}, 0.1f, 10.0f);
    def.bodyA = a2;
    def.bodyB = b2;
    JointId j2 = still.createJoint(def);
    run(still, 0.5f);
    const float weight = still.massData(b2).mass * 10.0f;
    EXPECT_NEAR(still.jointReactionForce(j2).y, weight, 0.01f * weight);
}

// A mass m on a spring of f hertz to a static anchor: k = m (2 pi f)^2, period 1 / f.
TEST_P(DistanceJoint, SpringOscillatesAtItsFrequency) {
    World world(worldDef({0.0f, 0.0f}));
    BodyId anchor = addStatic(world);
    BodyId ball = addDisc(world, {1.2f, 0.0f}, 0.1f);
    DistanceJointDef def;
    def.bodyA = anchor;
    def.bodyB = ball;
    def.length = 1.0f;
    def.enableSpring = true;
    def.hertz = 2.0f;
    JointId joint = world.createJoint(def);
    std::vector<double> crossings;
    float last = world.jointValue(joint) - 1.0f;
    for (int i = 1; i < 60 * 4; ++i) {
        world.step(kJointStep);
        float x = world.jointValue(joint) - 1.0f;
        if (last > 0.0f && x <= 0.0f) {
            crossings.push_back((i - 1 + last / (last - x)) * kJointStep);
        }
        last = x;
    }
    ASSERT_GE(crossings.size(), 5u);
    const double period = (crossings[4] - crossings[0]) / 4.0;
    EXPECT_NEAR(period, 0.5, 0.01);
}

// A rope: free while slack, never longer than maxLength.
TEST_P(DistanceJoint, RopeStopsAtItsMaxLength) {
    World world(worldDef());
    BodyId anchor = addStatic(world, {0.0f, 10.0f});
    BodyId ball = addDisc(world, {0.5f, 9.5f}, 0.1f, 5.0f);
    DistanceJointDef def;
    def.bodyA = anchor;
    def.bodyB = ball;
    def.enableLimit = true;
    def.minLength = 0.0f;
    def.maxLength = 2.0f;
    JointId joint = world.createJoint(def);
    // Slack: free fall for the first steps.
    run(world, 0.1f);
    EXPECT_NEAR(world.linearVelocity(ball).y, -10.0f * 0.1f, 0.02f);
    float longest = 0.0f;
    for (int i = 0; i < 300; ++i) {
        world.step(kJointStep);
        longest = std::max(longest, world.jointValue(joint));
    }
    EXPECT_LT(longest, 2.0f + 0.01f);
    EXPECT_GT(longest, 2.0f - 0.01f);
}

TEST_P(DistanceJoint, MotorDrivesTheLength) {
    World world(worldDef({0.0f, 0.0f}));
    BodyId anchor = addStatic(world);
    BodyId ball = addDisc(world, {1.0f, 0.0f}, 0.1f);
    DistanceJointDef def;
    def.bodyA = anchor;
    def.bodyB = ball;
    def.enableLimit = true;
    def.maxLength = 3.0f;
    def.enableMotor = true;
    def.motorSpeed = 0.5f;
    def.maxMotorForce = 1.0f; // 30 m/s^2 on the 0.03 kg ball
    JointId joint = world.createJoint(def);
    run(world, 1.0f);
    EXPECT_NEAR(world.jointValue(joint), 1.5f, 0.02f);
    run(world, 5.0f);
    EXPECT_NEAR(world.jointValue(joint), 3.0f, 0.01f);
}

// A body thrown towards its anchor stops at minLength (the limit is inelastic), and the limits
// changed later hold too.
TEST_P(DistanceJoint, MinLengthStopsABodyComingCloser) {
    World world(worldDef({0.0f, 0.0f}));
    BodyId anchor = addStatic(world);
    BodyId ball = addDisc(world, {2.0f, 0.0f}, 0.1f);
    DistanceJointDef def;
    def.bodyA = anchor;
    def.bodyB = ball;
    def.length = 2.0f;
    def.enableLimit = true;
    def.minLength = 1.0f;
    def.maxLength = 3.0f;
    JointId joint = world.createJoint(def);
    world.setLinearVelocity(ball, {-3.0f, 0.0f});
    float shortest = 2.0f;
    for (int i = 0; i < 60; ++i) {
        world.step(kJointStep);
        shortest = std::min(shortest, world.jointValue(joint));
    }
    EXPECT_GT(shortest, 1.0f - 0.01f);
    EXPECT_NEAR(world.jointValue(joint), 1.0f, 0.01f);
    EXPECT_NEAR(world.linearVelocity(ball).x, 0.0f, 0.05f);
    // Narrower limits: thrown outwards, it now stops at 1.5 m.
    world.setJointLimits(joint, 0.5f, 1.5f);
    world.setLinearVelocity(ball, {2.0f, 0.0f});
    run(world, 1.0f);
    EXPECT_NEAR(world.jointValue(joint), 1.5f, 0.01f);
    // Limits off, no spring: a rigid rod of def.length (2 m) again.
    world.enableJointLimit(joint, false);
    run(world, 1.0f);
    EXPECT_NEAR(world.jointValue(joint), 2.0f, 0.01f);
}

E2D_JOINT_MODES(DistanceJoint);

} // namespace
} // namespace e2d::physics::test
