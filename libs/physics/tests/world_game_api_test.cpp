// SPDX-License-Identifier: MIT
// Queries, explosions, point helpers, setters and handle views: what a game calls every frame.
#include <e2d/physics/views.hpp>
#include <e2d/physics/world.hpp>

#include "world_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>
#include <vector>

namespace e2d::physics {
namespace {

using test::Random;

constexpr float kDt = 1.0f / 60.0f;

BodyId dynamicBody(World& world, Vec2 position, Vec2 velocity = {0.0f, 0.0f}) {
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = position;
    bd.linearVelocity = velocity;
    return world.createBody(bd);
}

BodyId groundBody(World& world) {
    BodyId ground = world.createBody({});
    world.createShape(ground, {}, makeOffsetBox(20.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    return ground;
}

void run(World& world, float seconds) {
    for (int i = 0; i < static_cast<int>(seconds / kDt); ++i) {
        world.step(kDt);
    }
}

ShapeGeometry randomSolid(Random& rng) {
    switch (rng.below(3)) {
    case 0:
        return Circle{{rng.uniform(-0.3f, 0.3f), rng.uniform(-0.3f, 0.3f)},
                      rng.uniform(0.1f, 0.8f)};
    case 1:
        return Capsule{{rng.uniform(-0.8f, -0.1f), rng.uniform(-0.3f, 0.3f)},
                       {rng.uniform(0.1f, 0.8f), rng.uniform(-0.3f, 0.3f)},
                       rng.uniform(0.05f, 0.4f)};
    default: {
        std::vector<Vec2> points;
        for (int k = 0; k < 6; ++k) {
            points.push_back({rng.uniform(-0.8f, 0.8f), rng.uniform(-0.8f, 0.8f)});
        }
        return makePolygon(points, rng.below(2) == 0 ? 0.0f : 0.1f);
    }
    }
}

// What collide() (SAT, an independent routine) says about two shapes: clearly overlapping,
// clearly apart, or too close to call.
enum class Truth { Overlap, Apart, Unsure };

Truth bruteForce(const ShapeGeometry& query, const Transform& xfQ, const ShapeGeometry& shape,
                 const Transform& xfS) {
    ShapeGeometry plain = shape;
    if (const auto* chain = std::get_if<ChainSegment>(&shape)) {
        plain = chain->segment; // overlap has no sides
    }
    Manifold m = collide(query, xfQ, plain, xfS, CollisionAlgorithm::Sat, 0.01f);
    if (m.pointCount == 0) {
        return Truth::Apart;
    }
    float deepest = m.points[0].separation;
    for (int i = 1; i < m.pointCount; ++i) {
        deepest = std::min(deepest, m.points[i].separation);
    }
    if (deepest < -1e-3f) {
        return Truth::Overlap;
    }
    return deepest > 1e-3f ? Truth::Apart : Truth::Unsure;
}

TEST(WorldGameApi, OverlapShapeAgreesWithBruteForce) {
    World world;
    Random rng(1234);
    std::vector<ShapeId> shapes;
    for (int i = 0; i < 80; ++i) {
        BodyDef bd;
        bd.type = i % 3 == 0 ? BodyType::Static : BodyType::Dynamic;
        bd.position = {rng.uniform(-10.0f, 10.0f), rng.uniform(-10.0f, 10.0f)};
        bd.angle = rng.uniform(-3.0f, 3.0f);
        BodyId body = world.createBody(bd);
        shapes.push_back(world.createShape(body, {}, randomSolid(rng)));
    }
    BodyId ground = world.createBody({});
    shapes.push_back(world.createShape(ground, {}, Segment{{-10.0f, -3.0f}, {10.0f, -2.0f}}));
    ChainDef chain;
    chain.points = {{10.0f, 4.0f}, {0.0f, 5.0f}, {-10.0f, 4.0f}};
    for (ShapeId id : world.createChain(ground, chain)) {
        shapes.push_back(id);
    }
    ShapeDef sensorDef;
    sensorDef.isSensor = true;
    ShapeId sensor = world.createShape(ground, sensorDef, Circle{{0.0f, 0.0f}, 3.0f});

    int checked = 0;
    int overlaps = 0;
    for (int q = 0; q < 300; ++q) {
        ShapeGeometry query = randomSolid(rng);
        Transform xf{{rng.uniform(-11.0f, 11.0f), rng.uniform(-11.0f, 11.0f)},
                     Rot::fromAngle(rng.uniform(-3.0f, 3.0f))};
        std::vector<ShapeId> found = world.overlapShape(query, xf);
        EXPECT_TRUE(std::is_sorted(found.begin(), found.end(),
                                   [](ShapeId a, ShapeId b) { return a.index1 < b.index1; }));
        EXPECT_EQ(std::count(found.begin(), found.end(), sensor), 0);
        for (ShapeId id : shapes) {
            Truth truth = bruteForce(query, xf, world.shapeGeometry(id),
                                     world.transform(world.shapeBody(id)));
            bool reported = std::find(found.begin(), found.end(), id) != found.end();
            if (truth == Truth::Overlap) {
                EXPECT_TRUE(reported) << "query " << q << " missed shape " << id.index1;
                ++overlaps;
            } else if (truth == Truth::Apart) {
                EXPECT_FALSE(reported) << "query " << q << " reported shape " << id.index1;
            }
            checked += truth != Truth::Unsure;
        }
    }
    EXPECT_GT(overlaps, 100); // the scene is dense enough to test something
    EXPECT_GT(checked, 300 * 80);
    // Sensors on request; segments are refused as queries.
    QueryFilter withSensors;
    withSensors.includeSensors = true;
    std::vector<ShapeId> s = world.overlapShape(Circle{{0.0f, 0.0f}, 0.1f}, {}, withSensors);
    EXPECT_NE(std::find(s.begin(), s.end(), sensor), s.end());
    E2D_EXPECT_ERROR(
        (void)world.overlapShape(Segment{{0.0f, 0.0f}, {1.0f, 0.0f}}, {}),
        "physics::World::overlapShape(): geometry must be a circle, capsule or polygon");
    E2D_EXPECT_ERROR((void)world.overlapShape(Circle{{0.0f, 0.0f}, -1.0f}, {}),
                     "circle radius must be finite and in (0, kHuge (500000 m)], got -1");
}

TEST(WorldGameApi, ExplosionFallsOffWithDistanceAndNothingBlocksIt) {
    World world;
    world.setGravity({0.0f, 0.0f});
    // A wall between the centre and the balls: explosions are not blocked.
    BodyId wall = world.createBody({});
    world.createShape(wall, {}, makeOffsetBox(0.05f, 10.0f, {0.5f, 0.0f}, 0.0f));
    const float radius = 0.25f;
    const float mass = std::numbers::pi_v<float> * radius * radius; // density 1
    const float distances[] = {1.0f, 2.0f, 3.0f, 4.0f, 5.0f};
    std::vector<BodyId> balls;
    for (int i = 0; i < 5; ++i) {
        float angle = 0.3f * static_cast<float>(i) - 0.6f;
        BodyId ball = dynamicBody(world, distances[i] * Vec2{std::cos(angle), std::sin(angle)});
        world.createShape(ball, {}, Circle{{0.0f, 0.0f}, radius});
        balls.push_back(ball);
    }
    ExplosionDef def;
    def.radius = 1.5f;
    def.falloff = 2.0f;
    def.impulsePerLength = 2.0f;
    EXPECT_EQ(world.explode(def), 3);
    for (int i = 0; i < 5; ++i) {
        const float closest = distances[i] - radius;
        const float strength = closest <= def.radius
                                   ? 1.0f
                                   : std::max(0.0f, 1.0f - (closest - def.radius) / def.falloff);
        const float impulse = def.impulsePerLength * (2.0f * radius) * strength;
        const Vec2 p = world.transform(balls[i]).p;
        const Vec2 expected = (impulse / mass) * (p / length(p));
        const Vec2 v = world.linearVelocity(balls[i]);
        EXPECT_NEAR(v.x, expected.x, 1e-4f) << "ball " << i;
        EXPECT_NEAR(v.y, expected.y, 1e-4f) << "ball " << i;
        EXPECT_NEAR(world.angularVelocity(balls[i]), 0.0f, 1e-4f);
    }
    E2D_EXPECT_ERROR(world.explode(ExplosionDef{{0.0f, 0.0f}, -1.0f}),
                     "physics::World::explode(): def.radius must be finite and >= 0, got -1");
}

TEST(WorldGameApi, PointHelpers) {
    World world;
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = {1.0f, 2.0f};
    bd.angle = std::numbers::pi_v<float> / 2.0f;
    bd.linearVelocity = {1.0f, 0.0f};
    bd.angularVelocity = 2.0f;
    BodyId body = world.createBody(bd);
    world.createShape(body, {}, makeBox(0.5f, 0.5f)); // centre of mass at the origin
    Vec2 w = world.worldPoint(body, {1.0f, 0.0f});
    EXPECT_NEAR(w.x, 1.0f, 1e-6f);
    EXPECT_NEAR(w.y, 3.0f, 1e-6f);
    Vec2 l = world.localPoint(body, w);
    EXPECT_NEAR(l.x, 1.0f, 1e-6f);
    EXPECT_NEAR(l.y, 0.0f, 1e-6f);
    Vec2 wv = world.worldVector(body, {1.0f, 0.0f});
    EXPECT_NEAR(wv.x, 0.0f, 1e-6f);
    EXPECT_NEAR(wv.y, 1.0f, 1e-6f);
    Vec2 lv = world.localVector(body, wv);
    EXPECT_NEAR(lv.x, 1.0f, 1e-6f);
    // v + omega x r with r = (0, 1): (1, 0) + (-2, 0).
    Vec2 vp = world.linearVelocityAtWorldPoint(body, w);
    EXPECT_NEAR(vp.x, -1.0f, 1e-6f);
    EXPECT_NEAR(vp.y, 0.0f, 1e-6f);
    Vec2 vl = world.linearVelocityAtLocalPoint(body, {1.0f, 0.0f});
    EXPECT_NEAR(vl.x, vp.x, 1e-6f);
    EXPECT_NEAR(vl.y, vp.y, 1e-6f);
    E2D_EXPECT_ERROR((void)world.worldPoint(BodyId{}, {0.0f, 0.0f}),
                     "worldPoint(): stale or null BodyId");
}

TEST(WorldGameApi, DensityGeometryAndMaterialSetters) {
    World world;
    groundBody(world);
    BodyId box = dynamicBody(world, {0.0f, 0.5f});
    ShapeId shape = world.createShape(box, {}, makeBox(0.5f, 0.5f));
    EXPECT_NEAR(world.massData(box).mass, 1.0f, 1e-5f);
    world.setShapeDensity(shape, 3.0f);
    EXPECT_FLOAT_EQ(world.shapeDensity(shape), 3.0f);
    EXPECT_NEAR(world.massData(box).mass, 3.0f, 1e-5f);
    EXPECT_NEAR(world.massData(box).rotationalInertia, 3.0f * (1.0f + 1.0f) / 12.0f, 1e-5f);

    // A 2 m wide box now: mass 3 * 4, resting 1 m above the ground.
    world.setShapeGeometry(shape, makeBox(1.0f, 1.0f));
    EXPECT_NEAR(world.massData(box).mass, 12.0f, 1e-4f);
    run(world, 1.0f);
    EXPECT_NEAR(world.transform(box).p.y, 1.0f, 0.02f);

    // Friction 0 on the ground: mixed sqrt(0 * 0.6) = 0, the box keeps its speed.
    ShapeId groundShape =
        world.bodyShapes(world.shapeBody(world.overlapPoint({0.0f, -0.25f}).front())).front();
    world.setShapeFriction(groundShape, 0.0f);
    EXPECT_FLOAT_EQ(world.shapeFriction(groundShape), 0.0f);
    world.setLinearVelocity(box, {2.0f, 0.0f});
    run(world, 1.0f);
    EXPECT_NEAR(world.linearVelocity(box).x, 2.0f, 1e-3f);
    world.setShapeFriction(groundShape, 0.6f);
    run(world, 1.0f);
    EXPECT_NEAR(world.linearVelocity(box).x, 0.0f, 1e-3f);

    // Restitution 1 on a ball makes it bounce back to about where it fell from.
    BodyId ball = dynamicBody(world, {10.0f, 3.0f});
    ShapeId ballShape = world.createShape(ball, {}, Circle{{0.0f, 0.0f}, 0.25f});
    world.setShapeRestitution(ballShape, 1.0f);
    EXPECT_FLOAT_EQ(world.shapeRestitution(ballShape), 1.0f);
    float peak = 0.0f;
    bool rising = false;
    for (int i = 0; i < 90; ++i) {
        world.step(kDt);
        rising = rising || world.linearVelocity(ball).y > 0.0f;
        if (rising) {
            peak = std::max(peak, world.transform(ball).p.y);
        }
    }
    EXPECT_GT(peak, 2.7f);

    E2D_EXPECT_ERROR(world.setShapeDensity(shape, -1.0f),
                     "physics::World::setShapeDensity(): density must be finite and >= 0, got -1");
    E2D_EXPECT_ERROR(world.setShapeFriction(shape, NAN),
                     "setShapeFriction(): friction must be finite");
    E2D_EXPECT_ERROR(world.setShapeGeometry(shape, Circle{{0.0f, 0.0f}, 0.0f}),
                     "physics::World::setShapeGeometry(): circle radius must be finite and in "
                     "(0, kHuge (500000 m)], got 0");
    EXPECT_NEAR(world.massData(box).mass, 12.0f, 1e-4f); // unchanged by the rejected calls
}

TEST(WorldGameApi, SensorSetterTurnsTheGroundIntoATriggerAndBack) {
    World world;
    BodyId ground = groundBody(world);
    ShapeId groundShape = world.bodyShapes(ground).front();
    BodyId box = dynamicBody(world, {0.0f, 0.5f});
    world.createShape(box, {}, makeBox(0.5f, 0.5f));
    run(world, 0.5f);
    EXPECT_NEAR(world.transform(box).p.y, 0.5f, 0.02f);
    world.setShapeSensor(groundShape, true);
    EXPECT_TRUE(world.isSensor(groundShape));
    int sensorBegins = 0;
    for (int i = 0; i < 30; ++i) {
        world.step(kDt);
        sensorBegins += static_cast<int>(world.sensorBeginEvents().size());
    }
    EXPECT_EQ(sensorBegins, 1);
    EXPECT_LT(world.transform(box).p.y, 0.0f); // sinking through
}

TEST(WorldGameApi, BodyTypeChangesWakeAndSleepAsExpected) {
    World world;
    groundBody(world);
    // Static in the air: made dynamic, it wakes and falls.
    BodyId hanging = world.createBody({BodyType::Static, {-5.0f, 5.0f}});
    world.createShape(hanging, {}, makeBox(0.5f, 0.5f));
    EXPECT_FLOAT_EQ(world.massData(hanging).mass, 0.0f);
    world.setBodyType(hanging, BodyType::Dynamic);
    EXPECT_EQ(world.bodyType(hanging), BodyType::Dynamic);
    EXPECT_TRUE(world.isAwake(hanging));
    EXPECT_NEAR(world.massData(hanging).mass, 1.0f, 1e-5f);
    run(world, 2.0f);
    EXPECT_NEAR(world.transform(hanging).p.y, 0.5f, 0.02f);

    // A dynamic platform with a box on it, both asleep. Made static: the platform stops and
    // sleeps for good, the box on it wakes, then sleeps again on its now static support.
    BodyId platform = dynamicBody(world, {5.0f, 0.25f});
    world.createShape(platform, {}, makeBox(1.0f, 0.25f));
    BodyId rider = dynamicBody(world, {5.0f, 1.0f});
    world.createShape(rider, {}, makeBox(0.25f, 0.25f));
    run(world, 3.0f);
    ASSERT_FALSE(world.isAwake(rider));
    world.setBodyType(platform, BodyType::Static);
    EXPECT_FALSE(world.isAwake(platform));
    EXPECT_TRUE(world.isAwake(rider));
    EXPECT_EQ(world.linearVelocity(platform), Vec2(0.0f, 0.0f));
    run(world, 3.0f);
    EXPECT_FALSE(world.isAwake(rider));
    EXPECT_NEAR(world.transform(rider).p.y, 0.75f, 0.02f);

    // Kinematic: moves by its velocity alone, gravity and contacts aside.
    world.setBodyType(hanging, BodyType::Kinematic);
    EXPECT_TRUE(world.isAwake(hanging));
    EXPECT_FLOAT_EQ(world.massData(hanging).mass, 0.0f);
    world.setLinearVelocity(hanging, {0.0f, 1.0f});
    run(world, 1.0f);
    EXPECT_NEAR(world.transform(hanging).p.y, 1.5f, 0.02f);
    E2D_EXPECT_ERROR(
        world.setBodyType(hanging, static_cast<BodyType>(7)),
        "physics::World::setBodyType(): type must be Static, Kinematic or Dynamic, got 7");
}

TEST(WorldGameApi, HandleViewsForwardToTheWorld) {
    static_assert(std::is_trivially_copyable_v<Body> && std::is_trivially_copyable_v<Shape>);
    static_assert(sizeof(Body) <= 16 && sizeof(Shape) <= 16);
    World world;
    groundBody(world);
    Body ball = world.body(dynamicBody(world, {0.0f, 3.0f}));
    Shape skin = ball.createShape({}, Circle{{0.0f, 0.0f}, 0.5f});
    EXPECT_TRUE(ball.isValid());
    EXPECT_EQ(skin.body(), ball);
    EXPECT_EQ(ball.shapes(), std::vector<ShapeId>{skin.id()});
    EXPECT_EQ(ball.type(), BodyType::Dynamic);
    EXPECT_EQ(ball.position(), world.transform(ball.id()).p);
    EXPECT_NEAR(ball.mass(), std::numbers::pi_v<float> * 0.25f, 1e-5f);
    skin.setDensity(2.0f);
    EXPECT_NEAR(ball.mass(), std::numbers::pi_v<float> * 0.5f, 1e-5f);
    ball.applyLinearImpulseToCenter({ball.mass() * 2.0f, 0.0f});
    EXPECT_NEAR(ball.linearVelocity().x, 2.0f, 1e-5f);
    EXPECT_EQ(ball.worldPoint({1.0f, 0.0f}), world.worldPoint(ball.id(), {1.0f, 0.0f}));
    skin.setFriction(0.1f);
    EXPECT_FLOAT_EQ(world.shapeFriction(skin.id()), 0.1f);
    EXPECT_EQ(skin.type(), ShapeType::Circle);
    ball.setUserData(9);
    EXPECT_EQ(world.bodyUserData(ball.id()), 9u);
    ball.destroy();
    EXPECT_FALSE(ball.isValid());
    EXPECT_FALSE(skin.isValid());
    E2D_EXPECT_ERROR((void)ball.position(), "physics::World::transform(): stale or null BodyId");
    E2D_EXPECT_ERROR(skin.setFriction(0.2f),
                     "physics::World::setShapeFriction(): stale or null ShapeId");
}

} // namespace
} // namespace e2d::physics
