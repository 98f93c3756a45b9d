// SPDX-License-Identifier: MIT
#include "shape_detail.hpp"

namespace e2d::physics::detail {

namespace {
float clamp01(float x) { return x < 0.0f ? 0.0f : (x > 1.0f ? 1.0f : x); }
} // namespace

SegmentDistance segmentDistance(Vec2 p1, Vec2 q1, Vec2 p2, Vec2 q2) {
    // Minimise |(p1 + s d1) - (p2 + t d2)| over the unit square: take the unclamped line
    // solution for s, derive t, and re-derive s whenever t had to be clamped.
    constexpr float kEpsilon = 1.0e-12f;
    Vec2 d1 = q1 - p1;
    Vec2 d2 = q2 - p2;
    Vec2 r = p1 - p2;
    float a = dot(d1, d1);
    float e = dot(d2, d2);
    float f = dot(d2, r);
    float s = 0.0f;
    float t = 0.0f;
    if (a <= kEpsilon && e <= kEpsilon) {
        // both degenerate: s = t = 0
    } else if (a <= kEpsilon) {
        t = clamp01(f / e);
    } else {
        float c = dot(d1, r);
        if (e <= kEpsilon) {
            s = clamp01(-c / a);
        } else {
            float b = dot(d1, d2);
            float denom = a * e - b * b;
            // Parallel (or nearly): any s works, 0 is as good as another and stays stable.
            s = denom > 1.0e-6f * a * e ? clamp01((b * f - c * e) / denom) : 0.0f;
            t = (b * s + f) / e;
            if (t < 0.0f) {
                t = 0.0f;
                s = clamp01(-c / a);
            } else if (t > 1.0f) {
                t = 1.0f;
                s = clamp01((b - c) / a);
            }
        }
    }
    SegmentDistance result;
    result.fraction1 = s;
    result.fraction2 = t;
    result.closest1 = p1 + s * d1;
    result.closest2 = p2 + t * d2;
    result.distanceSquared = distanceSquared(result.closest1, result.closest2);
    return result;
}

} // namespace e2d::physics::detail
