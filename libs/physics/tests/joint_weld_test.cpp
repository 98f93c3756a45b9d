// SPDX-License-Identifier: MIT
// Weld, mouse and motor joints.
#include "joint_test_util.hpp"

#include <cmath>

namespace e2d::physics::test {
namespace {

class WeldJoint : public JointModes {};

// A 2 m beam welded to a wall by one end holds (nearly) level, carrying its weight and moment.
TEST_P(WeldJoint, RigidWeldHoldsACantilever) {
    World world(worldDef());
    BodyId wall = addStatic(world);
    BodyId beam = addPlank(world, {1.0f, 0.0f}, 1.0f, 0.1f);
    WeldJointDef def;
    def.bodyA = wall;
    def.bodyB = beam;
    def.localAnchorB = {-1.0f, 0.0f};
    JointId joint = world.createJoint(def);
    run(world, 2.0f);
    EXPECT_NEAR(world.transform(beam).q.angle(), 0.0f, 0.01f);
    EXPECT_NEAR(world.transform(beam).p.y, 0.0f, 0.01f);
    const float weight = world.massData(beam).mass * 10.0f;
    EXPECT_NEAR(world.jointReactionForce(joint).y, weight, 0.01f * weight);
    EXPECT_NEAR(world.jointReactionTorque(joint), weight * 1.0f, 0.02f * weight);
}

// A soft weld of f hertz (angular): the beam bends until its spring carries the moment.
TEST_P(WeldJoint, SoftWeldBendsUnderLoad) {
    World world(worldDef());
    BodyId wall = addStatic(world);
    BodyId beam = addPlank(world, {1.0f, 0.0f}, 1.0f, 0.1f);
    WeldJointDef def;
    def.bodyA = wall;
    def.bodyB = beam;
    def.localAnchorB = {-1.0f, 0.0f};
    def.angularHertz = 2.0f;
    def.angularDampingRatio = 1.0f;
    world.createJoint(def);
    run(world, 3.0f);
    // Angular spring k = I (2 pi f)^2, I the beam's inertia about its centre of mass (see
    // joint.hpp); it carries the moment m g (L / 2) at angle m g (L / 2) cos(angle) / k.
    MassData md = world.massData(beam);
    const float k = md.rotationalInertia * std::pow(2.0f * kPi * 2.0f, 2.0f);
    const float angle = world.transform(beam).q.angle();
    const float expected = -md.mass * 10.0f * 1.0f * std::cos(angle) / k;
    EXPECT_NEAR(angle, expected, 0.02f * std::abs(expected));
}

TEST_P(WeldJoint, MouseJointPullsABodyToItsTarget) {
    World world(worldDef({0.0f, 0.0f}));
    BodyId ground = addStatic(world);
    BodyId box = addPlank(world, {0.0f, 0.0f}, 0.5f, 0.5f);
    MouseJointDef def;
    def.bodyA = ground;
    def.bodyB = box;
    def.target = {3.0f, 2.0f};
    def.hertz = 4.0f;
    def.dampingRatio = 1.0f;
    def.maxForce = 1000.0f;
    JointId joint = world.createJoint(def);
    run(world, 2.0f);
    EXPECT_NEAR(world.transform(box).p.x, 3.0f, 0.01f);
    EXPECT_NEAR(world.transform(box).p.y, 2.0f, 0.01f);
    // A weak pull accelerates the body at maxForce / m at most.
    world.setJointMaxMotorForce(joint, 1.0f);
    world.setMouseJointTarget(joint, {103.0f, 2.0f});
    run(world, 1.0f);
    const float a = 1.0f / world.massData(box).mass;
    EXPECT_NEAR(world.linearVelocity(box).x, a * 1.0f, 0.02f * a);
}

TEST_P(WeldJoint, MotorJointReachesItsOffset) {
    World world(worldDef({0.0f, 0.0f}));
    BodyId ground = addStatic(world, {1.0f, 1.0f});
    BodyId box = addPlank(world, {0.0f, 0.0f}, 0.5f, 0.5f);
    MotorJointDef def;
    def.bodyA = ground;
    def.bodyB = box;
    def.linearOffset = {2.0f, 1.0f};
    def.angularOffset = 0.5f;
    def.maxForce = 100.0f;
    def.maxTorque = 100.0f;
    world.createJoint(def);
    run(world, 3.0f);
    EXPECT_NEAR(world.transform(box).p.x, 3.0f, 0.01f);
    EXPECT_NEAR(world.transform(box).p.y, 2.0f, 0.01f);
    EXPECT_NEAR(world.transform(box).q.angle(), 0.5f, 0.01f);
}

E2D_JOINT_MODES(WeldJoint);

} // namespace
} // namespace e2d::physics::test
