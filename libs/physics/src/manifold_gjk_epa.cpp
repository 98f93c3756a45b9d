// SPDX-License-Identifier: MIT
#include <e2d/physics/manifold.hpp>

#include "gjk.hpp"
#include "manifold_detail.hpp"
#include "polygon_clip.hpp"

#include <cfloat>
#include <cmath>

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
        float s = dot(n, other.vertices[j] - v);
        result = s < result ? s : result;
    }
    return result;
}

struct FaceChoice {
    int edge = 0;
    float separation = -FLT_MAX;
};

// The axis of least penetration (or greatest separation) of two convex polygons is a face
// normal of one of them. EPA's direction is that normal; GJK's closest-point direction lies
// between the normals of the two faces at the closest vertex. So only the two faces whose
// normals bracket `direction` (the faces at the support vertex in that direction) are tested
// on each polygon, instead of all of them as the separating-axis search does.
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
    int second =
        dot(poly.normals[prev], direction) > dot(poly.normals[next], direction) ? prev : next;
    FaceChoice first{best, edgeSeparation(poly, best, other)};
    FaceChoice neighbour{second, edgeSeparation(poly, second, other)};
    // On an exact tie keep the lower index, as a search over the faces in order would.
    if (neighbour.separation > first.separation ||
        (neighbour.separation == first.separation && neighbour.edge < first.edge)) {
        return neighbour;
    }
    return first;
}

int incidentEdge(const Polygon& poly, Vec2 referenceNormal) {
    int best = 0;
    float bestDot = FLT_MAX;
    for (int i = 0; i < poly.count; ++i) {
        float d = dot(poly.normals[i], referenceNormal);
        if (d < bestDot) {
            best = i;
            bestDot = d;
        }
    }
    return best;
}

// The vertex of one polygon where a separated closest point lies: the simplex point of that
// polygon with the largest barycentric weight.
int closestVertex(const detail::Simplex& s, bool ofA) {
    int best = 0;
    for (int i = 1; i < s.count; ++i) {
        if (s.v[i].a > s.v[best].a) {
            best = i;
        }
    }
    return ofA ? s.v[best].indexA : s.v[best].indexB;
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
    const float radius = a.radius + b.radius;
    const float limit = margin + radius;
    detail::GjkResult gjk = detail::runGjk(setA, setB, nullptr, limit);
    if (gjk.beyondLimit) {
        return Manifold{};
    }

    const bool separated = gjk.simplex.count < 3 && gjk.distance > kUseEpaBelow;
    FaceChoice faceA;
    FaceChoice faceB;
    Vec2 direction;
    if (separated) {
        if (gjk.distance > limit) {
            return Manifold{};
        }
        direction = (gjk.pointB - gjk.pointA) * (1.0f / gjk.distance);
        faceA = bestBracketingFace(a, localB, direction);
        faceB = bestBracketingFace(localB, a, -direction);
    } else {
        detail::EpaResult epa = detail::runEpa(setA, setB, gjk.simplex);
        direction = epa.normal;
        if (epa.converged && epa.faceA >= 0) {
            // A's face is the axis of least penetration: nothing of B's can beat it by the
            // flip tolerance, so B's faces need no test.
            faceA = {epa.faceA, -epa.depth};
            faceB = {0, -FLT_MAX};
        } else if (epa.converged && epa.faceB >= 0) {
            faceB = {epa.faceB, -epa.depth};
            faceA = bestBracketingFace(a, localB, direction);
        } else {
            faceA = bestBracketingFace(a, localB, direction);
            faceB = bestBracketingFace(localB, a, -direction);
        }
    }

    // Reference face, corner contacts: decided as in the separating-axis routine (the shared
    // tolerances of manifold_detail.hpp), so that both algorithms agree.
    const bool flip = faceB.separation > faceA.separation + detail::kFlipTolerance;
    const float separation = flip ? faceB.separation : faceA.separation;
    if (separation > limit) {
        return Manifold{};
    }
    int edgeA;
    int edgeB;
    Vec2 referenceNormal; // from A to B
    if (flip) {
        edgeB = faceB.edge;
        edgeA = incidentEdge(a, localB.normals[edgeB]);
        referenceNormal = -localB.normals[edgeB];
    } else {
        edgeA = faceA.edge;
        edgeB = incidentEdge(localB, a.normals[edgeA]);
        referenceNormal = a.normals[edgeA];
    }

    if (separated && separation > detail::kSeparatedCores &&
        std::fabs(cross(referenceNormal, gjk.pointB - gjk.pointA)) > detail::kFaceOffset) {
        // Separated at a corner: the face separation underestimates the gap, so the closest
        // points give a single point with the true distance and direction.
        Manifold m;
        ManifoldPoint& mp = m.points[0];
        Vec2 surfaceA = gjk.pointA + a.radius * direction;
        Vec2 surfaceB = gjk.pointB - b.radius * direction;
        mp.point = 0.5f * (surfaceA + surfaceB);
        mp.separation = gjk.distance - radius;
        mp.id = makeFeatureId(closestVertex(gjk.simplex, true), closestVertex(gjk.simplex, false));
        m.normal = direction;
        m.pointCount = 1;
        return detail::localToWorld(m, xfA, xfB);
    }

    Manifold m = detail::clipPolygons(a, localB, edgeA, edgeB, flip, margin);
    return detail::localToWorld(m, xfA, xfB);
}

} // namespace e2d::physics
