// SPDX-License-Identifier: MIT
#include <e2d/physics/manifold.hpp>

#include "gjk.hpp"
#include "polygon_clip.hpp"

#include <cfloat>

namespace e2d::physics {

namespace {

// Below this core distance (metres) GJK's normal is built from two nearly equal points and is
// too inaccurate to pick a face; EPA from the touching simplex gives the face normal instead.
constexpr float kUseEpaBelow = 10.0f * kEpaTolerance;

// Separation of `other` from edge `edge` of `poly`, both in one frame: how far the deepest
// vertex of `other` lies in front of the edge (negative when it is behind it).
float edgeSeparation(const Polygon& poly, int edge, const Polygon& other) {
    Vec2 n = poly.normals[edge];
    Vec2 v = poly.vertices[edge];
    float result = FLT_MAX;
    for (int j = 0; j < other.count; ++j) {
        result = std::fmin(result, dot(n, other.vertices[j] - v));
    }
    return result;
}

struct FaceChoice {
    int edge = 0;
    float separation = -FLT_MAX;
};

// The axis of least penetration of a pair of convex polygons is a face normal of one of them,
// and the direction GJK or EPA found lies between the normals of the two faces that bracket it
// (the faces at the support vertex in that direction). Testing those two on each polygon
// gives the same face as a full separating-axis search over all the faces: EPA's direction is
// that face's normal, and when separated the best face is adjacent to a closest feature.
FaceChoice bestBracketingFace(const Polygon& poly, const Polygon& other, Vec2 direction) {
    int best = 0;
    float bestDot = dot(poly.normals[0], direction);
    for (int i = 1; i < poly.count; ++i) {
        float d = dot(poly.normals[i], direction);
        if (d > bestDot) {
            best = i;
            bestDot = d;
        }
    }
    int prev = best == 0 ? poly.count - 1 : best - 1;
    int next = best + 1 == poly.count ? 0 : best + 1;
    int second = dot(poly.normals[prev], direction) > dot(poly.normals[next], direction) ? prev
                                                                                          : next;
    FaceChoice first{best, edgeSeparation(poly, best, other)};
    FaceChoice other2{second, edgeSeparation(poly, second, other)};
    // On an exact tie keep the lower index, as a search over the faces in order would.
    if (other2.separation > first.separation ||
        (other2.separation == first.separation && other2.edge < first.edge)) {
        return other2;
    }
    return first;
}

int incidentEdge(const Polygon& poly, Vec2 referenceNormal) {
    int best = 0;
    float bestDot = dot(poly.normals[0], referenceNormal);
    for (int i = 1; i < poly.count; ++i) {
        float d = dot(poly.normals[i], referenceNormal);
        if (d < bestDot) {
            best = i;
            bestDot = d;
        }
    }
    return best;
}

} // namespace

Manifold collidePolygonsGjkEpa(const Polygon& a, const Transform& xfA, const Polygon& b,
                               const Transform& xfB, float margin) {
    // Everything happens in A's frame: B's vertices and normals are moved once.
    Transform relative = invMulTransforms(xfA, xfB);
    Polygon localB;
    localB.count = b.count;
    localB.radius = b.radius;
    for (int i = 0; i < b.count; ++i) {
        localB.vertices[i] = transformPoint(relative, b.vertices[i]);
        localB.normals[i] = rotate(relative.q, b.normals[i]);
    }

    detail::PointSet setA{a.vertices.data(), a.count};
    detail::PointSet setB{localB.vertices.data(), localB.count};
    detail::GjkResult gjk = detail::runGjk(setA, setB, nullptr);
    float radius = a.radius + b.radius;

    Vec2 direction;
    if (gjk.simplex.count < 3 && gjk.distance > kUseEpaBelow) {
        if (gjk.distance > margin + radius) {
            return Manifold{};
        }
        direction = (gjk.pointB - gjk.pointA) * (1.0f / gjk.distance);
    } else {
        direction = detail::runEpa(setA, setB, gjk.simplex).normal;
    }

    FaceChoice faceA = bestBracketingFace(a, localB, direction);
    FaceChoice faceB = bestBracketingFace(localB, a, -direction);

    // The same preference for A's face as the separating-axis routine, so that both algorithms
    // pick the same reference face when two faces are nearly equally good.
    constexpr float kFlipTolerance = 0.1f * kLinearSlop;
    bool flip = faceB.separation > faceA.separation + kFlipTolerance;
    int edgeA;
    int edgeB;
    if (flip) {
        edgeB = faceB.edge;
        edgeA = incidentEdge(a, localB.normals[edgeB]);
    } else {
        edgeA = faceA.edge;
        edgeB = incidentEdge(localB, a.normals[edgeA]);
    }

    Manifold manifold = detail::clipPolygons(a, localB, edgeA, edgeB, flip, margin);
    manifold.normal = rotate(xfA.q, manifold.normal);
    for (int i = 0; i < manifold.pointCount; ++i) {
        ManifoldPoint& mp = manifold.points[i];
        Vec2 offset = rotate(xfA.q, mp.point);
        mp.anchorA = offset;
        mp.anchorB = offset + (xfA.p - xfB.p);
        mp.point = offset + xfA.p;
    }
    return manifold;
}

} // namespace e2d::physics
