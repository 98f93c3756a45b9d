// SPDX-License-Identifier: MIT
// collidePolygonAndCircle's SSE2 face search and collideCircles' two-lane routine against their
// portable scalar code. The library's
// source is compiled here a second time with the scalar path forced and its functions renamed;
// both must return bit-identical manifolds (same face on ties, same points, separations and
// ids). On a machine without SSE2 both are the scalar path and the test passes trivially.
#include <e2d/physics/manifold.hpp>

#include "geometry_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#define E2D_PHYSICS_SCALAR_ROUND 1
#define collideCircles collideCirclesScalar
#define collideCapsuleAndCircle collideCapsuleAndCircleScalar
#define collideCapsules collideCapsulesScalar
#define collidePolygonAndCircle collidePolygonAndCircleScalar
#define collidePolygonAndCapsule collidePolygonAndCapsuleScalar
#define collideSegmentAndCircle collideSegmentAndCircleScalar
#define collideSegmentAndCapsule collideSegmentAndCapsuleScalar
#define collideSegmentAndPolygon collideSegmentAndPolygonScalar
#include "../src/manifold_round.cpp"
#undef collideCircles
#undef collideCapsuleAndCircle
#undef collideCapsules
#undef collidePolygonAndCircle
#undef collidePolygonAndCapsule
#undef collideSegmentAndCircle
#undef collideSegmentAndCapsule
#undef collideSegmentAndPolygon

namespace e2d::physics {
namespace {

using test::makeTransform;

using Rng = test::TestRandom;

// Square boxes and an exactly symmetric octagon (faces on the axes tie exactly for a centre on
// a diagonal), boxes, rounded and offset boxes, 2-vertex capsule polygons and 3- to 8-gons:
// every lane padding and both register counts.
std::vector<Polygon> makeShapes(Rng& rng) {
    std::vector<Polygon> shapes;
    shapes.push_back(makeBox(0.5f, 0.5f));
    shapes.push_back(makeBox(1.0f, 1.0f));
    shapes.push_back(makePolygon(std::vector<Vec2>{{1.0f, -0.5f},
                                                   {1.0f, 0.5f},
                                                   {0.5f, 1.0f},
                                                   {-0.5f, 1.0f},
                                                   {-1.0f, 0.5f},
                                                   {-1.0f, -0.5f},
                                                   {-0.5f, -1.0f},
                                                   {0.5f, -1.0f}}));
    shapes.push_back(makePolygon(std::vector<Vec2>{
        {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}, {-1.0f, -0.5f}, {-0.5f, -1.0f}}));
    for (int i = 0; i < 16; ++i) {
        shapes.push_back(makeBox(rng.uniform(0.05f, 2.0f), rng.uniform(0.05f, 2.0f)));
    }
    for (int i = 0; i < 8; ++i) {
        shapes.push_back(makeRoundedBox(rng.uniform(0.05f, 1.0f), rng.uniform(0.05f, 1.0f),
                                        rng.uniform(0.01f, 0.3f)));
        shapes.push_back(makeOffsetBox(rng.uniform(0.1f, 1.0f), rng.uniform(0.1f, 1.0f),
                                       {rng.uniform(-1, 1), rng.uniform(-1, 1)},
                                       rng.uniform(-3.0f, 3.0f)));
        shapes.push_back(detail::makeCapsulePolygon({rng.uniform(-1, 1), rng.uniform(-1, 1)},
                                                    {rng.uniform(-1, 1), rng.uniform(-1, 1)},
                                                    rng.uniform(0.0f, 0.3f)));
    }
    for (int count = 3; count <= 8; ++count) {
        for (int i = 0; i < 8; ++i) {
            const float radius = rng.uniform(0.2f, 1.5f);
            std::vector<Vec2> points;
            for (int k = 0; k < count; ++k) {
                const float angle = (static_cast<float>(k) + rng.uniform(0.1f, 0.9f)) *
                                    (6.2831853f / static_cast<float>(count));
                points.push_back({radius * std::cos(angle), radius * std::sin(angle)});
            }
            shapes.push_back(makePolygon(points, i % 3 == 0 ? rng.uniform(0.0f, 0.2f) : 0.0f));
        }
    }
    return shapes;
}

TEST(CollidePolygonAndCircleScalarPath, BitIdenticalToSimdPath) {
    Rng rng{2025u};
    const std::vector<Polygon> shapes = makeShapes(rng);
    const int shapeCount = static_cast<int>(shapes.size());
    int contacts = 0;
    int ties = 0;
    for (int pair = 0; pair < 40000; ++pair) {
        const int mode = rng.index(4);
        // Mode 1: one of the symmetric shapes, unrotated, the centre on a diagonal at a
        // quarter-metre step, so two faces tie exactly (inside: both are candidates for the
        // normal; outside: both lead to the same vertex or to different ones).
        const Polygon& a =
            shapes[static_cast<std::size_t>(mode == 1 ? rng.index(4) : rng.index(shapeCount))];
        Circle b{{rng.uniform(-0.5f, 0.5f), rng.uniform(-0.5f, 0.5f)}, rng.uniform(0.01f, 1.0f)};
        Transform xfA = makeTransform(rng.uniform(-2.0f, 2.0f), rng.uniform(-2.0f, 2.0f),
                                      rng.uniform(-3.2f, 3.2f));
        Transform xfB{{0.0f, 0.0f}, Rot::fromAngle(rng.uniform(-3.2f, 3.2f))};
        // The circle's centre in A's frame.
        Vec2 local = a.centroid + Vec2{rng.uniform(-2.5f, 2.5f), rng.uniform(-2.5f, 2.5f)};
        if (mode == 1) {
            // Every step exact: centre at B's origin, A unrotated on a quarter-metre grid.
            const float t = std::round(local.x * 4.0f) / 4.0f;
            local = {t, rng.index(2) == 0 ? t : -t};
            b.center = {0.0f, 0.0f};
            xfA = {{std::round(xfA.p.x * 4.0f) / 4.0f, std::round(xfA.p.y * 4.0f) / 4.0f},
                   Rot::fromAngle(0.0f)};
            xfB.q = Rot::fromAngle(0.0f);
            ++ties;
        }
        // Mode 3: the centre on one of A's vertices (up to rounding).
        if (mode == 3) {
            local = a.vertices[static_cast<std::size_t>(rng.index(a.count))];
        }
        xfB.p = transformPoint(xfA, local) - rotate(xfB.q, b.center);
        const float margin = mode == 2 ? rng.uniform(0.0f, 0.5f) : kSpeculativeDistance;
        const Manifold simd = collidePolygonAndCircle(a, xfA, b, xfB, margin);
        const Manifold scalar = collidePolygonAndCircleScalar(a, xfA, b, xfB, margin);
        test::expectSameManifoldBits(simd, scalar, pair);
        contacts += simd.pointCount > 0 ? 1 : 0;
    }
    // Both touching and separated pairs were compared.
    EXPECT_GT(contacts, 5000);
    EXPECT_LT(contacts, 35000);
    EXPECT_GT(ties, 5000);
}

// Every field the routine writes, the zeros after the first point included: the SSE2 routine
// stores the Manifold as blocks, so a lane out of place would show here.
void expectSameCircleManifold(const Manifold& simd, const Manifold& scalar, int pair) {
    test::expectSameManifoldBits(simd, scalar, pair);
    for (int i = 0; i < 2; ++i) {
        EXPECT_EQ(simd.points[i].normalImpulse, 0.0f) << "pair " << pair;
        EXPECT_EQ(simd.points[i].tangentImpulse, 0.0f) << "pair " << pair;
        EXPECT_FALSE(simd.points[i].persisted) << "pair " << pair;
    }
}

TEST(CollideCirclesScalarPath, BitIdenticalToSimdPath) {
    Rng rng{2026u};
    int contacts = 0;
    int concentric = 0;
    for (int pair = 0; pair < 40000; ++pair) {
        const int mode = rng.index(4);
        // Centred circles (mode 0 and half of the concentric ones: as most bodies have them, the
        // routines' fast path), offset ones otherwise; a quarter of the offset pairs have one
        // centred circle, or one centred at -0 (the general path, which must agree).
        const int centring = rng.index(8);
        const bool centred = mode == 0 || (mode == 3 && centring < 4);
        const Vec2 zero = centring == 4 ? Vec2{-0.0f, 0.0f} : Vec2{0.0f, 0.0f};
        const Circle a{centred || centring == 4
                           ? zero
                           : Vec2{rng.uniform(-0.5f, 0.5f), rng.uniform(-0.5f, 0.5f)},
                       rng.uniform(0.01f, 1.0f)};
        const Circle b{centred || centring == 5
                           ? Vec2{0.0f, 0.0f}
                           : Vec2{rng.uniform(-0.5f, 0.5f), rng.uniform(-0.5f, 0.5f)},
                       rng.uniform(0.01f, 1.0f)};
        const Transform xfA = makeTransform(rng.uniform(-2.0f, 2.0f), rng.uniform(-2.0f, 2.0f),
                                            rng.uniform(-3.2f, 3.2f));
        Transform xfB = makeTransform(rng.uniform(-2.0f, 2.0f), rng.uniform(-2.0f, 2.0f),
                                      rng.uniform(-3.2f, 3.2f));
        if (mode == 3) {
            // Concentric (A's x axis is the normal), or within float noise of it.
            xfB.p = transformPoint(xfA, a.center) - rotate(xfB.q, b.center);
            ++concentric;
        }
        const float margin = mode == 2 ? rng.uniform(0.0f, 0.5f) : kSpeculativeDistance;
        const Manifold simd = collideCircles(a, xfA, b, xfB, margin);
        const Manifold scalar = collideCirclesScalar(a, xfA, b, xfB, margin);
        expectSameCircleManifold(simd, scalar, pair);
        contacts += simd.pointCount > 0 ? 1 : 0;
    }
    // Both touching and separated pairs were compared.
    EXPECT_GT(contacts, 10000);
    EXPECT_LT(contacts, 35000);
    EXPECT_GT(concentric, 5000);
}

// Exact coordinates, where rotating a zero centre gives a signed zero that the centred fast path
// (no rotation) does not: a small circle deep inside a large one straight above A (the normal's
// x is 0 and the anchor's scale negative), A turned so that rotate(qA, {0, 0}).x is -0. The
// anchor's x is -0 along the rotation and +0 along the fast path, so both routines must take the
// same path for centred circles.
TEST(CollideCirclesScalarPath, CentredFastPathInBothRoutines) {
    const Circle big{{0.0f, 0.0f}, 1.0f};
    const Circle small{{0.0f, 0.0f}, 0.25f};
    for (float angle : {0.0f, 1.0f, 2.0f, 3.0f, -1.0f, -2.0f, -3.0f}) {
        for (float dy : {0.25f, -0.25f, 0.5f, 0.0f}) {
            const Transform xfA{{0.0f, 0.0f}, Rot::fromAngle(angle)};
            const Transform xfB{{0.0f, dy}, Rot::fromAngle(-angle)};
            for (int order = 0; order < 2; ++order) {
                const Circle& a = order == 0 ? small : big;
                const Circle& b = order == 0 ? big : small;
                const Manifold simd = collideCircles(a, xfA, b, xfB);
                const Manifold scalar = collideCirclesScalar(a, xfA, b, xfB, kSpeculativeDistance);
                ASSERT_EQ(simd.pointCount, 1);
                expectSameCircleManifold(simd, scalar, static_cast<int>(angle * 100.0f + dy));
            }
        }
    }
}

} // namespace
} // namespace e2d::physics
