// SPDX-License-Identifier: MIT
// Compound bodies: a Collider on a child of an object with a Rigidbody is a shape of that body,
// at the child's pose relative to it, and follows reparenting, moves, scale and removal.
#include "component_scene.hpp"

#include <e2d/core/error.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/rigidbody.hpp>

#include <gtest/gtest.h>

namespace {

using namespace e2d;
using physics::Collider;
using physics::Rigidbody;
using physics::test::ComponentScene;

// A pixel scene: 100 world units per metre, a floor whose top is at y = -200.
class CompoundTest : public ::testing::Test, public ComponentScene {
protected:
    CompoundTest() : ComponentScene(100.0f) {}

    core::GameObject& floor(core::Scene& s) {
        core::GameObject& g = s.createGameObject();
        g.setName("floor");
        g.setPosition(glm::vec2{0.0f, -220.0f});
        g.addComponent<Collider>(physics::makeBox(1000.0f, 20.0f));
        return g;
    }
    // A 40 px box with a Rigidbody, and a child 40 px below its centre with a 20 px box.
    void crateWithChild(core::Scene& s, glm::vec2 at) {
        crate = &s.createGameObject();
        crate->setPosition(at);
        crate->addComponent<Rigidbody>();
        crate->addComponent<Collider>(physics::makeBox(20.0f, 20.0f));
        child = &s.createGameObject();
        crate->addChild(*child);
        child->setPosition(glm::vec2{0.0f, -40.0f});
        child->addComponent<Collider>(physics::makeBox(10.0f, 10.0f));
    }
    float mass() { return crate->getComponent<Rigidbody>()->mass(); }
    physics::BodyId childBody() { return child->getComponent<Collider>()->body(); }

    core::GameObject* crate = nullptr;
    core::GameObject* child = nullptr;
};

TEST_F(CompoundTest, ChildColliderIsAShapeOfTheParentBodyAndRestsOnTheGround) {
    start([&](core::Scene& s) {
        floor(s);
        crateWithChild(s, {0.0f, 0.0f});
    });
    frames(150);
    // The child's 20 px box carries the crate: its bottom (crate y - 50) on the floor's top.
    EXPECT_NEAR(crate->position().y, -150.0f, 1.0f);
    EXPECT_NEAR(child->worldPosition().y, -190.0f, 1.0f);
    EXPECT_EQ(childBody(), crate->getComponent<Rigidbody>()->body());
    EXPECT_EQ(physics.world().bodyCount(), 2) << "the floor and the crate, no body for the child";
    // 0.4 m and 0.2 m squares at 1 kg/m^2.
    EXPECT_NEAR(mass(), 0.16f + 0.04f, 1e-5f);
}

TEST_F(CompoundTest, ReparentedChildLeavesTheBodyAndComesBack) {
    start([&](core::Scene& s) { crateWithChild(s, {0.0f, 0.0f}); });
    frames(1);
    ASSERT_NEAR(mass(), 0.2f, 1e-5f);
    // Away from the crate: a static collider of its own where it was drawn.
    child->setParent(nullptr);
    child->setPosition(glm::vec2{500.0f, 0.0f});
    frames(1);
    EXPECT_NEAR(mass(), 0.16f, 1e-5f);
    EXPECT_NE(childBody(), crate->getComponent<Rigidbody>()->body());
    EXPECT_EQ(physics.world().bodyType(childBody()), physics::BodyType::Static);
    EXPECT_NEAR(physics.world().transform(childBody()).p.x, 5.0f, 1e-5f);
    EXPECT_EQ(physics.world().bodyCount(), 2);
    // Back under it, 30 px to the right of its centre, scaled twice by a middle object.
    core::GameObject& middle = scene().createGameObject();
    crate->addChild(middle);
    middle.setScale(2.0f);
    middle.addChild(*child);
    child->setPosition(glm::vec2{15.0f, 0.0f});
    frames(1);
    EXPECT_EQ(childBody(), crate->getComponent<Rigidbody>()->body());
    EXPECT_EQ(physics.world().bodyCount(), 1);
    EXPECT_NEAR(mass(), 0.16f + 0.16f, 1e-5f) << "the child's box scaled twice: 0.4 m square";
    const physics::Aabb box = physics.world().shapeAabb(child->getComponent<Collider>()->shape());
    const glm::vec2 crateAt = physics.world().transform(crate->getComponent<Rigidbody>()->body()).p;
    EXPECT_NEAR((box.lower.x + box.upper.x) * 0.5f - crateAt.x, 0.30f, 1e-4f);
    EXPECT_NEAR(box.upper.x - box.lower.x, 0.40f, 1e-4f);
}

TEST_F(CompoundTest, MovingTheChildMovesItsShapeOnTheBody) {
    start([&](core::Scene& s) { crateWithChild(s, {0.0f, 0.0f}); });
    const physics::Rigidbody* rb = nullptr;
    frames(1);
    rb = crate->getComponent<Rigidbody>();
    child->setPosition(glm::vec2{40.0f, 0.0f});
    child->setOrientation(0.5f);
    frames(1);
    const physics::Aabb box = physics.world().shapeAabb(child->getComponent<Collider>()->shape());
    const physics::Transform xf = physics.world().transform(rb->body());
    EXPECT_NEAR((box.lower.x + box.upper.x) * 0.5f - xf.p.x, 0.40f, 1e-4f);
    EXPECT_NEAR((box.lower.y + box.upper.y) * 0.5f - xf.p.y, 0.0f, 1e-4f);
    // A 0.2 m square turned by 0.5 rad spans 0.2 (cos 0.5 + sin 0.5).
    EXPECT_NEAR(box.upper.x - box.lower.x, 0.2f * (std::cos(0.5f) + std::sin(0.5f)), 1e-4f);
}

TEST_F(CompoundTest, RemovingTheChildColliderOrTheRigidbody) {
    start([&](core::Scene& s) { crateWithChild(s, {0.0f, 0.0f}); });
    frames(1);
    const int shapes = physics.world().shapeCount();
    child->removeComponent(child->getComponent<Collider>());
    frames(1);
    EXPECT_EQ(physics.world().shapeCount(), shapes - 1);
    EXPECT_NEAR(mass(), 0.16f, 1e-5f);
    // A new child collider rides on the crate until the crate's Rigidbody goes: then it is static.
    child->addComponent<Collider>(physics::makeBox(10.0f, 10.0f));
    frames(1);
    EXPECT_NEAR(mass(), 0.2f, 1e-5f);
    crate->removeComponent(crate->getComponent<Rigidbody>());
    frames(1);
    ASSERT_FALSE(childBody().isNull());
    EXPECT_EQ(physics.world().bodyType(childBody()), physics::BodyType::Static);
    EXPECT_EQ(physics.world().bodyCount(), 2)
        << "the crate's collider and the child's, both static";
}

TEST_F(CompoundTest, RigidbodyAddedLaterTakesItsChildrensColliders) {
    start([&](core::Scene& s) {
        crate = &s.createGameObject();
        child = &s.createGameObject();
        crate->addChild(*child);
        child->setPosition(glm::vec2{0.0f, -40.0f});
        child->addComponent<Collider>(physics::makeBox(10.0f, 10.0f));
    });
    frames(1);
    EXPECT_EQ(physics.world().bodyType(childBody()), physics::BodyType::Static);
    crate->addComponent<Rigidbody>();
    frames(1);
    EXPECT_EQ(childBody(), crate->getComponent<Rigidbody>()->body());
    EXPECT_EQ(physics.world().bodyCount(), 1);
    EXPECT_LT(crate->position().y, 0.0f) << "it falls, the child with it";
    EXPECT_NEAR(child->worldPosition().y - crate->position().y, -40.0f, 1e-3f);
}

// "Pop in from scale 0": no shape while the scale makes it degenerate, no error; the shape
// appears when the scale grows.
TEST_F(CompoundTest, ColliderScaledToNothingHasNoShapeUntilItGrows) {
    core::GameObject* coin = nullptr;
    core::GameObject* tiny = nullptr;
    start([&](core::Scene& s) {
        floor(s);
        coin = &s.createGameObject();
        coin->setName("coin");
        coin->setScale(0.0f);
        coin->setPosition(glm::vec2{0.0f, 100.0f});
        coin->addComponent<Rigidbody>();
        coin->addComponent<Collider>(physics::makeBox(20.0f, 20.0f));
        tiny = &s.createGameObject();
        tiny->setScale(1e-4f);
        tiny->addComponent<Collider>(physics::Circle{{0.0f, 0.0f}, 20.0f});
    });
    ASSERT_NO_THROW(frames(1));
    EXPECT_TRUE(coin->getComponent<Collider>()->shape().isNull());
    EXPECT_TRUE(tiny->getComponent<Collider>()->shape().isNull());
    for (int i = 1; i <= 10; ++i) {
        coin->setScale(0.1f * static_cast<float>(i));
        frames(1);
    }
    EXPECT_FALSE(coin->getComponent<Collider>()->shape().isNull());
    frames(120);
    EXPECT_NEAR(coin->position().y, -180.0f, 1.0f) << "grown to full size, it lands on the floor";
    EXPECT_NEAR(coin->getComponent<Rigidbody>()->mass(), 0.16f, 1e-5f);
}

} // namespace
