// SPDX-License-Identifier: MIT
#include <e2d/physics/geometry.hpp>

#include <e2d/core/error_text.hpp>

#include "shape_detail.hpp"

#include <string>

namespace e2d::physics {
namespace {

void checkRadius(float radius, const char* function) {
    if (!isWithinHuge(radius) || radius < 0.0f) {
        core::throwError(function, "radius must be finite and in [0, kHuge (" +
                                       core::formatNumber(kHuge) + " m)], got " +
                                       core::formatNumber(radius));
    }
}

void checkHalfExtent(float value, const char* name, const char* function) {
    if (!isWithinHuge(value) || value <= 0.0f) {
        core::throwError(function,
                         std::string("half-extent ") + name + " must be finite and in (0, kHuge (" +
                             core::formatNumber(kHuge) + " m)], got " + core::formatNumber(value));
    }
}

// Builds normals and centroid for counter-clockwise, convex, validated vertices.
Polygon finishPolygon(const Vec2* vertices, int count, float radius) {
    Polygon polygon;
    polygon.count = count;
    polygon.radius = radius;
    for (int i = 0; i < count; ++i) {
        polygon.vertices[i] = vertices[i];
    }
    for (int i = 0; i < count; ++i) {
        Vec2 edge = vertices[i + 1 < count ? i + 1 : 0] - vertices[i];
        polygon.normals[i] = normalize(rightPerp(edge));
    }
    // Triangle fan from vertex 0 rather than the origin: the vertices may be far from the
    // origin, and small relative coordinates keep the cross products accurate.
    Vec2 origin = vertices[0];
    Vec2 weighted{0.0f, 0.0f};
    float area = 0.0f;
    for (int i = 1; i + 1 < count; ++i) {
        Vec2 e1 = vertices[i] - origin;
        Vec2 e2 = vertices[i + 1] - origin;
        float a = 0.5f * cross(e1, e2);
        weighted += (a / 3.0f) * (e1 + e2);
        area += a;
    }
    polygon.centroid = origin + weighted / area;
    return polygon;
}

Polygon makeFromHull(const Hull& hull, float radius, const char* function) {
    checkRadius(radius, function);
    if (hull.count < 3 || hull.count > kMaxPolygonVertices) {
        core::throwError(function,
                         "hull has " + std::to_string(hull.count) + " points, expected 3 to " +
                             std::to_string(kMaxPolygonVertices) + " (use computeHull())");
    }
    for (int i = 0; i < hull.count; ++i) {
        if (!isWithinHuge(hull.points[i])) {
            core::throwError(function, "hull point " + std::to_string(i) +
                                           " must be finite and within kHuge, got " +
                                           core::formatVector(hull.points[i]));
        }
    }
    // A hand-made hull must still be strictly convex and counter-clockwise, or the normals and
    // every collision routine would be wrong.
    for (int i = 0; i < hull.count; ++i) {
        Vec2 a = hull.points[i];
        Vec2 b = hull.points[(i + 1) % hull.count];
        Vec2 c = hull.points[(i + 2) % hull.count];
        if (!(cross(b - a, c - b) > 0.0f)) {
            core::throwError(function,
                             "hull is not strictly convex and counter-clockwise at point " +
                                 std::to_string((i + 1) % hull.count) + " " +
                                 core::formatVector(b) + " (use computeHull())");
        }
    }
    return finishPolygon(hull.points.data(), hull.count, radius);
}

} // namespace

Polygon makePolygon(std::span<const Vec2> points, float radius) {
    constexpr const char* kFunction = "physics::makePolygon()";
    checkRadius(radius, kFunction);
    return makeFromHull(detail::computeHull(points, kFunction), radius, kFunction);
}

Polygon makePolygon(const Hull& hull, float radius) {
    return makeFromHull(hull, radius, "physics::makePolygon()");
}

Polygon makeBox(float hx, float hy) {
    constexpr const char* kFunction = "physics::makeBox()";
    checkHalfExtent(hx, "hx", kFunction);
    checkHalfExtent(hy, "hy", kFunction);
    Polygon box;
    box.count = 4;
    box.vertices[0] = {-hx, -hy};
    box.vertices[1] = {hx, -hy};
    box.vertices[2] = {hx, hy};
    box.vertices[3] = {-hx, hy};
    box.normals[0] = {0.0f, -1.0f};
    box.normals[1] = {1.0f, 0.0f};
    box.normals[2] = {0.0f, 1.0f};
    box.normals[3] = {-1.0f, 0.0f};
    return box;
}

Polygon makeOffsetBox(float hx, float hy, Vec2 center, float angle) {
    constexpr const char* kFunction = "physics::makeOffsetBox()";
    checkHalfExtent(hx, "hx", kFunction);
    checkHalfExtent(hy, "hy", kFunction);
    if (!isWithinHuge(center)) {
        core::throwError(kFunction, "center must be finite and within kHuge, got " +
                                        core::formatVector(center));
    }
    if (!std::isfinite(angle)) {
        core::throwError(kFunction, "angle must be finite, got " + core::formatNumber(angle));
    }
    Polygon box = makeBox(hx, hy);
    Transform xf{center, Rot::fromAngle(angle)};
    for (int i = 0; i < box.count; ++i) {
        box.vertices[i] = transformPoint(xf, box.vertices[i]);
        box.normals[i] = rotate(xf.q, box.normals[i]);
    }
    box.centroid = center;
    return box;
}

Polygon makeRoundedBox(float hx, float hy, float radius) {
    constexpr const char* kFunction = "physics::makeRoundedBox()";
    checkHalfExtent(hx, "hx", kFunction);
    checkHalfExtent(hy, "hy", kFunction);
    checkRadius(radius, kFunction);
    Polygon box = makeBox(hx, hy);
    box.radius = radius;
    return box;
}

void validate(const ShapeGeometry& shape, const char* function) {
    switch (typeOf(shape)) {
    case ShapeType::Circle: {
        const auto& circle = std::get<Circle>(shape);
        if (!isWithinHuge(circle.center)) {
            core::throwError(function, "circle center must be finite and within kHuge, got " +
                                           core::formatVector(circle.center));
        }
        if (!isWithinHuge(circle.radius) || circle.radius <= 0.0f) {
            core::throwError(function, "circle radius must be finite and in (0, kHuge (" +
                                           core::formatNumber(kHuge) + " m)], got " +
                                           core::formatNumber(circle.radius));
        }
        return;
    }
    case ShapeType::Capsule: {
        const auto& capsule = std::get<Capsule>(shape);
        if (!isWithinHuge(capsule.center1) || !isWithinHuge(capsule.center2)) {
            core::throwError(function, "capsule centers must be finite and within kHuge, got " +
                                           core::formatVector(capsule.center1) + " and " +
                                           core::formatVector(capsule.center2));
        }
        if (!isWithinHuge(capsule.radius) || capsule.radius <= 0.0f) {
            core::throwError(function, "capsule radius must be finite and in (0, kHuge (" +
                                           core::formatNumber(kHuge) + " m)], got " +
                                           core::formatNumber(capsule.radius));
        }
        // A capsule shorter than the slop has no usable axis; a Circle says what is meant.
        float len = distance(capsule.center1, capsule.center2);
        if (!(len >= kLinearSlop)) {
            core::throwError(function, "capsule centers must be at least kLinearSlop (" +
                                           core::formatNumber(kLinearSlop) + " m) apart, got " +
                                           core::formatNumber(len) + " (use a Circle)");
        }
        return;
    }
    case ShapeType::ChainSegment: {
        const auto& chain = std::get<ChainSegment>(shape);
        if ((chain.hasGhost1 && !isWithinHuge(chain.ghost1)) ||
            (chain.hasGhost2 && !isWithinHuge(chain.ghost2))) {
            core::throwError(function,
                             "chain segment ghost points must be finite and within kHuge, got " +
                                 core::formatVector(chain.ghost1) + " and " +
                                 core::formatVector(chain.ghost2));
        }
        validate(chain.segment, function);
        return;
    }
    case ShapeType::Segment: {
        const auto& segment = std::get<Segment>(shape);
        if (!isWithinHuge(segment.point1) || !isWithinHuge(segment.point2)) {
            core::throwError(function, "segment points must be finite and within kHuge, got " +
                                           core::formatVector(segment.point1) + " and " +
                                           core::formatVector(segment.point2));
        }
        float len = distance(segment.point1, segment.point2);
        if (!(len >= kLinearSlop)) {
            core::throwError(function, "segment points must be at least kLinearSlop (" +
                                           core::formatNumber(kLinearSlop) + " m) apart, got " +
                                           core::formatNumber(len));
        }
        return;
    }
    case ShapeType::Polygon: {
        const auto& polygon = std::get<Polygon>(shape);
        if (polygon.count < 3 || polygon.count > kMaxPolygonVertices) {
            core::throwError(function, "polygon has " + std::to_string(polygon.count) +
                                           " vertices, expected 3 to " +
                                           std::to_string(kMaxPolygonVertices) +
                                           " (use makePolygon())");
        }
        if (!isWithinHuge(polygon.radius) || polygon.radius < 0.0f) {
            core::throwError(function, "polygon radius must be finite and in [0, kHuge (" +
                                           core::formatNumber(kHuge) + " m)], got " +
                                           core::formatNumber(polygon.radius));
        }
        if (!isWithinHuge(polygon.centroid)) {
            core::throwError(function, "polygon centroid must be finite and within kHuge, got " +
                                           core::formatVector(polygon.centroid));
        }
        for (int i = 0; i < polygon.count; ++i) {
            if (!isWithinHuge(polygon.vertices[i])) {
                core::throwError(function, "polygon vertex " + std::to_string(i) +
                                               " must be finite and within kHuge, got " +
                                               core::formatVector(polygon.vertices[i]));
            }
            Vec2 n = polygon.normals[i];
            if (!isFinite(n) || std::fabs(lengthSquared(n) - 1.0f) > 1.0e-3f) {
                core::throwError(function, "polygon normal " + std::to_string(i) +
                                               " must be a unit vector, got " +
                                               core::formatVector(n) + " (use makePolygon())");
            }
        }
        for (int i = 0; i < polygon.count; ++i) {
            Vec2 a = polygon.vertices[i];
            Vec2 b = polygon.vertices[(i + 1) % polygon.count];
            Vec2 c = polygon.vertices[(i + 2) % polygon.count];
            if (!(cross(b - a, c - b) > 0.0f)) {
                core::throwError(
                    function, "polygon is not strictly convex and counter-clockwise at vertex " +
                                  std::to_string((i + 1) % polygon.count) + " (use makePolygon())");
            }
        }
        return;
    }
    }
}

} // namespace e2d::physics
