// SPDX-License-Identifier: MIT
// JointComponent: game objects with Rigidbodies connected without ids, in a real scene.
#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/log.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/core/scene_director.hpp>
#include <e2d/core/scene_registry.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/contact_info.hpp>
#include <e2d/physics/joint_component.hpp>
#include <e2d/physics/physics_system.hpp>
#include <e2d/physics/rigidbody.hpp>

#include "component_scene.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <functional>
#include <memory>
#include <string>

namespace {

using namespace e2d;
using physics::Collider;
using physics::JointComponent;
using physics::JointComponentDef;
using physics::PhysicsSystem;
using physics::Rigidbody;

class JointComponentTest : public ::testing::Test, public physics::test::ComponentScene {
protected:
    core::GameObject& ball(core::Scene& s, glm::vec2 at, float radius = 0.25f) {
        core::GameObject& o = s.createGameObject();
        o.setPosition(at);
        o.addComponent<Rigidbody>(physics);
        o.addComponent<Collider>(physics, physics::Circle{{0.0f, 0.0f}, radius});
        return o;
    }
};

// A ball hung from the world by a revolute joint 1 m above it: it stays 1 m from the pivot and
// the joint carries its weight.
TEST_F(JointComponentTest, BallHungFromTheWorldCarriesItsWeight) {
    core::GameObject* bob = nullptr;
    JointComponent* hinge = nullptr;
    start([&](core::Scene& s) {
        bob = &ball(s, {2.0f, 4.0f});
        physics::RevoluteJointDef r;
        r.localAnchorA = {2.0f, 5.0f}; // a world point: the anchor is at the origin
        r.localAnchorB = {0.0f, 1.0f};
        hinge = bob->addComponent<JointComponent>(physics, JointComponentDef{r, {}});
    });
    EXPECT_TRUE(hinge->isConnected()) << "made as the object entered the scene";
    frames(60);
    ASSERT_TRUE(hinge->isConnected());
    EXPECT_EQ(physics.world().jointCount(), 1);
    EXPECT_EQ(physics.world().jointBodyB(hinge->joint()), bob->getComponent<Rigidbody>()->body());
    const float weight = bob->getComponent<Rigidbody>()->mass() * 10.0f;
    EXPECT_NEAR(hinge->reactionForce().x, 0.0f, 0.01f * weight);
    EXPECT_NEAR(hinge->reactionForce().y, weight, 0.01f * weight);
    EXPECT_NEAR(bob->position().x, 2.0f, 1e-3f);
    EXPECT_NEAR(bob->position().y, 4.0f, 5e-3f);
    // Knocked sideways, it swings on its 1 m circle.
    bob->getComponent<Rigidbody>()->applyLinearImpulse(
        {bob->getComponent<Rigidbody>()->mass() * 2.0f, 0.0f});
    frames(20);
    const float r = std::hypot(bob->position().x - 2.0f, bob->position().y - 5.0f);
    EXPECT_GT(bob->position().x, 2.2f);
    EXPECT_NEAR(r, 1.0f, 5e-3f);
}

// Two balls on a rope (distance joint with a limit only): the lower one falls until the rope
// is taut, then hangs the rope's length below the upper one, which hangs from the world.
TEST_F(JointComponentTest, RopeBetweenTwoObjectsStopsAtItsLength) {
    core::GameObject* top = nullptr;
    core::GameObject* low = nullptr;
    JointComponent* rope = nullptr;
    start([&](core::Scene& s) {
        top = &ball(s, {0.0f, 10.0f});
        low = &ball(s, {0.0f, 9.5f});
        physics::WeldJointDef weld;
        weld.localAnchorA = {0.0f, 10.0f};
        top->addComponent<JointComponent>(physics, JointComponentDef{weld, {}});
        physics::DistanceJointDef d;
        d.enableLimit = true;
        d.minLength = 0.0f;
        d.maxLength = 2.0f;
        rope = low->addComponent<JointComponent>(physics, JointComponentDef{d, top->id()});
    });
    frames(120);
    ASSERT_TRUE(rope->isConnected());
    EXPECT_NEAR(top->position().y, 10.0f, 5e-3f);
    EXPECT_NEAR(top->position().y - low->position().y, 2.0f, 0.01f);
    EXPECT_NEAR(physics.world().jointValue(rope->joint()), 2.0f, 0.01f);
    // Breaking it: the lower ball falls free.
    rope->disconnect();
    EXPECT_FALSE(rope->isConnected());
    const float before = low->position().y;
    frames(30);
    // Half a second of free fall from rest: g t^2 / 2 = 1.25 m.
    EXPECT_NEAR(before - low->position().y, 1.25f, 0.05f);
    EXPECT_NEAR(top->position().y, 10.0f, 5e-3f);
}

// The joint goes with the connected object's Rigidbody, and with the component.
TEST_F(JointComponentTest, JointGoesWithEitherRigidbodyOrTheComponent) {
    core::GameObject* a = nullptr;
    core::GameObject* b = nullptr;
    JointComponent* joint = nullptr;
    start([&](core::Scene& s) {
        a = &ball(s, {0.0f, 0.0f});
        b = &ball(s, {1.0f, 0.0f});
        joint = b->addComponent<JointComponent>(
            physics, JointComponentDef{physics::RevoluteJointDef{}, a->id()});
    });
    frames(1);
    ASSERT_TRUE(joint->isConnected());
    a->removeComponent(a->getComponent<Rigidbody>());
    frames(1);
    EXPECT_FALSE(joint->isConnected());
    EXPECT_EQ(physics.world().jointCount(), 0);
    EXPECT_EQ(joint->reactionForce(), physics::Vec2(0.0f, 0.0f));

    core::GameObject* c = nullptr;
    JointComponent* second = nullptr;
    director.scene()->createGameObject(); // unrelated
    c = &ball(*director.scene(), {3.0f, 0.0f});
    second = c->addComponent<JointComponent>(
        physics, JointComponentDef{physics::RevoluteJointDef{}, b->id()});
    frames(1);
    ASSERT_TRUE(second->isConnected());
    c->removeComponent(second);
    frames(1);
    EXPECT_EQ(physics.world().jointCount(), 0);
}

// Breaks its object's joint when something hits the object.
class BreakOnHit : public core::Component, public core::Handles<physics::CollisionEnter> {
public:
    void on(const physics::CollisionEnter&) override {
        if (JointComponent* joint = gameObject()->getComponent<JointComponent>()) {
            joint->disconnect();
            ++breaks;
        }
    }
    int breaks = 0;
};

// A game breaks a joint from an event callback: a box dropped on a hanging ball breaks its
// cord, and the ball falls.
TEST_F(JointComponentTest, AJointBrokenInACollisionCallbackLetsGo) {
    core::GameObject* bob = nullptr;
    JointComponent* cord = nullptr;
    BreakOnHit* breaker = nullptr;
    start([&](core::Scene& s) {
        bob = &ball(s, {0.0f, 4.0f});
        physics::DistanceJointDef d;
        d.localAnchorA = {0.0f, 5.0f};
        d.length = 1.0f;
        cord = bob->addComponent<JointComponent>(physics, JointComponentDef{d, {}});
        breaker = bob->addComponent<BreakOnHit>();
        core::GameObject& box = s.createGameObject();
        box.setPosition(glm::vec2{0.0f, 4.6f});
        box.addComponent<Rigidbody>(physics);
        box.addComponent<Collider>(physics, physics::makeBox(0.2f, 0.2f));
    });
    frames(3);
    ASSERT_TRUE(cord->isConnected());
    frames(45);
    EXPECT_EQ(breaker->breaks, 1);
    EXPECT_FALSE(cord->isConnected());
    EXPECT_EQ(physics.world().jointCount(), 0);
    EXPECT_LT(bob->position().y, 3.5f) << "the ball fell once its cord broke";
}

TEST_F(JointComponentTest, BadDefsAndMissingRigidbodiesAreClearErrors) {
    physics::RevoluteJointDef r;
    r.lowerAngle = 1.0f;
    r.upperAngle = -1.0f;
    try {
        JointComponent bad(JointComponentDef{r, {}});
        FAIL() << "no error";
    } catch (const core::Error& e) {
        EXPECT_STREQ(e.what(), "physics::JointComponent::JointComponent(): def.joint.lowerAngle "
                               "must be <= def.joint.upperAngle, got 1 > -1");
    }
    physics::DistanceJointDef d;
    d.length = -2.0f;
    try {
        JointComponent bad(JointComponentDef{d, {}});
        FAIL() << "no error";
    } catch (const core::Error& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "physics::JointComponent::JointComponent(): def.joint.length must be"),
                  std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("-2"), std::string::npos)
            << "the value as given: " << e.what();
    }
    core::GameObject* lonely = nullptr;
    core::GameObject* selfish = nullptr;
    start([&](core::Scene& s) {
        lonely = &s.createGameObject();
        lonely->setName("lonely");
        selfish = &s.createGameObject();
        selfish->setTag("rope");
        selfish->addComponent<Rigidbody>();
    });
    lonely->addComponent<JointComponent>();
    try {
        frames(1);
        FAIL() << "no error";
    } catch (const core::Error& e) {
        EXPECT_STREQ(
            e.what(),
            "physics::JointComponent::onInitialize(): the object 'lonely' has no Rigidbody "
            "to connect");
    }
    lonely->removeComponent(lonely->getComponent<JointComponent>());
    selfish->addComponent<JointComponent>(
        JointComponentDef{physics::RevoluteJointDef{}, selfish->id()});
    try {
        frames(1);
        FAIL() << "no error";
    } catch (const core::Error& e) {
        EXPECT_STREQ(e.what(),
                     "physics::JointComponent::onInitialize(): def.connectedObject is the object "
                     "tagged 'rope' itself");
    }
}

// A def-only component (the system found through the scene) hangs a ball from a wall: an object
// with a Collider and no Rigidbody, the anchor in the wall's own frame.
TEST_F(JointComponentTest, DefOnlyJointHangsABallFromAWallWithoutARigidbody) {
    core::GameObject* bob = nullptr;
    JointComponent* hinge = nullptr;
    start([&](core::Scene& s) {
        core::GameObject& wall = s.createGameObject();
        wall.setPosition(glm::vec2{5.0f, 3.0f});
        wall.addComponent<Collider>(physics::makeBox(0.5f, 2.0f));
        bob = &s.createGameObject();
        bob->setPosition(glm::vec2{6.5f, 3.0f});
        bob->addComponent<Rigidbody>();
        bob->addComponent<Collider>(physics::Circle{{0.0f, 0.0f}, 0.25f});
        physics::DistanceJointDef rope;
        rope.localAnchorA = {1.0f, 0.0f}; // the wall's right face, at its centre height
        rope.length = 0.5f;
        hinge = bob->addComponent<JointComponent>(JointComponentDef{rope, wall.id()});
    });
    frames(240);
    ASSERT_TRUE(hinge->isConnected());
    EXPECT_EQ(&hinge->system(), &physics);
    const glm::vec2 anchor{6.0f, 3.0f};
    EXPECT_NEAR(glm::length(glm::vec2(bob->position()) - anchor), 0.5f, 0.02f)
        << "held on its rope";
    EXPECT_LT(bob->position().y, 2.7f) << "hanging below the anchor";
}

} // namespace
