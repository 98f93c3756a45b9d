// SPDX-License-Identifier: MIT
#include <e2d/physics/distance.hpp>
#include <e2d/physics/time_of_impact.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geometry_test_util.hpp"

namespace e2d::physics {
namespace {

using test::at;

ShapeProxy boxProxy(float hx, float hy, float radius = 0.0f) {
    std::vector<Vec2> points{{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
    return makeProxy(points, radius);
}

ShapeCastPairInput castInput(const ShapeProxy& a, const Transform& xfA, const ShapeProxy& b,
                             const Transform& xfB, Vec2 translation) {
    ShapeCastPairInput input;
    input.proxyA = a;
    input.proxyB = b;
    input.transformA = xfA;
    input.transformB = xfB;
    input.translationB = translation;
    return input;
}

// A half-0.5 box at x = 5 moves 10 to the left towards a unit box at the origin: faces meet
// when its centre is at 1.5, after 3.5 of the 10.
TEST(ShapeCast, BoxTowardWall) {
    CastOutput out = shapeCast(
        castInput(boxProxy(1, 1), at(0, 0), boxProxy(0.5f, 0.5f), at(5, 0.2f), {-10.0f, 0.0f}));
    ASSERT_TRUE(out.hit);
    EXPECT_NEAR(out.fraction, 0.35f, kShapeCastTolerance / 10.0f);
    EXPECT_NEAR(out.normal.x, 1.0f, 1e-5f);
    EXPECT_NEAR(out.normal.y, 0.0f, 1e-5f);
    EXPECT_NEAR(out.point.x, 1.0f, 1e-4f);
    EXPECT_LE(out.iterations, 3);
}

// Same in a rotated, translated frame for A (a square turned 90 degrees is the same square).
TEST(ShapeCast, BoxTowardRotatedWall) {
    CastOutput out = shapeCast(castInput(boxProxy(1, 1), at(2, 3, 0.5f * 3.14159265f),
                                         boxProxy(0.5f, 0.5f), at(2, 8), {0.0f, -10.0f}));
    ASSERT_TRUE(out.hit);
    EXPECT_NEAR(out.fraction, 0.35f, kShapeCastTolerance / 10.0f);
    EXPECT_NEAR(out.normal.x, 0.0f, 1e-5f);
    EXPECT_NEAR(out.normal.y, 1.0f, 1e-5f);
    EXPECT_NEAR(out.point.y, 4.0f, 1e-4f);
}

// Circle radius 0.5 from (4, 1) moving by (-8, 0) towards a unit circle at the origin: contact
// when |centre| = 1.5, i.e. (4 - 8t)^2 + 1 = 2.25, t = (4 - sqrt(1.25)) / 8.
TEST(ShapeCast, CircleTowardCircleExactFraction) {
    CastOutput out = shapeCast(castInput(makeProxy(Circle{{0, 0}, 1.0f}), at(0, 0),
                                         makeProxy(Circle{{0, 0}, 0.5f}), at(4, 1), {-8.0f, 0.0f}));
    ASSERT_TRUE(out.hit);
    float expected = (4.0f - std::sqrt(1.25f)) / 8.0f;
    // A gap of at most kShapeCastTolerance remains; the centre moves ~8 * cos along the normal.
    EXPECT_NEAR(out.fraction, expected, 1e-4f);
    EXPECT_LE(out.fraction, expected + 1e-6f);
    Vec2 centre{4.0f - 8.0f * expected, 1.0f};
    Vec2 n = centre * (1.0f / 1.5f);
    EXPECT_NEAR(out.normal.x, n.x, 1e-3f);
    EXPECT_NEAR(out.normal.y, n.y, 1e-3f);
    EXPECT_NEAR(out.point.x, n.x, 1e-3f);
    EXPECT_NEAR(out.point.y, n.y, 1e-3f);
}

TEST(ShapeCast, Misses) {
    ShapeProxy a = makeProxy(Circle{{0, 0}, 1.0f});
    ShapeProxy b = makeProxy(Circle{{0, 0}, 0.5f});
    // Moving away.
    EXPECT_FALSE(shapeCast(castInput(a, at(0, 0), b, at(4, 1), {8.0f, 0.0f})).hit);
    // Passing 3 above: never within 1.5.
    EXPECT_FALSE(shapeCast(castInput(a, at(0, 0), b, at(4, 3), {-8.0f, 0.0f})).hit);
    // Stopping short: would need 3.5 of 10, gets 0.3 of it.
    ShapeCastPairInput shortCast =
        castInput(boxProxy(1, 1), at(0, 0), boxProxy(0.5f, 0.5f), at(5, 0), {-10.0f, 0.0f});
    shortCast.maxFraction = 0.3f;
    EXPECT_FALSE(shapeCast(shortCast).hit);
}

TEST(ShapeCast, InitialOverlapHitsAtZero) {
    CastOutput out = shapeCast(
        castInput(boxProxy(1, 1), at(0, 0), boxProxy(0.5f, 0.5f), at(0.5f, 0), {-10.0f, 0.0f}));
    EXPECT_TRUE(out.hit);
    EXPECT_EQ(out.fraction, 0.0f);
    EXPECT_TRUE(isFinite(out.point));
    EXPECT_TRUE(isFinite(out.normal));
}

Sweep still(Vec2 c, float angle = 0.0f) {
    Sweep s;
    s.c1 = c;
    s.c2 = c;
    s.q1 = Rot::fromAngle(angle);
    s.q2 = s.q1;
    return s;
}

Sweep moving(Vec2 c1, Vec2 c2, float angle1 = 0.0f, float angle2 = 0.0f) {
    Sweep s;
    s.c1 = c1;
    s.c2 = c2;
    s.q1 = Rot::fromAngle(angle1);
    s.q2 = Rot::fromAngle(angle2);
    return s;
}

TEST(Sweep, TransformInterpolates) {
    Sweep s = moving({0, 0}, {2, 4}, 0.0f, 1.0f);
    s.localCenter = {1.0f, 0.0f};
    Transform xf = sweepTransform(s, 0.5f);
    EXPECT_NEAR(xf.q.angle(), 0.5f, 1e-6f);
    // The centre of mass (local (1, 0)) is at the interpolated centre (1, 2).
    Vec2 centre = transformPoint(xf, s.localCenter);
    EXPECT_NEAR(centre.x, 1.0f, 1e-6f);
    EXPECT_NEAR(centre.y, 2.0f, 1e-6f);
}

// Polygons (no radius): the target is kLinearSlop between the cores. The half-0.5 box moves
// from x = 5 to x = -5 towards the unit box: gap = 3.5 - 10 t = slop at t = (3.5 - slop) / 10.
TEST(TimeOfImpact, BoxTranslation) {
    TOIInput input;
    input.proxyA = boxProxy(1, 1);
    input.proxyB = boxProxy(0.5f, 0.5f);
    input.sweepA = still({0, 0});
    input.sweepB = moving({5, 0.3f}, {-5, 0.3f});
    TOIOutput out = timeOfImpact(input);
    EXPECT_EQ(out.state, TOIState::Hit);
    EXPECT_NEAR(out.fraction, (3.5f - kLinearSlop) / 10.0f, 0.25f * kLinearSlop / 10.0f);
}

// Circles: target = 1.5 - slop between the centres, reached at t = (4 - 1.5 + slop) / 8.
TEST(TimeOfImpact, CircleCircle) {
    TOIInput input;
    input.proxyA = makeProxy(Circle{{0, 0}, 1.0f});
    input.proxyB = makeProxy(Circle{{0, 0}, 0.5f});
    input.sweepA = still({0, 0});
    input.sweepB = moving({4, 0}, {-4, 0});
    TOIOutput out = timeOfImpact(input);
    EXPECT_EQ(out.state, TOIState::Hit);
    EXPECT_NEAR(out.fraction, (2.5f + kLinearSlop) / 8.0f, 0.25f * kLinearSlop / 8.0f);
}

// A 1 cm wall and a 10 cm box moving at 500 m/s for one 60 Hz step (8.33 m): must hit the wall
// before passing it. Wall at x = 0 (faces at +-0.005); the box starts at x = -2.
TEST(TimeOfImpact, BulletAgainstThinWall) {
    float step = 500.0f / 60.0f;
    TOIInput input;
    input.proxyA = boxProxy(0.005f, 2.0f);
    input.proxyB = boxProxy(0.05f, 0.05f);
    input.sweepA = still({0, 0});
    input.sweepB = moving({-2.0f, 0.1f}, {-2.0f + step, 0.1f}, 0.0f, 0.3f);
    TOIOutput out = timeOfImpact(input);
    ASSERT_EQ(out.state, TOIState::Hit);
    // The box's right face (at most 0.05 * sqrt(2) from its centre, it turns) reaches the wall's
    // left face at x = -0.005.
    float earliest = (2.0f - 0.005f - 0.05f * std::sqrt(2.0f)) / step;
    float latest = (2.0f - 0.005f - 0.05f) / step;
    EXPECT_GE(out.fraction, earliest - 1e-4f);
    EXPECT_LE(out.fraction, latest + 1e-4f);
    // At the reported time the shapes are at the target separation.
    DistanceInput d;
    d.proxyA = input.proxyA;
    d.proxyB = input.proxyB;
    d.transformA = sweepTransform(input.sweepA, out.fraction);
    d.transformB = sweepTransform(input.sweepB, out.fraction);
    d.useRadii = false;
    float gap = shapeDistance(d).distance;
    EXPECT_NEAR(gap, kLinearSlop, 0.25f * kLinearSlop + 1e-5f);
}

// A spinning rod swinging into a box: whatever the time found, no earlier time has the shapes
// closer than the target (conservative), and at the time found they are at the target.
TEST(TimeOfImpact, RotatingRodIsConservative) {
    TOIInput input;
    input.proxyA = boxProxy(0.5f, 0.5f);
    input.proxyB = makeProxy(Capsule{{-2.0f, 0.0f}, {2.0f, 0.0f}, 0.05f});
    input.sweepA = still({0, 0});
    input.sweepB = moving({0.0f, 2.0f}, {0.5f, 2.0f}, 0.0f, 1.2f);
    TOIOutput out = timeOfImpact(input);
    ASSERT_EQ(out.state, TOIState::Hit);
    float target = std::fmax(kLinearSlop, 0.05f - kLinearSlop);
    DistanceInput d;
    d.proxyA = input.proxyA;
    d.proxyB = input.proxyB;
    d.useRadii = false;
    for (int i = 0; i <= 20; ++i) {
        float t = out.fraction * static_cast<float>(i) / 20.0f;
        d.transformA = sweepTransform(input.sweepA, t);
        d.transformB = sweepTransform(input.sweepB, t);
        EXPECT_GT(shapeDistance(d).distance, target - 0.25f * kLinearSlop) << t;
    }
    d.transformB = sweepTransform(input.sweepB, out.fraction);
    EXPECT_NEAR(shapeDistance(d).distance, target, 0.25f * kLinearSlop);
}

TEST(TimeOfImpact, SeparatedAndOverlapped) {
    TOIInput input;
    input.proxyA = boxProxy(1, 1);
    input.proxyB = boxProxy(0.5f, 0.5f);
    input.sweepA = still({0, 0});
    input.sweepB = moving({5, 0}, {3, 0});
    TOIOutput apart = timeOfImpact(input);
    EXPECT_EQ(apart.state, TOIState::Separated);
    EXPECT_EQ(apart.fraction, 1.0f);
    input.sweepB = moving({5, 0}, {9, 0});
    EXPECT_EQ(timeOfImpact(input).state, TOIState::Separated);
    input.sweepB = moving({0.5f, 0}, {5, 0});
    TOIOutput overlapped = timeOfImpact(input);
    EXPECT_EQ(overlapped.state, TOIState::Overlapped);
    EXPECT_EQ(overlapped.fraction, 0.0f);
}

} // namespace
} // namespace e2d::physics
