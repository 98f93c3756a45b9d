// SPDX-License-Identifier: MIT
#include <e2d/physics/geometry.hpp>

#include "geometry_test_util.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace e2d::physics {
namespace {

using test::errorMessage;
using test::kPi;

TEST(Polygon, BoxVerticesNormalsAndCentroid) {
    Polygon box = makeBox(1.0f, 2.0f);
    ASSERT_EQ(box.count, 4);
    EXPECT_EQ(box.radius, 0.0f);
    E2D_EXPECT_VEC2_NEAR(box.centroid, 0.0f, 0.0f, 0.0f);
    const Vec2 vertices[4] = {{-1, -2}, {1, -2}, {1, 2}, {-1, 2}};
    const Vec2 normals[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    for (int i = 0; i < 4; ++i) {
        E2D_EXPECT_VEC2_NEAR(box.vertices[i], vertices[i].x, vertices[i].y, 0.0f);
        E2D_EXPECT_VEC2_NEAR(box.normals[i], normals[i].x, normals[i].y, 0.0f);
    }
}

TEST(Polygon, OffsetBoxIsRotatedThenMoved) {
    // A quarter turn maps (x, y) to (-y, x); then the centre (2, 3) is added.
    Polygon box = makeOffsetBox(1.0f, 0.5f, {2.0f, 3.0f}, 0.5f * kPi);
    ASSERT_EQ(box.count, 4);
    E2D_EXPECT_VEC2_NEAR(box.centroid, 2.0f, 3.0f, 1e-6f);
    E2D_EXPECT_VEC2_NEAR(box.vertices[0], 2.5f, 2.0f, 1e-6f); // from (-1, -0.5)
    E2D_EXPECT_VEC2_NEAR(box.vertices[2], 1.5f, 4.0f, 1e-6f); // from (1, 0.5)
    E2D_EXPECT_VEC2_NEAR(box.normals[0], 1.0f, 0.0f, 1e-6f);  // from (0, -1)
    E2D_EXPECT_VEC2_NEAR(box.normals[1], 0.0f, 1.0f, 1e-6f);  // from (1, 0)
}

TEST(Polygon, RoundedBoxKeepsTheCoreAndTheRadius) {
    Polygon box = makeRoundedBox(1.0f, 0.5f, 0.25f);
    EXPECT_EQ(box.radius, 0.25f);
    E2D_EXPECT_VEC2_NEAR(box.vertices[2], 1.0f, 0.5f, 0.0f);
}

TEST(Polygon, TriangleCentroidAndNormals) {
    std::vector<Vec2> points{{0, 3}, {3, 0}, {0, 0}};
    Polygon triangle = makePolygon(points, 0.1f);
    ASSERT_EQ(triangle.count, 3);
    EXPECT_EQ(triangle.radius, 0.1f);
    E2D_EXPECT_VEC2_NEAR(triangle.centroid, 1.0f, 1.0f, 1e-6f);
    const float h = std::sqrt(0.5f);
    for (int i = 0; i < 3; ++i) {
        // Each normal is a unit vector pointing away from the centroid, perpendicular to its edge.
        Vec2 a = triangle.vertices[i];
        Vec2 b = triangle.vertices[(i + 1) % 3];
        Vec2 n = triangle.normals[i];
        EXPECT_NEAR(length(n), 1.0f, 1e-6f);
        EXPECT_NEAR(dot(n, b - a), 0.0f, 1e-6f);
        EXPECT_GT(dot(n, a - triangle.centroid), 0.0f);
        if (a == Vec2{3, 0}) {
            E2D_EXPECT_VEC2_NEAR(n, h, h, 1e-6f);
        }
    }
}

TEST(Polygon, BadSizesNameTheFunctionAndTheValue) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(
        errorMessage([] { makeBox(-1.0f, 1.0f); }),
        "physics::makeBox(): half-extent hx must be finite and in (0, kHuge (500000 m)], got -1");
    EXPECT_EQ(
        errorMessage([&] { makeBox(1.0f, nan); }),
        "physics::makeBox(): half-extent hy must be finite and in (0, kHuge (500000 m)], got nan");
    EXPECT_EQ(
        errorMessage([] { makeBox(0.5f, 0.0f); }),
        "physics::makeBox(): half-extent hy must be finite and in (0, kHuge (500000 m)], got 0");
    EXPECT_EQ(errorMessage([] {
                  makeOffsetBox(0.0f, 1.0f, {0, 0}, 0.0f);
              }),
              "physics::makeOffsetBox(): half-extent hx must be finite and in (0, kHuge (500000 "
              "m)], got 0");
    EXPECT_EQ(errorMessage([&] {
                  makeOffsetBox(1.0f, 1.0f, {nan, 0}, 0.0f);
              }),
              "physics::makeOffsetBox(): center must be finite and within kHuge, got (nan, 0)");
    EXPECT_EQ(errorMessage([] {
                  makeOffsetBox(1.0f, 1.0f, {0, 0}, std::numeric_limits<float>::infinity());
              }),
              "physics::makeOffsetBox(): angle must be finite, got inf");
    EXPECT_EQ(
        errorMessage([] { makeRoundedBox(1.0f, 1.0f, -0.1f); }),
        "physics::makeRoundedBox(): radius must be finite and in [0, kHuge (500000 m)], got -0.1");
    std::vector<Vec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    EXPECT_EQ(errorMessage([&] { makePolygon(square, -2.0f); }),
              "physics::makePolygon(): radius must be finite and in [0, kHuge (500000 m)], got -2");
}

TEST(Polygon, HandMadeHullsAreChecked) {
    Hull tooSmall;
    tooSmall.count = 2;
    EXPECT_EQ(errorMessage([&] { makePolygon(tooSmall); }),
              "physics::makePolygon(): hull has 2 points, expected 3 to 8 (use computeHull())");
    Hull clockwise;
    clockwise.count = 3;
    clockwise.points[0] = {0, 0};
    clockwise.points[1] = {0, 1};
    clockwise.points[2] = {1, 0};
    EXPECT_EQ(errorMessage([&] { makePolygon(clockwise); }),
              "physics::makePolygon(): hull is not strictly convex and counter-clockwise at point "
              "1 (0, 1) (use computeHull())");
}

TEST(Validate, AcceptsGoodShapes) {
    EXPECT_NO_THROW(validate(Circle{{1, 2}, 0.5f}, "test()"));
    EXPECT_NO_THROW(validate(Capsule{{0, 0}, {1, 0}, 0.5f}, "test()"));
    EXPECT_NO_THROW(validate(Segment{{0, 0}, {1, 0}}, "test()"));
    EXPECT_NO_THROW(validate(makeRoundedBox(1.0f, 1.0f, 0.1f), "test()"));
    EXPECT_NO_THROW(validate(makeOffsetBox(1.0f, 1.0f, {3, 4}, 1.0f), "test()"));
}

TEST(Validate, NamesTheCallerAndTheBadValue) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const char* fn = "physics::World::createShape()";
    EXPECT_EQ(errorMessage([&] {
                  validate(Circle{{0, 0}, 0.0f}, fn);
              }),
              "physics::World::createShape(): circle radius must be finite and in (0, kHuge "
              "(500000 m)], got 0");
    EXPECT_EQ(errorMessage([&] {
                  validate(Circle{{nan, 0}, 1.0f}, fn);
              }),
              "physics::World::createShape(): circle center must be finite and within kHuge, got "
              "(nan, 0)");
    EXPECT_EQ(errorMessage([&] {
                  validate(Capsule{{0, 0}, {1, 0}, -1.0f}, fn);
              }),
              "physics::World::createShape(): capsule radius must be finite and in (0, kHuge "
              "(500000 m)], got -1");
    EXPECT_EQ(errorMessage([&] {
                  validate(Capsule{{0, 0}, {0.001f, 0}, 1.0f}, fn);
              }),
              "physics::World::createShape(): capsule centers must be at least kLinearSlop (0.005 "
              "m) apart, got 0.001 (use a Circle)");
    EXPECT_EQ(errorMessage([&] {
                  validate(Segment{{1, 1}, {1, 1}}, fn);
              }),
              "physics::World::createShape(): segment points must be at least kLinearSlop (0.005 "
              "m) apart, got 0");
    Polygon empty;
    EXPECT_EQ(errorMessage([&] { validate(empty, fn); }),
              "physics::World::createShape(): polygon has 0 vertices, expected 3 to 8 (use "
              "makePolygon())");
    Polygon negative = makeBox(1.0f, 1.0f);
    negative.radius = -0.5f;
    EXPECT_EQ(errorMessage([&] { validate(negative, fn); }),
              "physics::World::createShape(): polygon radius must be finite and in [0, kHuge "
              "(500000 m)], got -0.5");
    Polygon inside = makeBox(1.0f, 1.0f);
    inside.vertices[2] = {0.0f, 0.0f}; // dents the box
    EXPECT_EQ(errorMessage([&] { validate(inside, fn); }),
              "physics::World::createShape(): polygon is not strictly convex and counter-clockwise "
              "at vertex 2 (use makePolygon())");
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(errorMessage([&] {
                  validate(Capsule{{0, 0}, {inf, 0}, 1.0f}, fn);
              }),
              "physics::World::createShape(): capsule centers must be finite and within kHuge, got "
              "(0, 0) and (inf, 0)");
    EXPECT_EQ(errorMessage([&] {
                  validate(Segment{{0, 0}, {0, 6e5f}}, fn);
              }),
              "physics::World::createShape(): segment points must be finite and within kHuge, got "
              "(0, 0) and (0, 600000)");
    Polygon farVertex = makeBox(1.0f, 1.0f);
    farVertex.vertices[3] = {nan, 1.0f};
    EXPECT_EQ(
        errorMessage([&] { validate(farVertex, fn); }),
        "physics::World::createShape(): polygon vertex 3 must be finite and within kHuge, got "
        "(nan, 1)");
    Polygon badCentroid = makeBox(1.0f, 1.0f);
    badCentroid.centroid = {0.0f, -inf};
    EXPECT_EQ(
        errorMessage([&] { validate(badCentroid, fn); }),
        "physics::World::createShape(): polygon centroid must be finite and within kHuge, got "
        "(0, -inf)");
    Polygon badNormal = makeBox(1.0f, 1.0f);
    badNormal.normals[1] = {2.0f, 0.0f};
    EXPECT_EQ(errorMessage([&] { validate(badNormal, fn); }),
              "physics::World::createShape(): polygon normal 1 must be a unit vector, got (2, 0) "
              "(use makePolygon())");
}

} // namespace
} // namespace e2d::physics
