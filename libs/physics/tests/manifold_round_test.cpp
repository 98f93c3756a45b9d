// SPDX-License-Identifier: MIT
// Circles, capsules, polygon-circle and the segment routines, against hand-computed contacts.
#include <e2d/physics/manifold.hpp>

#include "geometry_test_util.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace e2d::physics {
namespace {

using test::expectAnchorsConsistent;
using test::kPi;
using test::makeTransform;

const Transform kIdentity{};

TEST(CollideCircles, OverlappingTouchingSeparated) {
    Circle a{{0.0f, 0.0f}, 1.0f};
    Circle b{{0.0f, 0.0f}, 0.5f};
    // Centres 1.2 apart: separation 1.2 - 1.5 = -0.3; surfaces at x = 1 and x = 0.7.
    Transform xfB = makeTransform(1.2f, 0.0f, 0.4f);
    Manifold m = collideCircles(a, kIdentity, b, xfB);
    ASSERT_EQ(m.pointCount, 1);
    E2D_EXPECT_VEC2_NEAR(m.normal, 1.0f, 0.0f, 1e-6f);
    EXPECT_NEAR(m.points[0].separation, -0.3f, 1e-6f);
    E2D_EXPECT_VEC2_NEAR(m.points[0].point, 0.85f, 0.0f, 1e-6f);
    expectAnchorsConsistent(m, kIdentity, xfB);

    m = collideCircles(a, kIdentity, b, makeTransform(1.5f, 0.0f, 0.0f));
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_NEAR(m.points[0].separation, 0.0f, 1e-6f);

    // Within the default margin (4 * kLinearSlop = 0.02): a speculative point.
    m = collideCircles(a, kIdentity, b, makeTransform(1.51f, 0.0f, 0.0f));
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_NEAR(m.points[0].separation, 0.01f, 1e-6f);

    EXPECT_EQ(collideCircles(a, kIdentity, b, makeTransform(1.53f, 0.0f, 0.0f)).pointCount, 0);
    EXPECT_EQ(collideCircles(a, kIdentity, b, makeTransform(1.53f, 0.0f, 0.0f), 0.05f).pointCount,
              1);
}

TEST(CollideCircles, LocalCentresAndRotatedFrames) {
    // A's local centre (1, 0) turned a quarter turn and moved by (2, 0) is (2, 1) in the world.
    Circle a{{1.0f, 0.0f}, 0.5f};
    Circle b{{0.0f, 0.0f}, 0.5f};
    Transform xfA = makeTransform(2.0f, 0.0f, 0.5f * kPi);
    Transform xfB = makeTransform(2.0f, 1.9f, 0.0f);
    Manifold m = collideCircles(a, xfA, b, xfB);
    ASSERT_EQ(m.pointCount, 1);
    E2D_EXPECT_VEC2_NEAR(m.normal, 0.0f, 1.0f, 1e-6f);
    EXPECT_NEAR(m.points[0].separation, -0.1f, 1e-6f);
    E2D_EXPECT_VEC2_NEAR(m.points[0].point, 2.0f, 1.45f, 1e-6f);
    expectAnchorsConsistent(m, xfA, xfB);
}

TEST(CollideCapsuleAndCircle, SideAndCap) {
    Capsule a{{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f};
    Circle b{{0.0f, 0.0f}, 0.5f};
    // Above the side: closest axis point (0.3, 0), 0.6 away; surfaces at y = 0.25 and 0.1.
    Manifold m = collideCapsuleAndCircle(a, kIdentity, b, makeTransform(0.3f, 0.6f, 0.0f));
    ASSERT_EQ(m.pointCount, 1);
    E2D_EXPECT_VEC2_NEAR(m.normal, 0.0f, 1.0f, 1e-6f);
    EXPECT_NEAR(m.points[0].separation, -0.15f, 1e-6f);
    E2D_EXPECT_VEC2_NEAR(m.points[0].point, 0.3f, 0.175f, 1e-6f);
    // Past the end cap, at 45 degrees: 0.76 from the cap centre (1, 0), a speculative point
    // midway between the surfaces 0.25 and 0.26 from the cap centre.
    const float h = std::sqrt(0.5f);
    m = collideCapsuleAndCircle(a, kIdentity, b, makeTransform(1.0f + 0.76f * h, -0.76f * h, 0.0f));
    ASSERT_EQ(m.pointCount, 1);
    E2D_EXPECT_VEC2_NEAR(m.normal, h, -h, 1e-6f);
    EXPECT_NEAR(m.points[0].separation, 0.01f, 1e-6f);
    E2D_EXPECT_VEC2_NEAR(m.points[0].point, 1.0f + 0.255f * h, -0.255f * h, 1e-6f);
    EXPECT_EQ(collideCapsuleAndCircle(a, kIdentity, b, makeTransform(0.0f, 0.8f, 0.0f)).pointCount,
              0);
}

TEST(CollideCapsules, ParallelOverlapGivesTwoPoints) {
    Capsule a{{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f};
    Capsule b{{-0.5f, 0.0f}, {1.5f, 0.0f}, 0.25f};
    Transform xfB = makeTransform(0.0f, 0.45f, 0.0f);
    Manifold m = collideCapsules(a, kIdentity, b, xfB);
    // B's axis clipped to A's extent: x in [-0.5, 1]; separation 0.45 - 0.5; surfaces 0.25, 0.2.
    ASSERT_EQ(m.pointCount, 2);
    E2D_EXPECT_VEC2_NEAR(m.normal, 0.0f, 1.0f, 1e-6f);
    float xs[2] = {m.points[0].point.x, m.points[1].point.x};
    EXPECT_NEAR(std::fmin(xs[0], xs[1]), -0.5f, 1e-6f);
    EXPECT_NEAR(std::fmax(xs[0], xs[1]), 1.0f, 1e-6f);
    for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(m.points[i].separation, -0.05f, 1e-6f);
        EXPECT_NEAR(m.points[i].point.y, 0.225f, 1e-6f);
    }
    EXPECT_NE(m.points[0].id, m.points[1].id);
    expectAnchorsConsistent(m, kIdentity, xfB);

    // B reversed and lying fully over A: still two points, at B's ends.
    Capsule reversed{{0.5f, 0.45f}, {-0.5f, 0.45f}, 0.25f};
    m = collideCapsules(a, kIdentity, reversed, kIdentity);
    ASSERT_EQ(m.pointCount, 2);
    EXPECT_NEAR(std::fabs(m.points[0].point.x - m.points[1].point.x), 1.0f, 1e-6f);
}

TEST(CollideCapsules, TiltedCapsuleRestsOnOnePoint) {
    Capsule a{{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f};
    // From (-0.5, 0.45) rising at 45 degrees: only its lower end is within the margin.
    Capsule b{{-0.5f, 0.45f}, {0.5f, 1.45f}, 0.25f};
    Manifold m = collideCapsules(a, kIdentity, b, kIdentity);
    ASSERT_EQ(m.pointCount, 1);
    E2D_EXPECT_VEC2_NEAR(m.normal, 0.0f, 1.0f, 1e-6f);
    EXPECT_NEAR(m.points[0].separation, -0.05f, 1e-6f);
    E2D_EXPECT_VEC2_NEAR(m.points[0].point, -0.5f, 0.225f, 1e-6f);
}

TEST(CollideCapsules, EndToEndAndCrossing) {
    Capsule a{{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f};
    Capsule b{{1.4f, 0.0f}, {3.0f, 0.0f}, 0.25f};
    Manifold m = collideCapsules(a, kIdentity, b, kIdentity);
    ASSERT_EQ(m.pointCount, 1);
    E2D_EXPECT_VEC2_NEAR(m.normal, 1.0f, 0.0f, 1e-6f);
    EXPECT_NEAR(m.points[0].separation, -0.1f, 1e-6f);
    E2D_EXPECT_VEC2_NEAR(m.points[0].point, 1.2f, 0.0f, 1e-6f);

    // Crossed like an X: the least penetration is 1.5 (push B along its own length or along
    // A's, both axes give 1 + 0.5).
    Capsule cross{{0.0f, -1.0f}, {0.0f, 1.0f}, 0.25f};
    m = collideCapsules(a, kIdentity, cross, kIdentity);
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_NEAR(m.points[0].separation, -1.5f, 1e-5f);
    EXPECT_NEAR(std::fabs(m.normal.x) + std::fabs(m.normal.y), 1.0f, 1e-6f);
}

TEST(CollidePolygonAndCircle, FaceCornerAndCentreInside) {
    Polygon box = makeBox(1.0f, 0.5f);
    Circle circle{{0.0f, 0.0f}, 0.25f};
    Manifold m = collidePolygonAndCircle(box, kIdentity, circle, makeTransform(0.3f, 0.7f, 0.0f));
    ASSERT_EQ(m.pointCount, 1);
    E2D_EXPECT_VEC2_NEAR(m.normal, 0.0f, 1.0f, 1e-6f);
    EXPECT_NEAR(m.points[0].separation, -0.05f, 1e-6f);
    E2D_EXPECT_VEC2_NEAR(m.points[0].point, 0.3f, 0.475f, 1e-6f);

    // Off the corner (1, 0.5) by (0.2, 0.2): 0.2828 away, beyond 0.25 + margin.
    EXPECT_EQ(
        collidePolygonAndCircle(box, kIdentity, circle, makeTransform(1.2f, 0.7f, 0.0f)).pointCount,
        0);
    Circle bigger{{0.0f, 0.0f}, 0.3f};
    m = collidePolygonAndCircle(box, kIdentity, bigger, makeTransform(1.2f, 0.7f, 0.0f));
    ASSERT_EQ(m.pointCount, 1);
    const float h = std::sqrt(0.5f);
    E2D_EXPECT_VEC2_NEAR(m.normal, h, h, 1e-6f);
    EXPECT_NEAR(m.points[0].separation, 0.2f * std::sqrt(2.0f) - 0.3f, 1e-6f);

    // Centre inside, 0.1 from the right face: pushed out through it.
    m = collidePolygonAndCircle(box, kIdentity, circle, makeTransform(0.9f, 0.0f, 0.0f));
    ASSERT_EQ(m.pointCount, 1);
    E2D_EXPECT_VEC2_NEAR(m.normal, 1.0f, 0.0f, 1e-6f);
    EXPECT_NEAR(m.points[0].separation, -0.35f, 1e-6f);
    E2D_EXPECT_VEC2_NEAR(m.points[0].point, 0.825f, 0.0f, 1e-6f);
}

TEST(CollidePolygonAndCircle, RoundedPolygonInRotatedFrame) {
    Polygon box = makeRoundedBox(1.0f, 0.5f, 0.1f);
    Circle circle{{0.0f, 0.0f}, 0.25f};
    // In A's frame the circle sits at (0.3, 0.8): 0.3 above the core's top face, so separation
    // 0.3 - 0.35. A is turned a quarter turn: its +y is world -x.
    Transform xfA = makeTransform(5.0f, 5.0f, 0.5f * kPi);
    Transform xfB = makeTransform(5.0f - 0.8f, 5.0f + 0.3f, 0.0f);
    Manifold m = collidePolygonAndCircle(box, xfA, circle, xfB);
    ASSERT_EQ(m.pointCount, 1);
    E2D_EXPECT_VEC2_NEAR(m.normal, -1.0f, 0.0f, 1e-6f);
    EXPECT_NEAR(m.points[0].separation, -0.05f, 1e-6f);
    // Midway between y_A = 0.6 and 0.55, i.e. 0.575 along A's +y.
    E2D_EXPECT_VEC2_NEAR(m.points[0].point, 5.0f - 0.575f, 5.3f, 1e-5f);
    expectAnchorsConsistent(m, xfA, xfB);
}

TEST(CollidePolygonAndCapsule, CapsuleLyingOnABox) {
    Polygon ground = makeBox(2.0f, 0.5f);
    Capsule capsule{{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f};
    // Core gap 0.2, separation -0.05: two points at the capsule's ends, midway at y = 0.475.
    Manifold m =
        collidePolygonAndCapsule(ground, kIdentity, capsule, makeTransform(0.0f, 0.7f, 0.0f));
    ASSERT_EQ(m.pointCount, 2);
    E2D_EXPECT_VEC2_NEAR(m.normal, 0.0f, 1.0f, 1e-6f);
    for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(m.points[i].separation, -0.05f, 1e-6f);
        EXPECT_NEAR(m.points[i].point.y, 0.475f, 1e-6f);
        EXPECT_NEAR(std::fabs(m.points[i].point.x), 1.0f, 1e-6f);
    }
    // Speculative: 0.01 above, both points kept; 0.05 above, nothing.
    m = collidePolygonAndCapsule(ground, kIdentity, capsule, makeTransform(0.0f, 0.76f, 0.0f));
    ASSERT_EQ(m.pointCount, 2);
    EXPECT_NEAR(m.points[0].separation, 0.01f, 1e-6f);
    EXPECT_NEAR(m.points[0].point.y, 0.505f, 1e-6f);
    EXPECT_EQ(collidePolygonAndCapsule(ground, kIdentity, capsule, makeTransform(0.0f, 0.8f, 0.0f))
                  .pointCount,
              0);
}

TEST(CollidePolygonAndCapsule, CapsuleEndAgainstABoxCorner) {
    // Capsule along x to the right of the box's corner (1, 0.5), its end cap centre at
    // (1.3, 0.9): 0.5 from the corner, separation 0.5 - 0.45.
    Polygon box = makeBox(1.0f, 0.5f);
    Capsule capsule{{1.3f, 0.9f}, {3.0f, 0.9f + 1.7f * 4.0f / 3.0f}, 0.45f};
    Manifold m = collidePolygonAndCapsule(box, kIdentity, capsule, kIdentity);
    ASSERT_EQ(m.pointCount, 0);
    m = collidePolygonAndCapsule(box, kIdentity, capsule, kIdentity, 0.1f);
    ASSERT_EQ(m.pointCount, 1);
    E2D_EXPECT_VEC2_NEAR(m.normal, 0.6f, 0.8f, 1e-5f);
    EXPECT_NEAR(m.points[0].separation, 0.05f, 1e-5f);
}

TEST(CollideSegments, SegmentAgainstCircleCapsuleAndPolygon) {
    Segment ground{{-5.0f, 0.0f}, {5.0f, 0.0f}};
    Manifold m = collideSegmentAndCircle(ground, kIdentity, Circle{{0, 0}, 0.5f},
                                         makeTransform(1.0f, 0.4f, 0.0f));
    ASSERT_EQ(m.pointCount, 1);
    E2D_EXPECT_VEC2_NEAR(m.normal, 0.0f, 1.0f, 1e-6f);
    EXPECT_NEAR(m.points[0].separation, -0.1f, 1e-6f);
    E2D_EXPECT_VEC2_NEAR(m.points[0].point, 1.0f, -0.05f, 1e-6f);

    m = collideSegmentAndCapsule(ground, kIdentity, Capsule{{-1, 0}, {1, 0}, 0.25f},
                                 makeTransform(0.0f, -0.2f, 0.0f));
    ASSERT_EQ(m.pointCount, 2);
    E2D_EXPECT_VEC2_NEAR(m.normal, 0.0f, -1.0f, 1e-6f); // from below: segments are two-sided
    EXPECT_NEAR(m.points[0].separation, -0.05f, 1e-6f);

    Polygon box = makeBox(0.5f, 0.5f);
    for (float side : {1.0f, -1.0f}) {
        m = collideSegmentAndPolygon(ground, kIdentity, box,
                                     makeTransform(2.0f, side * 0.49f, 0.0f));
        ASSERT_EQ(m.pointCount, 2) << side;
        E2D_EXPECT_VEC2_NEAR(m.normal, 0.0f, side, 1e-6f);
        for (int i = 0; i < 2; ++i) {
            EXPECT_NEAR(m.points[i].separation, -0.01f, 1e-6f);
            EXPECT_NEAR(std::fabs(m.points[i].point.x - 2.0f), 0.5f, 1e-6f);
        }
    }
}

std::vector<std::uint16_t> sortedIds(const Manifold& m) {
    std::vector<std::uint16_t> ids;
    for (int i = 0; i < m.pointCount; ++i) {
        ids.push_back(m.points[i].id);
    }
    std::sort(ids.begin(), ids.end());
    return ids;
}

TEST(CapsuleContacts, IdsStayTheSameUnderSmallMotions) {
    // A capsule lying on a box, and on another capsule, nudged by small random motions.
    Polygon ground = makeBox(3.0f, 0.5f);
    Capsule lower{{-2.0f, 0.0f}, {2.0f, 0.0f}, 0.25f};
    Capsule capsule{{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f};
    Manifold onBox =
        collidePolygonAndCapsule(ground, kIdentity, capsule, makeTransform(0.0f, 0.74f, 0.0f));
    Manifold onCapsule =
        collideCapsules(lower, kIdentity, capsule, makeTransform(0.0f, 0.49f, 0.0f));
    ASSERT_EQ(onBox.pointCount, 2);
    ASSERT_EQ(onCapsule.pointCount, 2);
    std::mt19937 rng(42);
    auto uniform = [&](float lo, float hi) {
        return lo + (hi - lo) * static_cast<float>(rng() - rng.min()) /
                        static_cast<float>(rng.max() - rng.min());
    };
    for (int trial = 0; trial < 100; ++trial) {
        float dx = uniform(-0.02f, 0.02f), dy = uniform(-0.004f, 0.004f),
              angle = uniform(-0.002f, 0.002f);
        Manifold m = collidePolygonAndCapsule(ground, kIdentity, capsule,
                                              makeTransform(dx, 0.74f + dy, angle));
        ASSERT_EQ(m.pointCount, 2) << trial;
        EXPECT_EQ(sortedIds(m), sortedIds(onBox)) << trial;
        m = collideCapsules(lower, kIdentity, capsule, makeTransform(dx, 0.49f + dy, angle));
        ASSERT_EQ(m.pointCount, 2) << trial;
        EXPECT_EQ(sortedIds(m), sortedIds(onCapsule)) << trial;
    }
}

} // namespace
} // namespace e2d::physics
