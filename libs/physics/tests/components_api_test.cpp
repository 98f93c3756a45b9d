// SPDX-License-Identifier: MIT
// What the components let a game do: use a Rigidbody right after addComponent, drive kinematic
// bodies on a path, filter contacts per collider (one-way platforms), hear sensors, query the
// world in world units, and read contacts as they are after the step.
#include "component_scene.hpp"

#include <e2d/core/error.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/rigidbody.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

using namespace e2d;
using physics::Collider;
using physics::ColliderDef;
using physics::ContactInfo;
using physics::Rigidbody;
using physics::RigidbodyDef;
using physics::test::ComponentScene;
using physics::test::EventLog;

class ComponentsApiTest : public ::testing::Test, public ComponentScene {
protected:
    ComponentsApiTest() : ComponentScene(100.0f, weightless()) {}
    static physics::WorldDef weightless() {
        physics::WorldDef def;
        def.gravity = {0.0f, 0.0f};
        return def;
    }
};

// One rule: everything a Rigidbody offers works right after addComponent, like
// SpriteRenderer::setTint; it happens when the body is made.
TEST_F(ComponentsApiTest, RigidbodyUsedRightAfterAddComponentActsWhenTheBodyIsMade) {
    Rigidbody* rb = nullptr;
    Rigidbody* pushed = nullptr;
    start([&](core::Scene& s) {
        core::GameObject& o = s.createGameObject();
        rb = o.addComponent<Rigidbody>();
        rb->setLinearVelocity({300.0f, 0.0f});
        rb->setAngularVelocity(2.0f);
        rb->setFixedRotation(false);
        rb->setGravityScale(0.5f);
        EXPECT_EQ(rb->linearVelocity(), glm::vec2(300.0f, 0.0f)) << "answered from the def";
        EXPECT_EQ(rb->gravityScale(), 0.5f);
        EXPECT_EQ(rb->mass(), 0.0f) << "no body to weigh yet";
        o.addComponent<Collider>(physics::makeBox(50.0f, 50.0f));
        core::GameObject& p = s.createGameObject();
        p.setPosition(glm::vec2{0.0f, 500.0f});
        pushed = p.addComponent<Rigidbody>();
        p.addComponent<Collider>(physics::makeBox(50.0f, 50.0f)); // 1 kg
        pushed->applyLinearImpulse({0.0f, 2.0f * 100.0f});        // 2 kg*m/s in units
        pushed->applyLinearImpulse({100.0f, 0.0f});
    });
    frames(1);
    EXPECT_TRUE(rb->body().isNull() == false);
    EXPECT_NEAR(rb->linearVelocity().x, 300.0f, 1e-3f);
    EXPECT_NEAR(rb->angularVelocity(), 2.0f, 1e-5f);
    EXPECT_NEAR(physics.world().gravityScale(rb->body()), 0.5f, 0.0f);
    EXPECT_NEAR(rb->gameObject()->position().x, 300.0f / 60.0f, 1e-3f);
    EXPECT_NEAR(pushed->linearVelocity().x, 100.0f, 1e-3f) << "1 kg pushed by 1 kg*m/s";
    EXPECT_NEAR(pushed->linearVelocity().y, 200.0f, 1e-3f);
    // Once the body is gone there is nothing to queue for: a clear error.
    Rigidbody* other = pushed;
    physics.world().destroyBody(other->body());
    frames(1);
    try {
        other->setLinearVelocity({1.0f, 0.0f});
        FAIL() << "no error";
    } catch (const core::Error& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "physics::Rigidbody::setLinearVelocity(): the Rigidbody on object "),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(other->applyLinearImpulse({std::nanf(""), 0.0f}), core::Error);
}

// A kinematic platform on a path through setTargetTransform: it is where the path says after
// each step, and carries a box standing on it.
TEST_F(ComponentsApiTest, KinematicTargetFollowsAPathAndCarriesWhatStandsOnIt) {
    physics::WorldDef def;
    ComponentScene scene2(100.0f, def);
    core::GameObject* lift = nullptr;
    core::GameObject* box = nullptr;
    scene2.start([&](core::Scene& s) {
        lift = &s.createGameObject();
        lift->addComponent<Rigidbody>(RigidbodyDef{.type = physics::BodyType::Kinematic});
        lift->addComponent<Collider>(physics::makeBox(100.0f, 10.0f));
        box = &s.createGameObject();
        box->setPosition(glm::vec2{0.0f, 30.0f});
        box->addComponent<Rigidbody>();
        box->addComponent<Collider>(physics::makeBox(20.0f, 20.0f));
    });
    scene2.frames(30); // the box settles on the lift
    const float rest = box->position().y;
    for (int i = 1; i <= 60; ++i) {
        const glm::vec2 target{0.0f, 2.0f * static_cast<float>(i)};
        lift->getComponent<Rigidbody>()->setTargetTransform(target, 0.0f);
        scene2.frames(1);
        ASSERT_NEAR(lift->position().y, target.y, 1e-3f) << "step " << i;
    }
    EXPECT_NEAR(box->position().y - rest, 120.0f, 2.0f) << "carried up with the lift";
    EXPECT_THROW(lift->getComponent<Rigidbody>()->setTargetTransform({0.0f, std::nanf("")}, 0.0f),
                 core::Error);
}

// One-way platform: a box shot up from below passes through it and lands on it.
TEST_F(ComponentsApiTest, OneWayColliderLetsThroughFromBelowAndHoldsFromAbove) {
    ComponentScene world(100.0f);
    core::GameObject* box = nullptr;
    world.start([&](core::Scene& s) {
        core::GameObject& plank = s.createGameObject();
        plank.setPosition(glm::vec2{0.0f, 100.0f});
        plank.addComponent<Collider>(physics::makeBox(200.0f, 5.0f), ColliderDef{.oneWay = true});
        box = &s.createGameObject();
        box->addComponent<Rigidbody>()->setLinearVelocity({0.0f, 700.0f});
        box->addComponent<Collider>(physics::makeBox(20.0f, 20.0f));
    });
    float highest = 0.0f;
    for (int i = 0; i < 150; ++i) {
        world.frames(1);
        highest = std::max(highest, box->position().y);
    }
    EXPECT_GT(highest, 125.0f) << "it went up through the plank";
    EXPECT_NEAR(box->position().y, 125.0f, 1.0f) << "and rests on top of it";
}

// A collider's own rule: a pre-solve that refuses everything lets a box fall through the floor;
// it sees the contact in world units with the normal pointing away from the floor.
TEST_F(ComponentsApiTest, PreSolveRuleSeesTheContactInWorldUnitsAndCanRefuseIt) {
    ComponentScene world(100.0f);
    core::GameObject* box = nullptr;
    int calls = 0;
    glm::vec2 normal{0.0f};
    world.start([&](core::Scene& s) {
        core::GameObject& floor = s.createGameObject();
        floor.addComponent<Collider>(
            physics::makeBox(200.0f, 10.0f), ColliderDef{.preSolve = [&](const ContactInfo& c) {
                if (++calls == 1) { // the first touch, on the floor's top
                    normal = c.points[0].normal;
                    EXPECT_EQ(c.other, box);
                    EXPECT_NEAR(c.points[0].point.y, 10.0f, 3.0f) << "units";
                }
                return false;
            }});
        box = &s.createGameObject();
        box->setPosition(glm::vec2{0.0f, 40.0f});
        box->addComponent<Rigidbody>();
        box->addComponent<Collider>(physics::makeBox(20.0f, 20.0f));
    });
    world.frames(60);
    EXPECT_GT(calls, 0);
    EXPECT_NEAR(normal.y, 1.0f, 1e-4f) << "from the floor towards the box";
    EXPECT_LT(box->position().y, -100.0f) << "the floor let it through";
}

// Contacts as they are when the event arrives: the box resting on the floor touches it
// (separation about 0 in world units, at the floor's top), not the narrow phase's view from
// before the step.
TEST_F(ComponentsApiTest, CollisionEnterReportsTheManifoldAfterTheStepInWorldUnits) {
    ComponentScene world(100.0f);
    EventLog* log = nullptr;
    core::GameObject* box = nullptr;
    world.start([&](core::Scene& s) {
        core::GameObject& floor = s.createGameObject();
        floor.addComponent<Collider>(physics::makeBox(200.0f, 10.0f));
        box = &s.createGameObject();
        box->setPosition(glm::vec2{0.0f, 60.0f});
        box->addComponent<Rigidbody>()->setLinearVelocity({0.0f, -300.0f});
        box->addComponent<Collider>(physics::makeBox(20.0f, 20.0f));
        log = box->addComponent<EventLog>();
    });
    world.frames(30);
    ASSERT_EQ(log->count("enter"), 1);
    const ContactInfo& c = log->events[0].info;
    ASSERT_EQ(c.pointCount, 2);
    const float bottom = box->position().y - 20.0f;
    for (int i = 0; i < 2; ++i) {
        const physics::ContactPoint& p = c.points[static_cast<std::size_t>(i)];
        EXPECT_NEAR(p.normal.y, -1.0f, 1e-4f) << "away from the box";
        EXPECT_NEAR(p.separation, 0.0f, 1.5f) << "world units, after the step";
        EXPECT_NEAR(p.point.y, 10.0f, 1.5f);
    }
    EXPECT_NEAR(bottom, 10.0f, 1.5f);
}

// Sensors reach components: a trigger zone hears a kinematic body when it asks to.
TEST_F(ComponentsApiTest, SensorSeesAKinematicBodyWhenAskedTo) {
    EventLog* zone = nullptr;
    EventLog* blind = nullptr;
    start([&](core::Scene& s) {
        core::GameObject& z = s.createGameObject();
        z.addComponent<Collider>(physics::makeBox(50.0f, 50.0f),
                                 ColliderDef{.isSensor = true, .sensorSeesNonDynamic = true});
        zone = z.addComponent<EventLog>();
        core::GameObject& b = s.createGameObject();
        b.addComponent<Collider>(physics::makeBox(50.0f, 50.0f), ColliderDef{.isSensor = true});
        blind = b.addComponent<EventLog>();
        core::GameObject& mover = s.createGameObject();
        mover.setPosition(glm::vec2{-300.0f, 0.0f});
        mover.addComponent<Rigidbody>(
            RigidbodyDef{.type = physics::BodyType::Kinematic, .linearVelocity = {600.0f, 0.0f}});
        mover.addComponent<Collider>(physics::makeBox(10.0f, 10.0f));
    });
    frames(60);
    EXPECT_EQ(zone->count("trigger-enter"), 1);
    EXPECT_EQ(zone->count("trigger-exit"), 1);
    EXPECT_EQ(blind->count("trigger-enter"), 0) << "sensors see dynamic bodies only by default";
}

// Queries in world units, answered with the colliders' shapes.
TEST_F(ComponentsApiTest, QueriesTakeAndGiveWorldUnits) {
    Collider* wall = nullptr;
    start([&](core::Scene& s) {
        core::GameObject& w = s.createGameObject();
        w.setPosition(glm::vec2{300.0f, 0.0f});
        wall = w.addComponent<Collider>(physics::makeBox(10.0f, 100.0f));
    });
    frames(1);
    const auto ray = physics.castRayClosest({0.0f, 0.0f}, {1000.0f, 0.0f});
    ASSERT_TRUE(ray);
    EXPECT_NEAR(ray->point.x, 290.0f, 1e-3f);
    EXPECT_EQ(physics.collider(ray->shape), wall);
    EXPECT_EQ(physics.overlapPoint({305.0f, 50.0f}).size(), 1u);
    EXPECT_TRUE(physics.overlapPoint({250.0f, 50.0f}).empty());
    EXPECT_EQ(physics.overlapAabb({{280.0f, 90.0f}, {295.0f, 95.0f}}).size(), 1u);
    EXPECT_EQ(
        physics.overlapShape(physics::Circle{{0.0f, 0.0f}, 15.0f}, {280.0f, 0.0f}, 0.0f).size(),
        1u);
    const auto cast = physics.castShape(physics::Circle{{0.0f, 0.0f}, 20.0f}, {0.0f, 0.0f}, 0.0f,
                                        {1000.0f, 0.0f});
    ASSERT_TRUE(cast);
    EXPECT_NEAR(cast->point.x, 290.0f, 0.5f);
    EXPECT_NEAR(cast->fraction, 0.27f, 0.002f);
}

// Gravity is given to the World in m/s^2 and read and set through the system in world units.
TEST(PhysicsSystemUnits, GravityInWorldUnitsIsTheWorldsTimesUnitsPerMetre) {
    physics::PhysicsSystem system{physics::WorldDef{.gravity = {0.0f, -9.81f}}, 100.0f};
    EXPECT_FLOAT_EQ(system.gravity().y, -981.0f);
    system.setGravity({0.0f, -500.0f});
    EXPECT_FLOAT_EQ(system.world().gravity().y, -5.0f);
}

} // namespace
