// SPDX-License-Identifier: MIT
#include <e2d/physics/distance.hpp>
#include <e2d/physics/world.hpp>

#include "world_random_scene.hpp"

#include <cmath>

namespace e2d::physics {
namespace {

// shapeCast() stops within kShapeCastTolerance of contact, so fractions over a cast of length L
// are good to about that tolerance / L.
constexpr float kTol = 2e-4f;

ShapeId addStatic(World& world, Vec2 position, const ShapeGeometry& geometry,
                  BodyType type = BodyType::Static, const ShapeDef& def = {}) {
    BodyDef bd;
    bd.type = type;
    bd.position = position;
    return world.createShape(world.createBody(bd), def, geometry);
}

TEST(WorldCast, CircleMovingOntoAWallStopsAtItsFace) {
    World world;
    // Wall face at x = 4.5; a circle of radius 0.5 from the origin touches it with its centre at
    // x = 4, i.e. at 4 / 10 of the translation.
    ShapeId wall = addStatic(world, {5.0f, 0.0f}, makeBox(0.5f, 2.0f));
    std::optional<RayResult> hit =
        world.castShape(Circle{{0.0f, 0.0f}, 0.5f}, Transform{}, {10.0f, 0.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, wall);
    EXPECT_NEAR(hit->fraction, 0.4f, kTol);
    EXPECT_NEAR(hit->point.x, 4.5f, 1e-3f);
    EXPECT_NEAR(hit->point.y, 0.0f, 1e-3f);
    EXPECT_NEAR(hit->normal.x, -1.0f, 1e-4f);
    EXPECT_NEAR(hit->normal.y, 0.0f, 1e-4f);
}

TEST(WorldCast, ClosestOfSeveralShapesAcrossTrees) {
    World world;
    addStatic(world, {8.0f, 0.0f}, makeBox(0.5f, 2.0f));
    ShapeId near = addStatic(world, {0.0f, 5.0f}, Circle{{0.0f, 0.0f}, 1.0f}, BodyType::Dynamic);
    addStatic(world, {0.0f, 9.0f}, makeBox(3.0f, 0.5f), BodyType::Kinematic);
    // A unit box rising from the origin: its top (y = 1) meets the circle's bottom (y = 4)
    // after 3 of the 10 metres.
    std::optional<RayResult> hit = world.castShape(makeBox(1.0f, 1.0f), Transform{}, {0.0f, 10.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, near);
    EXPECT_NEAR(hit->fraction, 0.3f, kTol);
    EXPECT_NEAR(hit->normal.y, -1.0f, 1e-4f);
}

TEST(WorldCast, MissesFiltersAndStartingOverlap) {
    World world;
    Filter filter;
    filter.categoryBits = 0x2;
    ShapeDef def;
    def.filter = filter;
    ShapeId ball =
        addStatic(world, {5.0f, 0.0f}, Circle{{0.0f, 0.0f}, 1.0f}, BodyType::Static, def);
    Circle probe{{0.0f, 0.0f}, 0.25f};
    // Passes above: centre at y = 1.3, lowest point at 1.05, 0.05 above the ball's top.
    EXPECT_FALSE(world.castShape(probe, Transform{{0.0f, 1.3f}, {}}, {10.0f, 0.0f}).has_value());
    // Straight at it, but the query does not look at category 0x2.
    QueryFilter onlyBit0;
    onlyBit0.maskBits = 0x1;
    EXPECT_FALSE(world.castShape(probe, Transform{}, {10.0f, 0.0f}, onlyBit0).has_value());
    // Too short to reach it (the gap is 5 - 1 - 0.25 = 3.75).
    EXPECT_FALSE(world.castShape(probe, Transform{}, {3.5f, 0.0f}).has_value());
    std::optional<RayResult> hit = world.castShape(probe, Transform{}, {4.0f, 0.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, ball);
    EXPECT_NEAR(hit->fraction, 3.75f / 4.0f, kTol);
    // Starting inside: fraction 0.
    hit = world.castShape(probe, Transform{{5.5f, 0.0f}, {}}, {1.0f, 0.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, ball);
    EXPECT_EQ(hit->fraction, 0.0f);
}

TEST(WorldCast, RotatedCastShapeUsesItsTransform) {
    World world;
    ShapeId floor = addStatic(world, {0.0f, -1.0f}, makeBox(10.0f, 1.0f));
    // A unit box turned 45 degrees falls corner first: its lowest corner is sqrt(2) below its
    // centre, so from y = 5 it meets the floor (y = 0) after 5 - sqrt(2) metres.
    Transform xf{{0.0f, 5.0f}, Rot::fromAngle(0.78539816f)};
    std::optional<RayResult> hit = world.castShape(makeBox(1.0f, 1.0f), xf, {0.0f, -10.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, floor);
    EXPECT_NEAR(hit->fraction, (5.0f - std::sqrt(2.0f)) / 10.0f, kTol);
    EXPECT_NEAR(hit->point.x, 0.0f, 1e-3f);
    EXPECT_NEAR(hit->normal.y, 1.0f, 1e-4f);
}

TEST(WorldCast, InputIsChecked) {
    World world;
    E2D_EXPECT_ERROR((void)world.castShape(Circle{{0.0f, 0.0f}, -1.0f}, Transform{}, {1.0f, 0.0f}),
                     "physics::World::castShape()");
    E2D_EXPECT_ERROR((void)world.castShape(Circle{{0.0f, 0.0f}, 1.0f},
                                           Transform{{0.0f, 0.0f}, {2.0f, 0.0f}}, {1.0f, 0.0f}),
                     "physics::World::castShape(): transform.q must be a unit rotation");
    E2D_EXPECT_ERROR((void)world.castShape(Circle{{0.0f, 0.0f}, 1.0f}, Transform{}, {0.0f, 0.0f}),
                     "physics::World::castShape(): translation must be finite and non-zero");
}

TEST(WorldCast, ClosestHitMatchesBruteForceOverRandomWorlds) {
    for (std::uint32_t seed : {31u, 32u}) {
        test::RandomScene scene(seed, 80, 12.0f);
        test::Random& random = scene.random();
        int hits = 0;
        for (int q = 0; q < 40; ++q) {
            ShapeGeometry probe = scene.randomGeometry();
            Transform xf{{random.uniform(-14.0f, 14.0f), random.uniform(-14.0f, 14.0f)},
                         Rot::fromAngle(random.uniform(-3.0f, 3.0f))};
            Vec2 translation{random.uniform(-8.0f, 8.0f), random.uniform(-8.0f, 8.0f)};
            QueryFilter filter;
            // Brute force: the exact cast against every shape the filter lets through.
            float bestFraction = 2.0f;
            for (const test::ShapeRecord& s : scene.shapes) {
                if (!test::seenBy(s, filter)) {
                    continue;
                }
                ShapeCastPairInput input;
                input.proxyA = makeProxy(s.geometry);
                input.transformA = scene.transformOf(s);
                input.proxyB = makeProxy(probe);
                input.transformB = xf;
                input.translationB = translation;
                CastOutput out = shapeCast(input);
                if (out.hit) {
                    bestFraction = std::min(bestFraction, out.fraction);
                }
            }
            std::optional<RayResult> hit = scene.world.castShape(probe, xf, translation, filter);
            if (bestFraction > 1.0f) {
                EXPECT_FALSE(hit.has_value()) << "query " << q;
            } else {
                ASSERT_TRUE(hit.has_value()) << "query " << q;
                EXPECT_NEAR(hit->fraction, bestFraction, 1e-4f) << "query " << q;
                ++hits;
            }
        }
        EXPECT_GT(hits, 10);
    }
}

} // namespace
} // namespace e2d::physics
