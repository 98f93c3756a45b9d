// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/distance.hpp>

#include <cfloat>

// GJK and EPA on two point sets given in one common frame (the callers use A's local frame, so
// only B's points are transformed and the numbers stay small). Shared by shapeDistance(),
// penetration(), shapeCast(), timeOfImpact() and collidePolygonsGjkEpa().
namespace e2d::physics::detail {

struct PointSet {
    const Vec2* points = nullptr;
    int count = 0;
};

// Index of the point farthest along `direction` (the first one on ties, so that duplicated
// points give a stable answer). Written as selects, not a branch: which point wins is random
// from call to call, and a mispredicted branch per call cost more than the loop itself.
inline int supportIndex(PointSet set, Vec2 direction) {
    int best = 0;
    float bestValue = dot(set.points[0], direction);
    for (int i = 1; i < set.count; ++i) {
        const float value = dot(set.points[i], direction);
        const bool better = value > bestValue;
        best = better ? i : best;
        bestValue = better ? value : bestValue;
    }
    return best;
}

// A vertex of the Minkowski difference B - A.
struct SimplexVertex {
    Vec2 w{0.0f, 0.0f}; // b.points[indexB] - a.points[indexA]
    float a = 1.0f;     // barycentric weight of the closest point
    int indexA = 0;
    int indexB = 0;
};

struct Simplex {
    SimplexVertex v[3];
    int count = 0;
};

struct GjkResult {
    Simplex simplex;
    Vec2 pointA{0.0f, 0.0f}; // closest point on hull A (common frame)
    Vec2 pointB{0.0f, 0.0f}; // closest point on hull B
    float distance = 0.0f;   // between the hulls, no radii
    int iterations = 0;
    bool beyondLimit = false; // stopped early: the hulls are farther apart than the limit
};

// Core distances below this (metres) count as touching: no normal can be derived from them.
inline constexpr float kGjkTouching = 1.0e-6f;

// `limit` (metres): callers that only care about hulls closer than this let GJK stop as soon as
// a support plane proves the distance is larger (then only beyondLimit is meaningful and the
// cache is left as it was).
// Without a cache the search starts along `direction` (from A towards B, e.g. between the
// centroids; (0, 0) means "from the first points").
GjkResult runGjk(PointSet a, PointSet b, SimplexCache* cache, float limit = FLT_MAX,
                 Vec2 direction = Vec2{0.0f, 0.0f});

// The simplex's closest points on each hull (barycentric combination of its vertices).
inline void witnessPoints(PointSet a, PointSet b, const Simplex& s, Vec2& pointA, Vec2& pointB) {
    pointA = Vec2{0.0f, 0.0f};
    pointB = Vec2{0.0f, 0.0f};
    for (int i = 0; i < s.count; ++i) {
        pointA += s.v[i].a * a.points[s.v[i].indexA];
        pointB += s.v[i].a * b.points[s.v[i].indexB];
    }
}

struct EpaResult {
    Vec2 normal{1.0f, 0.0f}; // unit, from A to B
    Vec2 pointA{0.0f, 0.0f};
    Vec2 pointB{0.0f, 0.0f};
    float depth = 0.0f; // of the hulls, no radii; negative if in fact separated
    int iterations = 0;
    bool converged = true;
};

// Expands GJK's final simplex into the Minkowski difference until the edge closest to the
// origin is found. Any simplex (1, 2 or 3 vertices) of support points (as runGjk makes without a
// cache) is accepted.
EpaResult runEpa(PointSet a, PointSet b, const Simplex& simplex);

} // namespace e2d::physics::detail
