// SPDX-License-Identifier: MIT
#pragma once

#include "manifold_detail.hpp"

#include <cfloat>
#include <cmath>

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
/// Shared by SAT and GJK/EPA so both algorithms clip the same way. Forced inline: called out of
/// line (as GCC chose once the corner-crossing test joined its caller), its arguments and
/// result went through memory on every pair's critical path.
[[gnu::always_inline]] static inline LocalManifold clipPolygons(const PolygonRef& a,
                                                                const PolygonRef& b, int edgeA,
                                                                int edgeB, bool flip,
                                                                float margin) {
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

/// Two overlapping polygons whose best faces meet at an angle and separate them by about the
/// same amount (within this, metres) are crossing at two corners (two cards tip to tip): each
/// corner lies against the other polygon's face, and neither face is the contact's.
inline constexpr float kCrossingTolerance = kLinearSlop;
/// ... unless the two faces are this close to anti-parallel (cosine of 0.1 rad): faces in line
/// (a box resting on a box) are a face contact, clipped even where their corners meet.
inline constexpr float kCrossingMaxCos = 0.995f;

/// The first of `count` items (vertices or normals) with the least dot product with
/// `direction`: the vertex deepest along -direction, or the normal most anti-parallel to it
/// (an incident face). Kept by selects, not branches.
static inline int firstMinDot(const Vec2* items, int count, Vec2 direction) {
    int best = 0;
    float bestDot = FLT_MAX;
    for (int i = 0; i < count; ++i) {
        const float d = dot(direction, items[i]);
        const bool better = d < bestDot;
        best = better ? i : best;
        bestDot = better ? d : bestDot;
    }
    return best;
}

/// Whether two polygons (in one frame) may be crossing at two corners: face `edgeA` of `a`
/// separates them by `separationA`, face `edgeB` of `b` by `separationB`. The cores overlap or
/// touch (both at most kSeparatedCores) by less than the speculative distance, the two
/// separations are within kCrossingTolerance of each other, and the two faces face each other
/// without being in line. Cheap enough for every touching pair; crossingCorners() decides.
static inline bool mayCrossAtCorners(const PolygonRef& a, const PolygonRef& b, int edgeA,
                                     float separationA, int edgeB, float separationB) {
    if (separationA > kSeparatedCores || separationB > kSeparatedCores ||
        separationA < -kSpeculativeDistance ||
        std::fabs(separationA - separationB) > kCrossingTolerance) {
        return false;
    }
    const float facing = dot(a.normals[edgeA], b.normals[edgeB]);
    return facing <= 0.0f && facing >= -kCrossingMaxCos;
}

/// The contact of two polygons that mayCrossAtCorners() (same arguments): count 0 when they do
/// not cross at two corners after all. A reference face would make such a contact lopsided:
/// its normal is one card's face normal, tilted by the whole angle between the faces, and
/// which face wins depends on a few tenths of a millimetre in the first touching steps. The
/// crossing gets the answer the separated routine gives while the corners are apart: one point
/// midway between the two corners, its normal the bisector of the two face normals, its
/// separation the overlap of the corners along it, its id the two corners. Only for corners
/// within kLinearSlop of each other across that normal: corners far apart are the ends of a
/// wedge-shaped face contact (a tilted box lying on another's edge), which clipping gives two
/// points. Out of line: it runs for few pairs, and inlined it slowed every touching pair.
[[gnu::noinline]] static LocalManifold crossingCorners(const PolygonRef& a, const PolygonRef& b,
                                                       int edgeA, int edgeB, float margin) {
    LocalManifold m{};
    const Vec2 normalA = a.normals[edgeA];
    const Vec2 normalB = b.normals[edgeB];
    const Vec2 bisector = normalize(normalA - normalB);
    const int cornerA = firstMinDot(a.vertices, a.count, normalB);
    const int cornerB = firstMinDot(b.vertices, b.count, normalA);
    const Vec2 pA = a.vertices[cornerA];
    const Vec2 pB = b.vertices[cornerB];
    const float separation = dot(pB - pA, bisector) - (a.radius + b.radius);
    if (std::fabs(cross(bisector, pB - pA)) > kLinearSlop || separation > margin) {
        return m;
    }
    m.normal = bisector;
    m.points[0] = 0.5f * ((pA + a.radius * bisector) + (pB - b.radius * bisector));
    m.separations[0] = separation;
    m.ids[0] = makeFeatureId(cornerA, cornerB);
    m.count = 1;
    return m;
}

} // namespace e2d::physics::detail
