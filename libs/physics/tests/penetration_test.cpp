// SPDX-License-Identifier: MIT
#include <e2d/physics/distance.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geometry_test_util.hpp"

namespace e2d::physics {
namespace {

using test::at;
using test::pair;

constexpr float kTol = 1.0e-5f;

ShapeProxy boxProxy(float hx, float hy, float radius = 0.0f) {
    std::vector<Vec2> points{{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
    return makeProxy(points, radius);
}

void expectFinite(const PenetrationOutput& out) {
    EXPECT_TRUE(isFinite(out.pointA));
    EXPECT_TRUE(isFinite(out.pointB));
    EXPECT_TRUE(isFinite(out.normal));
    EXPECT_TRUE(isFinite(out.depth));
    EXPECT_NEAR(length(out.normal), 1.0f, 1e-5f);
}

// Unit boxes, B at (1.5, 0.2): they overlap by 0.5 in x and 1.8 in y, so x is the way out.
TEST(Penetration, BoxBoxShallowX) {
    PenetrationOutput out =
        penetration(pair(boxProxy(1, 1), at(0, 0), boxProxy(1, 1), at(1.5f, 0.2f)));
    expectFinite(out);
    EXPECT_TRUE(out.converged);
    EXPECT_NEAR(out.depth, 0.5f, kTol);
    EXPECT_NEAR(out.normal.x, 1.0f, kTol);
    EXPECT_NEAR(out.normal.y, 0.0f, kTol);
    // pointA is on A's right face, pointB on B's left face, pointB = pointA - depth * normal.
    EXPECT_NEAR(out.pointA.x, 1.0f, kTol);
    EXPECT_NEAR(out.pointB.x, 0.5f, kTol);
    EXPECT_NEAR(out.pointA.y, out.pointB.y, kTol);
}

// B below A, overlapping by 0.3 in y; A rotated by 90 degrees (a square is unchanged by it).
TEST(Penetration, BoxBoxRotatedFrameY) {
    PenetrationOutput out = penetration(
        pair(boxProxy(1, 1), at(0, 0, 0.5f * 3.14159265f), boxProxy(1, 1), at(0.2f, -1.7f)));
    expectFinite(out);
    EXPECT_NEAR(out.depth, 0.3f, 1e-5f);
    EXPECT_NEAR(out.normal.x, 0.0f, 1e-5f);
    EXPECT_NEAR(out.normal.y, -1.0f, 1e-5f);
}

// Rounded shapes: radii add to the core depth.
TEST(Penetration, RadiiAddToDepth) {
    PenetrationOutput out =
        penetration(pair(boxProxy(1, 1, 0.1f), at(0, 0), boxProxy(1, 1, 0.05f), at(1.5f, 0.2f)));
    expectFinite(out);
    EXPECT_NEAR(out.depth, 0.65f, kTol);
    EXPECT_NEAR(out.normal.x, 1.0f, kTol);
    EXPECT_NEAR(out.pointA.x, 1.1f, kTol);
    EXPECT_NEAR(out.pointB.x, 0.45f, kTol);
    PenetrationOutput cores = penetration(
        pair(boxProxy(1, 1, 0.1f), at(0, 0), boxProxy(1, 1, 0.05f), at(1.5f, 0.2f), false));
    EXPECT_NEAR(cores.depth, 0.5f, kTol);
}

// A circle of radius 0.5 whose centre is inside a unit box, 0.2 from the right face: it must
// move 0.2 + 0.5 to the right.
TEST(Penetration, CircleCentreInsideBox) {
    PenetrationOutput out = penetration(
        pair(boxProxy(1, 1), at(0, 0), makeProxy(Circle{{0, 0}, 0.5f}), at(0.8f, 0.1f)));
    expectFinite(out);
    EXPECT_NEAR(out.depth, 0.7f, kTol);
    EXPECT_NEAR(out.normal.x, 1.0f, kTol);
    EXPECT_NEAR(out.pointA.x, 1.0f, kTol);
    EXPECT_NEAR(out.pointA.y, 0.1f, kTol);
    EXPECT_NEAR(out.pointB.x, 0.3f, kTol);
}

// Rotated, deep: a 45-degree box B at the centre of a 2 x 1 box A. A's closest faces are the
// top and bottom (half-height 1) and B's corners stick out sqrt(2)*0.5 vertically, so the
// depth along y is 1 + sqrt(2)/2 ... but along B's face normals (45 degrees) it is the support
// width of A along (1,1)/sqrt(2), (2 + 1)/sqrt(2), plus B's half-width 0.5: larger. So y wins.
TEST(Penetration, DeepRotated) {
    PenetrationOutput out = penetration(
        pair(boxProxy(2, 1), at(0, 0), boxProxy(0.5f, 0.5f), at(0, 0.1f, 0.25f * 3.14159265f)));
    expectFinite(out);
    EXPECT_NEAR(out.depth, 1.0f + 0.5f * std::sqrt(2.0f) - 0.1f, 1e-5f);
    EXPECT_NEAR(out.normal.x, 0.0f, 1e-5f);
    EXPECT_NEAR(out.normal.y, 1.0f, 1e-5f);
    EXPECT_LE(out.iterations, kMaxGjkIterations + kMaxEpaIterations);
}

// Identical boxes at one place: every face needs the full width 2.
TEST(Penetration, IdenticalBoxes) {
    PenetrationOutput out = penetration(pair(boxProxy(1, 1), at(3, 3), boxProxy(1, 1), at(3, 3)));
    expectFinite(out);
    EXPECT_NEAR(out.depth, 2.0f, kTol);
    EXPECT_NEAR(std::fabs(out.normal.x) + std::fabs(out.normal.y), 1.0f, kTol);
}

TEST(Penetration, TouchingBoxesHaveZeroDepthAndFaceNormal) {
    PenetrationOutput out =
        penetration(pair(boxProxy(1, 1), at(0, 0), boxProxy(1, 1), at(2, 0.5f)));
    expectFinite(out);
    EXPECT_NEAR(out.depth, 0.0f, kTol);
    EXPECT_NEAR(out.normal.x, 1.0f, kTol);
}

TEST(Penetration, SeparatedGivesMinusDistance) {
    PenetrationOutput out = penetration(pair(boxProxy(1, 1), at(0, 0), boxProxy(1, 1), at(3, 3)));
    expectFinite(out);
    EXPECT_NEAR(out.depth, -std::sqrt(2.0f), kTol);
    EXPECT_NEAR(out.normal.x, std::sqrt(0.5f), kTol);
}

TEST(Penetration, FlatMinkowskiDifferenceFallsBack) {
    ShapeProxy s = makeProxy(Segment{{0.0f, 0.0f}, {1.0f, 0.0f}});
    PenetrationOutput out = penetration(pair(s, at(0, 0), s, at(0.5f, 0)));
    expectFinite(out);
    EXPECT_FALSE(out.converged);
    EXPECT_EQ(out.depth, 0.0f);
    EXPECT_NEAR(std::fabs(out.normal.y), 1.0f, kTol);
    std::vector<Vec2> origin{{0.0f, 0.0f}};
    ShapeProxy point = makeProxy(origin, 0.25f);
    PenetrationOutput points = penetration(pair(point, at(1, 1), point, at(1, 1)));
    expectFinite(points);
    EXPECT_NEAR(points.depth, 0.5f, kTol);
}

} // namespace
} // namespace e2d::physics
