// SPDX-License-Identifier: MIT
// Random pairs of valid shapes at random places: both collision algorithms through collide(),
// then distance, penetration, shape cast and time of impact on the same pair. Any crash, NaN,
// out-of-range count or fraction aborts.
#include <e2d/core/error.hpp>
#include <e2d/physics/distance.hpp>
#include <e2d/physics/manifold.hpp>
#include <e2d/physics/time_of_impact.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <vector>

namespace {

using namespace e2d::physics;

void check(bool condition) {
    if (!condition) {
        std::abort();
    }
}

// Lengths in [lo, hi] metres with a fine grid, so that exact touching and parallel cases occur.
float length01(FuzzedDataProvider& data, float lo, float hi) {
    return lo + (hi - lo) * static_cast<float>(data.ConsumeIntegral<std::uint16_t>()) / 65535.0f;
}

Vec2 point(FuzzedDataProvider& data, float extent) {
    return {length01(data, -extent, extent), length01(data, -extent, extent)};
}

std::optional<ShapeGeometry> makeShape(FuzzedDataProvider& data) {
    switch (data.ConsumeIntegralInRange<int>(0, 3)) {
    case 0:
        return ShapeGeometry{Circle{point(data, 1.0f), length01(data, 0.01f, 3.0f)}};
    case 1: {
        Capsule c{point(data, 2.0f), point(data, 2.0f), length01(data, 0.01f, 1.0f)};
        try {
            validate(ShapeGeometry{c}, "fuzz_narrowphase");
        } catch (const e2d::core::Error&) {
            return std::nullopt;
        }
        return ShapeGeometry{c};
    }
    case 2: {
        Segment s{point(data, 3.0f), point(data, 3.0f)};
        try {
            validate(ShapeGeometry{s}, "fuzz_narrowphase");
        } catch (const e2d::core::Error&) {
            return std::nullopt;
        }
        return ShapeGeometry{s};
    }
    default: {
        int count = data.ConsumeIntegralInRange<int>(3, 8);
        float scale = length01(data, 0.05f, 4.0f);
        std::vector<Vec2> points;
        for (int i = 0; i < count; ++i) {
            points.push_back(scale * point(data, 1.0f));
        }
        float radius = data.ConsumeBool() ? length01(data, 0.0f, 0.5f) : 0.0f;
        try {
            return ShapeGeometry{makePolygon(points, radius)};
        } catch (const e2d::core::Error&) {
            return std::nullopt;
        }
    }
    }
}

Transform transform(FuzzedDataProvider& data) {
    return {point(data, 6.0f), Rot::fromAngle(length01(data, -4.0f, 4.0f))};
}

void checkManifold(const Manifold& m) {
    check(m.pointCount >= 0 && m.pointCount <= 2);
    if (m.pointCount > 0) {
        check(isFinite(m.normal));
        check(std::fabs(length(m.normal) - 1.0f) < 1.0e-3f);
    }
    for (int i = 0; i < m.pointCount; ++i) {
        const ManifoldPoint& p = m.points[i];
        check(isFinite(p.point) && isFinite(p.anchorA) && isFinite(p.anchorB));
        check(std::isfinite(p.separation));
        check(p.separation <= kSpeculativeDistance + 1.0e-4f);
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
    FuzzedDataProvider data(bytes, size);
    std::optional<ShapeGeometry> a = makeShape(data);
    std::optional<ShapeGeometry> b = makeShape(data);
    if (!a || !b) {
        return 0;
    }
    Transform xfA = transform(data);
    Transform xfB = transform(data);

    checkManifold(collide(*a, xfA, *b, xfB, CollisionAlgorithm::Sat));
    checkManifold(collide(*a, xfA, *b, xfB, CollisionAlgorithm::GjkEpa));

    DistanceInput input;
    input.proxyA = makeProxy(*a);
    input.proxyB = makeProxy(*b);
    input.transformA = xfA;
    input.transformB = xfB;
    input.useRadii = data.ConsumeBool();
    SimplexCache cache;
    DistanceOutput d = shapeDistance(input, &cache);
    check(isFinite(d.pointA) && isFinite(d.pointB) && isFinite(d.normal));
    check(std::isfinite(d.distance) && d.distance >= 0.0f);
    check(d.iterations <= kMaxGjkIterations);
    DistanceOutput again = shapeDistance(input, &cache);
    check(std::fabs(again.distance - d.distance) <= 1.0e-3f * (1.0f + d.distance));

    PenetrationOutput p = penetration(input);
    check(isFinite(p.pointA) && isFinite(p.pointB) && isFinite(p.normal));
    check(std::isfinite(p.depth));
    check(p.iterations <= kMaxGjkIterations + kMaxEpaIterations);

    ShapeCastPairInput cast;
    cast.proxyA = input.proxyA;
    cast.proxyB = input.proxyB;
    cast.transformA = xfA;
    cast.transformB = xfB;
    cast.translationB = point(data, 20.0f);
    cast.maxFraction = length01(data, 0.0f, 1.0f);
    CastOutput c = shapeCast(cast);
    check(isFinite(c.point) && isFinite(c.normal) && std::isfinite(c.fraction));
    check(c.fraction >= 0.0f && c.fraction <= cast.maxFraction);
    check(c.iterations <= kMaxShapeCastIterations);

    TOIInput toi;
    toi.proxyA = input.proxyA;
    toi.proxyB = input.proxyB;
    toi.sweepA.localCenter = point(data, 0.5f);
    toi.sweepA.c1 = xfA.p;
    toi.sweepA.c2 = xfA.p + point(data, 10.0f);
    toi.sweepA.q1 = xfA.q;
    toi.sweepA.q2 = Rot::fromAngle(xfA.q.angle() + length01(data, -3.0f, 3.0f));
    toi.sweepB.localCenter = point(data, 0.5f);
    toi.sweepB.c1 = xfB.p;
    toi.sweepB.c2 = xfB.p + point(data, 10.0f);
    toi.sweepB.q1 = xfB.q;
    toi.sweepB.q2 = Rot::fromAngle(xfB.q.angle() + length01(data, -3.0f, 3.0f));
    toi.maxFraction = length01(data, 0.0f, 1.0f);
    TOIOutput t = timeOfImpact(toi);
    check(t.state != TOIState::Unknown);
    check(std::isfinite(t.fraction) && t.fraction >= 0.0f && t.fraction <= toi.maxFraction);
    return 0;
}
