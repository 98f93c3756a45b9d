// SPDX-License-Identifier: MIT
// Which bodies a sensor sees (ShapeDef::isSensor): one dynamic body per pair by default;
// ShapeDef::sensorSeesNonDynamic adds kinematic bodies (and static ones for a kinematic sensor).
#include <e2d/physics/world.hpp>

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace e2d::physics {
namespace {

constexpr float kDt = 1.0f / 60.0f;

struct Seen {
    int begins = 0;
    int ends = 0;
    float firstBegin = -1.0f; // seconds
    float firstEnd = -1.0f;
};

// Steps `world` for `seconds`, counting the sensor events of `sensor`.
Seen watch(World& world, ShapeId sensor, float seconds) {
    Seen seen;
    const int steps = static_cast<int>(seconds / kDt + 0.5f);
    for (int i = 1; i <= steps; ++i) {
        world.step(kDt);
        for (const SensorBeginTouchEvent& e : world.sensorBeginEvents()) {
            if (e.sensorShape == sensor) {
                if (seen.begins++ == 0) {
                    seen.firstBegin = static_cast<float>(i) * kDt;
                }
            }
        }
        for (const SensorEndTouchEvent& e : world.sensorEndEvents()) {
            if (e.sensorShape == sensor) {
                if (seen.ends++ == 0) {
                    seen.firstEnd = static_cast<float>(i) * kDt;
                }
            }
        }
    }
    return seen;
}

// A static zone 2 m wide centred at x = 0 and a kinematic 1 m box moving through it at 2 m/s
// from x = -4: its edge reaches the zone at x = -1.5, so after 1.25 s, and leaves after 2.75 s.
Seen kinematicThroughStaticZone(bool seesNonDynamic) {
    World world{WorldDef{.gravity = {0.0f, 0.0f}}};
    BodyId zone = world.createBody({});
    ShapeDef sd;
    sd.isSensor = true;
    sd.sensorSeesNonDynamic = seesNonDynamic;
    ShapeId sensor = world.createShape(zone, sd, makeBox(1.0f, 1.0f));
    BodyId platform = world.createBody(
        {.type = BodyType::Kinematic, .position = {-4.0f, 0.0f}, .linearVelocity = {2.0f, 0.0f}});
    world.createShape(platform, {}, makeBox(0.5f, 0.5f));
    return watch(world, sensor, 4.0f);
}

TEST(WorldSensorRule, AStaticZoneSeesAKinematicBodyOnlyWithTheOption) {
    const Seen plain = kinematicThroughStaticZone(false);
    EXPECT_EQ(plain.begins, 0);
    EXPECT_EQ(plain.ends, 0);
    const Seen wide = kinematicThroughStaticZone(true);
    EXPECT_EQ(wide.begins, 1);
    EXPECT_EQ(wide.ends, 1);
    // The boxes overlap from 1.25 s to 2.75 s. A step tests sensors where the previous step
    // left the bodies, and needs them to overlap, not just meet: each event comes one or two
    // steps after the moment.
    EXPECT_GT(wide.firstBegin, 1.25f + 0.5f * kDt);
    EXPECT_LT(wide.firstBegin, 1.25f + 2.5f * kDt);
    EXPECT_GT(wide.firstEnd, 2.75f + 0.5f * kDt);
    EXPECT_LT(wide.firstEnd, 2.75f + 2.5f * kDt);
}

TEST(WorldSensorRule, AKinematicDetectorSeesStaticScenery) {
    for (bool seesNonDynamic : {false, true}) {
        SCOPED_TRACE(seesNonDynamic);
        World world{WorldDef{.gravity = {0.0f, 0.0f}}};
        BodyId rock = world.createBody({.position = {0.0f, 0.0f}});
        world.createShape(rock, {}, makeBox(1.0f, 1.0f));
        BodyId detector = world.createBody({.type = BodyType::Kinematic,
                                            .position = {-4.0f, 0.0f},
                                            .linearVelocity = {2.0f, 0.0f}});
        ShapeDef sd;
        sd.isSensor = true;
        sd.sensorSeesNonDynamic = seesNonDynamic;
        ShapeId sensor = world.createShape(detector, sd, makeBox(0.5f, 0.5f));
        const Seen seen = watch(world, sensor, 4.0f);
        EXPECT_EQ(seen.begins, seesNonDynamic ? 1 : 0);
        EXPECT_EQ(seen.ends, seesNonDynamic ? 1 : 0);
    }
}

TEST(WorldSensorRule, TwoStaticBodiesNeverPairAndDynamicBodiesAreSeenEitherWay) {
    for (bool seesNonDynamic : {false, true}) {
        SCOPED_TRACE(seesNonDynamic);
        World world;
        BodyId zone = world.createBody({});
        ShapeDef sd;
        sd.isSensor = true;
        sd.sensorSeesNonDynamic = seesNonDynamic;
        ShapeId sensor = world.createShape(zone, sd, makeBox(2.0f, 2.0f));
        // A static wall inside the zone: never seen.
        world.createShape(world.createBody({}), {}, makeOffsetBox(0.5f, 0.5f, {1.0f, -1.0f}, 0.0f));
        // A ball falling through the zone: seen with or without the option.
        BodyId ball = world.createBody({.type = BodyType::Dynamic, .position = {-1.0f, 3.0f}});
        world.createShape(ball, {}, Circle{{0.0f, 0.0f}, 0.25f});
        const Seen seen = watch(world, sensor, 1.5f);
        EXPECT_EQ(seen.begins, 1);
        EXPECT_EQ(seen.ends, 1);
        world.setTransform(ball, {-50.0f, 0.0f}, 0.0f);
        world.setBodyType(ball, BodyType::Static);
        world.step(kDt);
        int pairs = 0;
        world.forEachCandidatePair(
            [&](ShapeId a, ShapeId b) { pairs += static_cast<int>(a == sensor || b == sensor); });
        EXPECT_EQ(pairs, 0);
    }
}

TEST(WorldSensorRule, TheOptionSurvivesTypeAndSensorChanges) {
    World world{WorldDef{.gravity = {0.0f, 0.0f}}};
    BodyId zone = world.createBody({});
    ShapeDef sd;
    sd.isSensor = true;
    sd.sensorSeesNonDynamic = true;
    ShapeId sensor = world.createShape(zone, sd, makeBox(1.0f, 1.0f));
    BodyId mover = world.createBody({.type = BodyType::Dynamic, .position = {0.0f, 0.0f}});
    world.createShape(mover, {}, makeBox(0.5f, 0.5f));
    world.setBodyType(mover, BodyType::Kinematic); // still overlapping, now kinematic
    world.step(kDt);
    ASSERT_EQ(world.sensorBeginEvents().size(), 1u);
    EXPECT_EQ(world.sensorBeginEvents()[0].sensorShape, sensor);
    world.setShapeSensor(sensor, false); // solid now: a static box against a kinematic one
    world.step(kDt);
    EXPECT_EQ(world.contactCount(), 0);
    world.setShapeSensor(sensor, true);
    world.step(kDt);
    EXPECT_EQ(world.sensorBeginEvents().size(), 1u);
}

} // namespace
} // namespace e2d::physics
