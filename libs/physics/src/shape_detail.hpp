// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/geometry.hpp>

#include <span>

namespace e2d::physics::detail {

// computeHull() with the public function's name for the messages (makePolygon() reuses it).
Hull computeHull(std::span<const Vec2> points, const char* function);

// A capsule (or, with radius 0, a segment) as a 2-vertex rounded polygon: edge 0 runs
// p1 -> p2 with the right-hand normal, edge 1 runs back with the opposite one. Only the
// collision routines use this form; makePolygon() never returns it.
inline Polygon makeCapsulePolygon(Vec2 p1, Vec2 p2, float radius) {
    Polygon polygon;
    polygon.vertices[0] = p1;
    polygon.vertices[1] = p2;
    Vec2 n = normalize(rightPerp(p2 - p1));
    polygon.normals[0] = n;
    polygon.normals[1] = -n;
    polygon.centroid = 0.5f * (p1 + p2);
    polygon.radius = radius;
    polygon.count = 2;
    return polygon;
}

// Closest points of segments [p1, q1] and [p2, q2]; fraction1/2 locate them on each segment.
struct SegmentDistance {
    Vec2 closest1{0.0f, 0.0f};
    Vec2 closest2{0.0f, 0.0f};
    float fraction1 = 0.0f;
    float fraction2 = 0.0f;
    float distanceSquared = 0.0f;
};

SegmentDistance segmentDistance(Vec2 p1, Vec2 q1, Vec2 p2, Vec2 q2);

// Closest point to `p` on segment [a, b].
inline Vec2 closestPointOnSegment(Vec2 a, Vec2 b, Vec2 p) {
    Vec2 e = b - a;
    float ee = dot(e, e);
    if (ee <= 0.0f) {
        return a;
    }
    float t = dot(p - a, e) / ee;
    t = t < 0.0f ? 0.0f : (t > 1.0f ? 1.0f : t);
    return a + t * e;
}

} // namespace e2d::physics::detail
