// SPDX-License-Identifier: MIT
#include <e2d/physics/geometry.hpp>

#include "geometry_test_util.hpp"

#include <cmath>

namespace e2d::physics {
namespace {

void expectHit(const CastOutput& out, float fraction, Vec2 point, Vec2 normal) {
    ASSERT_TRUE(out.hit);
    EXPECT_NEAR(out.fraction, fraction, 1e-5f);
    E2D_EXPECT_VEC2_NEAR(out.point, point.x, point.y, 1e-5f);
    E2D_EXPECT_VEC2_NEAR(out.normal, normal.x, normal.y, 1e-5f);
}

TEST(RayCast, CircleHitFromTheQuadratic) {
    // Ray y = 2.3 from x = -3 towards +x, circle centre (1, 2), r = 0.5:
    // (x - 1)^2 + 0.3^2 = 0.5^2 gives x = 1 - 0.4 = 0.6 on the near side, t = 3.6 / 10.
    Circle circle{{1.0f, 2.0f}, 0.5f};
    RayCastInput input{{-3.0f, 2.3f}, {10.0f, 0.0f}, 1.0f};
    expectHit(rayCast(input, circle), 0.36f, {0.6f, 2.3f}, {-0.8f, 0.6f});
    expectHit(rayCast(input, ShapeGeometry{circle}), 0.36f, {0.6f, 2.3f}, {-0.8f, 0.6f});
}

TEST(RayCast, CircleMissesAndStartsInside) {
    Circle circle{{1.0f, 2.0f}, 0.5f};
    EXPECT_FALSE(
        rayCast(RayCastInput{{-3.0f, 2.6f}, {10.0f, 0.0f}, 1.0f}, circle).hit); // passes by
    EXPECT_FALSE(
        rayCast(RayCastInput{{-3.0f, 2.3f}, {10.0f, 0.0f}, 0.35f}, circle).hit);        // too short
    EXPECT_FALSE(rayCast(RayCastInput{{1.1f, 2.0f}, {10.0f, 0.0f}, 1.0f}, circle).hit); // inside
    EXPECT_FALSE(rayCast(RayCastInput{{-3.0f, 2.0f}, {-10.0f, 0.0f}, 1.0f}, circle).hit); // away
    EXPECT_FALSE(rayCast(RayCastInput{{-3.0f, 2.0f}, {0.0f, 0.0f}, 1.0f}, circle).hit); // no length
}

TEST(RayCast, BoxKnownFaces) {
    Polygon box = makeBox(1.0f, 0.5f);
    expectHit(rayCast(RayCastInput{{-3.0f, 0.2f}, {4.0f, 0.0f}, 1.0f}, box), 0.5f, {-1.0f, 0.2f},
              {-1.0f, 0.0f});
    expectHit(rayCast(RayCastInput{{0.3f, 2.0f}, {0.0f, -3.0f}, 1.0f}, box), 0.5f, {0.3f, 0.5f},
              {0.0f, 1.0f});
    // Diagonal into the corner region: enters through the right face at y = 0.25.
    expectHit(rayCast(RayCastInput{{2.0f, 1.25f}, {-2.0f, -2.0f}, 1.0f}, box), 0.5f, {1.0f, 0.25f},
              {1.0f, 0.0f});
}

TEST(RayCast, BoxMissStartInsideAndBackFace) {
    Polygon box = makeBox(1.0f, 0.5f);
    EXPECT_FALSE(rayCast(RayCastInput{{-3.0f, 0.6f}, {6.0f, 0.0f}, 1.0f}, box).hit); // above it
    EXPECT_FALSE(rayCast(RayCastInput{{0.0f, 0.0f}, {3.0f, 0.0f}, 1.0f}, box).hit);  // inside
    EXPECT_FALSE(rayCast(RayCastInput{{2.0f, 0.0f}, {3.0f, 0.0f}, 1.0f}, box).hit);  // moving away
    EXPECT_FALSE(rayCast(RayCastInput{{-3.0f, 0.0f}, {4.0f, 0.0f}, 0.4f}, box).hit); // too short
}

TEST(RayCast, RotatedBoxHitsItsCorner) {
    // A 2 x 2 box turned 45 degrees has a corner at (-sqrt(2), 0).
    Polygon diamond = makeOffsetBox(1.0f, 1.0f, {0.0f, 0.0f}, 0.25f * test::kPi);
    CastOutput out = rayCast(RayCastInput{{-5.0f, 0.0f}, {10.0f, 0.0f}, 1.0f}, diamond);
    ASSERT_TRUE(out.hit);
    EXPECT_NEAR(out.fraction, (5.0f - std::sqrt(2.0f)) / 10.0f, 1e-5f);
    EXPECT_NEAR(out.normal.x, -std::sqrt(0.5f), 1e-5f);
    EXPECT_NEAR(std::fabs(out.normal.y), std::sqrt(0.5f), 1e-5f);
}

TEST(RayCast, RoundedBoxFaceAndCorner) {
    Polygon box = makeRoundedBox(1.0f, 0.5f, 0.25f);
    // Face: the left side is pushed out to x = -1.25.
    expectHit(rayCast(RayCastInput{{-3.0f, 0.0f}, {3.0f, 0.0f}, 1.0f}, box), 1.75f / 3.0f,
              {-1.25f, 0.0f}, {-1.0f, 0.0f});
    // Corner arc around (-1, 0.5): at y = 0.7 the arc is at x = -1 - sqrt(0.25^2 - 0.2^2) = -1.15.
    expectHit(rayCast(RayCastInput{{-3.0f, 0.7f}, {4.0f, 0.0f}, 1.0f}, box), 1.85f / 4.0f,
              {-1.15f, 0.7f}, {-0.6f, 0.8f});
    // Misses just past the arc, and does not hit from inside.
    EXPECT_FALSE(rayCast(RayCastInput{{-3.0f, 0.76f}, {4.0f, 0.0f}, 1.0f}, box).hit);
    EXPECT_FALSE(rayCast(RayCastInput{{-1.2f, 0.0f}, {4.0f, 0.0f}, 1.0f}, box).hit);
}

TEST(RayCast, CapsuleSideAndCap) {
    Capsule capsule{{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f};
    expectHit(rayCast(RayCastInput{{0.5f, 3.0f}, {0.0f, -4.0f}, 1.0f}, capsule), 2.5f / 4.0f,
              {0.5f, 0.5f}, {0.0f, 1.0f});
    expectHit(rayCast(RayCastInput{{-5.0f, 0.0f}, {10.0f, 0.0f}, 1.0f}, capsule), 0.35f,
              {-1.5f, 0.0f}, {-1.0f, 0.0f});
    // Cap at y = 0.3: x = -1 - sqrt(0.25 - 0.09) = -1.4.
    expectHit(rayCast(RayCastInput{{-5.0f, 0.3f}, {10.0f, 0.0f}, 1.0f}, capsule), 0.36f,
              {-1.4f, 0.3f}, {-0.8f, 0.6f});
    EXPECT_FALSE(rayCast(RayCastInput{{0.0f, 0.2f}, {10.0f, 0.0f}, 1.0f}, capsule).hit); // inside
    EXPECT_FALSE(rayCast(RayCastInput{{-5.0f, 0.6f}, {10.0f, 0.0f}, 1.0f}, capsule).hit);
}

TEST(RayCast, SegmentIsTwoSided) {
    Segment segment{{0.0f, 0.0f}, {2.0f, 0.0f}};
    expectHit(rayCast(RayCastInput{{1.0f, 1.0f}, {0.0f, -2.0f}, 1.0f}, segment), 0.5f, {1.0f, 0.0f},
              {0.0f, 1.0f});
    expectHit(rayCast(RayCastInput{{1.5f, -1.0f}, {0.0f, 4.0f}, 1.0f}, segment), 0.25f,
              {1.5f, 0.0f}, {0.0f, -1.0f});
    EXPECT_FALSE(rayCast(RayCastInput{{-1.0f, 0.0f}, {4.0f, 0.0f}, 1.0f}, segment).hit); // parallel
    EXPECT_FALSE(rayCast(RayCastInput{{2.5f, 1.0f}, {0.0f, -2.0f}, 1.0f}, segment).hit); // past end
    EXPECT_FALSE(rayCast(RayCastInput{{1.0f, 1.0f}, {0.0f, -2.0f}, 0.4f}, segment).hit); // short
}

} // namespace
} // namespace e2d::physics
