// SPDX-License-Identifier: MIT
// Rigidbody, Collider and PhysicsSystem driving game objects of a real scene.
#include <e2d/core/component.hpp>
#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/log.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/core/scene_director.hpp>
#include <e2d/core/scene_registry.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/contact_info.hpp>
#include <e2d/physics/physics_system.hpp>
#include <e2d/physics/rigidbody.hpp>

#include "component_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace e2d;
using physics::Collider;
using physics::PhysicsSystem;
using physics::Rigidbody;

using physics::test::kStep;

using Recorder = physics::test::EventLog;

// A scene run by a director with the physics system plugged in, stepped by hand; "Empty" is the
// scene a scene change goes to.
class ComponentsTest : public ::testing::Test, public physics::test::ComponentScene {
protected:
    void start(std::function<void(core::Scene&)> setup) {
        registry.add("Empty", core::SceneFunctions{});
        ComponentScene::start(std::move(setup));
    }
};

physics::Polygon box(float half) { return physics::makeBox(half, half); }

core::GameObject& ground(core::Scene& scene, PhysicsSystem& physics) {
    core::GameObject& g = scene.createGameObject();
    g.setPosition(glm::vec2{0.0f, -1.0f});
    g.addComponent<Collider>(physics, physics::makeBox(20.0f, 1.0f));
    return g;
}

TEST_F(ComponentsTest, FallingBoxComesToRestOnStaticGroundAndItsObjectFollows) {
    core::GameObject* boxObject = nullptr;
    start([&](core::Scene& s) {
        ground(s, physics);
        boxObject = &s.createGameObject();
        boxObject->setPosition(glm::vec3{0.0f, 3.0f, 7.0f});
        boxObject->addComponent<Rigidbody>(physics);
        boxObject->addComponent<Collider>(physics, box(0.5f));
    });
    frames(180);
    // Resting on the ground's top (y = 0): the centre at 0.5 m, within the soft contact's sag.
    EXPECT_NEAR(boxObject->position().y, 0.5f, 0.01f);
    EXPECT_NEAR(boxObject->position().x, 0.0f, 1e-4f);
    EXPECT_NEAR(boxObject->orientation(), 0.0f, 1e-3f);
    EXPECT_EQ(boxObject->position().z, 7.0f) << "z is draw order, physics leaves it alone";
    EXPECT_EQ(physics.world().bodyCount(), 2);
}

TEST_F(ComponentsTest, SpinningBodyWritesItsAngleBackEveryStep) {
    core::GameObject* spinner = nullptr;
    start([&](core::Scene& s) {
        spinner = &s.createGameObject();
        spinner->setPosition(glm::vec2{0.0f, 50.0f});
        physics::RigidbodyDef def;
        def.gravityScale = 0.0f;
        def.angularVelocity = 1.5f;
        def.linearVelocity = {2.0f, 0.0f};
        spinner->addComponent<Rigidbody>(physics, def);
        spinner->addComponent<Collider>(physics, box(0.5f));
    });
    for (int n = 1; n <= 30; ++n) {
        frames(1);
        // No damping, no contacts: angle w t and position v t after each fixed step.
        auto t = static_cast<float>(n * kStep);
        ASSERT_NEAR(spinner->orientation(), 1.5f * t, 1e-4f) << "frame " << n;
        ASSERT_NEAR(spinner->position().x, 2.0f * t, 1e-4f) << "frame " << n;
    }
}

TEST_F(ComponentsTest, CollisionEnterAndExitReachBothObjectsWithNormalsAwayFromEach) {
    core::GameObject* g = nullptr;
    core::GameObject* b = nullptr;
    Recorder* groundEvents = nullptr;
    Recorder* boxEvents = nullptr;
    start([&](core::Scene& s) {
        g = &ground(s, physics);
        groundEvents = g->addComponent<Recorder>();
        b = &s.createGameObject();
        b->setPosition(glm::vec2{0.0f, 1.0f});
        b->addComponent<Rigidbody>(physics);
        b->addComponent<Collider>(physics, box(0.5f));
        boxEvents = b->addComponent<Recorder>();
    });
    frames(60);
    ASSERT_EQ(boxEvents->count("enter"), 1);
    ASSERT_EQ(groundEvents->count("enter"), 1);
    const physics::ContactInfo& onBox = boxEvents->events[0].info;
    EXPECT_EQ(onBox.other, g);
    EXPECT_EQ(onBox.otherCollider, g->getComponent<Collider>());
    ASSERT_GE(onBox.pointCount, 1);
    EXPECT_NEAR(onBox.points[0].normal.y, -1.0f, 1e-4f) << "from the box towards the ground";
    const physics::ContactInfo& onGround = groundEvents->events[0].info;
    EXPECT_EQ(onGround.other, b);
    EXPECT_NEAR(onGround.points[0].normal.y, 1.0f, 1e-4f) << "from the ground towards the box";

    // Lifting the object by hand teleports its body: the contact ends.
    b->setPosition(glm::vec2{0.0f, 10.0f});
    frames(1);
    EXPECT_EQ(boxEvents->count("exit"), 1);
    EXPECT_EQ(groundEvents->count("exit"), 1);
    EXPECT_GT(b->position().y, 9.9f);
}

TEST_F(ComponentsTest, TriggerReportsEnterAndExitAndDoesNotStopTheBody) {
    core::GameObject* ball = nullptr;
    Recorder* zoneEvents = nullptr;
    Recorder* ballEvents = nullptr;
    start([&](core::Scene& s) {
        core::GameObject& zone = s.createGameObject();
        zone.setPosition(glm::vec2{0.0f, 5.0f});
        physics::ColliderDef trigger;
        trigger.isSensor = true;
        zone.addComponent<Collider>(physics, physics::makeBox(2.0f, 0.5f), trigger);
        zoneEvents = zone.addComponent<Recorder>();
        ball = &s.createGameObject();
        ball->setPosition(glm::vec2{0.0f, 8.0f});
        ball->addComponent<Rigidbody>(physics);
        ball->addComponent<Collider>(physics, physics::Circle{{0.0f, 0.0f}, 0.25f});
        ballEvents = ball->addComponent<Recorder>();
    });
    frames(90); // 1.5 s of free fall: 11 m, through the zone at y = 4.5 .. 5.5
    EXPECT_EQ(zoneEvents->count("trigger-enter"), 1);
    EXPECT_EQ(zoneEvents->count("trigger-exit"), 1);
    EXPECT_EQ(ballEvents->count("trigger-enter"), 1);
    EXPECT_EQ(ballEvents->count("trigger-exit"), 1);
    EXPECT_EQ(zoneEvents->count("enter"), 0) << "a trigger is not solid";
    EXPECT_LT(ball->position().y, 0.0f);
}

TEST_F(ComponentsTest, RigidbodyIsUniqueAndRejectsBadDefinitions) {
    start([&](core::Scene& s) {
        core::GameObject& o = s.createGameObject();
        EXPECT_NE(o.addComponent<Rigidbody>(physics), nullptr);
        EXPECT_EQ(o.addComponent<Rigidbody>(physics), nullptr);
    });
    physics::RigidbodyDef bad;
    bad.linearDamping = -1.0f;
    try {
        Rigidbody rb(physics, bad);
        FAIL() << "negative damping accepted";
    } catch (const core::Error& e) {
        EXPECT_STREQ(
            e.what(),
            "physics::Rigidbody::Rigidbody(): def.linearDamping must be finite and >= 0, got -1");
    }
    physics::RigidbodyDef staticDef;
    staticDef.type = physics::BodyType::Static;
    EXPECT_THROW(Rigidbody(physics, staticDef), core::Error);
    EXPECT_THROW(Collider(physics, physics::Circle{{0.0f, 0.0f}, -1.0f}), core::Error);
}

TEST_F(ComponentsTest, DefinitionErrorsNameTheFieldAndValue) {
    const auto message = [](auto&& make) {
        try {
            make();
        } catch (const core::Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    physics::ColliderDef def;
    def.friction = -0.5f;
    EXPECT_EQ(message([&] { Collider c(physics, box(0.5f), def); }),
              "physics::Collider::Collider(): def.friction must be finite and >= 0, got -0.5");
    def = {};
    def.density = std::nanf("");
    EXPECT_EQ(message([&] { Collider c(physics, box(0.5f), def); }),
              "physics::Collider::Collider(): def.density must be finite and >= 0, got nan");
    def = {};
    def.restitution = 1.25f;
    EXPECT_EQ(message([&] { Collider c(physics, box(0.5f), def); }),
              "physics::Collider::Collider(): def.restitution must be finite and in [0, 1], got "
              "1.25");
    physics::RigidbodyDef rb;
    rb.gravityScale = INFINITY;
    EXPECT_EQ(message([&] { Rigidbody r(physics, rb); }),
              "physics::Rigidbody::Rigidbody(): def.gravityScale must be finite, got inf");
}

TEST_F(ComponentsTest, ImpulseAndFreezeFlagsActThroughTheComponent) {
    Rigidbody* rb = nullptr;
    core::GameObject* o = nullptr;
    start([&](core::Scene& s) {
        o = &s.createGameObject();
        physics::RigidbodyDef def;
        def.gravityScale = 0.0f;
        def.lockY = true;
        def.fixedRotation = true;
        rb = o->addComponent<Rigidbody>(physics, def);
        o->addComponent<Collider>(physics, box(0.5f)); // 1 m^2 at density 1: 1 kg
    });
    frames(1);
    EXPECT_NEAR(rb->mass(), 1.0f, 1e-5f);
    rb->applyLinearImpulse({2.0f, 3.0f});                // y is frozen
    rb->applyImpulseAtPoint({0.0f, 1.0f}, {0.5f, 0.0f}); // would spin it, rotation is frozen
    frames(30);                                          // 0.5 s at 2 m/s
    EXPECT_NEAR(o->position().x, 1.0f, 0.02f);
    EXPECT_NEAR(o->position().y, 0.0f, 1e-5f);
    EXPECT_NEAR(o->orientation(), 0.0f, 1e-6f);
}

TEST_F(ComponentsTest, ColliderAddedBeforeItsRigidbodyRidesOnIt) {
    core::GameObject* o = nullptr;
    start([&](core::Scene& s) {
        o = &s.createGameObject();
        o->setPosition(glm::vec2{0.0f, 10.0f});
        o->addComponent<Collider>(physics, box(0.5f));
    });
    frames(1);
    Collider* c = o->getComponent<Collider>();
    EXPECT_EQ(physics.world().bodyType(physics.world().shapeBody(c->shape())),
              physics::BodyType::Static);
    o->addComponent<Rigidbody>(physics);
    frames(31);
    EXPECT_EQ(physics.world().bodyType(physics.world().shapeBody(c->shape())),
              physics::BodyType::Dynamic);
    EXPECT_LT(o->position().y, 9.0f) << "it falls once it has a Rigidbody";
    EXPECT_EQ(physics.world().bodyCount(), 1) << "the static body it had is gone";

    // Removing the Rigidbody leaves the collider static where the object is.
    o->removeComponent(o->getComponent<Rigidbody>());
    frames(1);
    const float y = o->position().y;
    frames(30);
    EXPECT_EQ(o->position().y, y);
    EXPECT_EQ(physics.world().bodyType(physics.world().shapeBody(c->shape())),
              physics::BodyType::Static);
}

TEST_F(ComponentsTest, ChildObjectFollowsItsBodyInWorldSpace) {
    core::GameObject* child = nullptr;
    start([&](core::Scene& s) {
        core::GameObject& parent = s.createGameObject();
        parent.setPosition(glm::vec2{5.0f, 0.0f});
        parent.setScale(glm::vec2{2.0f, 2.0f});
        child = &s.createGameObject();
        parent.addChild(*child);
        child->setPosition(glm::vec2{0.0f, 5.0f}); // world (5, 10)
        physics::RigidbodyDef def;
        def.gravityScale = 0.0f;
        def.linearVelocity = {1.0f, 0.0f};
        child->addComponent<Rigidbody>(physics, def);
        child->addComponent<Collider>(physics, physics::Circle{{0.0f, 0.0f}, 0.25f});
    });
    frames(60); // 1 s at 1 m/s in world space
    EXPECT_NEAR(child->worldPosition().x, 6.0f, 1e-3f);
    EXPECT_NEAR(child->worldPosition().y, 10.0f, 1e-3f);
    EXPECT_NEAR(child->position().x, 0.5f, 1e-3f) << "local = world through the parent's scale 2";
    // The collider was scaled with the object: radius 0.25 * 2.
    const auto& shape = physics.world().shapeGeometry(child->getComponent<Collider>()->shape());
    EXPECT_NEAR(std::get<physics::Circle>(shape).radius, 0.5f, 1e-6f);
}

TEST_F(ComponentsTest, SceneChangeEmptiesTheWorld) {
    start([&](core::Scene& s) {
        ground(s, physics);
        core::GameObject& o = s.createGameObject();
        o.addComponent<Rigidbody>(physics);
        o.addComponent<Collider>(physics, box(0.5f));
    });
    frames(2);
    EXPECT_EQ(physics.world().bodyCount(), 2);
    director.changeToScene("Empty");
    frames(1);
    EXPECT_EQ(physics.world().bodyCount(), 0);
    EXPECT_EQ(physics.world().shapeCount(), 0);
}

TEST_F(ComponentsTest, DestroyingAnObjectRemovesItsBodyAndShapes) {
    core::GameObject* o = nullptr;
    start([&](core::Scene& s) {
        o = &s.createGameObject();
        o->addComponent<Rigidbody>(physics);
        o->addComponent<Collider>(physics, box(0.5f));
        o->addComponent<Collider>(physics, physics::Circle{{0.0f, 1.0f}, 0.5f});
    });
    frames(1);
    EXPECT_EQ(physics.world().shapeCount(), 2);
    director.scene()->destroyGameObject(*o);
    frames(1);
    EXPECT_EQ(physics.world().bodyCount(), 0);
    EXPECT_EQ(physics.world().shapeCount(), 0);
}

// Destroys, through the World, the body of the object it collides with (or its own) on the
// first collision: what a game does to a projectile that hits something.
class BodyDestroyer : public core::Component, public core::Handles<physics::CollisionEnter> {
public:
    BodyDestroyer(PhysicsSystem& physics, bool own) : physics_(physics), own_(own) {}
    void on(const physics::CollisionEnter& c) override {
        core::GameObject* target = own_ ? gameObject() : c.other;
        Rigidbody* rb = target != nullptr ? target->getComponent<Rigidbody>() : nullptr;
        if (rb != nullptr && physics_.world().isValid(rb->body())) {
            physics_.world().destroyBody(rb->body());
            ++destroyed;
        }
    }
    int destroyed = 0;

private:
    PhysicsSystem& physics_;
    bool own_;
};

TEST_F(ComponentsTest, BodyDestroyedThroughTheWorldInsideACollisionEventLeavesItsObjectStill) {
    for (bool own : {true, false}) {
        SCOPED_TRACE(own ? "own body" : "the other object's body");
        core::GameObject* ball = nullptr;
        core::GameObject* floor = nullptr;
        BodyDestroyer* destroyer = nullptr;
        PhysicsSystem system;
        core::SceneRegistry reg;
        core::SceneDirector dir{reg, logger};
        reg.add("Test", core::SceneFunctions{.initialize = [&](core::Scene& s) {
                    // A dynamic floor (so the other object has a Rigidbody too), held by zero gravity.
                    floor = &s.createGameObject();
                    physics::RigidbodyDef still;
                    still.gravityScale = 0.0f;
                    floor->addComponent<Rigidbody>(system, still);
                    floor->addComponent<Collider>(system, physics::makeBox(5.0f, 0.5f));
                    ball = &s.createGameObject();
                    ball->setPosition(glm::vec2{0.0f, 2.0f});
                    physics::RigidbodyDef falling;
                    falling.linearVelocity = {0.0f, -5.0f};
                    ball->addComponent<Rigidbody>(system, falling);
                    ball->addComponent<Collider>(system, physics::Circle{{0.0f, 0.0f}, 0.25f});
                    destroyer = ball->addComponent<BodyDestroyer>(system, own);
                }});
        dir.addSystem(system);
        ASSERT_TRUE(dir.start("Test"));
        auto run = [&](int n) {
            for (int i = 0; i < n; ++i) {
                dir.applyPendingChange();
                dir.scene()->beginFrame();
                system.fixedUpdate(kStep);
            }
        };
        ASSERT_NO_THROW(run(60));
        ASSERT_EQ(destroyer->destroyed, 1);
        core::GameObject* victim = own ? ball : floor;
        Rigidbody* rb = victim->getComponent<Rigidbody>();
        // The component saw its body go: it has none, its colliders have no shapes, and its
        // object stays where the body last put it.
        EXPECT_TRUE(rb->body().isNull());
        EXPECT_TRUE(victim->getComponent<Collider>()->shape().isNull());
        EXPECT_EQ(system.world().bodyCount(), 1);
        EXPECT_EQ(system.world().shapeCount(), 1);
        const glm::vec3 where = victim->position();
        ASSERT_NO_THROW(run(10));
        EXPECT_EQ(victim->position(), where);
        // Its calls now say why they cannot work; destroying the object is still fine.
        try {
            rb->setLinearVelocity({1.0f, 0.0f});
            ADD_FAILURE() << "no error";
        } catch (const core::Error& e) {
            EXPECT_NE(std::string(e.what()).find("physics::Rigidbody::setLinearVelocity(): the "
                                                 "Rigidbody on object "),
                      std::string::npos)
                << e.what();
        }
        dir.scene()->destroyGameObject(*victim);
        ASSERT_NO_THROW(run(2));
        EXPECT_EQ(system.world().bodyCount(), 1);
    }
}

} // namespace

TEST_F(ComponentsTest, ComponentsMadeFromTheirDefAloneFindTheSystemThroughTheScene) {
    core::GameObjectId boxId;
    start([&](core::Scene& scene) {
        core::GameObject& g = scene.createGameObject();
        g.setPosition(glm::vec2{0.0f, -1.0f});
        g.addComponent<Collider>(physics::ShapeGeometry{physics::makeBox(10.0f, 1.0f)});
        core::GameObject& b = scene.createGameObject();
        b.setPosition(glm::vec2{0.0f, 3.0f});
        // The collider first: it makes the Rigidbody's body, which must find the system too.
        b.addComponent<Collider>(physics::ShapeGeometry{box(0.5f)});
        b.addComponent<Rigidbody>(physics::RigidbodyDef{});
        boxId = b.id();
    });
    core::GameObject* b = director.scene()->find(boxId);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(&b->getComponent<Rigidbody>()->system(), &physics);
    EXPECT_EQ(physics.world().bodyCount(), 2);
    frames(180);
    // At rest on the ground: its bottom (y - 0.5) on the ground's top (0), within the contact
    // overlap tolerated.
    EXPECT_NEAR(b->worldPosition().y, 0.5f, 0.02f);
}

TEST(ComponentsWithoutSystem, DefOnlyComponentsInASceneWithoutPhysicsNameTheMissingSystem) {
    core::Logger logger{core::LogLevel::Off};
    core::SceneRegistry registry;
    registry.add("Test", core::SceneFunctions{.initialize = [](core::Scene& scene) {
                     scene.createGameObject().addComponent<Rigidbody>(physics::RigidbodyDef{});
                 }});
    core::SceneDirector director{registry, logger};
    try {
        director.start("Test");
        FAIL() << "expected core::Error";
    } catch (const core::Error& e) {
        EXPECT_NE(std::string(e.what()).find("PhysicsSystem"), std::string::npos) << e.what();
    }
    const Rigidbody loose{physics::RigidbodyDef{}};
    EXPECT_THROW(static_cast<void>(loose.system()), core::Error);
}
