// SPDX-License-Identifier: MIT
// AABBs and point tests.
#include <e2d/physics/geometry.hpp>

#include "geometry_test_util.hpp"

#include <cmath>

namespace e2d::physics {
namespace {

using test::kPi;
using test::makeTransform;

void expectAabb(const Aabb& box, float lx, float ly, float ux, float uy) {
    E2D_EXPECT_VEC2_NEAR(box.lower, lx, ly, 1e-5f);
    E2D_EXPECT_VEC2_NEAR(box.upper, ux, uy, 1e-5f);
}

TEST(Aabb, RotatedBox) {
    // A 2 x 2 box turned 45 degrees reaches sqrt(2) along both axes.
    const float s = std::sqrt(2.0f);
    expectAabb(computeAabb(makeBox(1.0f, 1.0f), makeTransform(1.0f, 2.0f, 0.25f * kPi)), 1 - s,
               2 - s, 1 + s, 2 + s);
    // A 4 x 1 box turned a quarter turn is 1 wide and 4 tall.
    expectAabb(computeAabb(makeBox(2.0f, 0.5f), makeTransform(0.0f, 0.0f, 0.5f * kPi)), -0.5f,
               -2.0f, 0.5f, 2.0f);
}

TEST(Aabb, RoundedBoxAddsTheRadius) {
    const float s = std::sqrt(2.0f);
    expectAabb(
        computeAabb(makeRoundedBox(1.0f, 1.0f, 0.25f), makeTransform(0.0f, 0.0f, 0.25f * kPi)),
        -s - 0.25f, -s - 0.25f, s + 0.25f, s + 0.25f);
}

TEST(Aabb, CircleWithOffsetCentreFollowsTheRotation) {
    // Local centre (1, 0) turned a quarter turn lands at (0, 1), then moves by (2, 0).
    expectAabb(computeAabb(Circle{{1.0f, 0.0f}, 0.5f}, makeTransform(2.0f, 0.0f, 0.5f * kPi)), 1.5f,
               0.5f, 2.5f, 1.5f);
}

TEST(Aabb, RotatedCapsuleAndSegment) {
    Capsule capsule{{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f};
    expectAabb(computeAabb(capsule, makeTransform(0.0f, 0.0f, 0.5f * kPi)), -0.5f, -1.5f, 0.5f,
               1.5f);
    Segment segment{{0.0f, 0.0f}, {2.0f, 0.0f}};
    const float h = std::sqrt(2.0f);
    expectAabb(computeAabb(ShapeGeometry{segment}, makeTransform(1.0f, 1.0f, 0.75f * kPi)), 1 - h,
               1, 1, 1 + h);
}

TEST(TestPoint, Circle) {
    Circle circle{{1.0f, 1.0f}, 0.5f};
    EXPECT_TRUE(testPoint(circle, {1.0f, 1.0f}));
    EXPECT_TRUE(testPoint(circle, {1.0f, 1.49f}));
    EXPECT_FALSE(testPoint(circle, {1.36f, 1.36f})); // 0.509 from the centre
}

TEST(TestPoint, Capsule) {
    Capsule capsule{{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f};
    EXPECT_TRUE(testPoint(capsule, {0.3f, 0.49f}));
    EXPECT_FALSE(testPoint(capsule, {0.3f, 0.51f}));
    EXPECT_TRUE(testPoint(capsule, {1.49f, 0.0f}));
    EXPECT_FALSE(testPoint(capsule, {1.36f, 0.36f})); // 0.509 from the cap centre
}

TEST(TestPoint, SegmentContainsNothing) {
    EXPECT_FALSE(testPoint(Segment{{0.0f, 0.0f}, {1.0f, 0.0f}}, {0.5f, 0.0f}));
}

TEST(TestPoint, Box) {
    Polygon box = makeBox(1.0f, 0.5f);
    EXPECT_TRUE(testPoint(box, {0.0f, 0.0f}));
    EXPECT_TRUE(testPoint(box, {0.99f, -0.49f}));
    EXPECT_TRUE(testPoint(box, {1.0f, 0.0f})); // on the boundary
    EXPECT_FALSE(testPoint(box, {1.01f, 0.0f}));
    EXPECT_FALSE(testPoint(box, {0.0f, -0.51f}));
}

TEST(TestPoint, RoundedBoxHasRoundCorners) {
    Polygon box = makeRoundedBox(1.0f, 0.5f, 0.2f);
    EXPECT_TRUE(testPoint(box, {1.19f, 0.0f}));
    EXPECT_FALSE(testPoint(box, {1.21f, 0.0f}));
    // Diagonally off the corner (1, 0.5): 0.19 away is inside, 0.15 * sqrt(2) = 0.212 is not,
    // although both are within 0.2 of each face's line.
    const float h = std::sqrt(0.5f);
    EXPECT_TRUE(testPoint(box, Vec2{1.0f, 0.5f} + 0.19f * Vec2{h, h}));
    EXPECT_FALSE(testPoint(box, {1.15f, 0.65f}));
    EXPECT_TRUE(testPoint(ShapeGeometry{box}, {0.0f, 0.69f}));
}

} // namespace
} // namespace e2d::physics
