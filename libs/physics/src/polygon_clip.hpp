// SPDX-License-Identifier: MIT
#pragma once

#include "manifold_detail.hpp"

namespace e2d::physics::detail {

/// A polygon's collision data seen through pointers: lets the pair routines use a polygon in
/// place or a copy moved to another frame without building (and zeroing) a whole Polygon.
struct PolygonRef {
    const Vec2* vertices;
    const Vec2* normals;
    float radius;
    int count;
};

inline PolygonRef refOf(const Polygon& p) {
    return {p.vertices.data(), p.normals.data(), p.radius, p.count};
}

/// Up to kMaxPolygonVertices vertices and normals, left uninitialised until written: the
/// frame change of the pair routines fills only `count` of them.
struct PolygonScratch {
    Vec2 vertices[kMaxPolygonVertices];
    Vec2 normals[kMaxPolygonVertices];
};

/// Contact points of two polygons once the axis is known: the reference edge `edgeA` of `a`
/// and the incident edge `edgeB` of `b`, both polygons in the same frame (A's local frame).
/// `flip` swaps the roles (b holds the reference edge `edgeB`, a the incident edge `edgeA`).
/// Returns the points in that frame (normal from a to b, each point midway between the two
/// rounded surfaces). Points with separation > margin are dropped.
/// Shared by SAT and GJK/EPA so both algorithms clip the same way. Inline: called out of line,
/// its arguments and result went through memory on every pair's critical path.
static inline LocalManifold clipPolygons(const PolygonRef& a, const PolygonRef& b, int edgeA,
                                         int edgeB, bool flip, float margin) {
    // poly1 holds the reference edge i11 -> i12, poly2 the incident edge i21 -> i22.
    const PolygonRef& poly1 = flip ? b : a;
    const PolygonRef& poly2 = flip ? a : b;
    const int i11 = flip ? edgeB : edgeA;
    const int i12 = i11 + 1 < poly1.count ? i11 + 1 : 0;
    const int i21 = flip ? edgeA : edgeB;
    const int i22 = i21 + 1 < poly2.count ? i21 + 1 : 0;

    const Vec2 v11 = poly1.vertices[i11];
    const Vec2 v12 = poly1.vertices[i12];
    const Vec2 v21 = poly2.vertices[i21];
    const Vec2 v22 = poly2.vertices[i22];
    const Vec2 normal = poly1.normals[i11];
    const Vec2 tangent = leftPerp(normal); // along v11 -> v12 for counter-clockwise polygons

    // Clip the incident edge to the reference edge's side planes, in tangent coordinates. The
    // incident edge runs against the reference edge, so v22 is its lower end. Parameters are
    // clamped so a point never leaves the incident edge even when the edges barely overlap.
    const float lower1 = 0.0f;
    const float upper1 = dot(v12 - v11, tangent);
    const float upper2 = dot(v21 - v11, tangent);
    const float lower2 = dot(v22 - v11, tangent);
    //
    // A clipped point is placed from the reference edge, not interpolated along the incident
    // edge: its tangent coordinate is the side plane's and only its height above the reference
    // face is interpolated, from heights measured from v11. Interpolated from the incident
    // edge's far ends, a long edge (a 400 m ground under a box) put the point 1.5e-5 m off the
    // box's corner (the rounding at 200 m), a lever arm that differs between the two corners.
    Vec2 vLower = v22;
    Vec2 vUpper = v21;
    const float span = upper2 - lower2;
    if (span > 1.1920929e-7f) {
        const float height21 = dot(v21 - v11, normal);
        const float height22 = dot(v22 - v11, normal);
        auto onSidePlane = [&](float t, float s) {
            return v11 + t * tangent + (height22 + s * (height21 - height22)) * normal;
        };
        if (lower2 < lower1) {
            float s = (lower1 - lower2) / span;
            vLower = s > 1.0f ? v21 : onSidePlane(lower1, s);
        }
        if (upper2 > upper1) {
            float s = (upper1 - lower2) / span;
            vUpper = s < 0.0f ? v22 : onSidePlane(upper1, s);
        }
    }

    const float r1 = poly1.radius;
    const float r2 = poly2.radius;
    float separationLower = dot(vLower - v11, normal);
    float separationUpper = dot(vUpper - v11, normal);
    // Move each point from the incident core to midway between the two rounded surfaces.
    vLower += (0.5f * (r1 - r2 - separationLower)) * normal;
    vUpper += (0.5f * (r1 - r2 - separationUpper)) * normal;
    separationLower -= r1 + r2;
    separationUpper -= r1 + r2;

    LocalManifold m;
    m.count = 0;
    auto add = [&](Vec2 p, float separation, int featureA, int featureB) {
        if (separation > margin) {
            return;
        }
        m.points[m.count] = p;
        m.separations[m.count] = separation;
        m.ids[m.count] = makeFeatureId(featureA, featureB);
        ++m.count;
    };
    // Ids are (feature of a, feature of b) whichever polygon holds the reference edge.
    if (!flip) {
        m.normal = normal;
        add(vLower, separationLower, i11, i22);
        add(vUpper, separationUpper, i12, i21);
    } else {
        m.normal = -normal;
        add(vUpper, separationUpper, i21, i12);
        add(vLower, separationLower, i22, i11);
    }
    return m;
}

} // namespace e2d::physics::detail
