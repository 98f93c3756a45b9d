// SPDX-License-Identifier: MIT
// Hooks a game needs: pre-solve (one-way platforms), the pair filter, per-shape event
// switches and body move events.
#include <e2d/physics/world.hpp>

#include "world_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace e2d::physics {
namespace {

constexpr float kDt = 1.0f / 60.0f;

BodyId makeBox(World& world, Vec2 position, Vec2 velocity = {0.0f, 0.0f}, const ShapeDef& sd = {}) {
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = position;
    bd.linearVelocity = velocity;
    BodyId id = world.createBody(bd);
    world.createShape(id, sd, physics::makeBox(0.5f, 0.5f));
    return id;
}

BodyId makeGround(World& world, const ShapeDef& sd = {}) {
    BodyId ground = world.createBody({});
    world.createShape(ground, sd, makeOffsetBox(20.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    return ground;
}

// A platform 0.2 m thick whose top is at y = 5, and a box jumping up through it from below.
struct Jump {
    float highest = -1e9f;
    float finalY = 0.0f;
    float finalVy = 0.0f;
    int preSolveCalls = 0;
};

Jump jumpThroughPlatform(bool oneWay) {
    World world;
    makeGround(world);
    BodyId platformBody = world.createBody({});
    ShapeId platform =
        world.createShape(platformBody, {}, makeOffsetBox(3.0f, 0.1f, {0.0f, 4.9f}, 0.0f));
    BodyId box = makeBox(world, {0.0f, 2.0f}, {0.0f, 10.0f}); // rises 5 m: to y = 7
    Jump jump;
    if (oneWay) {
        world.setPreSolveCallback([&](ShapeId a, ShapeId b, const Manifold& m) {
            ++jump.preSolveCalls;
            if (a != platform && b != platform) {
                return true;
            }
            // The normal from the platform to the other shape must point up, and the other
            // shape must not have sunk into the platform (it comes from below).
            const float up = a == platform ? m.normal.y : -m.normal.y;
            if (up < 0.7f) {
                return false;
            }
            for (int i = 0; i < m.pointCount; ++i) {
                if (m.points[i].separation < -0.05f) {
                    return false;
                }
            }
            return true;
        });
    }
    for (int i = 0; i < 240; ++i) {
        world.step(kDt);
        jump.highest = std::max(jump.highest, world.transform(box).p.y);
    }
    jump.finalY = world.transform(box).p.y;
    jump.finalVy = world.linearVelocity(box).y;
    return jump;
}

TEST(WorldHooks, OneWayPlatformLetsABodyJumpUpThroughAndLandOnIt) {
    Jump oneWay = jumpThroughPlatform(true);
    EXPECT_GT(oneWay.preSolveCalls, 0);
    EXPECT_GT(oneWay.highest, 6.5f);         // went up through the platform (to about 7 m)
    EXPECT_NEAR(oneWay.finalY, 5.5f, 0.02f); // and landed on top of it
    EXPECT_NEAR(oneWay.finalVy, 0.0f, 0.01f);
    // Without the callback the platform's underside stops it: its top stays below y = 4.8.
    Jump solid = jumpThroughPlatform(false);
    EXPECT_LT(solid.highest, 4.8f - 0.5f + 0.02f);
    EXPECT_NEAR(solid.finalY, 0.5f, 0.02f);
}

TEST(WorldHooks, PreSolveSeesEachTouchingContactOnceAndAnEmptyFunctionRemovesIt) {
    World world;
    makeGround(world);
    BodyId a = makeBox(world, {-2.0f, 0.5f});
    BodyId b = makeBox(world, {2.0f, 0.5f});
    int calls = 0;
    world.setPreSolveCallback([&](ShapeId sa, ShapeId sb, const Manifold& m) {
        ++calls;
        EXPECT_GT(m.pointCount, 0);
        BodyId ba = world.shapeBody(sa);
        BodyId bb = world.shapeBody(sb);
        EXPECT_TRUE(ba == a || ba == b || bb == a || bb == b);
        return true;
    });
    world.step(kDt);
    EXPECT_EQ(calls, 2);
    world.setPreSolveCallback({});
    world.step(kDt);
    EXPECT_EQ(calls, 2);
}

TEST(WorldHooks, PairFilterKeepsChosenShapesApart) {
    World world;
    BodyId ground = makeGround(world);
    ShapeId groundShape = world.bodyShapes(ground).front();
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = {-2.0f, 2.0f};
    BodyId ghost = world.createBody(bd);
    ShapeDef ghostDef;
    ghostDef.userData = 42;
    ShapeId ghostShape = world.createShape(ghost, ghostDef, physics::makeBox(0.5f, 0.5f));
    BodyId solid = makeBox(world, {2.0f, 2.0f});
    int calls = 0;
    world.setPairFilterCallback([&](ShapeId x, ShapeId y) {
        ++calls;
        return world.shapeUserData(x) != 42 && world.shapeUserData(y) != 42;
    });
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
    }
    EXPECT_GT(calls, 0);
    EXPECT_LT(world.transform(ghost).p.y, -5.0f); // fell through the ground
    EXPECT_NEAR(world.transform(solid).p.y, 0.5f, 0.02f);
    bool ghostPaired = false;
    world.forEachCandidatePair([&](ShapeId x, ShapeId y) {
        ghostPaired = ghostPaired || x == ghostShape || y == ghostShape;
    });
    EXPECT_FALSE(ghostPaired);
    (void)groundShape;
}

float bulletThroughWall(bool filtered) {
    World world;
    BodyId wallBody = world.createBody({});
    ShapeDef wallDef;
    wallDef.userData = 1;
    world.createShape(wallBody, wallDef, makeOffsetBox(0.05f, 5.0f, {5.0f, 0.0f}, 0.0f));
    world.setGravity({0.0f, 0.0f});
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.isBullet = true;
    bd.linearVelocity = {300.0f, 0.0f}; // 5 m per step: the wall is crossed within one step
    BodyId bullet = world.createBody(bd);
    world.createShape(bullet, {}, Circle{{0.0f, 0.0f}, 0.05f});
    if (filtered) {
        world.setPairFilterCallback([&](ShapeId x, ShapeId y) {
            return world.shapeUserData(x) != 1 && world.shapeUserData(y) != 1;
        });
    }
    for (int i = 0; i < 3; ++i) {
        world.step(kDt);
    }
    return world.transform(bullet).p.x;
}

TEST(WorldHooks, PairFilterAlsoGuardsContinuousCollision) {
    // Continuous collision stops the bullet at the wall; the filter refusing the pair lets it
    // through.
    EXPECT_LT(bulletThroughWall(false), 5.0f);
    EXPECT_NEAR(bulletThroughWall(true), 15.0f, 1e-3f);
}

TEST(WorldHooks, EventSwitchesSilenceAShapesEvents) {
    World world;
    makeGround(world);
    ShapeDef quiet;
    quiet.enableContactEvents = false;
    quiet.enableHitEvents = false;
    BodyId loud = makeBox(world, {-3.0f, 2.0f});
    BodyId silent = makeBox(world, {3.0f, 2.0f}, {0.0f, 0.0f}, quiet);
    int loudBegins = 0;
    int loudHits = 0;
    for (int i = 0; i < 60; ++i) {
        world.step(kDt);
        for (const ContactBeginTouchEvent& e : world.contactBeginEvents()) {
            BodyId a = world.shapeBody(e.shapeA);
            BodyId b = world.shapeBody(e.shapeB);
            EXPECT_FALSE(a == silent || b == silent);
            loudBegins += a == loud || b == loud;
        }
        for (const ContactHitEvent& e : world.hitEvents()) {
            BodyId a = world.shapeBody(e.shapeA);
            BodyId b = world.shapeBody(e.shapeB);
            EXPECT_FALSE(a == silent || b == silent);
            loudHits += a == loud || b == loud;
        }
    }
    EXPECT_EQ(loudBegins, 1);
    EXPECT_EQ(loudHits, 1); // fell 1.5 m: about 5.5 m/s, above the hit threshold
    // Both landed: the switch silences events, not contacts.
    EXPECT_NEAR(world.transform(silent).p.y, 0.5f, 0.02f);

    // Switching off on the ground (the other side) silences the loud box's end event too.
    ShapeId groundShape = kNullShapeId;
    world.forEachTouchingContact([&](const ContactData& c) {
        if (world.shapeBody(c.shapeA) == loud) {
            groundShape = c.shapeB;
        } else if (world.shapeBody(c.shapeB) == loud) {
            groundShape = c.shapeA;
        }
    });
    ASSERT_FALSE(groundShape.isNull());
    world.setShapeEventFlags(groundShape, false, true, true);
    world.setLinearVelocity(loud, {0.0f, 8.0f});
    for (int i = 0; i < 30; ++i) {
        world.step(kDt);
        EXPECT_TRUE(world.contactEndEvents().empty());
    }
}

TEST(WorldHooks, SensorEventSwitch) {
    World world;
    world.setGravity({0.0f, 0.0f});
    BodyId zoneBody = world.createBody({});
    ShapeDef sensor;
    sensor.isSensor = true;
    world.createShape(zoneBody, sensor, makeOffsetBox(1.0f, 1.0f, {0.0f, 0.0f}, 0.0f));
    ShapeDef unseen;
    unseen.enableSensorEvents = false;
    BodyId seenBox = makeBox(world, {-3.0f, 0.0f}, {3.0f, 0.0f});
    BodyId unseenBox = makeBox(world, {-3.0f, 3.0f}, {3.0f, 0.0f}, unseen);
    world.createShape(unseenBox, unseen, Circle{{0.0f, -3.0f}, 0.2f}); // passes through the zone
    int seen = 0;
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        for (const SensorBeginTouchEvent& e : world.sensorBeginEvents()) {
            EXPECT_EQ(world.shapeBody(e.visitorShape), seenBox);
            ++seen;
        }
    }
    EXPECT_EQ(seen, 1);
}

TEST(WorldHooks, MoveEventsListTheBodiesThatMovedWithTheirTransforms) {
    World world;
    makeGround(world);
    BodyId resting = makeBox(world, {-3.0f, 0.5f});
    BodyId falling = makeBox(world, {3.0f, 5.0f});
    BodyDef kd;
    kd.type = BodyType::Kinematic;
    kd.linearVelocity = {1.0f, 0.0f};
    kd.position = {0.0f, 10.0f};
    BodyId platform = world.createBody(kd);
    world.step(0.0f);
    EXPECT_TRUE(world.bodyMoveEvents().empty()); // step(0) moves nothing
    world.step(kDt);
    std::vector<BodyId> moved;
    for (const BodyMoveEvent& e : world.bodyMoveEvents()) {
        moved.push_back(e.body);
        Transform xf = world.transform(e.body);
        EXPECT_EQ(e.transform.p, xf.p);
        EXPECT_EQ(e.transform.q.c, xf.q.c);
        EXPECT_FALSE(e.fellAsleep);
    }
    EXPECT_EQ(moved.size(), 3u); // the ground is static
    EXPECT_NE(std::find(moved.begin(), moved.end(), platform), moved.end());
    // The resting box falls asleep (after 0.5 s at rest): one event says so, then none.
    int asleepEvents = 0;
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        for (const BodyMoveEvent& e : world.bodyMoveEvents()) {
            if (e.body == resting) {
                asleepEvents += e.fellAsleep;
                EXPECT_TRUE(world.isAwake(resting) != e.fellAsleep);
            }
        }
    }
    EXPECT_EQ(asleepEvents, 1);
    EXPECT_FALSE(world.isAwake(resting));
    world.step(kDt);
    for (const BodyMoveEvent& e : world.bodyMoveEvents()) {
        EXPECT_NE(e.body, resting);
    }
    (void)falling;
}

TEST(WorldHooks, MoveEventsSkipDisabledBodiesAndMarkSleepersInTheSameStep) {
    // Resting bodies falling asleep interleaved with runaways leaving the coordinate range
    // (one a step, so some leave in the step the others fall asleep): the events list the
    // bodies awake before the step and still enabled after it, in creation order, each with
    // its transform and whether it is asleep now.
    World world{WorldDef{.gravity = {0.0f, 0.0f}}};
    const float perStep = 400.0f * kDt;
    std::vector<BodyId> bodies;
    for (int j = 0; j < 60; ++j) {
        bodies.push_back(makeBox(world, {3.0f * static_cast<float>(j), 0.0f}));
        bodies.push_back(makeBox(
            world, {kHuge - (static_cast<float>(j) + 0.5f) * perStep, 2.0f * static_cast<float>(j)},
            {400.0f, 0.0f}));
    }
    bool sawBoth = false;
    for (int i = 0; i < 60; ++i) {
        std::vector<BodyId> expected;
        for (BodyId b : bodies) {
            if (world.isBodyEnabled(b) && world.isAwake(b)) {
                expected.push_back(b);
            }
        }
        world.step(kDt);
        std::erase_if(expected, [&](BodyId b) { return !world.isBodyEnabled(b); });
        const std::span<const BodyMoveEvent> events = world.bodyMoveEvents();
        ASSERT_EQ(events.size(), expected.size()) << i;
        int asleep = 0;
        for (std::size_t k = 0; k < events.size(); ++k) {
            const BodyMoveEvent& e = events[k];
            EXPECT_EQ(e.body, expected[k]) << i;
            EXPECT_EQ(e.transform.p, world.transform(e.body).p) << i;
            EXPECT_EQ(e.transform.q.s, world.transform(e.body).q.s) << i;
            EXPECT_EQ(e.fellAsleep, !world.isAwake(e.body)) << i;
            asleep += e.fellAsleep ? 1 : 0;
        }
        sawBoth = sawBoth || (asleep > 0 && !world.outOfRangeBodies().empty());
    }
    EXPECT_TRUE(sawBoth);
}

} // namespace
} // namespace e2d::physics
