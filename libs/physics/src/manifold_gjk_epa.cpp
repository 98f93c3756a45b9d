// SPDX-License-Identifier: MIT
#include <e2d/physics/manifold.hpp>

#include "gjk.hpp"
#include "manifold_detail.hpp"
#include "polygon_clip.hpp"

#include <cfloat>
#include <cmath>

namespace e2d::physics {

namespace {

using detail::PolygonRef;

// Below this core distance (metres) GJK's normal is built from two nearly equal points and is
// too inaccurate to pick a face; the polygon EPA (polygonEpa) gives the face instead.
constexpr float kUseEpaBelow = 10.0f * kEpaTolerance;

// Separation of `other` from edge `edge` of `poly`, both in one frame: how far the deepest
// vertex of `other` lies in front of the edge (negative when it is behind it).
float edgeSeparation(PolygonRef poly, int edge, PolygonRef other) {
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
// normal of one of them. For separated cores, GJK's closest-point direction lies between the
// normals of the two faces at the closest vertex. So only the two faces whose normals bracket
// `direction` (the faces at the support vertex in that direction) are tested on each polygon,
// instead of all of them as the separating-axis search does.
FaceChoice bestBracketingFace(PolygonRef poly, PolygonRef other, Vec2 direction) {
    int best = 0;
    float bestDot = dot(poly.normals[0], direction);
    for (int i = 1; i < poly.count; ++i) {
        const float d = dot(poly.normals[i], direction);
        const bool better = d > bestDot;
        best = better ? i : best;
        bestDot = better ? d : bestDot;
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

struct FacePair {
    FaceChoice a; // A's face of greatest separation
    FaceChoice b; // B's face of greatest separation
};

// EPA specialised to two convex polygons in one frame. General EPA grows a polytope inside the
// Minkowski difference B - A one support point at a time until its edge nearest the origin is
// on the boundary. For polygons that boundary is known in advance: its edges are the edges of
// B (normal nB[j]) and the edges of A reversed (normal -nA[i]), in order of normal angle, so
// it is walked whole, n + m edges, merging the two edge sequences as in a Minkowski sum. Each
// edge's distance from the origin is minus the face separation of the other polygon's deepest
// vertex, which the walk carries along (the vertex of the boundary it stands on). No support
// search, no square root, exact up to rounding (the iterative version stops at kEpaTolerance).
// Returns the best face of each polygon; ties go to the lower index, as in the SAT search.
FacePair polygonEpa(PolygonRef a, PolygonRef b) {
    const int n = a.count;
    const int m = b.count;
    // The boundary vertex for directions just before nB[0]: B's vertex 0 and A's vertex
    // deepest along nB[0] (its support in -nB[0]).
    int ia = detail::firstMinDot(a.vertices, n, b.normals[0]);
    int jb = 0;
    int doneA = 0;
    int doneB = 0;
    FacePair best{{0, -FLT_MAX}, {0, -FLT_MAX}};
    for (int step = 0; step < n + m; ++step) {
        const Vec2 nA = a.normals[ia];
        const Vec2 nB = b.normals[jb];
        const Vec2 vA = a.vertices[ia];
        const Vec2 vB = b.vertices[jb];
        // Both candidate normals lie less than pi counter-clockwise of the current direction,
        // so the sign of their cross product orders them. On a tie (parallel faces) either
        // order gives the same distances.
        const bool takeB = doneA == n || (doneB < m && cross(nB, -nA) >= 0.0f);
        if (takeB) {
            const float sep = dot(nB, vA - vB);
            if (sep > best.b.separation) {
                best.b = {jb, sep};
            }
            ++doneB;
            jb = jb + 1 == m ? 0 : jb + 1;
        } else {
            const float sep = dot(nA, vB - vA);
            if (sep > best.a.separation || (sep == best.a.separation && ia < best.a.edge)) {
                best.a = {ia, sep};
            }
            ++doneA;
            ia = ia + 1 == n ? 0 : ia + 1;
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
    // Everything happens in A's frame: B's vertices are moved once, its normals once GJK has
    // not ruled the pair out.
    Transform relative = invMulTransforms(xfA, xfB);
    detail::PolygonScratch movedB;
    for (int i = 0; i < b.count; ++i) {
        movedB.vertices[i] = transformPoint(relative, b.vertices[i]);
    }
    const PolygonRef localB{movedB.vertices, movedB.normals, b.radius, b.count};
    const PolygonRef refA = detail::refOf(a);

    detail::PointSet setA{a.vertices.data(), a.count};
    detail::PointSet setB{localB.vertices, localB.count};
    const float radius = a.radius + b.radius;
    const float limit = margin + radius;
    detail::GjkResult gjk = detail::runGjk(setA, setB, nullptr, limit);
    if (gjk.beyondLimit) {
        return Manifold{};
    }
    for (int i = 0; i < b.count; ++i) {
        movedB.normals[i] = rotate(relative.q, b.normals[i]);
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
        faceA = bestBracketingFace(refA, localB, direction);
        faceB = bestBracketingFace(localB, refA, -direction);
    } else {
        const FacePair faces = polygonEpa(refA, localB);
        faceA = faces.a;
        faceB = faces.b;
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
        edgeA = detail::firstMinDot(refA.normals, refA.count, localB.normals[edgeB]);
        referenceNormal = -localB.normals[edgeB];
    } else {
        edgeA = faceA.edge;
        edgeB = detail::firstMinDot(localB.normals, localB.count, a.normals[edgeA]);
        referenceNormal = a.normals[edgeA];
    }

    if (separated && separation > detail::kSeparatedCores &&
        std::fabs(cross(referenceNormal, gjk.pointB - gjk.pointA)) > detail::kFaceOffset) {
        // Separated at a corner: the face separation underestimates the gap, so the closest
        // points give a single point with the true distance and direction.
        Vec2 surfaceA = gjk.pointA + a.radius * direction;
        Vec2 surfaceB = gjk.pointB - b.radius * direction;
        return detail::singlePointToWorld(
            direction, 0.5f * (surfaceA + surfaceB), gjk.distance - radius,
            makeFeatureId(closestVertex(gjk.simplex, true), closestVertex(gjk.simplex, false)), xfA,
            xfB);
    }

    if (detail::mayCrossAtCorners(refA, localB, faceA.edge, faceA.separation, faceB.edge,
                                  faceB.separation)) {
        // Two corners crossing: the same symmetric contact as the separating-axis routine's.
        const detail::LocalManifold crossing =
            detail::crossingCorners(refA, localB, faceA.edge, faceB.edge, margin);
        if (crossing.count > 0) {
            return detail::localToWorld(crossing, xfA, xfB);
        }
    }
    return detail::localToWorld(detail::clipPolygons(refA, localB, edgeA, edgeB, flip, margin), xfA,
                                xfB);
}

} // namespace e2d::physics
