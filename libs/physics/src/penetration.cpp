// SPDX-License-Identifier: MIT
#include "gjk.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <utility>

namespace e2d::physics {

namespace detail {

namespace {

// The Minkowski difference of two sets of kMaxPolygonVertices points has at most twice that
// many vertices; the slack covers the initial triangle and rounding.
constexpr int kMaxPolytope = 2 * kMaxPolygonVertices + 4;

struct Polytope {
    Vec2 w[kMaxPolytope];
    int indexA[kMaxPolytope];
    int indexB[kMaxPolytope];
    Vec2 normal[kMaxPolytope];    // outward normal of edge i -> i + 1
    float distance[kMaxPolytope]; // signed distance of that edge's line from the origin
    int count = 0;

    void updateEdge(int i) {
        int j = i + 1 == count ? 0 : i + 1;
        Vec2 e = w[j] - w[i];
        float len = length(e);
        if (len < 1.0e-12f) {
            // A zero-length edge has no direction; its neighbours stand for it.
            normal[i] = Vec2{0.0f, 0.0f};
            distance[i] = FLT_MAX;
            return;
        }
        normal[i] = rightPerp(e) * (1.0f / len);
        distance[i] = dot(normal[i], w[i]);
    }

    void add(Vec2 point, int a, int b) {
        w[count] = point;
        indexA[count] = a;
        indexB[count] = b;
        ++count;
    }

    // Puts a new vertex between i and i + 1.
    void insertAfter(int i, Vec2 point, int a, int b) {
        for (int k = count; k > i + 1; --k) {
            w[k] = w[k - 1];
            indexA[k] = indexA[k - 1];
            indexB[k] = indexB[k - 1];
            normal[k] = normal[k - 1];
            distance[k] = distance[k - 1];
        }
        w[i + 1] = point;
        indexA[i + 1] = a;
        indexB[i + 1] = b;
        ++count;
        updateEdge(i);
        updateEdge(i + 1);
    }
};

struct Support {
    Vec2 w;
    int a;
    int b;
};

Support supportOf(PointSet a, PointSet b, Vec2 direction) {
    int ia = supportIndex(a, -direction);
    int ib = supportIndex(b, direction);
    return {b.points[ib] - a.points[ia], ia, ib};
}

// The answer for a Minkowski difference with no area: any move along `axis` (unit) separates.
EpaResult flatAnswer(PointSet a, PointSet b, const Simplex& simplex, Vec2 axis) {
    EpaResult result;
    Vec2 pointA;
    Vec2 pointB;
    witnessPoints(a, b, simplex, pointA, pointB);
    result.normal = axis;
    result.pointA = pointA;
    result.pointB = pointB;
    result.depth = 0.0f;
    result.converged = false;
    return result;
}

} // namespace

EpaResult runEpa(PointSet a, PointSet b, const Simplex& simplex) {
    Polytope poly;
    if (simplex.count < 1 || simplex.count > 3) {
        EpaResult invalid; // not a GJK simplex
        invalid.converged = false;
        return invalid;
    }
    for (int i = 0; i < simplex.count; ++i) {
        poly.add(simplex.v[i].w, simplex.v[i].indexA, simplex.v[i].indexB);
    }

    // Grow a GJK simplex of one or two vertices (touching shapes) into a triangle.
    if (poly.count == 1) {
        const Vec2 axes[4] = {{1.0f, 0.0f}, {-1.0f, 0.0f}, {0.0f, 1.0f}, {0.0f, -1.0f}};
        for (Vec2 axis : axes) {
            Support s = supportOf(a, b, axis);
            if (distanceSquared(s.w, poly.w[0]) > 1.0e-12f) {
                poly.add(s.w, s.a, s.b);
                break;
            }
        }
        if (poly.count == 1) {
            return flatAnswer(a, b, simplex, Vec2{1.0f, 0.0f});
        }
    }
    if (poly.count == 2) {
        Vec2 e = poly.w[1] - poly.w[0];
        Vec2 side = normalize(leftPerp(e));
        float bestArea = 0.0f;
        Support best{};
        for (float sign : {1.0f, -1.0f}) {
            Support s = supportOf(a, b, sign * side);
            float area = std::fabs(cross(e, s.w - poly.w[0]));
            if (area > bestArea) {
                bestArea = area;
                best = s;
            }
        }
        if (!(bestArea > 1.0e-9f * length(e))) {
            return flatAnswer(a, b, simplex, side);
        }
        poly.add(best.w, best.a, best.b);
    }
    if (cross(poly.w[1] - poly.w[0], poly.w[2] - poly.w[0]) < 0.0f) {
        std::swap(poly.w[1], poly.w[2]);
        std::swap(poly.indexA[1], poly.indexA[2]);
        std::swap(poly.indexB[1], poly.indexB[2]);
    }
    for (int i = 0; i < poly.count; ++i) {
        poly.updateEdge(i);
    }

    EpaResult result;
    int closest = 0;
    int iteration = 0;
    result.converged = false;
    while (true) {
        closest = 0;
        float closestDistance = poly.distance[0];
        for (int i = 1; i < poly.count; ++i) {
            const bool closer = poly.distance[i] < closestDistance;
            closest = closer ? i : closest;
            closestDistance = closer ? poly.distance[i] : closestDistance;
        }
        if (iteration == kMaxEpaIterations || poly.count == kMaxPolytope) {
            break;
        }
        Vec2 n = poly.normal[closest];
        Support s = supportOf(a, b, n);
        ++iteration;
        if (dot(s.w, n) - poly.distance[closest] <= kEpaTolerance) {
            result.converged = true;
            break;
        }
        bool known = false;
        for (int i = 0; i < poly.count; ++i) {
            if (poly.indexA[i] == s.a && poly.indexB[i] == s.b) {
                known = true;
                break;
            }
        }
        if (known) {
            result.converged = true;
            break;
        }
        poly.insertAfter(closest, s.w, s.a, s.b);
    }

    int i = closest;
    int j = i + 1 == poly.count ? 0 : i + 1;
    Vec2 n = poly.normal[i];
    Vec2 e = poly.w[j] - poly.w[i];
    float t = 0.0f;
    float ee = lengthSquared(e);
    if (ee > 0.0f) {
        t = std::clamp(dot(poly.distance[i] * n - poly.w[i], e) / ee, 0.0f, 1.0f);
    }
    Vec2 aI = a.points[poly.indexA[i]];
    Vec2 aJ = a.points[poly.indexA[j]];
    Vec2 bI = b.points[poly.indexB[i]];
    Vec2 bJ = b.points[poly.indexB[j]];
    // The Minkowski difference is B - A, so its face normal points from B to A.
    result.normal = -n;
    result.pointA = aI + t * (aJ - aI);
    result.pointB = bI + t * (bJ - bI);
    result.depth = poly.distance[i];
    result.iterations = iteration;
    return result;
}

} // namespace detail

PenetrationOutput penetration(const DistanceInput& input) {
    Transform relative = invMulTransforms(input.transformA, input.transformB);
    std::array<Vec2, kMaxPolygonVertices> pointsB;
    for (int i = 0; i < input.proxyB.count; ++i) {
        pointsB[i] = transformPoint(relative, input.proxyB.points[i]);
    }
    detail::PointSet setA{input.proxyA.points.data(), input.proxyA.count};
    detail::PointSet setB{pointsB.data(), input.proxyB.count};
    detail::GjkResult gjk = detail::runGjk(setA, setB, nullptr);

    float radius = input.useRadii ? input.proxyA.radius + input.proxyB.radius : 0.0f;
    float rA = input.useRadii ? input.proxyA.radius : 0.0f;
    float rB = input.useRadii ? input.proxyB.radius : 0.0f;

    PenetrationOutput output;
    Vec2 normal;
    Vec2 pointA;
    Vec2 pointB;
    // Near contact GJK's normal comes from two almost equal points and is inaccurate; EPA
    // starting from the touching simplex gives the face normal instead.
    if (gjk.simplex.count < 3 && gjk.distance > 10.0f * kEpaTolerance) {
        normal = (gjk.pointB - gjk.pointA) * (1.0f / gjk.distance);
        pointA = gjk.pointA;
        pointB = gjk.pointB;
        output.depth = radius - gjk.distance;
        output.iterations = gjk.iterations;
    } else {
        detail::EpaResult epa = detail::runEpa(setA, setB, gjk.simplex);
        normal = epa.normal;
        pointA = epa.pointA;
        pointB = epa.pointB;
        output.depth = epa.depth + radius;
        output.iterations = gjk.iterations + epa.iterations;
        output.converged = epa.converged;
    }
    pointA += rA * normal;
    pointB -= rB * normal;
    output.normal = rotate(input.transformA.q, normal);
    output.pointA = transformPoint(input.transformA, pointA);
    output.pointB = transformPoint(input.transformA, pointB);
    return output;
}

} // namespace e2d::physics
