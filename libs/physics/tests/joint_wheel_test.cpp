// SPDX-License-Identifier: MIT
// Wheel joints: suspension rest compression, drive motor, limits.
#include "joint_test_util.hpp"

#include <cmath>

namespace e2d::physics::test {
namespace {

class WheelJoint : public JointModes {};

// A wheel of mass m hanging on its suspension (k = m (2 pi f)^2) rests m g / k below the
// anchor.
TEST_P(WheelJoint, SuspensionRestCompressionIsWeightOverStiffness) {
    World world(worldDef());
    BodyId chassis = addStatic(world, {0.0f, 2.0f});
    BodyId wheel = addDisc(world, {0.0f, 1.0f}, 0.4f);
    WheelJointDef def;
    def.bodyA = chassis;
    def.bodyB = wheel;
    def.localAnchorA = {0.0f, -1.0f};
    def.hertz = 3.0f;
    def.dampingRatio = 1.0f;
    JointId joint = world.createJoint(def);
    run(world, 3.0f);
    const float m = world.massData(wheel).mass;
    const float k = m * std::pow(2.0f * kPi * 3.0f, 2.0f);
    const float expected = -m * 10.0f / k;
    EXPECT_NEAR(world.jointValue(joint), expected, 0.02f * std::abs(expected));
    EXPECT_NEAR(world.transform(wheel).p.x, 0.0f, 1e-4f);
    EXPECT_NEAR(world.jointReactionForce(joint).y, m * 10.0f, 0.01f * m * 10.0f);
}

TEST_P(WheelJoint, MotorSpinsTheWheelAndLimitsStopTheTravel) {
    World world(worldDef());
    BodyId chassis = addStatic(world, {0.0f, 2.0f});
    BodyId wheel = addDisc(world, {0.0f, 2.0f}, 0.4f);
    WheelJointDef def;
    def.bodyA = chassis;
    def.bodyB = wheel;
    def.enableSpring = false;
    def.enableLimit = true;
    def.lowerTranslation = -0.2f;
    def.upperTranslation = 0.2f;
    def.enableMotor = true;
    def.motorSpeed = -10.0f;
    def.maxMotorTorque = 50.0f;
    JointId joint = world.createJoint(def);
    run(world, 1.0f);
    EXPECT_NEAR(world.angularVelocity(wheel), -10.0f, 0.05f);
    EXPECT_NEAR(world.jointValue(joint), -0.2f, 0.005f);
}

E2D_JOINT_MODES(WheelJoint);

} // namespace
} // namespace e2d::physics::test
