// SPDX-License-Identifier: MIT
#include <e2d/physics/geometry.hpp>

#include "geometry_test_util.hpp"

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace e2d::physics {
namespace {

using test::errorMessage;
using ::testing::HasSubstr;

float signedArea(const Hull& hull) {
    float area = 0.0f;
    for (int i = 0; i < hull.count; ++i) {
        area += cross(hull.points[i], hull.points[(i + 1) % hull.count]);
    }
    return 0.5f * area;
}

bool hasPoint(const Hull& hull, Vec2 p) {
    for (int i = 0; i < hull.count; ++i) {
        if (hull.points[i] == p) {
            return true;
        }
    }
    return false;
}

void expectStrictlyConvexCcw(const Hull& hull) {
    for (int i = 0; i < hull.count; ++i) {
        Vec2 a = hull.points[i];
        Vec2 b = hull.points[(i + 1) % hull.count];
        Vec2 c = hull.points[(i + 2) % hull.count];
        EXPECT_GT(cross(b - a, c - b), 0.0f) << "at point " << (i + 1) % hull.count;
    }
}

TEST(Hull, SquareWithInteriorPointsKeepsTheCorners) {
    std::vector<Vec2> points{{0.5f, 0.5f}, {0, 0},       {0.2f, 0.7f}, {1, 0},
                             {1, 1},       {0.9f, 0.1f}, {0, 1}};
    Hull hull = computeHull(points);
    ASSERT_EQ(hull.count, 4);
    for (Vec2 corner : {Vec2{0, 0}, Vec2{1, 0}, Vec2{1, 1}, Vec2{0, 1}}) {
        EXPECT_TRUE(hasPoint(hull, corner)) << corner.x << ", " << corner.y;
    }
    EXPECT_FLOAT_EQ(signedArea(hull), 1.0f);
    expectStrictlyConvexCcw(hull);
}

TEST(Hull, ClockwiseInputComesOutCounterClockwise) {
    std::vector<Vec2> clockwise{{0, 0}, {0, 2}, {3, 2}, {3, 0}};
    Hull hull = computeHull(clockwise);
    ASSERT_EQ(hull.count, 4);
    EXPECT_FLOAT_EQ(signedArea(hull), 6.0f); // positive: counter-clockwise
    expectStrictlyConvexCcw(hull);
}

TEST(Hull, DuplicateAndNearDuplicatePointsAreWelded) {
    // 0.001 is closer than kLinearSlop (0.005): welded into the corner it sits next to.
    std::vector<Vec2> points{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {1.001f, 0.0f}, {1, 1.001f}};
    Hull hull = computeHull(points);
    EXPECT_EQ(hull.count, 4);
    expectStrictlyConvexCcw(hull);
}

TEST(Hull, CollinearAndNearlyCollinearPointsOnEdgesAreDropped) {
    // Midpoints of edges, one of them 0.001 outside the edge (within kLinearSlop).
    std::vector<Vec2> points{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2.001f}, {0, 2}, {0, 1}};
    Hull hull = computeHull(points);
    EXPECT_EQ(hull.count, 4);
    for (Vec2 corner : {Vec2{0, 0}, Vec2{2, 0}, Vec2{2, 2}, Vec2{0, 2}}) {
        EXPECT_TRUE(hasPoint(hull, corner));
    }
}

TEST(Hull, AllCollinearPointsAreRejected) {
    std::vector<Vec2> points{{0, 0}, {1, 1}, {2, 2}, {3, 3.001f}};
    EXPECT_EQ(errorMessage([&] { computeHull(points); }),
              "physics::computeHull(): the points are collinear (the hull has no area)");
}

TEST(Hull, FewerThanThreePointsAreRejected) {
    std::vector<Vec2> two{{0, 0}, {1, 0}};
    EXPECT_EQ(errorMessage([&] { computeHull(two); }),
              "physics::computeHull(): expected at least 3 points, got 2");
    std::vector<Vec2> welded{{0, 0}, {1, 0}, {1.002f, 0.0f}};
    EXPECT_EQ(errorMessage([&] { computeHull(welded); }),
              "physics::computeHull(): expected at least 3 distinct points (points closer than "
              "kLinearSlop are welded), got 2");
}

TEST(Hull, NonFiniteAndHugeCoordinatesAreRejected) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<Vec2> withNan{{0, 0}, {nan, 0}, {0, 1}};
    EXPECT_EQ(errorMessage([&] { computeHull(withNan); }),
              "physics::computeHull(): point 1 is not finite, got (nan, 0)");
    std::vector<Vec2> withInf{{0, 0}, {1, 0}, {0, -inf}};
    EXPECT_EQ(errorMessage([&] { computeHull(withInf); }),
              "physics::computeHull(): point 2 is not finite, got (0, -inf)");
    std::vector<Vec2> huge{{0, 0}, {600000, 0}, {0, 1}};
    EXPECT_EQ(errorMessage([&] { computeHull(huge); }),
              "physics::computeHull(): point 1 is beyond kHuge (500000 m), got (600000, 0)");
}

std::vector<Vec2> regularPolygon(int n, float radius) {
    std::vector<Vec2> points;
    for (int i = 0; i < n; ++i) {
        float angle = 2.0f * test::kPi * static_cast<float>(i) / static_cast<float>(n);
        points.push_back({radius * std::cos(angle), radius * std::sin(angle)});
    }
    return points;
}

TEST(Hull, EightPointsAreAllowedNineAreNot) {
    EXPECT_EQ(computeHull(regularPolygon(8, 1.0f)).count, 8);
    EXPECT_EQ(errorMessage([] { computeHull(regularPolygon(9, 1.0f)); }),
              "physics::computeHull(): 9 points on the convex hull, at most 8 allowed");
    EXPECT_EQ(errorMessage([] { computeHull(regularPolygon(11, 1.0f)); }),
              "physics::computeHull(): 11 points on the convex hull, at most 8 allowed");
    // Interior points do not count: a 6-gon cloud with many inner points is fine.
    std::vector<Vec2> cloud = regularPolygon(6, 2.0f);
    for (Vec2 p : regularPolygon(12, 1.0f)) {
        cloud.push_back(p);
    }
    EXPECT_EQ(computeHull(cloud).count, 6);
}

TEST(Hull, LargeCloudInsideAHexagon) {
    // 50 000 points inside the unit disc, many of them within kLinearSlop of each other, and a
    // hexagon of radius 2 around them: the hull is the hexagon.
    std::vector<Vec2> cloud = regularPolygon(6, 2.0f);
    std::mt19937 rng(7);
    for (int i = 0; i < 50000; ++i) {
        float a = 6.2831853f * static_cast<float>(rng() % 100000u) / 100000.0f;
        float r = static_cast<float>(rng() % 1000u) / 1000.0f;
        cloud.push_back({r * std::cos(a), r * std::sin(a)});
    }
    Hull hull = computeHull(cloud);
    ASSERT_EQ(hull.count, 6);
    expectStrictlyConvexCcw(hull);
    EXPECT_NEAR(signedArea(hull), 1.5f * std::sqrt(3.0f) * 4.0f, 1e-4f);
}

TEST(Hull, MakePolygonNamesItselfInErrors) {
    std::vector<Vec2> two{{0, 0}, {1, 0}};
    EXPECT_EQ(errorMessage([&] { makePolygon(two); }),
              "physics::makePolygon(): expected at least 3 points, got 2");
}

} // namespace
} // namespace e2d::physics
