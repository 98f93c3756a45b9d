// SPDX-License-Identifier: MIT
// World::setTargetTransform(): kinematic bodies following a path by velocity.
#include <e2d/core/error.hpp>
#include <e2d/physics/world.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace e2d::physics {
namespace {

constexpr float kDt = 1.0f / 60.0f;

BodyId kinematicBox(World& world, Vec2 position, float angle = 0.0f) {
    BodyDef bd;
    bd.type = BodyType::Kinematic;
    bd.position = position;
    bd.angle = angle;
    BodyId id = world.createBody(bd);
    world.createShape(id, {}, makeOffsetBox(1.0f, 0.25f, {0.3f, 0.1f}, 0.0f));
    return id;
}

TEST(WorldTargetTransform, AKinematicBodyArrivesWhereItWasSentAfterEachStep) {
    World world;
    BodyId lift = kinematicBox(world, {0.0f, 0.0f});
    for (int i = 1; i <= 240; ++i) {
        const float t = static_cast<float>(i) * kDt;
        const Vec2 target{3.0f * std::sin(t), 2.0f * t};
        const float angle = 0.5f * std::sin(2.0f * t);
        world.setTargetTransform(lift, target, angle, kDt);
        world.step(kDt);
        const Transform xf = world.transform(lift);
        ASSERT_NEAR(xf.p.x, target.x, 1e-4f) << i;
        ASSERT_NEAR(xf.p.y, target.y, 1e-4f) << i;
        ASSERT_NEAR(xf.q.angle(), angle, 1e-4f) << i;
    }
}

TEST(WorldTargetTransform, TurnsTheShortWayAcrossPi) {
    World world;
    BodyId door = kinematicBox(world, {1.0f, 1.0f}, 3.1f);
    world.setTargetTransform(door, {1.0f, 1.0f}, -3.1f, kDt);
    // From 3.1 to -3.1 rad is 0.083 rad counter-clockwise, not 6.2 rad clockwise.
    EXPECT_NEAR(world.angularVelocity(door), (2.0f * 3.14159265f - 6.2f) / kDt, 1e-2f);
    world.step(kDt);
    EXPECT_NEAR(std::remainder(world.transform(door).q.angle() + 3.1f, 2.0f * 3.14159265f), 0.0f,
                1e-4f);
}

TEST(WorldTargetTransform, CarriesABoxStandingOnAPlatform) {
    World world;
    BodyId platform = kinematicBox(world, {0.0f, 0.0f});
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = {0.3f, 0.85f};
    BodyId box = world.createBody(bd);
    world.createShape(box, {}, makeBox(0.5f, 0.5f));
    for (int i = 0; i < 60; ++i) { // settle
        world.setTargetTransform(platform, {0.0f, 0.0f}, 0.0f, kDt);
        world.step(kDt);
    }
    const float startX = world.transform(box).p.x;
    // 2 m right in 2 s along a smoothstep (peak acceleration 3 m/s^2, below what friction 0.6
    // under 10 m/s^2 holds, so the box does not slip), then up 1 m.
    for (int i = 1; i <= 120; ++i) {
        const float u = static_cast<float>(i) / 120.0f;
        world.setTargetTransform(platform, {2.0f * u * u * (3.0f - 2.0f * u), 0.0f}, 0.0f, kDt);
        world.step(kDt);
    }
    for (int i = 1; i <= 60; ++i) {
        world.setTargetTransform(platform, {2.0f, static_cast<float>(i) / 60.0f}, 0.0f, kDt);
        world.step(kDt);
    }
    EXPECT_NEAR(world.transform(box).p.x - startX, 2.0f, 0.01f);
    EXPECT_NEAR(world.transform(box).p.y, 1.85f, 0.03f);
}

TEST(WorldTargetTransform, RejectsStaticBodiesAndBadInput) {
    World world;
    BodyId ground = world.createBody({});
    BodyId lift = kinematicBox(world, {0.0f, 0.0f});
    auto message = [&](BodyId id, Vec2 p, float angle, float dt) {
        try {
            world.setTargetTransform(id, p, angle, dt);
        } catch (const core::Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message(ground, {0, 0}, 0, kDt),
              "physics::World::setTargetTransform(): the body is static (it never moves)");
    EXPECT_EQ(message(lift, {0, 0}, 0, 0.0f),
              "physics::World::setTargetTransform(): timeStep must be finite and > 0, got 0");
    EXPECT_NE(message(lift, {NAN, 0}, 0, kDt).find("position must be finite"), std::string::npos);
    EXPECT_NE(message(lift, {0, 0}, INFINITY, kDt).find("angle must be finite"), std::string::npos);
    EXPECT_EQ(world.linearVelocity(lift).x, 0.0f); // unchanged by the failed calls
}

} // namespace
} // namespace e2d::physics
