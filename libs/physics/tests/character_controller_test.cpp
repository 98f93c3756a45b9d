// SPDX-License-Identifier: MIT
// CharacterController on game objects of a real scene, in pixels (100 world units per metre).
#include <e2d/core/component.hpp>
#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/log.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/core/scene_director.hpp>
#include <e2d/core/scene_registry.hpp>
#include <e2d/physics/character_controller.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/contact_info.hpp>
#include <e2d/physics/physics_system.hpp>
#include <e2d/physics/rigidbody.hpp>

#include <gtest/gtest.h>

#include "component_scene.hpp"

#include <functional>
#include <string>
#include <vector>

namespace {

using namespace e2d;
using physics::CharacterController;
using physics::CharacterControllerDef;
using physics::Collider;
using physics::CollisionEnter;
using physics::CollisionExit;
using physics::ContactInfo;
using physics::PhysicsSystem;
using physics::Rigidbody;
using physics::TriggerEnter;
using physics::TriggerExit;

constexpr float kDt = 1.0f / 60.0f;
constexpr float kGravity = -1000.0f; // px/s^2
// The character stands this high above what it stands on: capsule centres 50 px above and below
// its position, radius 30, skin 1.
constexpr float kRest = 50.0f + 30.0f + 1.0f;

CharacterControllerDef pixelCharacter() {
    CharacterControllerDef def;
    def.capsule = {{0.0f, -50.0f}, {0.0f, 50.0f}, 30.0f};
    def.skin = 1.0f;
    def.maxPushOut = 10.0f;
    def.groundSnapDistance = 5.0f;
    return def;
}

class CharacterControllerTest : public ::testing::Test {
protected:
    void start(std::function<void(core::Scene&)> setup) {
        registry.add("Test", core::SceneFunctions{.initialize = setup});
        director.addSystem(physics);
        ASSERT_TRUE(director.start("Test"));
        director.scene()->beginFrame(); // components added by the setup attach here
    }
    // One fixed step as a game does it: the world steps, then the character moves by its
    // velocity plus the ground's, gravity and walking being the game's rules.
    void frames(CharacterController& c, int n, float walk) {
        for (int i = 0; i < n; ++i) {
            director.applyPendingChange();
            director.scene()->beginFrame();
            physics.fixedUpdate(kDt);
            velocity.x = walk;
            velocity.y = c.isGrounded() ? 0.0f : velocity.y + kGravity * kDt;
            c.move((velocity + c.groundVelocity()) * kDt);
            velocity = c.clipVelocity(velocity);
        }
    }

    core::Logger logger{core::LogLevel::Off};
    core::SceneRegistry registry;
    core::SceneDirector director{registry, logger};
    PhysicsSystem physics{{}, 100.0f};
    glm::vec2 velocity{0.0f, 0.0f};
};

// A static floor whose top is y = 0 px.
void floor(core::Scene& s) {
    core::GameObject& g = s.createGameObject();
    g.setPosition(glm::vec2{0.0f, -50.0f});
    g.addComponent<Collider>(physics::makeBox(5000.0f, 50.0f));
}

TEST_F(CharacterControllerTest, FallsLandsAndWalksInWorldUnitsMovingItsObjectAndBody) {
    core::GameObject* player = nullptr;
    CharacterController* controller = nullptr;
    start([&](core::Scene& s) {
        floor(s);
        player = &s.createGameObject();
        player->setPosition(glm::vec3{0.0f, 300.0f, 4.0f});
        controller = player->addComponent<CharacterController>(pixelCharacter());
    });
    ASSERT_FALSE(controller->body().isNull());
    frames(*controller, 60, 0.0f); // (300 - 81) px at 1000 px/s^2: down in 0.66 s
    EXPECT_TRUE(controller->isGrounded());
    EXPECT_NEAR(player->position().y, kRest, 0.5f);
    EXPECT_NEAR(player->position().x, 0.0f, 1e-3f);
    EXPECT_EQ(player->position().z, 4.0f);
    EXPECT_NEAR(controller->lastMove().groundPoint.y, 0.0f, 0.1f); // px, not metres

    frames(*controller, 60, 300.0f); // a second of walking at 300 px/s
    EXPECT_TRUE(controller->isGrounded());
    EXPECT_NEAR(player->position().x, 300.0f, 0.5f);
    EXPECT_NEAR(player->position().y, kRest, 0.5f);
    EXPECT_NEAR(controller->lastMove().translation.x, 5.0f, 1e-3f);
    // The body follows in metres.
    const physics::Vec2 body = physics.world().transform(controller->body()).p;
    EXPECT_NEAR(body.x, 3.0f, 0.005f);
    EXPECT_NEAR(body.y, kRest / 100.0f, 0.005f);
}

TEST_F(CharacterControllerTest, RidesAKinematicRigidbodyPlatform) {
    core::GameObject* player = nullptr;
    core::GameObject* lift = nullptr;
    CharacterController* controller = nullptr;
    start([&](core::Scene& s) {
        lift = &s.createGameObject();
        lift->setPosition(glm::vec2{0.0f, 0.0f});
        lift->addComponent<Rigidbody>(physics::RigidbodyDef{.type = physics::BodyType::Kinematic,
                                                            .linearVelocity = {120.0f, 60.0f}});
        lift->addComponent<Collider>(physics::makeBox(150.0f, 20.0f));
        player = &s.createGameObject();
        player->setPosition(glm::vec2{0.0f, 20.0f + kRest});
        controller = player->addComponent<CharacterController>(pixelCharacter());
    });
    controller->move({0.0f, 0.0f});
    ASSERT_TRUE(controller->isGrounded());
    frames(*controller, 60, 0.0f);
    EXPECT_TRUE(controller->isGrounded());
    EXPECT_NEAR(lift->position().x, 120.0f, 0.1f);
    EXPECT_NEAR(player->position().x, lift->position().x, 0.5f);
    EXPECT_NEAR(player->position().y, lift->position().y + 20.0f + kRest, 0.5f);
    EXPECT_NEAR(controller->groundVelocity().x, 120.0f, 0.01f); // px/s
    EXPECT_NEAR(controller->groundVelocity().y, 60.0f, 0.01f);
}

TEST_F(CharacterControllerTest, ItsBodyIsSolidToDynamicBodiesAndNeverBlocksItself) {
    core::GameObject* crate = nullptr;
    CharacterController* controller = nullptr;
    start([&](core::Scene& s) {
        floor(s);
        core::GameObject& player = s.createGameObject();
        player.setPosition(glm::vec2{0.0f, kRest});
        controller = player.addComponent<CharacterController>(pixelCharacter());
        crate = &s.createGameObject();
        crate->setPosition(glm::vec2{0.0f, 400.0f});
        crate->addComponent<Rigidbody>();
        crate->addComponent<Collider>(physics::makeBox(20.0f, 20.0f));
    });
    frames(*controller, 120, 0.0f);
    // The crate rests on the character's head: top of the capsule (81 + 80 px) plus its half.
    EXPECT_NEAR(crate->position().y, kRest + 80.0f + 20.0f, 2.0f);
    EXPECT_NEAR(controller->lastMove().pushedOut, 0.0f, 1e-3f);
    EXPECT_NEAR(controller->gameObject()->position().y, kRest, 0.5f);
}

TEST_F(CharacterControllerTest, AnObjectMovedByHandTeleportsTheCharacter) {
    core::GameObject* player = nullptr;
    CharacterController* controller = nullptr;
    start([&](core::Scene& s) {
        floor(s);
        player = &s.createGameObject();
        player->setPosition(glm::vec2{0.0f, kRest});
        controller = player->addComponent<CharacterController>(pixelCharacter());
    });
    frames(*controller, 2, 0.0f);
    // A solid Collider on the same object does not block its own character.
    player->addComponent<Collider>(physics::makeBox(40.0f, 40.0f));
    frames(*controller, 3, 0.0f);
    EXPECT_NEAR(player->position().x, 0.0f, 1e-3f);
    EXPECT_NEAR(player->position().y, kRest, 0.5f);
    EXPECT_NEAR(controller->lastMove().pushedOut, 0.0f, 1e-3f);
    player->setPosition(glm::vec2{700.0f, kRest});
    controller->move({10.0f, 0.0f});
    EXPECT_NEAR(player->position().x, 710.0f, 1e-2f);
    EXPECT_NEAR(controller->mover().position().x, 7.1f, 1e-4f);
}

TEST_F(CharacterControllerTest, TellsBothObjectsAboutWallsAndStaticTriggers) {
    core::GameObject* player = nullptr;
    core::GameObject* coin = nullptr;
    core::GameObject* wall = nullptr;
    CharacterController* controller = nullptr;
    physics::test::EventLog* playerLog = nullptr;
    physics::test::EventLog* coinLog = nullptr;
    physics::test::EventLog* wallLog = nullptr;
    start([&](core::Scene& s) {
        floor(s);
        coin = &s.createGameObject();
        coin->setPosition(glm::vec2{200.0f, 100.0f});
        physics::ColliderDef sensor;
        sensor.isSensor = true;
        coin->addComponent<Collider>(physics::Circle{{0.0f, 0.0f}, 20.0f}, sensor);
        coinLog = coin->addComponent<physics::test::EventLog>();
        wall = &s.createGameObject();
        wall->setPosition(glm::vec2{500.0f, 200.0f});
        wall->addComponent<Collider>(physics::makeBox(50.0f, 200.0f)); // face at x = 450
        wallLog = wall->addComponent<physics::test::EventLog>();
        player = &s.createGameObject();
        player->setPosition(glm::vec2{0.0f, kRest});
        controller = player->addComponent<CharacterController>(pixelCharacter());
        playerLog = player->addComponent<physics::test::EventLog>();
    });
    frames(*controller, 1, 0.0f);
    // Standing on the floor: one collision enter, with the floor's object.
    ASSERT_EQ(playerLog->kinds(), std::vector<std::string>{"enter"});
    EXPECT_NEAR(playerLog->events[0].info.points[0].normal.y, -1.0f, 1e-4f); // towards the floor
    playerLog->events.clear();

    frames(*controller, 90, 300.0f); // through the coin (x 200) and on to the wall (x 450)
    EXPECT_NEAR(player->position().x, 450.0f - 31.0f, 0.5f);
    ASSERT_EQ(coinLog->kinds(), (std::vector<std::string>{"trigger-enter", "trigger-exit"}));
    EXPECT_EQ(coinLog->events[0].info.other, player);
    EXPECT_EQ(coinLog->events[0].info.otherCollider, controller);
    ASSERT_EQ(wallLog->kinds(), std::vector<std::string>{"enter"});
    EXPECT_EQ(wallLog->events[0].info.other, player);
    EXPECT_NEAR(wallLog->events[0].info.points[0].normal.x, -1.0f, 1e-4f); // towards the player
    EXPECT_NEAR(wallLog->events[0].info.points[0].point.x, 450.0f, 0.1f);  // world units
    ASSERT_EQ(playerLog->kinds(),
              (std::vector<std::string>{"trigger-enter", "trigger-exit", "enter"}));
    EXPECT_EQ(playerLog->events[0].info.other, coin);
    EXPECT_EQ(playerLog->events[2].info.other, wall);

    frames(*controller, 10, -300.0f); // and away from it
    EXPECT_EQ(wallLog->kinds(), (std::vector<std::string>{"enter", "exit"}));
}

TEST(CharacterControllerErrors, NameTheComponentTheFieldAndTheValue) {
    CharacterControllerDef def = pixelCharacter();
    def.skin = 40.0f;
    try {
        CharacterController c(def);
        FAIL() << "no error";
    } catch (const core::Error& e) {
        EXPECT_STREQ(e.what(), "physics::CharacterController::CharacterController(): def.skin must "
                               "be finite and in [0, capsule.radius = 30], got 40");
    }
    CharacterController outside(pixelCharacter());
    try {
        outside.move({1.0f, 0.0f});
        FAIL() << "no error";
    } catch (const core::Error& e) {
        EXPECT_STREQ(e.what(),
                     "physics::CharacterController::move(): the object is not in a scene yet");
    }
}

} // namespace
