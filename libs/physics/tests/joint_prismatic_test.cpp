// SPDX-License-Identifier: MIT
// Prismatic joints: the axis, limits, motor against a limit, spring.
#include "joint_test_util.hpp"

#include <cmath>

namespace e2d::physics::test {
namespace {

class PrismaticJoint : public JointModes {};

// A box on a diagonal rail slides down it without turning (no friction: a = g sin 45).
TEST_P(PrismaticJoint, SlidesAlongItsAxisWithoutTurning) {
    World world(worldDef());
    BodyId ground = addStatic(world);
    BodyId box = addPlank(world, {0.0f, 0.0f}, 0.3f, 0.2f);
    PrismaticJointDef def;
    def.bodyA = ground;
    def.bodyB = box;
    def.localAxisA = {1.0f, 1.0f};
    JointId joint = world.createJoint(def);
    run(world, 1.0f);
    const float a = 10.0f * std::sqrt(0.5f);
    EXPECT_NEAR(world.jointValue(joint), -0.5f * a, 0.02f * 0.5f * a);
    Vec2 p = world.transform(box).p;
    EXPECT_NEAR(p.x, p.y, 0.005f);
    EXPECT_NEAR(world.transform(box).q.angle(), 0.0f, 0.002f);
}

TEST_P(PrismaticJoint, LowerLimitHoldsTheWeight) {
    World world(worldDef());
    BodyId ground = addStatic(world);
    BodyId box = addPlank(world, {0.0f, 0.0f}, 0.3f, 0.3f, 3.0f);
    PrismaticJointDef def;
    def.bodyA = ground;
    def.bodyB = box;
    def.localAxisA = {0.0f, 1.0f};
    def.enableLimit = true;
    def.lowerTranslation = -1.0f;
    def.upperTranslation = 0.5f;
    JointId joint = world.createJoint(def);
    float lowest = 0.0f;
    for (int i = 0; i < 120; ++i) {
        world.step(kJointStep);
        lowest = std::min(lowest, world.jointValue(joint));
    }
    EXPECT_GT(lowest, -1.0f - 0.01f);
    EXPECT_NEAR(world.jointValue(joint), -1.0f, 0.005f);
    const float weight = world.massData(box).mass * 10.0f;
    EXPECT_NEAR(world.jointReactionForce(joint).y, weight, 0.01f * weight);
}

// A motor lifting a load runs at its speed, then holds the load against the upper limit.
TEST_P(PrismaticJoint, MotorRunsAtSpeedThenRestsOnItsLimit) {
    World world(worldDef());
    BodyId ground = addStatic(world);
    BodyId box = addPlank(world, {0.0f, 0.0f}, 0.3f, 0.3f);
    PrismaticJointDef def;
    def.bodyA = ground;
    def.bodyB = box;
    def.localAxisA = {0.0f, 1.0f};
    def.enableLimit = true;
    def.lowerTranslation = -1.0f;
    def.upperTranslation = 1.0f;
    def.enableMotor = true;
    def.motorSpeed = 1.0f;
    def.maxMotorForce = 200.0f;
    JointId joint = world.createJoint(def);
    run(world, 0.5f);
    EXPECT_NEAR(world.linearVelocity(box).y, 1.0f, 0.01f);
    EXPECT_NEAR(world.jointValue(joint), 0.5f, 0.03f);
    float highest = 0.0f;
    for (int i = 0; i < 120; ++i) {
        world.step(kJointStep);
        highest = std::max(highest, world.jointValue(joint));
    }
    EXPECT_LT(highest, 1.0f + 0.01f);
    EXPECT_NEAR(world.jointValue(joint), 1.0f, 0.005f);
}

// A spring of f hertz along the axis: the load hangs g / (2 pi f)^2 below the anchor.
TEST_P(PrismaticJoint, SpringSagsByGOverOmegaSquared) {
    World world(worldDef());
    BodyId ground = addStatic(world);
    BodyId box = addPlank(world, {0.0f, 0.0f}, 0.3f, 0.3f);
    PrismaticJointDef def;
    def.bodyA = ground;
    def.bodyB = box;
    def.localAxisA = {0.0f, 1.0f};
    def.enableSpring = true;
    def.hertz = 2.0f;
    def.dampingRatio = 1.0f;
    JointId joint = world.createJoint(def);
    run(world, 3.0f);
    const float omega = 2.0f * kPi * 2.0f;
    EXPECT_NEAR(world.jointValue(joint), -10.0f / (omega * omega), 0.02f * 10.0f / (omega * omega));
}

E2D_JOINT_MODES(PrismaticJoint);

} // namespace
} // namespace e2d::physics::test
