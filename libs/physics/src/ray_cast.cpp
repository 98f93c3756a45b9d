// SPDX-License-Identifier: MIT
#include <e2d/physics/geometry.hpp>

namespace e2d::physics {
namespace {

CastOutput makeHit(const RayCastInput& input, float fraction, Vec2 normal) {
    CastOutput out;
    out.fraction = fraction;
    out.point = input.origin + fraction * input.translation;
    out.normal = normal;
    out.hit = true;
    return out;
}

// Entering hit of the ray with a disc, or no hit when the ray starts inside it. Works on the
// closest approach of the line to the centre rather than on the raw quadratic, which loses
// precision when the origin is far from a small disc.
CastOutput rayCastDisc(const RayCastInput& input, Vec2 center, float radius) {
    float len = length(input.translation);
    if (len == 0.0f) {
        return {};
    }
    Vec2 u = input.translation / len;
    Vec2 s = input.origin - center;
    float along = -dot(s, u); // distance along the ray to the closest approach
    Vec2 closest = s + along * u;
    float cc = dot(closest, closest);
    float rr = radius * radius;
    if (cc > rr) {
        return {};
    }
    float t = along - std::sqrt(rr - cc);
    if (t < 0.0f || t > input.maxFraction * len) {
        return {};
    }
    float fraction = t / len;
    return makeHit(input, fraction, normalize(s + t * u));
}

// First entering hit with a polygon (count >= 2) rounded by radius > 0: the boundary is the
// edges pushed out by radius plus an arc at each vertex. The caller has checked that the
// origin is outside, so the first hit on any of those pieces is the first hit on the shape.
CastOutput rayCastRounded(const RayCastInput& input, const Vec2* vertices, const Vec2* normals,
                          int count, float radius) {
    CastOutput best;
    float bestFraction = input.maxFraction;
    Vec2 d = input.translation;
    for (int i = 0; i < count; ++i) {
        Vec2 n = normals[i];
        float approach = dot(n, d);
        if (approach >= 0.0f) {
            continue; // face looks away from the ray: only its back can be hit
        }
        Vec2 a = vertices[i] + radius * n;
        Vec2 b = vertices[i + 1 < count ? i + 1 : 0] + radius * n;
        float t = dot(n, a - input.origin) / approach;
        if (t < 0.0f || t > bestFraction) {
            continue;
        }
        Vec2 e = b - a;
        float u = dot(input.origin + t * d - a, e);
        if (u < 0.0f || u > dot(e, e)) {
            continue;
        }
        best = makeHit(input, t, n);
        bestFraction = t;
    }
    for (int i = 0; i < count; ++i) {
        RayCastInput sub = input;
        sub.maxFraction = bestFraction;
        CastOutput out = rayCastDisc(sub, vertices[i], radius);
        if (out.hit && out.fraction < bestFraction) {
            best = out;
            bestFraction = out.fraction;
        }
    }
    return best;
}

} // namespace

CastOutput rayCast(const RayCastInput& input, const Circle& shape) {
    return rayCastDisc(input, shape.center, shape.radius);
}

CastOutput rayCast(const RayCastInput& input, const Capsule& shape) {
    if (testPoint(shape, input.origin)) {
        return {};
    }
    Vec2 vertices[2] = {shape.center1, shape.center2};
    Vec2 n = normalize(rightPerp(shape.center2 - shape.center1));
    Vec2 normals[2] = {n, -n};
    return rayCastRounded(input, vertices, normals, 2, shape.radius);
}

CastOutput rayCast(const RayCastInput& input, const Segment& shape) {
    // origin + t d = p1 + u e, solved with 2D cross products; hits either side.
    Vec2 d = input.translation;
    Vec2 e = shape.point2 - shape.point1;
    float denom = cross(d, e);
    if (denom == 0.0f) {
        return {}; // parallel, including a zero translation
    }
    Vec2 w = shape.point1 - input.origin;
    float t = cross(w, e) / denom;
    float u = cross(w, d) / denom;
    if (t < 0.0f || t > input.maxFraction || u < 0.0f || u > 1.0f) {
        return {};
    }
    Vec2 n = normalize(leftPerp(e));
    return makeHit(input, t, dot(n, d) > 0.0f ? -n : n);
}

CastOutput rayCast(const RayCastInput& input, const ChainSegment& shape) {
    // One-sided: a ray along the front normal (or parallel to the segment) comes from behind.
    const Segment& s = shape.segment;
    if (dot(input.translation, rightPerp(s.point2 - s.point1)) >= 0.0f) {
        return {};
    }
    return rayCast(input, s);
}

CastOutput rayCast(const RayCastInput& input, const Polygon& shape) {
    if (shape.radius > 0.0f) {
        if (testPoint(shape, input.origin)) {
            return {};
        }
        return rayCastRounded(input, shape.vertices.data(), shape.normals.data(), shape.count,
                              shape.radius);
    }
    // Cyrus-Beck: clip the ray's parameter interval against each face's half plane. The
    // entering face is the one that last raised the lower bound; none means the origin was
    // already inside every half plane.
    float lower = 0.0f;
    float upper = input.maxFraction;
    int index = -1;
    for (int i = 0; i < shape.count; ++i) {
        Vec2 n = shape.normals[i];
        float numerator = dot(n, shape.vertices[i] - input.origin);
        float denominator = dot(n, input.translation);
        if (denominator == 0.0f) {
            if (numerator < 0.0f) {
                return {};
            }
        } else if (denominator < 0.0f && numerator < lower * denominator) {
            lower = numerator / denominator;
            index = i;
        } else if (denominator > 0.0f && numerator < upper * denominator) {
            upper = numerator / denominator;
        }
        if (upper < lower) {
            return {};
        }
    }
    if (index < 0) {
        return {};
    }
    return makeHit(input, lower, shape.normals[index]);
}

CastOutput rayCast(const RayCastInput& input, const ShapeGeometry& shape) {
    return std::visit([&](const auto& s) { return rayCast(input, s); }, shape);
}

} // namespace e2d::physics
