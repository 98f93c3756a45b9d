// SPDX-License-Identifier: MIT
#include "gjk.hpp"

#include <e2d/core/error.hpp>

#include <e2d/core/error_text.hpp>

#include <cmath>
#include <string>

namespace e2d::physics {

ShapeProxy makeProxy(std::span<const Vec2> points, float radius) {
    if (points.empty() || points.size() > static_cast<std::size_t>(kMaxPolygonVertices)) {
        throw core::Error("physics::makeProxy(): expected 1 to " +
                          std::to_string(kMaxPolygonVertices) + " points, got " +
                          std::to_string(points.size()));
    }
    if (!isFinite(radius) || radius < 0.0f || radius > kHuge) {
        throw core::Error(
            "physics::makeProxy(): radius must be finite, >= 0 and within kHuge, got " +
            core::formatNumber(radius));
    }
    ShapeProxy proxy;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!isFinite(points[i]) || std::fabs(points[i].x) > kHuge ||
            std::fabs(points[i].y) > kHuge) {
            throw core::Error("physics::makeProxy(): point " + std::to_string(i) +
                              " must be finite and within kHuge, got " +
                              core::formatVector(points[i]));
        }
        proxy.points[i] = points[i];
    }
    proxy.count = static_cast<int>(points.size());
    proxy.radius = radius;
    return proxy;
}

ShapeProxy makeProxy(const Polygon& polygon) {
    ShapeProxy proxy;
    proxy.points = polygon.vertices;
    proxy.count = polygon.count;
    proxy.radius = polygon.radius;
    return proxy;
}

ShapeProxy makeProxy(const Circle& circle) {
    ShapeProxy proxy;
    proxy.points[0] = circle.center;
    proxy.count = 1;
    proxy.radius = circle.radius;
    return proxy;
}

ShapeProxy makeProxy(const Capsule& capsule) {
    ShapeProxy proxy;
    proxy.points[0] = capsule.center1;
    proxy.points[1] = capsule.center2;
    proxy.count = 2;
    proxy.radius = capsule.radius;
    return proxy;
}

ShapeProxy makeProxy(const Segment& segment) {
    ShapeProxy proxy;
    proxy.points[0] = segment.point1;
    proxy.points[1] = segment.point2;
    proxy.count = 2;
    return proxy;
}

ShapeProxy makeProxy(const ChainSegment& segment) { return makeProxy(segment.segment); }

ShapeProxy makeProxy(const ShapeGeometry& shape) {
    return std::visit([](const auto& s) { return makeProxy(s); }, shape);
}

namespace detail {

namespace {

// Closest point of segment w1-w2 to the origin, as barycentric weights; drops the vertex whose
// Voronoi region holds the origin.
void solve2(Simplex& s) {
    Vec2 w1 = s.v[0].w;
    Vec2 w2 = s.v[1].w;
    Vec2 e12 = w2 - w1;
    float d12b = -dot(w1, e12);
    if (d12b <= 0.0f) {
        s.v[0].a = 1.0f;
        s.count = 1;
        return;
    }
    float d12a = dot(w2, e12);
    if (d12a <= 0.0f) {
        s.v[1].a = 1.0f;
        s.v[0] = s.v[1];
        s.count = 1;
        return;
    }
    float inv = 1.0f / (d12a + d12b);
    s.v[0].a = d12a * inv;
    s.v[1].a = d12b * inv;
    s.count = 2;
}

// Closest feature of triangle w1 w2 w3 to the origin by Voronoi regions (Ericson, Real-Time
// Collision Detection 5.1.5). A triangle with no area falls through every interior test and is
// reduced to one of its edges, so no division by zero can happen.
void solve3(Simplex& s) {
    Vec2 w1 = s.v[0].w;
    Vec2 w2 = s.v[1].w;
    Vec2 w3 = s.v[2].w;

    Vec2 e12 = w2 - w1;
    float d12a = dot(w2, e12);
    float d12b = -dot(w1, e12);
    Vec2 e13 = w3 - w1;
    float d13a = dot(w3, e13);
    float d13b = -dot(w1, e13);
    Vec2 e23 = w3 - w2;
    float d23a = dot(w3, e23);
    float d23b = -dot(w2, e23);

    float n123 = cross(e12, e13);
    float d123a = n123 * cross(w2, w3);
    float d123b = n123 * cross(w3, w1);
    float d123c = n123 * cross(w1, w2);

    if (d12b <= 0.0f && d13b <= 0.0f) {
        s.v[0].a = 1.0f;
        s.count = 1;
        return;
    }
    if (d12a > 0.0f && d12b > 0.0f && d123c <= 0.0f) {
        float inv = 1.0f / (d12a + d12b);
        s.v[0].a = d12a * inv;
        s.v[1].a = d12b * inv;
        s.count = 2;
        return;
    }
    if (d13a > 0.0f && d13b > 0.0f && d123b <= 0.0f) {
        float inv = 1.0f / (d13a + d13b);
        s.v[0].a = d13a * inv;
        s.v[2].a = d13b * inv;
        s.v[1] = s.v[2];
        s.count = 2;
        return;
    }
    if (d12a <= 0.0f && d23b <= 0.0f) {
        s.v[1].a = 1.0f;
        s.v[0] = s.v[1];
        s.count = 1;
        return;
    }
    if (d13a <= 0.0f && d23a <= 0.0f) {
        s.v[2].a = 1.0f;
        s.v[0] = s.v[2];
        s.count = 1;
        return;
    }
    if (d23a > 0.0f && d23b > 0.0f && d123a <= 0.0f) {
        float inv = 1.0f / (d23a + d23b);
        s.v[1].a = d23a * inv;
        s.v[2].a = d23b * inv;
        s.v[0] = s.v[2];
        s.count = 2;
        return;
    }
    float sum = d123a + d123b + d123c;
    if (!(sum > 0.0f)) {
        // Only reachable when rounding defeats every region test of a flat triangle.
        s.count = 2;
        solve2(s);
        return;
    }
    float inv = 1.0f / sum;
    s.v[0].a = d123a * inv;
    s.v[1].a = d123b * inv;
    s.v[2].a = d123c * inv;
    s.count = 3;
}

// Direction from the simplex towards the origin (not normalised).
Vec2 searchDirection(const Simplex& s) {
    if (s.count == 1) {
        return -s.v[0].w;
    }
    Vec2 e12 = s.v[1].w - s.v[0].w;
    float side = cross(e12, -s.v[0].w);
    return side > 0.0f ? leftPerp(e12) : rightPerp(e12);
}

SimplexVertex makeVertex(PointSet a, PointSet b, int indexA, int indexB) {
    SimplexVertex v;
    v.indexA = indexA;
    v.indexB = indexB;
    v.w = b.points[indexB] - a.points[indexA];
    v.a = 1.0f;
    return v;
}

Simplex readCache(PointSet a, PointSet b, const SimplexCache* cache, Vec2 direction) {
    Simplex s;
    if (cache != nullptr && cache->count > 0 && cache->count <= 3) {
        bool valid = true;
        for (int i = 0; i < cache->count; ++i) {
            if (cache->indexA[i] >= a.count || cache->indexB[i] >= b.count) {
                valid = false;
                break;
            }
            s.v[i] = makeVertex(a, b, cache->indexA[i], cache->indexB[i]);
        }
        s.count = valid ? cache->count : 0;
        // A cached simplex that has become flat since it was stored is a poor start: restart.
        if (s.count == 2 && lengthSquared(s.v[1].w - s.v[0].w) < kGjkTouching * kGjkTouching) {
            s.count = 1;
        } else if (s.count == 3) {
            float area = cross(s.v[1].w - s.v[0].w, s.v[2].w - s.v[0].w);
            if (area * area < kGjkTouching * kGjkTouching * kGjkTouching * kGjkTouching) {
                s.count = 1;
            }
        }
    }
    if (s.count == 0) {
        // Start from a true support pair (a vertex of the Minkowski difference), not from an
        // arbitrary pair: EPA later needs every simplex vertex on the boundary.
        Vec2 d = direction;
        if (lengthSquared(d) == 0.0f) {
            d = b.points[0] - a.points[0];
        }
        if (lengthSquared(d) == 0.0f) {
            d = Vec2{1.0f, 0.0f};
        }
        s.v[0] = makeVertex(a, b, supportIndex(a, -d), supportIndex(b, d));
        s.count = 1;
    }
    return s;
}

} // namespace

GjkResult runGjk(PointSet a, PointSet b, SimplexCache* cache, float limit, Vec2 direction) {
    GjkResult result;
    // Built in place: copying the simplex into the result at the end showed in profiles.
    Simplex& s = result.simplex;
    s = readCache(a, b, cache, direction);

    // The support pairs of the simplex before each reduction, as one key per pair (indices are
    // below 256) and -1 for an empty slot: three compares, no loop, tell a repeated pair.
    auto key = [](const SimplexVertex& v) { return (v.indexA << 8) | v.indexB; };
    int iteration = 0;
    while (iteration < kMaxGjkIterations) {
        const int saved0 = key(s.v[0]);
        const int saved1 = s.count > 1 ? key(s.v[1]) : -1;
        const int saved2 = s.count > 2 ? key(s.v[2]) : -1;

        if (s.count == 2) {
            solve2(s);
        } else if (s.count == 3) {
            solve3(s);
        }
        if (s.count == 3) {
            break; // the origin is inside: the hulls overlap
        }

        Vec2 d = searchDirection(s);
        if (lengthSquared(d) < kGjkTouching * kGjkTouching * 1.0e-6f) {
            break; // the origin is on the simplex: touching
        }

        SimplexVertex v = makeVertex(a, b, supportIndex(a, -d), supportIndex(b, d));
        ++iteration;

        // A repeated support pair means no progress is possible (this is what guarantees
        // termination on point sets).
        const int newKey = key(v);
        if ((newKey == saved0) | (newKey == saved1) | (newKey == saved2)) {
            break;
        }
        // Every point of the Minkowski difference is at most dot(v.w, d) along d, so when that
        // is negative the origin is at least -dot(v.w, d) / |d| away.
        float reach = dot(v.w, d);
        float dd = lengthSquared(d);
        if (reach < 0.0f && reach * reach > limit * limit * dd) {
            // Only beyondLimit is meaningful then: skip the closest points and the cache.
            result.beyondLimit = true;
            result.iterations = iteration;
            return result;
        }
        // Duplicated input points give new indices at old positions: stop when the new point
        // is no farther towards the origin than the simplex, up to rounding.
        float gain = reach - dot(s.v[0].w, d);
        // A select, not std::fmax: without -ffinite-math that is a libm call.
        const float newSq = lengthSquared(v.w);
        const float oldSq = lengthSquared(s.v[0].w);
        float scale2 = newSq > oldSq ? newSq : oldSq;
        if (gain <= 0.0f ||
            gain * gain <= kGjkRelativeTolerance * kGjkRelativeTolerance * scale2 * dd) {
            break;
        }
        s.v[s.count] = v;
        ++s.count;
    }

    Vec2 pointA;
    Vec2 pointB;
    witnessPoints(a, b, s, pointA, pointB);
    if (s.count == 3) {
        pointB = pointA;
    }
    result.pointA = pointA;
    result.pointB = pointB;
    result.distance = s.count == 3 ? 0.0f : distance(pointA, pointB);
    result.iterations = iteration;

    if (cache != nullptr) {
        cache->count = static_cast<std::uint8_t>(s.count);
        for (int i = 0; i < s.count; ++i) {
            cache->indexA[i] = static_cast<std::uint8_t>(s.v[i].indexA);
            cache->indexB[i] = static_cast<std::uint8_t>(s.v[i].indexB);
        }
    }
    return result;
}

} // namespace detail

DistanceOutput shapeDistance(const DistanceInput& input, SimplexCache* cache) {
    // Work in A's frame: only B's points move, and A's stay exact.
    Transform relative = invMulTransforms(input.transformA, input.transformB);
    std::array<Vec2, kMaxPolygonVertices> pointsB;
    for (int i = 0; i < input.proxyB.count; ++i) {
        pointsB[i] = transformPoint(relative, input.proxyB.points[i]);
    }
    detail::GjkResult gjk = detail::runGjk({input.proxyA.points.data(), input.proxyA.count},
                                           {pointsB.data(), input.proxyB.count}, cache);

    Vec2 pointA = gjk.pointA;
    Vec2 pointB = gjk.pointB;
    float dist = gjk.distance;
    Vec2 normal{0.0f, 0.0f};
    if (gjk.simplex.count < 3 && dist > detail::kGjkTouching) {
        normal = (pointB - pointA) * (1.0f / dist);
    }
    if (input.useRadii) {
        float rA = input.proxyA.radius;
        float rB = input.proxyB.radius;
        if (dist > rA + rB) {
            dist -= rA + rB;
            pointA += rA * normal;
            pointB -= rB * normal;
        } else {
            Vec2 p = 0.5f * ((pointA + rA * normal) + (pointB - rB * normal));
            pointA = p;
            pointB = p;
            dist = 0.0f;
        }
    }

    DistanceOutput output;
    output.pointA = transformPoint(input.transformA, pointA);
    output.pointB = transformPoint(input.transformA, pointB);
    output.normal = rotate(input.transformA.q, normal);
    output.distance = dist;
    output.iterations = gjk.iterations;
    output.simplexCount = gjk.simplex.count;
    return output;
}

} // namespace e2d::physics
