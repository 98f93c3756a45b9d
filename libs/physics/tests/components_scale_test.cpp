// SPDX-License-Identifier: MIT
// PhysicsSystem's unitsPerMetre: components speak world units, the World metres. A scene built at
// 100 units per metre, with every length, speed, force and torque 100 (or 100^2) times larger,
// must move exactly as the same scene at 1 unit per metre, its positions 100 times larger.
#include <e2d/core/component.hpp>
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

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>
#include <vector>

namespace {

using namespace e2d;
using physics::Collider;
using physics::PhysicsSystem;
using physics::Rigidbody;

constexpr double kStep = 1.0 / 60.0;

class FirstContact : public core::Component, public core::Handles<physics::CollisionEnter> {
public:
    void on(const physics::CollisionEnter& c) override {
        if (!info) {
            info = c;
        }
    }
    std::optional<physics::ContactInfo> info;
};

// What one run reads back, in its own world units.
struct Outcome {
    std::vector<glm::vec3> poses; // x, y, angle of box, ball and pendulum after every step
    glm::vec2 boxVelocity{0.0f};
    glm::vec2 contactPoint{0.0f};
    float contactSeparation = 0.0f;
    glm::vec2 rayPoint{0.0f};
    glm::vec2 reaction{0.0f};
    float ballStartY = 0.0f;
    float ballY = 0.0f;
    float boxMass = 0.0f;
};

// The scene at `s` units per metre: every length given in metres times s.
Outcome simulate(float s, int steps) {
    core::Logger logger{core::LogLevel::Off};
    core::SceneRegistry registry;
    core::SceneDirector director{registry, logger};
    physics::WorldDef worldDef; // metres: gravity -10 m/s^2 whatever the scale
    worldDef.gravity = {0.0f, -10.0f};
    PhysicsSystem physics{worldDef, s};
    core::GameObject* box = nullptr;
    core::GameObject* ball = nullptr;
    core::GameObject* bob = nullptr;
    FirstContact* contact = nullptr;
    registry.add("Scaled", core::SceneFunctions{.initialize = [&](core::Scene& scene) {
                     core::GameObject& ground = scene.createGameObject();
                     ground.setPosition(glm::vec2{0.0f, -1.0f * s});
                     ground.addComponent<Collider>(physics::makeBox(20.0f * s, 1.0f * s));

                     box = &scene.createGameObject();
                     box->setPosition(glm::vec2{0.5f * s, 3.0f * s});
                     box->setOrientation(0.25f);
                     physics::RigidbodyDef boxDef;
                     boxDef.linearVelocity = {1.0f * s, 0.0f};
                     boxDef.angularVelocity = 0.5f;
                     box->addComponent<Rigidbody>(boxDef);
                     box->addComponent<Collider>(physics::makeBox(0.5f * s, 0.25f * s));
                     contact = box->addComponent<FirstContact>();

                     ball = &scene.createGameObject();
                     ball->setPosition(glm::vec2{-4.0f * s, 6.0f * s});
                     ball->addComponent<Rigidbody>();
                     ball->addComponent<Collider>(
                         physics::Circle{{0.0f, 0.0f}, 0.5f * s},
                         physics::ColliderDef{.density = 2.0f, .restitution = 0.5f});

                     // A pendulum hung from the world point (6, 5) m, its bob 1 m to the right.
                     bob = &scene.createGameObject();
                     bob->setPosition(glm::vec2{7.0f * s, 5.0f * s});
                     bob->addComponent<Rigidbody>();
                     bob->addComponent<Collider>(physics::Circle{{0.0f, 0.0f}, 0.25f * s});
                     physics::RevoluteJointDef hinge;
                     hinge.localAnchorA = {6.0f * s, 5.0f * s};
                     hinge.localAnchorB = {-1.0f * s, 0.0f};
                     bob->addComponent<physics::JointComponent>(
                         physics, physics::JointComponentDef{hinge, {}});
                 }});
    director.addSystem(physics);
    EXPECT_TRUE(director.start("Scaled"));
    Outcome run;
    Rigidbody* ballBody = nullptr;
    Rigidbody* boxBody = nullptr;
    for (int i = 0; i < steps; ++i) {
        director.applyPendingChange();
        director.scene()->beginFrame(); // components attach here
        if (i == 0) {
            ballBody = ball->getComponent<Rigidbody>();
            boxBody = box->getComponent<Rigidbody>();
            run.ballStartY = ball->position().y;
            run.boxMass = boxBody->mass();
        }
        if (i == 10) {
            // kg*units/s, kg*units/s^2, kg*units^2/s^2 and kg*units^2/s.
            ballBody->applyLinearImpulse({2.0f * s, 0.0f});
            boxBody->applyAngularImpulse(0.125f * s * s);
        }
        if (i >= 20 && i < 40) {
            ballBody->applyForce({0.0f, 4.0f * s});
            ballBody->applyTorque(0.5f * s * s);
            boxBody->applyForceAtPoint({3.0f * s, 0.0f},
                                       glm::vec2(box->position()) + glm::vec2{0.0f, 0.25f * s});
        }
        physics.fixedUpdate(kStep);
        for (core::GameObject* o : {box, ball, bob}) {
            run.poses.emplace_back(o->position().x, o->position().y, o->orientation());
        }
        if (i == 29) {
            run.ballY = ball->position().y;
        }
    }
    run.boxVelocity = boxBody->linearVelocity();
    if (contact->info && contact->info->pointCount > 0) {
        run.contactPoint = contact->info->points[0].point;
        run.contactSeparation = contact->info->points[0].separation;
    }
    // Straight down onto the box from 10 m up.
    const glm::vec2 from = glm::vec2(box->position()) + glm::vec2{0.0f, 10.0f * s};
    if (const auto hit = physics.castRayClosest(from, {0.0f, -20.0f * s})) {
        run.rayPoint = hit->point;
    }
    run.reaction = bob->getComponent<physics::JointComponent>()->reactionForce();
    return run;
}

TEST(PhysicsScale, SceneAtHundredUnitsPerMetreMovesExactlyLikeTheSameSceneInMetres) {
    constexpr int kSteps = 150;
    const Outcome metres = simulate(1.0f, kSteps);
    const Outcome units = simulate(100.0f, kSteps);
    ASSERT_EQ(metres.poses.size(), units.poses.size());
    float largest = 0.0f;
    for (std::size_t i = 0; i < metres.poses.size(); ++i) {
        // A hundredth of a millimetre, in case a polygon's hull is rebuilt from scaled points.
        ASSERT_NEAR(units.poses[i].x, 100.0f * metres.poses[i].x, 1e-3f) << "sample " << i;
        ASSERT_NEAR(units.poses[i].y, 100.0f * metres.poses[i].y, 1e-3f) << "sample " << i;
        ASSERT_NEAR(units.poses[i].z, metres.poses[i].z, 1e-5f) << "angle, sample " << i;
        largest = std::max(largest, std::fabs(metres.poses[i].x - metres.poses[0].x));
    }
    EXPECT_GT(largest, 1.0f) << "the scene must actually move";
    // Masses are kg at any scale (density is per square metre).
    EXPECT_NEAR(units.boxMass, metres.boxMass, 1e-6f);
    EXPECT_NEAR(metres.boxMass, 1.0f * 0.5f, 1e-6f) << "1 kg/m^2 times 1 m x 0.5 m";
    // Reads back in world units.
    EXPECT_NEAR(units.boxVelocity.x, 100.0f * metres.boxVelocity.x, 1e-3f);
    EXPECT_NEAR(units.boxVelocity.y, 100.0f * metres.boxVelocity.y, 1e-3f);
    ASSERT_NE(metres.contactPoint, glm::vec2(0.0f)) << "the box touched the ground";
    EXPECT_NEAR(units.contactPoint.x, 100.0f * metres.contactPoint.x, 1e-3f);
    EXPECT_NEAR(units.contactPoint.y, 100.0f * metres.contactPoint.y, 1e-3f);
    EXPECT_NEAR(units.contactSeparation, 100.0f * metres.contactSeparation, 1e-3f);
    ASSERT_NE(metres.rayPoint, glm::vec2(0.0f)) << "the ray hit the box";
    EXPECT_NEAR(units.rayPoint.x, 100.0f * metres.rayPoint.x, 1e-3f);
    EXPECT_NEAR(units.rayPoint.y, 100.0f * metres.rayPoint.y, 1e-3f);
    EXPECT_GT(std::hypot(metres.reaction.x, metres.reaction.y), 0.05f) << "the hinge holds the bob";
    EXPECT_NEAR(units.reaction.x, 100.0f * metres.reaction.x, 1e-2f);
    EXPECT_NEAR(units.reaction.y, 100.0f * metres.reaction.y, 1e-2f);
}

TEST(PhysicsScale, GravityInMetresFallsAHundredUnitsPerMetreAtThatScale) {
    // The ball from first principles: free fall at -10 m/s^2 for 20 steps (1/3 s; the impulse
    // at step 10 is horizontal), then 10 steps (1/6 s) with the upward 4 N on its
    // 2 kg/m^2 * pi * (0.5 m)^2 mass. It touches nothing meanwhile. Semi-implicit Euler at the
    // soft step's 1/240 s substeps falls about g h t / 2 = 1 cm further in half a second than the
    // continuous answer: 1 unit here, where a scale left out would be off by 120.
    const Outcome units = simulate(100.0f, 30);
    const double t1 = 20 * kStep;
    const double t2 = 10 * kStep;
    const double mass = 2.0 * 3.14159265358979 * 0.25;
    const double a = -10.0 + 4.0 / mass;
    const double v1 = -10.0 * t1;
    const double metres = -10.0 * t1 * t1 / 2.0 + v1 * t2 + a * t2 * t2 / 2.0;
    EXPECT_NEAR(units.ballY - units.ballStartY, 100.0 * metres, 1.5) << "units; metres: " << metres;
}

TEST(PhysicsScale, UnitsPerMetreMustBeFiniteAndPositive) {
    for (float bad : {0.0f, -2.0f, NAN, INFINITY}) {
        try {
            PhysicsSystem system{physics::WorldDef{}, bad};
            FAIL() << "accepted " << bad;
        } catch (const core::Error& e) {
            EXPECT_NE(std::string(e.what()).find(
                          "physics::PhysicsSystem::PhysicsSystem(): unitsPerMetre must "
                          "be finite and > 0, got "),
                      std::string::npos)
                << e.what();
        }
    }
}

TEST(PhysicsScale, JointDefsAreCheckedInMetresAfterScaling) {
    // A 0.3-unit distance joint is 3 mm at 100 units per metre: below the 5 mm minimum.
    PhysicsSystem system{physics::WorldDef{}, 100.0f};
    physics::DistanceJointDef rope;
    rope.length = 0.3f;
    try {
        physics::JointComponent joint{system, physics::JointComponentDef{rope, {}}};
        FAIL() << "accepted a 3 mm joint";
    } catch (const core::Error& e) {
        EXPECT_NE(std::string(e.what()).find("length"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(
                      "(in metres: the def's world units divided by unitsPerMetre 100)"),
                  std::string::npos)
            << e.what();
    }
    rope.length = 30.0f; // 0.3 m
    EXPECT_NO_THROW((physics::JointComponent{system, physics::JointComponentDef{rope, {}}}));
    // The default maxLength (kHuge, no limit) stays valid at any scale.
    PhysicsSystem small{physics::WorldDef{}, 0.5f};
    EXPECT_NO_THROW((physics::JointComponent{small, physics::JointComponentDef{rope, {}}}));
}

} // namespace
