// SPDX-License-Identifier: MIT
// Joint ids carry their world, joints are not made or destroyed inside callbacks, and the
// Joint view forwards to the world.
#include "joint_test_util.hpp"

#include <e2d/physics/views.hpp>

#include <string>
#include <utility>
#include <vector>

namespace e2d::physics::test {
namespace {

template <class F>
std::string errorText(F&& f) {
    return errorOf(std::forward<F>(f));
}

TEST(JointHandles, JointIdsCarryTheirWorld) {
    World a{WorldDef{.tag = 21}};
    World b{WorldDef{.tag = 22}};
    BodyId groundA = addStatic(a);
    BodyId discA = addDisc(a, {1.0f, 0.0f}, 0.2f);
    BodyId groundB = addStatic(b);
    BodyId discB = addDisc(b, {1.0f, 0.0f}, 0.2f);
    JointId ja = a.createJoint(RevoluteJointDef{.bodyA = groundA, .bodyB = discA});
    JointId jb = b.createJoint(RevoluteJointDef{.bodyA = groundB, .bodyB = discB});
    EXPECT_EQ(ja.owner, 21);
    EXPECT_EQ(jb.owner, 22);
    ASSERT_EQ(ja.index1, jb.index1); // the same slot in each world
    ASSERT_EQ(ja.generation, jb.generation);
    EXPECT_FALSE(ja == jb);
    EXPECT_FALSE(b.isValid(ja));
    EXPECT_EQ(errorText([&] { (void)b.jointReactionForce(ja); }),
              "physics::World::jointReactionForce(): JointId (index1 1, generation 1, world 21) "
              "belongs to "
              "another world (this world's tag is 22)");
    EXPECT_EQ(errorText([&] { b.destroyJoint(ja); }),
              "physics::World::destroyJoint(): JointId (index1 1, generation 1, world 21) belongs "
              "to another "
              "world (this world's tag is 22)");
    EXPECT_TRUE(b.isValid(jb)) << "nothing of b's was touched";
    // A joint across worlds: a's body in b is refused by its tag.
    EXPECT_NE(errorText([&] { b.createJoint(WeldJointDef{.bodyA = groundB, .bodyB = discA}); })
                  .find("physics::World::createJoint(): BodyId (index1 2, generation 1, world 21) "
                        "belongs to another world"),
              std::string::npos);
    EXPECT_EQ(b.jointCount(), 1);
    // Ids listed by the world carry the tag too.
    EXPECT_EQ(a.bodyJoints(discA), std::vector<JointId>{ja});
    EXPECT_EQ(a.jointDebugData().at(0).id, ja);
}

TEST(JointHandles, NoJointIsMadeOrDestroyedInsideACallback) {
    World world;
    BodyId ground = addStatic(world);
    world.createShape(ground, {}, makeBox(5.0f, 0.5f));
    BodyId disc = addDisc(world, {0.0f, 2.0f}, 0.5f);
    JointId rope =
        world.createJoint(DistanceJointDef{.bodyA = ground, .bodyB = disc, .length = 2.0f});
    const Aabb all{{-10.0f, -10.0f}, {10.0f, 10.0f}};
    EXPECT_EQ(
        errorText([&] {
            world.overlapAabb(all, {}, [&](ShapeId) {
                world.createJoint(WeldJointDef{.bodyA = ground, .bodyB = disc});
                return true;
            });
        }),
        "physics::World::createJoint(): cannot run inside the callback of overlapAabb() (it would "
        "change "
        "what the callback is walking); collect the ids and call it after overlapAabb() returns");
    EXPECT_NE(
        errorText([&] {
            world.overlapAabb(all, {}, [&](ShapeId) {
                world.destroyJoint(rope);
                return true;
            });
        }).find("physics::World::destroyJoint(): cannot run inside the callback of overlapAabb()"),
        std::string::npos);
    EXPECT_EQ(world.jointCount(), 1);
    EXPECT_TRUE(world.isValid(rope));
    // Reading a joint and changing its motor or spring inside a walk is allowed.
    world.overlapAabb(all, {}, [&](ShapeId) {
        world.setJointSpring(rope, 2.0f, 0.5f);
        (void)world.jointReactionForce(rope);
        return false;
    });
    // After the walk, both work.
    world.destroyJoint(rope);
    world.createJoint(WeldJointDef{.bodyA = ground, .bodyB = disc});
    EXPECT_EQ(world.jointCount(), 1);
}

TEST(JointHandles, JointViewForwardsToTheWorld) {
    World world(WorldDef{.gravity = {0.0f, 0.0f}});
    Body ground = world.body(addStatic(world));
    Body wheel = world.body(addDisc(world, {0.0f, 0.0f}, 0.5f));
    Joint hinge = ground.createJoint(RevoluteJointDef{.bodyA = ground.id(), .bodyB = wheel.id()});
    EXPECT_TRUE(hinge.isValid());
    EXPECT_EQ(hinge.type(), JointType::Revolute);
    EXPECT_EQ(hinge.bodyA(), ground);
    EXPECT_EQ(hinge.bodyB(), wheel);
    EXPECT_EQ(wheel.joints(), std::vector<JointId>{hinge.id()});
    EXPECT_EQ(world.joint(hinge.id()), hinge);
    hinge.setMaxMotorForce(1000.0f);
    hinge.setMotorSpeed(2.0f);
    hinge.enableMotor(true);
    run(world, 0.5f);
    EXPECT_NEAR(wheel.angularVelocity(), 2.0f, 0.01f);
    EXPECT_NEAR(hinge.value(), world.jointValue(hinge.id()), 0.0f);
    EXPECT_GT(hinge.value(), 0.5f); // turned about 2 rad/s for most of half a second
    hinge.setUserData(77);
    EXPECT_EQ(world.jointUserData(hinge.id()), 77u);
    hinge.destroy();
    EXPECT_FALSE(hinge.isValid());
    E2D_EXPECT_ERROR((void)hinge.reactionForce(),
                     "physics::World::jointReactionForce(): stale or null JointId");
}

} // namespace
} // namespace e2d::physics::test
