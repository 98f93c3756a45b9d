// SPDX-License-Identifier: MIT
// collidePolygons (SAT with reference-face clipping) and collide() dispatch.
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

std::vector<float> sortedX(const Manifold& m) {
    std::vector<float> xs;
    for (int i = 0; i < m.pointCount; ++i) {
        xs.push_back(m.points[i].point.x);
    }
    std::sort(xs.begin(), xs.end());
    return xs;
}

std::vector<std::uint16_t> sortedIds(const Manifold& m) {
    std::vector<std::uint16_t> ids;
    for (int i = 0; i < m.pointCount; ++i) {
        ids.push_back(m.points[i].id);
    }
    std::sort(ids.begin(), ids.end());
    return ids;
}

// A 1 x 1 box on a 10 x 1 ground whose top is y = 0.5; the box's centre is at height y.
Manifold boxOnGround(float x, float y, float angle = 0.0f, float margin = kSpeculativeDistance) {
    return collidePolygons(makeBox(5.0f, 0.5f), kIdentity, makeBox(0.5f, 0.5f),
                           makeTransform(x, y, angle), margin);
}

TEST(CollidePolygons, RestingBoxShallowPenetration) {
    Manifold m = boxOnGround(0.0f, 0.99f);
    ASSERT_EQ(m.pointCount, 2);
    E2D_EXPECT_VEC2_NEAR(m.normal, 0.0f, 1.0f, 1e-6f);
    std::vector<float> xs = sortedX(m);
    EXPECT_NEAR(xs[0], -0.5f, 1e-6f);
    EXPECT_NEAR(xs[1], 0.5f, 1e-6f);
    for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(m.points[i].separation, -0.01f, 1e-6f);
        EXPECT_NEAR(m.points[i].point.y, 0.495f, 1e-6f); // midway between 0.5 and 0.49
    }
    EXPECT_NE(m.points[0].id, m.points[1].id);
    expectAnchorsConsistent(m, kIdentity, makeTransform(0.0f, 0.99f, 0.0f));
}

// The box is shape A, so the work happens in its frame and the ground's top face (400 m long)
// is the incident edge clipped to the box's bottom face: the clipped points must land on the
// box's corners, exactly as on a narrow ground, whichever algorithm found the axis (a point
// interpolated from the far ends of the long edge was 1.5e-5 m off one corner, an uneven
// lever arm that seeded the sway of a 50-box column standing on it).
TEST(CollidePolygons, BoxOnAWideGroundGetsItsOwnCorners) {
    const Polygon box = makeBox(0.5f, 0.5f);
    const Polygon wide = makeBox(200.0f, 1.0f);
    const Transform xfBox = makeTransform(0.0f, 0.4995f, 0.0f);
    const Transform xfGround = makeTransform(0.0f, -1.0f, 0.0f);
    for (const Manifold& m : {collidePolygons(box, xfBox, wide, xfGround),
                              collidePolygonsGjkEpa(box, xfBox, wide, xfGround)}) {
        ASSERT_EQ(m.pointCount, 2);
        std::vector<float> xs = sortedX(m);
        EXPECT_EQ(xs[0], -0.5f);
        EXPECT_EQ(xs[1], 0.5f);
        EXPECT_EQ(m.points[0].anchorA.x, -m.points[1].anchorA.x);
        EXPECT_EQ(m.points[0].separation, m.points[1].separation);
        EXPECT_NEAR(m.points[0].separation, -0.0005f, 1e-6f);
        expectAnchorsConsistent(m, xfBox, xfGround);
    }
}

// Two cards (2 mm x 40 cm) leaning 25 degrees towards each other, tips touching, as at the apex
// of a card house: `overlap` (metres) is how far the two top corners have crossed (negative: a
// gap), `drop` how much lower the right card stands. The left card is shape A.
struct CardPair {
    Polygon card = makeBox(0.001f, 0.2f);
    Transform left;
    Transform right;
};

CardPair tipToTipCards(float overlap, float drop = 0.0f) {
    CardPair p;
    const float lean = 25.0f * kPi / 180.0f;
    // The left card's top right corner from its centre, when it leans right by `lean`.
    const Vec2 corner = rotate(Rot::fromAngle(-lean), Vec2{0.001f, 0.2f});
    p.left = makeTransform(0.5f * overlap - corner.x, 0.0f, -lean);
    p.right = makeTransform(corner.x - 0.5f * overlap, -drop, lean);
    return p;
}

// The two top corners cross each other: each lies against the other card's face and no face is
// the contact's. The contact is the one the separated tips give (the line between the corners,
// horizontal), kept as they cross: one point midway, normal along the bisector of the two face
// normals, separation the overlap along it, ids the two corners. A reference face instead
// tilts the normal 25 degrees (the whole angle to one card's face), so the apex friction must
// carry a share of the load the symmetric contact puts on the normal, and which card's face it
// is depends on the first touching steps (card_house_v3's top pair slid apart at 4 sub-steps).
TEST(CollidePolygons, CardsCrossingAtTheirTipsMeetAlongTheBisector) {
    for (const CollisionAlgorithm algorithm :
         {CollisionAlgorithm::Sat, CollisionAlgorithm::GjkEpa}) {
        SCOPED_TRACE(algorithm == CollisionAlgorithm::Sat ? "SAT" : "GJK/EPA");
        const CardPair apart = tipToTipCards(-0.001f);
        const Manifold separated =
            collide(apart.card, apart.left, apart.card, apart.right, algorithm);
        ASSERT_EQ(separated.pointCount, 1);
        E2D_EXPECT_VEC2_NEAR(separated.normal, 1.0f, 0.0f, 1e-4f);
        EXPECT_NEAR(separated.points[0].separation, 0.001f, 1e-5f);

        for (const float drop : {0.0f, 0.0002f, -0.0003f}) {
            SCOPED_TRACE(drop);
            const CardPair p = tipToTipCards(0.0004f, drop);
            const Manifold m = collide(p.card, p.left, p.card, p.right, algorithm);
            ASSERT_EQ(m.pointCount, 1);
            E2D_EXPECT_VEC2_NEAR(m.normal, 1.0f, 0.0f, 1e-4f);
            EXPECT_NEAR(m.points[0].separation, -0.0004f, 2e-5f);
            EXPECT_NEAR(m.points[0].point.x, 0.0f, 1e-4f);
            EXPECT_EQ(m.points[0].id, separated.points[0].id);
            expectAnchorsConsistent(m, p.left, p.right);

            // The same pair in the other order: the same contact, seen from the right card.
            const Manifold r = collide(p.card, p.right, p.card, p.left, algorithm);
            ASSERT_EQ(r.pointCount, 1);
            E2D_EXPECT_VEC2_NEAR(r.normal, -1.0f, 0.0f, 1e-4f);
            EXPECT_NEAR(r.points[0].separation, m.points[0].separation, 1e-6f);
        }
    }
}

// Faces in line are a face contact even where two corners meet: a card lying flat on another
// with their ends flush, and a box slightly tilted over another box's edge, keep two points.
TEST(CollidePolygons, FacesInLineAreNotACornerCrossing) {
    const Polygon card = makeBox(0.2f, 0.001f);
    for (const CollisionAlgorithm algorithm :
         {CollisionAlgorithm::Sat, CollisionAlgorithm::GjkEpa}) {
        const Manifold flush = collide(card, makeTransform(0.0f, 0.0f, 0.0f), card,
                                       makeTransform(0.0f, 0.0019f, 0.0f), algorithm);
        EXPECT_EQ(flush.pointCount, 2);
        E2D_EXPECT_VEC2_NEAR(flush.normal, 0.0f, 1.0f, 1e-6f);
        const Manifold tilted = collide(card, makeTransform(0.0f, 0.0f, 0.0f), card,
                                        makeTransform(0.3f, 0.0019f, 0.02f), algorithm);
        EXPECT_EQ(tilted.pointCount, 2);
    }
}

TEST(CollidePolygons, TouchingSpeculativeAndBeyondMargin) {
    Manifold touching = boxOnGround(0.0f, 1.0f);
    ASSERT_EQ(touching.pointCount, 2);
    EXPECT_NEAR(touching.points[0].separation, 0.0f, 1e-6f);

    Manifold speculative = boxOnGround(0.0f, 1.015f);
    ASSERT_EQ(speculative.pointCount, 2);
    E2D_EXPECT_VEC2_NEAR(speculative.normal, 0.0f, 1.0f, 1e-6f);
    EXPECT_NEAR(speculative.points[0].separation, 0.015f, 1e-6f);
    EXPECT_NEAR(speculative.points[1].separation, 0.015f, 1e-6f);
    EXPECT_EQ(sortedIds(speculative), sortedIds(touching));

    EXPECT_EQ(boxOnGround(0.0f, 1.03f).pointCount, 0);
    EXPECT_EQ(boxOnGround(0.0f, 1.03f, 0.0f, 0.05f).pointCount, 2);
    EXPECT_EQ(boxOnGround(0.0f, 1.015f, 0.0f, 0.0f).pointCount, 0);
}

TEST(CollidePolygons, DeepPenetrationAndOverhang) {
    Manifold m = boxOnGround(0.0f, 0.5f);
    ASSERT_EQ(m.pointCount, 2);
    E2D_EXPECT_VEC2_NEAR(m.normal, 0.0f, 1.0f, 1e-6f);
    EXPECT_NEAR(m.points[0].separation, -0.5f, 1e-6f);
    EXPECT_NEAR(m.points[0].point.y, 0.25f, 1e-6f);

    // Hanging over the ground's right end (x = 5): the incident face is clipped there.
    m = boxOnGround(4.8f, 0.99f);
    ASSERT_EQ(m.pointCount, 2);
    std::vector<float> xs = sortedX(m);
    EXPECT_NEAR(xs[0], 4.3f, 1e-5f);
    EXPECT_NEAR(xs[1], 5.0f, 1e-5f);
}

TEST(CollidePolygons, PolygonFarFromItsBodyOrigin) {
    // Level geometry often puts offset boxes far from a static body's origin: the result must
    // match the same ground centred on its body, to well below kLinearSlop.
    const Polygon farGround = makeOffsetBox(5.0f, 0.5f, {1000.0f, -2000.0f}, 0.0f);
    const Transform xfBox = makeTransform(1000.2f, -2000.0f + 0.99f, 0.0f);
    Manifold m = collidePolygons(farGround, kIdentity, makeBox(0.5f, 0.5f), xfBox);
    ASSERT_EQ(m.pointCount, 2);
    E2D_EXPECT_VEC2_NEAR(m.normal, 0.0f, 1.0f, 1e-6f);
    std::vector<float> xs = sortedX(m);
    EXPECT_NEAR(xs[0], 999.7f, 1e-4f);
    EXPECT_NEAR(xs[1], 1000.7f, 1e-4f);
    for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(m.points[i].separation, -0.01f, 1e-4f);
    }
    expectAnchorsConsistent(m, kIdentity, xfBox);
}

TEST(CollidePolygons, TiltedBoxRestsOnOneCorner) {
    // Turned by 0.1 rad, the lower corner (-0.5, -0.5) sits 0.5 (sin + cos) below the centre;
    // put it 0.01 into the ground. The other bottom corner is then sin(0.1) - 0.01 = 0.0898
    // above the ground, beyond the margin.
    const float angle = 0.1f, c = std::cos(angle), s = std::sin(angle);
    const float y = 0.5f - 0.01f + 0.5f * (s + c);
    Manifold m = boxOnGround(0.0f, y, angle);
    ASSERT_EQ(m.pointCount, 1);
    E2D_EXPECT_VEC2_NEAR(m.normal, 0.0f, 1.0f, 1e-6f);
    EXPECT_NEAR(m.points[0].separation, -0.01f, 1e-5f);
    E2D_EXPECT_VEC2_NEAR(m.points[0].point, -0.5f * c + 0.5f * s, 0.495f, 1e-5f);
}

TEST(CollidePolygons, WorldFrameFollowsBothTransforms) {
    // The resting case, with the whole scene turned by 0.7 rad and moved by (3, -2).
    const Transform scene = makeTransform(3.0f, -2.0f, 0.7f);
    const Transform xfA = mulTransforms(scene, makeTransform(0.0f, 0.0f, 0.0f));
    const Transform xfB = mulTransforms(scene, makeTransform(0.2f, 0.99f, 0.0f));
    Manifold m = collidePolygons(makeBox(5.0f, 0.5f), xfA, makeBox(0.5f, 0.5f), xfB);
    ASSERT_EQ(m.pointCount, 2);
    Vec2 up = rotate(scene.q, {0.0f, 1.0f});
    E2D_EXPECT_VEC2_NEAR(m.normal, up.x, up.y, 1e-6f);
    std::vector<Vec2> expected{transformPoint(scene, {-0.3f, 0.495f}),
                               transformPoint(scene, {0.7f, 0.495f})};
    for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(m.points[i].separation, -0.01f, 1e-5f);
        float d0 = distance(m.points[i].point, expected[0]);
        float d1 = distance(m.points[i].point, expected[1]);
        EXPECT_LT(std::fmin(d0, d1), 1e-5f);
    }
    expectAnchorsConsistent(m, xfA, xfB);
}

TEST(CollidePolygons, FlipUsesTheOtherPolygonsFace) {
    // A diamond (box turned 45 degrees) whose lowest corner is 0.01 into the ground: the
    // ground's face (B) is the reference; the normal still points from A (diamond) to B.
    const float h = std::sqrt(0.5f);
    Polygon diamond = makeBox(0.5f, 0.5f);
    Transform xfA = makeTransform(0.0f, 0.5f + h - 0.01f, 0.25f * kPi);
    Manifold m = collidePolygons(diamond, xfA, makeBox(5.0f, 0.5f), kIdentity);
    ASSERT_EQ(m.pointCount, 1);
    E2D_EXPECT_VEC2_NEAR(m.normal, 0.0f, -1.0f, 1e-6f);
    EXPECT_NEAR(m.points[0].separation, -0.01f, 1e-5f);
    E2D_EXPECT_VEC2_NEAR(m.points[0].point, 0.0f, 0.495f, 1e-5f);
    expectAnchorsConsistent(m, xfA, kIdentity);
}

TEST(CollidePolygons, CornerToCornerUsesTheTrueDistance) {
    // Corners (0.5, 0.5) and (0.51, 0.51): a vertex contact along the diagonal, 0.01 sqrt(2)
    // apart, not a face contact with the face separation 0.01.
    const float h = std::sqrt(0.5f);
    Manifold m = collidePolygons(makeBox(0.5f, 0.5f), kIdentity, makeBox(0.5f, 0.5f),
                                 makeTransform(1.01f, 1.01f, 0.0f));
    ASSERT_EQ(m.pointCount, 1);
    E2D_EXPECT_VEC2_NEAR(m.normal, h, h, 1e-5f);
    EXPECT_NEAR(m.points[0].separation, 0.01f * std::sqrt(2.0f), 1e-5f);
    E2D_EXPECT_VEC2_NEAR(m.points[0].point, 0.505f, 0.505f, 1e-5f);
}

TEST(CollidePolygons, RoundedCornersDoNotTouchEarly) {
    // Rounded by 0.1: cores' corners 0.2 sqrt(2) = 0.283 apart, separation 0.083: no contact,
    // though the face separation (0.2 - 0.2 = 0) would say touching.
    Polygon rounded = makeRoundedBox(0.5f, 0.5f, 0.1f);
    EXPECT_EQ(
        collidePolygons(rounded, kIdentity, rounded, makeTransform(1.2f, 1.2f, 0.0f)).pointCount,
        0);
    Manifold m = collidePolygons(rounded, kIdentity, rounded, makeTransform(1.12f, 1.12f, 0.0f));
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_NEAR(m.points[0].separation, 0.12f * std::sqrt(2.0f) - 0.2f, 1e-5f);
    E2D_EXPECT_VEC2_NEAR(m.points[0].point, 0.56f, 0.56f, 1e-5f);
}

TEST(CollidePolygons, RoundedBoxRestingOnRoundedGround) {
    // Surfaces at 0.5 + 0.1 (ground) and y - 0.5 - 0.1 (box): y = 1.19 overlaps by 0.01.
    Manifold m =
        collidePolygons(makeRoundedBox(5.0f, 0.5f, 0.1f), kIdentity,
                        makeRoundedBox(0.5f, 0.5f, 0.1f), makeTransform(0.0f, 1.19f, 0.0f));
    ASSERT_EQ(m.pointCount, 2);
    E2D_EXPECT_VEC2_NEAR(m.normal, 0.0f, 1.0f, 1e-6f);
    std::vector<float> xs = sortedX(m);
    EXPECT_NEAR(xs[0], -0.5f, 1e-6f);
    EXPECT_NEAR(xs[1], 0.5f, 1e-6f);
    for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(m.points[i].separation, -0.01f, 1e-5f);
        EXPECT_NEAR(m.points[i].point.y, 0.595f, 1e-5f);
    }
}

TEST(CollidePolygons, SeparatedBeyondMarginOnEveryAxis) {
    EXPECT_EQ(collidePolygons(makeBox(0.5f, 0.5f), kIdentity, makeBox(0.5f, 0.5f),
                              makeTransform(3.0f, 0.0f, 0.3f))
                  .pointCount,
              0);
}

TEST(CollidePolygons, IdsStayTheSameUnderSmallMotions) {
    Manifold base = boxOnGround(0.0f, 0.99f);
    ASSERT_EQ(base.pointCount, 2);
    std::mt19937 rng(1234);
    auto uniform = [&](float lo, float hi) {
        return lo + (hi - lo) * static_cast<float>(rng() - rng.min()) /
                        static_cast<float>(rng.max() - rng.min());
    };
    for (int trial = 0; trial < 200; ++trial) {
        Manifold m = boxOnGround(uniform(-0.01f, 0.01f), 0.99f + uniform(-0.005f, 0.005f),
                                 uniform(-0.002f, 0.002f));
        ASSERT_EQ(m.pointCount, 2) << trial;
        EXPECT_EQ(sortedIds(m), sortedIds(base)) << trial;
    }
}

TEST(CollidePolygons, EqualBoxesDoNotFlipFlop) {
    // Box on an equal box: both faces separate equally; A's face must win consistently while
    // small rotations make B's face barely better.
    Polygon box = makeBox(0.5f, 0.5f);
    Manifold base = collidePolygons(box, kIdentity, box, makeTransform(0.0f, 0.995f, 0.0f));
    ASSERT_EQ(base.pointCount, 2);
    for (float angle : {-0.0004f, -0.0001f, 0.0001f, 0.0004f}) {
        Manifold m = collidePolygons(box, kIdentity, box, makeTransform(0.001f, 0.995f, angle));
        ASSERT_EQ(m.pointCount, 2) << angle;
        EXPECT_EQ(sortedIds(m), sortedIds(base)) << angle;
        E2D_EXPECT_VEC2_NEAR(m.normal, 0.0f, 1.0f, 1e-6f);
    }
}

TEST(Collide, ArgumentOrderFlipsTheNormalAndSwapsAnchors) {
    const Transform xfA = makeTransform(0.3f, -0.2f, 0.4f);
    const Transform xfB = makeTransform(0.6f, 0.25f, -0.3f);
    const std::vector<ShapeGeometry> shapes{
        Circle{{0.1f, 0.0f}, 0.5f},
        Capsule{{-0.5f, 0.0f}, {0.5f, 0.1f}, 0.3f},
        Segment{{-1.0f, -0.2f}, {1.0f, 0.3f}},
        makeBox(0.5f, 0.4f),
        makeRoundedBox(0.4f, 0.3f, 0.1f),
    };
    int pairsWithContact = 0;
    for (const ShapeGeometry& a : shapes) {
        for (const ShapeGeometry& b : shapes) {
            Manifold ab = collide(a, xfA, b, xfB);
            Manifold ba = collide(b, xfB, a, xfA);
            ASSERT_EQ(ab.pointCount, ba.pointCount) << a.index() << " " << b.index();
            if (typeOf(a) == ShapeType::Segment && typeOf(b) == ShapeType::Segment) {
                EXPECT_EQ(ab.pointCount, 0);
                continue;
            }
            if (ab.pointCount == 0) {
                continue;
            }
            ++pairsWithContact;
            E2D_EXPECT_VEC2_NEAR(ab.normal, -ba.normal.x, -ba.normal.y, 1e-5f);
            // Every shape sits near its body's origin and B's origin is up and right of A's.
            EXPECT_GT(dot(ab.normal, xfB.p - xfA.p), 0.0f) << a.index() << " " << b.index();
            expectAnchorsConsistent(ab, xfA, xfB);
            for (int i = 0; i < ab.pointCount; ++i) {
                float bestDistance = 1e9f;
                for (int j = 0; j < ba.pointCount; ++j) {
                    bestDistance =
                        std::fmin(bestDistance, distance(ab.points[i].point, ba.points[j].point));
                }
                EXPECT_LT(bestDistance, 1e-4f) << a.index() << " " << b.index();
            }
        }
    }
    EXPECT_EQ(pairsWithContact, 24); // every pair but segment-segment
}

TEST(Collide, ReversedPairMatchesTheDirectRoutine) {
    Polygon box = makeBox(0.5f, 0.5f);
    Circle circle{{0.0f, 0.0f}, 0.25f};
    Transform xfBox = makeTransform(0.0f, 0.0f, 0.0f);
    Transform xfCircle = makeTransform(0.3f, 0.7f, 0.0f);
    Manifold direct = collidePolygonAndCircle(box, xfBox, circle, xfCircle);
    Manifold reversed = collide(circle, xfCircle, box, xfBox);
    ASSERT_EQ(direct.pointCount, 1);
    ASSERT_EQ(reversed.pointCount, 1);
    E2D_EXPECT_VEC2_NEAR(reversed.normal, 0.0f, -1.0f, 1e-6f);
    EXPECT_FLOAT_EQ(reversed.points[0].separation, direct.points[0].separation);
    E2D_EXPECT_VEC2_NEAR(reversed.points[0].anchorA, direct.points[0].anchorB.x,
                         direct.points[0].anchorB.y, 0.0f);
    E2D_EXPECT_VEC2_NEAR(reversed.points[0].anchorB, direct.points[0].anchorA.x,
                         direct.points[0].anchorA.y, 0.0f);

    // Polygon pairs: the ids keep (feature of A, feature of B) order after the swap.
    Segment ground{{-5.0f, 0.0f}, {5.0f, 0.0f}};
    Transform xfBox2 = makeTransform(0.0f, 0.49f, 0.0f);
    Manifold segFirst = collide(ground, kIdentity, box, xfBox2);
    Manifold boxFirst = collide(box, xfBox2, ground, kIdentity);
    ASSERT_EQ(segFirst.pointCount, 2);
    ASSERT_EQ(boxFirst.pointCount, 2);
    for (int i = 0; i < 2; ++i) {
        std::uint16_t id = segFirst.points[i].id;
        std::uint16_t swappedId = static_cast<std::uint16_t>((id >> 8) | ((id & 0xFF) << 8));
        EXPECT_EQ(boxFirst.points[i].id, swappedId);
    }
}

} // namespace
} // namespace e2d::physics
