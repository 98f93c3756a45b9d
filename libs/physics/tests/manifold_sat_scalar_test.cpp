// SPDX-License-Identifier: MIT
// collidePolygons' SSE2 path against its portable scalar path. The library's source is
// compiled here a second time with the scalar path forced and the function renamed; both must
// return bit-identical manifolds (same face on ties, same points, separations and ids). On a
// machine without SSE2 both are the scalar path and the test passes trivially.
#include <e2d/physics/manifold.hpp>

#include "geometry_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#define E2D_PHYSICS_SCALAR_SAT 1
#define collidePolygons collidePolygonsScalar
#include "../src/manifold_sat.cpp"
#undef collidePolygons

namespace e2d::physics {
namespace {

using test::makeTransform;

using Rng = test::TestRandom;

// Boxes, rounded and offset boxes, 3- to 8-gons (some far from their origin, which moves the
// work to a shifted frame), and 2-vertex capsule polygons: every lane padding and both
// register counts on either side.
std::vector<Polygon> makeShapes(Rng& rng) {
    std::vector<Polygon> shapes;
    for (int i = 0; i < 48; ++i) {
        shapes.push_back(makeBox(rng.uniform(0.05f, 2.0f), rng.uniform(0.05f, 2.0f)));
    }
    for (int i = 0; i < 8; ++i) {
        shapes.push_back(makeRoundedBox(rng.uniform(0.05f, 1.0f), rng.uniform(0.05f, 1.0f),
                                        rng.uniform(0.01f, 0.3f)));
        shapes.push_back(makeOffsetBox(rng.uniform(0.1f, 1.0f), rng.uniform(0.1f, 1.0f),
                                       {rng.uniform(-1, 1), rng.uniform(-1, 1)},
                                       rng.uniform(-3.0f, 3.0f)));
        shapes.push_back(makeOffsetBox(rng.uniform(0.1f, 1.0f), rng.uniform(0.1f, 1.0f),
                                       {rng.uniform(100.0f, 300.0f), rng.uniform(-300.0f, 300.0f)},
                                       rng.uniform(-3.0f, 3.0f)));
        shapes.push_back(detail::makeCapsulePolygon({rng.uniform(-1, 1), rng.uniform(-1, 1)},
                                                    {rng.uniform(-1, 1), rng.uniform(-1, 1)},
                                                    rng.uniform(0.0f, 0.3f)));
    }
    for (int count = 3; count <= 8; ++count) {
        for (int i = 0; i < 8; ++i) {
            const float radius = rng.uniform(0.2f, 1.5f);
            const Vec2 offset =
                i == 7 ? Vec2{rng.uniform(-300.0f, -100.0f), rng.uniform(-300.0f, 300.0f)}
                       : Vec2{0.0f, 0.0f};
            std::vector<Vec2> points;
            for (int k = 0; k < count; ++k) {
                const float angle = (static_cast<float>(k) + rng.uniform(0.1f, 0.9f)) *
                                    (6.2831853f / static_cast<float>(count));
                points.push_back(offset + Vec2{radius * std::cos(angle), radius * std::sin(angle)});
            }
            shapes.push_back(makePolygon(points, i % 3 == 0 ? rng.uniform(0.0f, 0.2f) : 0.0f));
        }
    }
    return shapes;
}

TEST(CollidePolygonsScalarPath, BitIdenticalToSimdPath) {
    Rng rng{2024u};
    const std::vector<Polygon> shapes = makeShapes(rng);
    const int shapeCount = static_cast<int>(shapes.size());
    int contacts = 0;
    for (int pair = 0; pair < 40000; ++pair) {
        const Polygon& a = shapes[static_cast<std::size_t>(rng.index(shapeCount))];
        const Polygon& b = shapes[static_cast<std::size_t>(rng.index(shapeCount))];
        const int mode = rng.index(4);
        // Mode 1: axis-aligned and on a quarter grid, so faces tie exactly.
        const float angleA = mode == 1 ? 0.0f : rng.uniform(-3.2f, 3.2f);
        const float angleB = mode == 1 ? 0.0f : rng.uniform(-3.2f, 3.2f);
        const Transform xfA =
            makeTransform(rng.uniform(-2.0f, 2.0f), rng.uniform(-2.0f, 2.0f), angleA);
        Vec2 offset{rng.uniform(-3.0f, 3.0f), rng.uniform(-3.0f, 3.0f)};
        if (mode == 1) {
            offset = {std::round(offset.x * 4.0f) / 4.0f, std::round(offset.y * 4.0f) / 4.0f};
        }
        // B placed about A's centroid, so shapes far from their origin still meet.
        const Rot qB = Rot::fromAngle(angleB);
        const Vec2 pB = transformPoint(xfA, a.centroid) + offset - rotate(qB, b.centroid);
        const Transform xfB{pB, qB};
        const float margin = mode == 2 ? rng.uniform(0.0f, 0.5f) : kSpeculativeDistance;
        const Manifold simd = collidePolygons(a, xfA, b, xfB, margin);
        const Manifold scalar = collidePolygonsScalar(a, xfA, b, xfB, margin);
        test::expectSameManifoldBits(simd, scalar, pair);
        contacts += simd.pointCount > 0 ? 1 : 0;
    }
    // Both touching and separated pairs were compared.
    EXPECT_GT(contacts, 5000);
    EXPECT_LT(contacts, 35000);
}

} // namespace
} // namespace e2d::physics
