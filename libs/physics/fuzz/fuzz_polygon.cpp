// SPDX-License-Identifier: MIT
// Point clouds (raw float bits, so NaN, infinities, denormals and huge values all occur) into
// computeHull and makePolygon: the result is either a valid polygon or core::Error, never
// anything else (no crash, no other exception, no NaN, no clockwise or degenerate polygon).
#include <e2d/core/error.hpp>
#include <e2d/physics/geometry.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace {

using namespace e2d::physics;

void check(bool condition) {
    if (!condition) {
        std::abort();
    }
}

float pickFloat(FuzzedDataProvider& data) {
    // Half the time a raw bit pattern, half the time a "reasonable" number so that the valid
    // path is exercised as much as the rejection path.
    if (data.ConsumeBool()) {
        return data.ConsumeFloatingPoint<float>();
    }
    return static_cast<float>(data.ConsumeIntegralInRange<int>(-2000, 2000)) * 0.01f;
}

void checkHull(const Hull& hull) {
    check(hull.count >= 3 && hull.count <= kMaxPolygonVertices);
    for (int i = 0; i < hull.count; ++i) {
        Vec2 p = hull.points[i];
        Vec2 q = hull.points[(i + 1) % hull.count];
        Vec2 r = hull.points[(i + 2) % hull.count];
        check(isFinite(p));
        check(cross(q - p, r - q) > 0.0f); // strictly convex, counter-clockwise
    }
}

void checkPolygon(const Polygon& polygon, float radius) {
    check(polygon.count >= 3 && polygon.count <= kMaxPolygonVertices);
    check(polygon.radius == radius);
    check(isFinite(polygon.centroid));
    float area = 0.0f;
    for (int i = 0; i < polygon.count; ++i) {
        Vec2 p = polygon.vertices[i];
        Vec2 q = polygon.vertices[(i + 1) % polygon.count];
        check(isFinite(p));
        check(isFinite(polygon.normals[i]));
        check(std::fabs(length(polygon.normals[i]) - 1.0f) < 1.0e-4f);
        // The normal of edge p -> q points out, to the right of the edge.
        check(dot(polygon.normals[i], q - p) <= 1.0e-3f * length(q - p));
        check(cross(q - p, polygon.normals[i]) < 0.0f);
        area += cross(p, q);
    }
    check(area > 0.0f);
    check(testPoint(polygon, polygon.centroid));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
    FuzzedDataProvider data(bytes, size);
    int count = data.ConsumeIntegralInRange<int>(0, 12);
    std::vector<Vec2> points;
    for (int i = 0; i < count; ++i) {
        float x = pickFloat(data);
        float y = pickFloat(data);
        points.push_back({x, y});
    }
    float radius = data.ConsumeBool() ? pickFloat(data) : 0.0f;

    try {
        Hull hull = computeHull(points);
        checkHull(hull);
    } catch (const e2d::core::Error&) {
    }
    try {
        Polygon polygon = makePolygon(points, radius);
        checkPolygon(polygon, radius);
        validate(ShapeGeometry{polygon}, "fuzz_polygon");
        MassData mass = computeMass(polygon, 1.0f);
        check(std::isfinite(mass.mass) && mass.mass > 0.0f);
        check(isFinite(mass.center) && std::isfinite(mass.rotationalInertia));
    } catch (const e2d::core::Error&) {
    }
    return 0;
}
