// SPDX-License-Identifier: MIT
#include <e2d/physics/world.hpp>

#include "world_test_util.hpp"

#include <cmath>

namespace e2d::physics {
namespace {

constexpr float kTol = 1e-5f;

void expectVec(Vec2 actual, Vec2 expected, float tol = kTol) {
    EXPECT_NEAR(actual.x, expected.x, tol);
    EXPECT_NEAR(actual.y, expected.y, tol);
}

ShapeId addShape(World& world, BodyType type, Vec2 position, float angle,
                 const ShapeGeometry& geometry, const ShapeDef& def = {}) {
    BodyDef bd;
    bd.type = type;
    bd.position = position;
    bd.angle = angle;
    return world.createShape(world.createBody(bd), def, geometry);
}

// A unit box (half-extents 1) at (5, 0) on a static body and a circle of radius 1 at (10, 0.5)
// on a dynamic one; the ray runs along the x axis from the origin to (20, 0).
struct WorldRayScene : ::testing::Test {
    World world;
    ShapeId box = addShape(world, BodyType::Static, {5.0f, 0.0f}, 0.0f, makeBox(1.0f, 1.0f));
    ShapeId circle =
        addShape(world, BodyType::Dynamic, {10.0f, 0.5f}, 0.0f, Circle{{0.0f, 0.0f}, 1.0f});
    Vec2 origin{0.0f, 0.0f};
    Vec2 translation{20.0f, 0.0f};
    // The circle's chord at y = 0: x = 10 -+ sqrt(1 - 0.5^2).
    float half = std::sqrt(0.75f);
};

TEST_F(WorldRayScene, ClosestHitIsTheBoxFrontFace) {
    std::optional<RayResult> hit = world.castRayClosest(origin, translation);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, box);
    EXPECT_NEAR(hit->fraction, 4.0f / 20.0f, kTol);
    expectVec(hit->point, {4.0f, 0.0f});
    expectVec(hit->normal, {-1.0f, 0.0f});
    EXPECT_FALSE(hit->exit);
}

TEST_F(WorldRayScene, ClosestHitAcrossTreesIsTheNearestOne) {
    // From the right, the dynamic circle comes first even though the static tree is cast first.
    std::optional<RayResult> hit = world.castRayClosest({20.0f, 0.0f}, {-20.0f, 0.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, circle);
    EXPECT_NEAR(hit->fraction, (10.0f - half) / 20.0f, kTol);
    expectVec(hit->point, {10.0f + half, 0.0f});
    // Outward normal at the hit: from the centre (10, 0.5) to the point.
    expectVec(hit->normal, {half, -0.5f});
}

TEST_F(WorldRayScene, AllHitsAreSortedByFraction) {
    std::vector<RayResult> hits = world.castRayAll(origin, translation);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_EQ(hits[0].shape, box);
    EXPECT_NEAR(hits[0].fraction, 0.2f, kTol);
    EXPECT_EQ(hits[1].shape, circle);
    EXPECT_NEAR(hits[1].fraction, (10.0f - half) / 20.0f, kTol);
    expectVec(hits[1].point, {10.0f - half, 0.0f});
    expectVec(hits[1].normal, {-half, -0.5f});
}

TEST_F(WorldRayScene, BackFacesAddTheExitPoints) {
    QueryFilter filter;
    filter.ignoreBackFaces = false;
    std::vector<RayResult> hits = world.castRayAll(origin, translation, filter);
    ASSERT_EQ(hits.size(), 4u);
    EXPECT_EQ(hits[0].shape, box);
    EXPECT_FALSE(hits[0].exit);
    EXPECT_EQ(hits[1].shape, box);
    EXPECT_TRUE(hits[1].exit);
    EXPECT_NEAR(hits[1].fraction, 6.0f / 20.0f, kTol);
    expectVec(hits[1].point, {6.0f, 0.0f});
    expectVec(hits[1].normal, {1.0f, 0.0f});
    EXPECT_EQ(hits[2].shape, circle);
    EXPECT_FALSE(hits[2].exit);
    EXPECT_EQ(hits[3].shape, circle);
    EXPECT_TRUE(hits[3].exit);
    EXPECT_NEAR(hits[3].fraction, (10.0f + half) / 20.0f, kTol);
    expectVec(hits[3].normal, {half, -0.5f});
}

TEST_F(WorldRayScene, RayStartingInsideSeesOnlyTheExitWithBackFaces) {
    Vec2 inside{5.5f, 0.0f};
    std::optional<RayResult> hit = world.castRayClosest(inside, translation);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, circle); // the box it starts in is not hit
    QueryFilter filter;
    filter.ignoreBackFaces = false;
    hit = world.castRayClosest(inside, translation, filter);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, box);
    EXPECT_TRUE(hit->exit);
    EXPECT_NEAR(hit->fraction, 0.5f / 20.0f, kTol);
    expectVec(hit->normal, {1.0f, 0.0f});
}

TEST_F(WorldRayScene, ARayEndingInsideAShapeHasNoExitThere) {
    QueryFilter filter;
    filter.ignoreBackFaces = false;
    std::vector<RayResult> hits = world.castRayAll(origin, {5.0f, 0.0f}, filter);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_EQ(hits[0].shape, box);
    EXPECT_FALSE(hits[0].exit);
    EXPECT_NEAR(hits[0].fraction, 4.0f / 5.0f, kTol);
}

TEST_F(WorldRayScene, MaskFilterHidesShapesBothWays) {
    Filter boxFilter;
    boxFilter.categoryBits = 0x2;
    world.setShapeFilter(box, boxFilter);
    QueryFilter onlyCircles;
    onlyCircles.maskBits = 0x1; // the circle keeps the default category bit 0
    std::optional<RayResult> hit = world.castRayClosest(origin, translation, onlyCircles);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, circle);
    EXPECT_EQ(world.castRayAll(origin, translation, onlyCircles).size(), 1u);

    // The shape's own mask must accept the query's category too.
    Filter circleFilter;
    circleFilter.maskBits = 0x4;
    world.setShapeFilter(circle, circleFilter);
    QueryFilter everything;
    EXPECT_EQ(world.castRayAll(origin, translation, everything).size(), 1u); // the box
    everything.categoryBits = 0x4;
    EXPECT_EQ(world.castRayAll(origin, translation, everything).size(), 2u);
}

TEST_F(WorldRayScene, RayCastShapeLooksAtOneShapeOnly) {
    std::optional<RayResult> hit = world.rayCastShape(circle, origin, translation);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, circle);
    EXPECT_NEAR(hit->fraction, (10.0f - half) / 20.0f, kTol);
    EXPECT_FALSE(world.rayCastShape(box, {0.0f, 3.0f}, translation).has_value());
    hit = world.rayCastShape(box, {5.0f, 0.0f}, translation, false);
    ASSERT_TRUE(hit.has_value());
    EXPECT_TRUE(hit->exit);
    expectVec(hit->point, {6.0f, 0.0f});
}

TEST_F(WorldRayScene, RayPassesDisabledBodiesAndMovedShapes) {
    world.setBodyEnabled(world.shapeBody(box), false);
    std::optional<RayResult> hit = world.castRayClosest(origin, translation);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, circle);
    world.setBodyEnabled(world.shapeBody(box), true);
    // Move the box off the ray: the tree must follow.
    world.setTransform(world.shapeBody(box), {5.0f, 3.0f}, 0.0f);
    hit = world.castRayClosest(origin, translation);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, circle);
    hit = world.castRayClosest({0.0f, 3.0f}, translation);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, box);
    EXPECT_NEAR(hit->fraction, 0.2f, kTol);
}

TEST(WorldRay, RotatedBoxGivesTheSlantedFaceNormal) {
    World world;
    // A unit box turned 45 degrees: the diamond |x - 5| + |y| <= sqrt(2).
    ShapeId box =
        addShape(world, BodyType::Kinematic, {5.0f, 0.0f}, 0.78539816f, makeBox(1.0f, 1.0f));
    std::optional<RayResult> hit = world.castRayClosest({0.0f, 0.2f}, {10.0f, 0.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, box);
    float x = 5.0f - (std::sqrt(2.0f) - 0.2f);
    EXPECT_NEAR(hit->fraction, x / 10.0f, 1e-5f);
    expectVec(hit->point, {x, 0.2f});
    float r = 1.0f / std::sqrt(2.0f);
    expectVec(hit->normal, {-r, r});
}

TEST(WorldRay, SensorsAreSkippedUnlessAskedFor) {
    World world;
    ShapeDef sensor;
    sensor.isSensor = true;
    ShapeId s =
        addShape(world, BodyType::Static, {2.0f, 0.0f}, 0.0f, Circle{{0.0f, 0.0f}, 0.5f}, sensor);
    EXPECT_FALSE(world.castRayClosest({0.0f, 0.0f}, {4.0f, 0.0f}).has_value());
    EXPECT_TRUE(world.overlapPoint({2.0f, 0.0f}).empty());
    QueryFilter filter;
    filter.includeSensors = true;
    std::optional<RayResult> hit = world.castRayClosest({0.0f, 0.0f}, {4.0f, 0.0f}, filter);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, s);
    EXPECT_NEAR(hit->fraction, 1.5f / 4.0f, kTol);
    EXPECT_EQ(world.overlapPoint({2.0f, 0.0f}, filter), std::vector<ShapeId>{s});
}

TEST(WorldRay, SegmentIsHitOnceEvenWithBackFaces) {
    World world;
    ShapeId wall =
        addShape(world, BodyType::Static, {0.0f, 0.0f}, 0.0f, Segment{{3.0f, -1.0f}, {3.0f, 1.0f}});
    QueryFilter filter;
    filter.ignoreBackFaces = false;
    std::vector<RayResult> hits = world.castRayAll({0.0f, 0.5f}, {6.0f, 0.0f}, filter);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_EQ(hits[0].shape, wall);
    EXPECT_NEAR(hits[0].fraction, 0.5f, kTol);
    expectVec(hits[0].point, {3.0f, 0.5f});
    expectVec(hits[0].normal, {-1.0f, 0.0f});
}

TEST(WorldRay, CapsuleSideAndCap) {
    World world;
    // Horizontal capsule from (-1, 0) to (1, 0), radius 0.5, centred at (0, 4).
    ShapeId capsule = addShape(world, BodyType::Dynamic, {0.0f, 4.0f}, 0.0f,
                               Capsule{{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f});
    // Straight down onto the flat side.
    std::optional<RayResult> hit = world.castRayClosest({0.5f, 10.0f}, {0.0f, -10.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, capsule);
    EXPECT_NEAR(hit->fraction, 0.55f, kTol);
    expectVec(hit->normal, {0.0f, 1.0f});
    // Along the axis into the right cap: enters at x = 1.5.
    hit = world.castRayClosest({5.0f, 4.0f}, {-5.0f, 0.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->fraction, 3.5f / 5.0f, kTol);
    expectVec(hit->normal, {1.0f, 0.0f});
}

} // namespace
} // namespace e2d::physics
