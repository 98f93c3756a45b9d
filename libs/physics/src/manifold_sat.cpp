// SPDX-License-Identifier: MIT
#include <e2d/physics/manifold.hpp>

#include "manifold_detail.hpp"
#include "polygon_clip.hpp"
#include "shape_detail.hpp"

#include <cfloat>

namespace e2d::physics {
namespace {

using detail::kFaceOffset;
using detail::kFlipTolerance;
using detail::kSeparatedCores;
using detail::LocalManifold;
using detail::PolygonRef;

struct EdgeSeparation {
    int edge = 0;
    float separation = -FLT_MAX;
};

// The edge of poly1 whose normal separates poly2 the most (the least penetration). Every edge
// is tested and the best one kept by selects, not branches: which edge wins (or first
// separates a separated pair) is random from pair to pair, and stopping early at that edge
// cost a mispredicted branch per call, more than the edges it skipped.
//
// min_j dot(n, w_j - v) is computed as min_j dot(n, w_j) - dot(n, v): subtracting one number
// preserves the order of rounded values, so the same vertex is deepest, and the inner loop
// does two products and a sum per vertex, two vertices at a time on independent minima.
inline EdgeSeparation findMaxSeparation(PolygonRef poly1, PolygonRef poly2) {
    EdgeSeparation best;
    const Vec2* w = poly2.vertices;
    const int count2 = poly2.count;
    for (int i = 0; i < poly1.count; ++i) {
        const Vec2 n = poly1.normals[i];
        float min0 = FLT_MAX;
        float min1 = FLT_MAX;
        int j = 0;
        for (; j + 1 < count2; j += 2) {
            const float d0 = dot(n, w[j]);
            const float d1 = dot(n, w[j + 1]);
            min0 = d0 < min0 ? d0 : min0;
            min1 = d1 < min1 ? d1 : min1;
        }
        if (j < count2) {
            const float d0 = dot(n, w[j]);
            min0 = d0 < min0 ? d0 : min0;
        }
        const float si = (min1 < min0 ? min1 : min0) - dot(n, poly1.vertices[i]);
        const bool better = si > best.separation;
        best.edge = better ? i : best.edge;
        best.separation = better ? si : best.separation;
    }
    return best;
}

// Marks "no contact" in a LocalManifold without touching its points.
inline LocalManifold noContact() {
    LocalManifold m;
    m.count = 0;
    return m;
}

// The SAT manifold of two polygons given in one frame; each point is in that frame.
// `localB` (B moved to that frame) has its vertices ready; its normals are moved lazily by
// `moveNormals` once A's faces found no separating axis, so separated pairs skip that work.
template <class MoveNormals>
LocalManifold collideInFrame(PolygonRef localA, PolygonRef localB, float margin,
                             MoveNormals&& moveNormals) {
    const float radius = localA.radius + localB.radius;
    const float limit = margin + radius;
    const EdgeSeparation sepA = findMaxSeparation(localA, localB);
    if (sepA.separation > limit) {
        return noContact();
    }
    moveNormals();
    const EdgeSeparation sepB = findMaxSeparation(localB, localA);
    if (sepB.separation > limit) {
        return noContact();
    }

    const bool flip = sepB.separation > sepA.separation + kFlipTolerance;
    const PolygonRef& poly1 = flip ? localB : localA;
    const PolygonRef& poly2 = flip ? localA : localB;
    const int edge1 = flip ? sepB.edge : sepA.edge;
    const float separation = flip ? sepB.separation : sepA.separation;

    // The incident edge: the one of poly2 whose normal is most anti-parallel to the reference.
    const Vec2 normal1 = poly1.normals[edge1];
    int incident = 0;
    float minDot = FLT_MAX;
    for (int j = 0; j < poly2.count; ++j) {
        const float d = dot(normal1, poly2.normals[j]);
        const bool better = d < minDot;
        incident = better ? j : incident;
        minDot = better ? d : minDot;
    }

    if (separation > kSeparatedCores) [[unlikely]] {
        // Face separation only bounds the distance from below; near a corner the real gap is
        // larger, which matters for rounded polygons and for speculative points. The closest
        // points of the two edges tell a face contact from a vertex contact.
        const int i11 = edge1;
        const int i12 = i11 + 1 < poly1.count ? i11 + 1 : 0;
        const int i21 = incident;
        const int i22 = i21 + 1 < poly2.count ? i21 + 1 : 0;
        const detail::SegmentDistance sd =
            detail::segmentDistance(poly1.vertices[i11], poly1.vertices[i12], poly2.vertices[i21],
                                    poly2.vertices[i22]);
        if (sd.distanceSquared > limit * limit) {
            return noContact();
        }
        // distance >= separation > 0, so w is well defined.
        const float distance = std::sqrt(sd.distanceSquared);
        const Vec2 w = (sd.closest2 - sd.closest1) / distance;
        if (std::fabs(cross(normal1, sd.closest2 - sd.closest1)) > kFaceOffset) {
            Vec2 c1 = sd.closest1 + poly1.radius * w;
            Vec2 c2 = sd.closest2 - poly2.radius * w;
            int feature1 = sd.fraction1 < 0.5f ? i11 : i12;
            int feature2 = sd.fraction2 < 0.5f ? i21 : i22;
            LocalManifold m;
            m.points[0] = 0.5f * (c1 + c2);
            m.separations[0] = distance - radius;
            m.ids[0] = flip ? makeFeatureId(feature2, feature1) : makeFeatureId(feature1, feature2);
            m.normal = flip ? -w : w;
            m.count = 1;
            return m;
        }
    }
    return detail::clipPolygons(localA, localB, flip ? incident : edge1, flip ? edge1 : incident,
                                flip, margin);
}

// Beyond this distance (metres) of A's first vertex from A's origin, the work moves to a
// frame at that vertex: coordinates relative to A's origin would lose precision (float ulp is
// 8e-6 m at 100 m). Below it, copying A to shift it costs more than it gains.
constexpr float kShiftSquared = 100.0f * 100.0f;

} // namespace

Manifold collidePolygons(const Polygon& a, const Transform& xfA, const Polygon& b,
                         const Transform& xfB, float margin) {
    // Work in A's frame: B is moved there once (its normals only when they are needed).
    const Vec2 origin = a.vertices[0];
    const bool shift = lengthSquared(origin) > kShiftSquared;
    Transform frame = xfA;
    if (shift) [[unlikely]] {
        frame.p = transformPoint(xfA, origin);
    }
    const Transform xf = invMulTransforms(frame, xfB);
    detail::PolygonScratch movedB;
    for (int i = 0; i < b.count; ++i) {
        movedB.vertices[i] = transformPoint(xf, b.vertices[i]);
    }
    auto moveNormals = [&] {
        for (int i = 0; i < b.count; ++i) {
            movedB.normals[i] = rotate(xf.q, b.normals[i]);
        }
    };
    const PolygonRef localB{movedB.vertices, movedB.normals, b.radius, b.count};
    PolygonRef localA = detail::refOf(a);
    detail::PolygonScratch movedA;
    if (shift) [[unlikely]] {
        for (int i = 0; i < a.count; ++i) {
            movedA.vertices[i] = a.vertices[i] - origin;
        }
        localA.vertices = movedA.vertices;
    }
    // One call site, so the compiler inlines collideInFrame: a call passing the two
    // PolygonRefs through the stack put a store and a reload on every pair's critical path.
    LocalManifold m = collideInFrame(localA, localB, margin, moveNormals);
    if (shift) [[unlikely]] {
        for (int i = 0; i < m.count; ++i) {
            m.points[i] += origin;
        }
    }
    return detail::localToWorld(m, xfA, xfB);
}

} // namespace e2d::physics
