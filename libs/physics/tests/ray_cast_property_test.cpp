// SPDX-License-Identifier: MIT
// Randomised ray casts checked against testPoint(): a hit lies on the boundary, and the ray
// is outside the shape before it.
#include <e2d/physics/geometry.hpp>

#include "geometry_test_util.hpp"

#include <cmath>
#include <random>
#include <vector>

namespace e2d::physics {
namespace {

using Random = test::TestRandom;

ShapeGeometry randomSolidShape(Random& rng) {
    switch (rng.index(3)) {
    case 0:
        return Circle{{rng.uniform(-0.3f, 0.3f), rng.uniform(-0.3f, 0.3f)},
                      rng.uniform(0.2f, 1.0f)};
    case 1: {
        float a = rng.uniform(0.0f, 6.3f), half = rng.uniform(0.1f, 1.0f);
        Vec2 u{std::cos(a), std::sin(a)};
        return Capsule{-half * u, half * u, rng.uniform(0.1f, 0.5f)};
    }
    default: {
        int n = 3 + rng.index(6);
        std::vector<Vec2> points;
        for (int i = 0; i < n; ++i) {
            float a = 6.2831853f * (static_cast<float>(i) + rng.uniform(0.0f, 0.8f)) /
                      static_cast<float>(n);
            float r = rng.uniform(0.3f, 1.0f);
            points.push_back({r * std::cos(a), r * std::sin(a)});
        }
        return makePolygon(points, rng.index(2) == 0 ? 0.0f : rng.uniform(0.0f, 0.3f));
    }
    }
}

TEST(RayCastProperties, HitsLieOnTheBoundaryAndNothingIsSkipped) {
    Random rng(99);
    const float eps = 1e-3f;
    int hits = 0, misses = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        ShapeGeometry shape = randomSolidShape(rng);
        RayCastInput input;
        float a = rng.uniform(0.0f, 6.3f);
        input.origin = {3.0f * std::cos(a), 3.0f * std::sin(a)};
        Vec2 target{rng.uniform(-1.2f, 1.2f), rng.uniform(-1.2f, 1.2f)};
        input.translation = 1.5f * (target - input.origin);
        input.maxFraction = rng.uniform(0.3f, 1.0f);
        SCOPED_TRACE(testing::Message() << "trial " << trial << " type " << shape.index());
        ASSERT_FALSE(testPoint(shape, input.origin));

        CastOutput out = rayCast(input, shape);
        float end = out.hit ? out.fraction : input.maxFraction;
        // Nothing inside the shape along the ray before the hit (or before the end).
        for (int k = 0; k < 50; ++k) {
            float t = end * static_cast<float>(k) / 50.0f;
            Vec2 p = input.origin + t * input.translation;
            if (distance(p, input.origin + end * input.translation) > eps) {
                EXPECT_FALSE(testPoint(shape, p)) << "t " << t;
            }
        }
        if (!out.hit) {
            ++misses;
            continue;
        }
        ++hits;
        EXPECT_GE(out.fraction, 0.0f);
        EXPECT_LE(out.fraction, input.maxFraction);
        EXPECT_NEAR(length(out.normal), 1.0f, 1e-5f);
        EXPECT_LE(dot(out.normal, input.translation), 0.0f); // faces the ray
        EXPECT_TRUE(testPoint(shape, out.point - eps * out.normal));
        EXPECT_FALSE(testPoint(shape, out.point + eps * out.normal));
    }
    EXPECT_GT(hits, 500);
    EXPECT_GT(misses, 300);
}

} // namespace
} // namespace e2d::physics
