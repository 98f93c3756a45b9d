// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/constants.hpp>

#include <glm/vec2.hpp>

#include <cmath>

/// Small 2D math for the physics library. Vectors are `glm::vec2` so that physics, core and
/// render share one vector type; rotations and transforms are stored as cosine/sine pairs,
/// which is what the collision code needs in its inner loops.
namespace e2d::physics {

using Vec2 = glm::vec2;

/// A rotation stored as (cos, sin). Counter-clockwise positive, y up.
struct Rot {
    float c = 1.0f; ///< cosine of the angle
    float s = 0.0f; ///< sine of the angle

    /// The rotation by `angle` radians (counter-clockwise).
    static Rot fromAngle(float angle) { return {std::cos(angle), std::sin(angle)}; }
    /// The angle in radians, in [-pi, pi].
    [[nodiscard]] float angle() const { return std::atan2(s, c); }
};

/// A rigid transform: rotate, then translate.
struct Transform {
    Vec2 p{0.0f, 0.0f}; ///< translation, metres
    Rot q{};            ///< rotation
};

/// An axis-aligned box, lower and upper corners.
struct Aabb {
    Vec2 lower{0.0f, 0.0f};
    Vec2 upper{0.0f, 0.0f};
};

inline float dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
/// The 2D cross product (z of the 3D one).
inline float cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
/// cross(v, s): v rotated clockwise by 90 degrees, scaled by s.
inline Vec2 cross(Vec2 v, float s) { return {s * v.y, -s * v.x}; }
/// cross(s, v): v rotated counter-clockwise by 90 degrees, scaled by s.
inline Vec2 cross(float s, Vec2 v) { return {-s * v.y, s * v.x}; }
/// v rotated counter-clockwise by 90 degrees.
inline Vec2 leftPerp(Vec2 v) { return {-v.y, v.x}; }
/// v rotated clockwise by 90 degrees.
inline Vec2 rightPerp(Vec2 v) { return {v.y, -v.x}; }
inline float lengthSquared(Vec2 v) { return v.x * v.x + v.y * v.y; }
inline float length(Vec2 v) { return std::sqrt(v.x * v.x + v.y * v.y); }
inline float distanceSquared(Vec2 a, Vec2 b) { return lengthSquared(b - a); }
inline float distance(Vec2 a, Vec2 b) { return length(b - a); }
inline bool isFinite(float x) { return std::isfinite(x); }
inline bool isFinite(Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }
/// Finite and within kHuge: what a world takes for a length or a coordinate.
inline bool isWithinHuge(float x) { return std::isfinite(x) && std::fabs(x) <= kHuge; }
inline bool isWithinHuge(Vec2 v) { return isWithinHuge(v.x) && isWithinHuge(v.y); }

/// v / |v|, or (0, 0) when |v| is below the float epsilon.
inline Vec2 normalize(Vec2 v) {
    float len = length(v);
    if (len < 1.1920929e-7f) {
        return {0.0f, 0.0f};
    }
    float inv = 1.0f / len;
    return {inv * v.x, inv * v.y};
}

inline Vec2 rotate(Rot q, Vec2 v) { return {q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y}; }
inline Vec2 invRotate(Rot q, Vec2 v) { return {q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y}; }
/// q * r
inline Rot mulRot(Rot q, Rot r) { return {q.c * r.c - q.s * r.s, q.s * r.c + q.c * r.s}; }
/// transpose(q) * r
inline Rot invMulRot(Rot q, Rot r) { return {q.c * r.c + q.s * r.s, q.c * r.s - q.s * r.c}; }

inline Vec2 transformPoint(const Transform& t, Vec2 p) { return rotate(t.q, p) + t.p; }
inline Vec2 invTransformPoint(const Transform& t, Vec2 p) { return invRotate(t.q, p - t.p); }
/// a * b
inline Transform mulTransforms(const Transform& a, const Transform& b) {
    return {rotate(a.q, b.p) + a.p, mulRot(a.q, b.q)};
}
/// inverse(a) * b: b expressed in a's frame.
inline Transform invMulTransforms(const Transform& a, const Transform& b) {
    return {invRotate(a.q, b.p - a.p), invMulRot(a.q, b.q)};
}

inline bool overlaps(const Aabb& a, const Aabb& b) {
    return !(b.lower.x > a.upper.x || b.lower.y > a.upper.y || a.lower.x > b.upper.x ||
             a.lower.y > b.upper.y);
}
inline bool contains(const Aabb& outer, const Aabb& inner) {
    return outer.lower.x <= inner.lower.x && outer.lower.y <= inner.lower.y &&
           inner.upper.x <= outer.upper.x && inner.upper.y <= outer.upper.y;
}
inline Aabb unionOf(const Aabb& a, const Aabb& b) {
    return {{std::fmin(a.lower.x, b.lower.x), std::fmin(a.lower.y, b.lower.y)},
            {std::fmax(a.upper.x, b.upper.x), std::fmax(a.upper.y, b.upper.y)}};
}
inline float perimeter(const Aabb& a) {
    return 2.0f * ((a.upper.x - a.lower.x) + (a.upper.y - a.lower.y));
}

} // namespace e2d::physics
