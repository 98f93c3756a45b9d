// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/distance.hpp>

// GJK and EPA on two point sets given in one common frame (the callers use A's local frame, so
// only B's points are transformed and the numbers stay small). Shared by shapeDistance(),
// penetration(), shapeCast(), timeOfImpact() and collidePolygonsGjkEpa().
namespace e2d::physics::detail {

struct PointSet {
    const Vec2* points = nullptr;
    int count = 0;
};

// Index of the point farthest along `direction` (the first one on ties, so that duplicated
// points give a stable answer).
inline int supportIndex(PointSet set, Vec2 direction) {
    int best = 0;
    float bestValue = dot(set.points[0], direction);
    for (int i = 1; i < set.count; ++i) {
        float value = dot(set.points[i], direction);
        if (value > bestValue) {
            best = i;
            bestValue = value;
        }
    }
    return best;
}

// A vertex of the Minkowski difference B - A.
struct SimplexVertex {
    Vec2 wA{0.0f, 0.0f}; // support point of A
    Vec2 wB{0.0f, 0.0f}; // support point of B
    Vec2 w{0.0f, 0.0f};  // wB - wA
    float a = 1.0f;      // barycentric weight of the closest point
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
};

// Core distances below this (metres) count as touching: no normal can be derived from them.
inline constexpr float kGjkTouching = 1.0e-6f;

GjkResult runGjk(PointSet a, PointSet b, SimplexCache* cache);

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
