// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
#include <e2d/physics/distance.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geometry_test_util.hpp"

namespace e2d::physics {
namespace {

using test::at;
using test::pair;

using ::testing::HasSubstr;

constexpr float kTol = 1.0e-5f;

ShapeProxy boxProxy(float hx, float hy, float radius = 0.0f) {
    std::vector<Vec2> points{{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
    return makeProxy(points, radius);
}

ShapeProxy pointProxy(Vec2 p, float radius) {
    std::vector<Vec2> points{p};
    return makeProxy(points, radius);
}

void expectFinite(const DistanceOutput& out) {
    EXPECT_TRUE(isFinite(out.pointA));
    EXPECT_TRUE(isFinite(out.pointB));
    EXPECT_TRUE(isFinite(out.normal));
    EXPECT_TRUE(isFinite(out.distance));
    EXPECT_GE(out.distance, 0.0f);
    EXPECT_LE(out.iterations, kMaxGjkIterations);
}

TEST(MakeProxy, RejectsBadInput) {
    std::vector<Vec2> none;
    EXPECT_THAT([&] { (void)makeProxy(none, 0.0f); },
                ::testing::ThrowsMessage<core::Error>(
                    HasSubstr("physics::makeProxy(): expected 1 to 8 points, got 0")));
    std::vector<Vec2> nine(9, Vec2{0.0f, 0.0f});
    EXPECT_THAT([&] { (void)makeProxy(nine, 0.0f); },
                ::testing::ThrowsMessage<core::Error>(HasSubstr("got 9")));
    std::vector<Vec2> one{{0.0f, 0.0f}};
    EXPECT_THAT([&] { (void)makeProxy(one, -1.0f); },
                ::testing::ThrowsMessage<core::Error>(HasSubstr(
                    "physics::makeProxy(): radius must be finite, >= 0 and within kHuge, got -1")));
    std::vector<Vec2> bad{{0.0f, 0.0f}, {NAN, 1.0f}};
    EXPECT_THAT(
        [&] { (void)makeProxy(bad, 0.0f); },
        ::testing::ThrowsMessage<core::Error>(HasSubstr(
            "physics::makeProxy(): point 1 must be finite and within kHuge, got (nan, 1)")));
    std::vector<Vec2> far{{0.0f, 0.0f}, {1.0f, 6.0e5f}};
    EXPECT_THAT([&] { (void)makeProxy(far, 0.0f); },
                ::testing::ThrowsMessage<core::Error>(HasSubstr("got (1, 600000)")));
}

TEST(MakeProxy, FromShapes) {
    ShapeProxy c = makeProxy(ShapeGeometry{Circle{{1.0f, 2.0f}, 0.5f}});
    EXPECT_EQ(c.count, 1);
    EXPECT_EQ(c.points[0], Vec2(1.0f, 2.0f));
    EXPECT_EQ(c.radius, 0.5f);
    ShapeProxy cap = makeProxy(Capsule{{0.0f, 0.0f}, {2.0f, 0.0f}, 0.25f});
    EXPECT_EQ(cap.count, 2);
    EXPECT_EQ(cap.points[1], Vec2(2.0f, 0.0f));
    EXPECT_EQ(cap.radius, 0.25f);
    ShapeProxy seg = makeProxy(Segment{{0.0f, 0.0f}, {0.0f, 3.0f}});
    EXPECT_EQ(seg.count, 2);
    EXPECT_EQ(seg.radius, 0.0f);
}

// Unit boxes (half-extent 1), B three to the right and 0.5 up: faces x = 1 and x = 2 face each
// other, gap 1, overlapping in y over [-0.5, 1].
TEST(ShapeDistance, BoxBoxEdgeEdge) {
    DistanceOutput out = shapeDistance(pair(boxProxy(1, 1), at(0, 0), boxProxy(1, 1), at(3, 0.5f)));
    expectFinite(out);
    EXPECT_NEAR(out.distance, 1.0f, kTol);
    EXPECT_NEAR(out.normal.x, 1.0f, kTol);
    EXPECT_NEAR(out.normal.y, 0.0f, kTol);
    EXPECT_NEAR(out.pointA.x, 1.0f, kTol);
    EXPECT_NEAR(out.pointB.x, 2.0f, kTol);
    EXPECT_NEAR(out.pointA.y, out.pointB.y, kTol);
    EXPECT_GE(out.pointA.y, -0.5f - kTol);
    EXPECT_LE(out.pointA.y, 1.0f + kTol);
}

// B is a unit box turned 45 degrees: its left corner lies sqrt(2) left of its centre. With the
// centre at 1.5 + sqrt(2) that corner is at (1.5, 0), 0.5 from A's face x = 1.
TEST(ShapeDistance, BoxBoxVertexEdge) {
    float cx = 1.5f + std::sqrt(2.0f);
    DistanceOutput out = shapeDistance(
        pair(boxProxy(1, 1), at(0, 0), boxProxy(1, 1), at(cx, 0.0f, 0.25f * 3.14159265f)));
    expectFinite(out);
    EXPECT_NEAR(out.distance, 0.5f, kTol);
    EXPECT_NEAR(out.pointA.x, 1.0f, kTol);
    EXPECT_NEAR(out.pointA.y, 0.0f, 1e-4f);
    EXPECT_NEAR(out.pointB.x, 1.5f, kTol);
    EXPECT_NEAR(out.pointB.y, 0.0f, 1e-4f);
    EXPECT_NEAR(out.normal.x, 1.0f, kTol);
}

// Corners (1, 1) and (2, 2) are closest: distance sqrt(2) along the diagonal.
TEST(ShapeDistance, BoxBoxVertexVertex) {
    DistanceOutput out = shapeDistance(pair(boxProxy(1, 1), at(0, 0), boxProxy(1, 1), at(3, 3)));
    expectFinite(out);
    EXPECT_NEAR(out.distance, std::sqrt(2.0f), kTol);
    EXPECT_NEAR(out.pointA.x, 1.0f, kTol);
    EXPECT_NEAR(out.pointA.y, 1.0f, kTol);
    EXPECT_NEAR(out.pointB.x, 2.0f, kTol);
    EXPECT_NEAR(out.pointB.y, 2.0f, kTol);
    EXPECT_NEAR(out.normal.x, std::sqrt(0.5f), kTol);
    EXPECT_NEAR(out.normal.y, std::sqrt(0.5f), kTol);
}

// Circles of radius 1 and 0.5, centres 5 apart along (3, 4): gap 3.5.
TEST(ShapeDistance, CircleCircle) {
    DistanceOutput out = shapeDistance(
        pair(makeProxy(Circle{{0, 0}, 1.0f}), at(0, 0), makeProxy(Circle{{0, 0}, 0.5f}), at(3, 4)));
    expectFinite(out);
    EXPECT_NEAR(out.distance, 3.5f, kTol);
    EXPECT_NEAR(out.pointA.x, 0.6f, kTol);
    EXPECT_NEAR(out.pointA.y, 0.8f, kTol);
    EXPECT_NEAR(out.pointB.x, 2.7f, kTol);
    EXPECT_NEAR(out.pointB.y, 3.6f, kTol);
    EXPECT_NEAR(out.normal.x, 0.6f, kTol);
    EXPECT_NEAR(out.normal.y, 0.8f, kTol);

    DistanceOutput cores = shapeDistance(pair(makeProxy(Circle{{0, 0}, 1.0f}), at(0, 0),
                                              makeProxy(Circle{{0, 0}, 0.5f}), at(3, 4), false));
    EXPECT_NEAR(cores.distance, 5.0f, kTol);
}

// A 4 x 2 box turned 90 degrees at (10, 10) spans x in [9, 11]; a circle of radius 0.5 at
// (13, 10) is 1.5 from it.
TEST(ShapeDistance, CircleBoxTransformed) {
    DistanceOutput out = shapeDistance(pair(boxProxy(2, 1), at(10, 10, 0.5f * 3.14159265f),
                                            makeProxy(Circle{{0.5f, 0.0f}, 0.5f}), at(12.5f, 10)));
    expectFinite(out);
    EXPECT_NEAR(out.distance, 1.5f, 1e-4f);
    EXPECT_NEAR(out.pointA.x, 11.0f, 1e-4f);
    EXPECT_NEAR(out.pointA.y, 10.0f, 1e-4f);
    EXPECT_NEAR(out.pointB.x, 12.5f, 1e-4f);
    EXPECT_NEAR(out.normal.x, 1.0f, 1e-4f);
}

// Rounded shapes whose rounded surfaces overlap: distance 0, one point in the overlap.
TEST(ShapeDistance, RoundedOverlapGivesZero) {
    DistanceOutput out = shapeDistance(
        pair(boxProxy(1, 1, 0.2f), at(0, 0), makeProxy(Circle{{0, 0}, 0.5f}), at(1.5f, 0)));
    expectFinite(out);
    EXPECT_EQ(out.distance, 0.0f);
    EXPECT_EQ(out.pointA, out.pointB);
    // Surfaces at x = 1.2 (A) and x = 1.0 (B): the middle of the overlap is 1.1.
    EXPECT_NEAR(out.pointA.x, 1.1f, kTol);
}

TEST(ShapeDistance, SymmetricUnderSwap) {
    ShapeProxy a = boxProxy(1.0f, 0.5f);
    std::vector<Vec2> tri{{0.0f, 0.0f}, {1.0f, 0.2f}, {0.3f, 0.9f}};
    ShapeProxy b = makeProxy(tri, 0.1f);
    Transform xfA = at(0.3f, -0.2f, 0.4f);
    Transform xfB = at(2.2f, 1.1f, -1.3f);
    DistanceOutput ab = shapeDistance(pair(a, xfA, b, xfB));
    DistanceOutput ba = shapeDistance(pair(b, xfB, a, xfA));
    expectFinite(ab);
    expectFinite(ba);
    EXPECT_GT(ab.distance, 0.1f);
    EXPECT_NEAR(ab.distance, ba.distance, kTol);
    EXPECT_NEAR(ab.pointA.x, ba.pointB.x, 1e-4f);
    EXPECT_NEAR(ab.pointA.y, ba.pointB.y, 1e-4f);
    EXPECT_NEAR(ab.normal.x, -ba.normal.x, 1e-4f);
    EXPECT_NEAR(ab.normal.y, -ba.normal.y, 1e-4f);
    // The reported distance is the distance between the reported points.
    EXPECT_NEAR(distance(ab.pointA, ab.pointB), ab.distance, kTol);
}

TEST(ShapeDistance, WarmStartGivesSameAnswer) {
    ShapeProxy a = boxProxy(1.0f, 0.5f);
    std::vector<Vec2> hexagon;
    for (int i = 0; i < 6; ++i) {
        float angle = static_cast<float>(i) * 3.14159265f / 3.0f;
        hexagon.push_back({0.7f * std::cos(angle), 0.7f * std::sin(angle)});
    }
    ShapeProxy b = makeProxy(hexagon, 0.0f);
    SimplexCache cache;
    for (int step = 0; step < 20; ++step) {
        Transform xfB =
            at(2.5f - 0.02f * static_cast<float>(step), 0.4f, 0.05f * static_cast<float>(step));
        DistanceInput input = pair(a, at(0, 0), b, xfB);
        DistanceOutput cold = shapeDistance(input);
        SimplexCache before = cache;
        DistanceOutput warm = shapeDistance(input, &cache);
        EXPECT_NEAR(cold.distance, warm.distance, 1e-6f) << step;
        EXPECT_NEAR(cold.pointA.x, warm.pointA.x, 1e-5f) << step;
        EXPECT_NEAR(cold.pointA.y, warm.pointA.y, 1e-5f) << step;
        EXPECT_NEAR(cold.pointB.x, warm.pointB.x, 1e-5f) << step;
        EXPECT_NEAR(cold.pointB.y, warm.pointB.y, 1e-5f) << step;
        if (step > 0) {
            // Small motion: the old simplex is (nearly) the answer.
            EXPECT_LE(warm.iterations, cold.iterations) << step;
        }
        EXPECT_GE(cache.count, 1);
        (void)before;
    }
    // The same query again with the cache needs no new support point.
    DistanceInput again = pair(a, at(0, 0), b, at(2.0f, 0.4f, 0.3f));
    (void)shapeDistance(again, &cache);
    DistanceOutput repeat = shapeDistance(again, &cache);
    EXPECT_LE(repeat.iterations, 1);
}

TEST(ShapeDistance, TouchingBoxes) {
    DistanceOutput out = shapeDistance(pair(boxProxy(1, 1), at(0, 0), boxProxy(1, 1), at(2, 0.3f)));
    expectFinite(out);
    EXPECT_NEAR(out.distance, 0.0f, 1e-6f);
}

TEST(ShapeDistance, IdenticalShapesSamePlace) {
    std::vector<Vec2> tri{{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}};
    ShapeProxy p = makeProxy(tri, 0.0f);
    DistanceOutput out = shapeDistance(pair(p, at(1, 2, 0.3f), p, at(1, 2, 0.3f)));
    expectFinite(out);
    EXPECT_EQ(out.distance, 0.0f);
    EXPECT_EQ(out.normal, Vec2(0.0f, 0.0f));
}

TEST(ShapeDistance, CollinearSegments) {
    ShapeProxy s = makeProxy(Segment{{0.0f, 0.0f}, {1.0f, 0.0f}});
    DistanceOutput apart = shapeDistance(pair(s, at(0, 0), s, at(2, 0)));
    expectFinite(apart);
    EXPECT_NEAR(apart.distance, 1.0f, kTol);
    EXPECT_NEAR(apart.pointA.x, 1.0f, kTol);
    EXPECT_NEAR(apart.pointB.x, 2.0f, kTol);
    DistanceOutput overlapping = shapeDistance(pair(s, at(0, 0), s, at(0.5f, 0)));
    expectFinite(overlapping);
    EXPECT_NEAR(overlapping.distance, 0.0f, 1e-6f);
    // Parallel segments one above the other: every pair of facing points is closest.
    DistanceOutput parallel = shapeDistance(pair(s, at(0, 0), s, at(0.25f, 2)));
    expectFinite(parallel);
    EXPECT_NEAR(parallel.distance, 2.0f, kTol);
    EXPECT_NEAR(parallel.normal.y, 1.0f, kTol);
}

TEST(ShapeDistance, OnePointProxies) {
    DistanceOutput out =
        shapeDistance(pair(pointProxy({0, 0}, 0.0f), at(1, 1), pointProxy({0, 0}, 0.0f), at(4, 5)));
    expectFinite(out);
    EXPECT_NEAR(out.distance, 5.0f, kTol);
    EXPECT_LE(out.iterations, 1);
    DistanceOutput same =
        shapeDistance(pair(pointProxy({0, 0}, 0.0f), at(1, 1), pointProxy({0, 0}, 0.0f), at(1, 1)));
    expectFinite(same);
    EXPECT_EQ(same.distance, 0.0f);
    // A point inside a box.
    DistanceOutput inside =
        shapeDistance(pair(boxProxy(1, 1), at(0, 0), pointProxy({0, 0}, 0.0f), at(0.2f, 0.3f)));
    expectFinite(inside);
    EXPECT_EQ(inside.distance, 0.0f);
}

TEST(ShapeDistance, DuplicatedPoints) {
    std::vector<Vec2> doubled{{-1, -1}, {-1, -1}, {1, -1}, {1, -1},
                              {1, 1},   {1, 1},   {-1, 1}, {-1, 1}};
    ShapeProxy box = makeProxy(doubled, 0.0f);
    for (int i = 0; i < 16; ++i) {
        float angle = static_cast<float>(i) * 0.3927f;
        Transform xfB = at(3.0f * std::cos(angle), 3.0f * std::sin(angle), angle);
        DistanceOutput out = shapeDistance(pair(box, at(0, 0), box, xfB));
        DistanceOutput reference =
            shapeDistance(pair(boxProxy(1, 1), at(0, 0), boxProxy(1, 1), xfB));
        expectFinite(out);
        EXPECT_NEAR(out.distance, reference.distance, 1e-5f) << i;
    }
}

} // namespace
} // namespace e2d::physics
