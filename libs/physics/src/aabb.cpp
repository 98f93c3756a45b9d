// SPDX-License-Identifier: MIT
#include <e2d/physics/geometry.hpp>

#include <glm/common.hpp>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

namespace e2d::physics {

Aabb computeAabb(const Circle& shape, const Transform& xf) {
    Vec2 c = transformPoint(xf, shape.center);
    Vec2 r{shape.radius, shape.radius};
    return {c - r, c + r};
}

Aabb computeAabb(const Capsule& shape, const Transform& xf) {
    Vec2 a = transformPoint(xf, shape.center1);
    Vec2 b = transformPoint(xf, shape.center2);
    Vec2 r{shape.radius, shape.radius};
    return {glm::min(a, b) - r, glm::max(a, b) + r};
}

Aabb computeAabb(const ChainSegment& shape, const Transform& xf) {
    return computeAabb(shape.segment, xf);
}

Aabb computeAabb(const Segment& shape, const Transform& xf) {
    Vec2 a = transformPoint(xf, shape.point1);
    Vec2 b = transformPoint(xf, shape.point2);
    return {glm::min(a, b), glm::max(a, b)};
}

#if defined(__SSE2__)

// Two vertices a register (x0 y0 x1 y1), each transformed as transformPoint() does: c x - s y
// is computed as c x + (-s) y, and s x + c y as c y + s x, the same roundings. The minimum and
// maximum then take the vertices in order (glm::min(lower, v) is minps(v, lower)), so even the
// sign of a zero bound (and a NaN's fate) is the scalar loop's. About a third of its instructions for a box, the
// write-back's main cost per body.
Aabb computeAabb(const Polygon& shape, const Transform& xf) {
    const __m128 c = _mm_set1_ps(xf.q.c);
    const __m128 s = _mm_setr_ps(-xf.q.s, xf.q.s, -xf.q.s, xf.q.s);
    const __m128 p = _mm_setr_ps(xf.p.x, xf.p.y, xf.p.x, xf.p.y);
    auto transform = [&](__m128 v) {
        const __m128 swapped = _mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 3, 0, 1)); // y0 x0 y1 x1
        return _mm_add_ps(_mm_add_ps(_mm_mul_ps(c, v), _mm_mul_ps(s, swapped)), p);
    };
    const float* vertices = &shape.vertices[0].x;
    const int count = shape.count;
    // Vertex 0 (and 1, when there is one) first.
    __m128 pair = transform(_mm_loadu_ps(vertices));
    __m128 lower = pair;
    __m128 upper = pair;
    int i = 1;
    for (;;) {
        // pair holds vertices i - 1 and i (lane 2-3): fold in vertex i.
        if (i >= count) {
            break;
        }
        const __m128 high = _mm_movehl_ps(pair, pair);
        lower = _mm_min_ps(high, lower);
        upper = _mm_max_ps(high, upper);
        ++i;
        if (i >= count) {
            break;
        }
        // The last vertex of an odd count alone: nothing is read past it.
        pair = transform(
            i + 1 < count
                ? _mm_loadu_ps(vertices + 2 * i)
                : _mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(vertices + 2 * i)));
        lower = _mm_min_ps(pair, lower);
        upper = _mm_max_ps(pair, upper);
        ++i;
    }
    alignas(16) float lo[4];
    alignas(16) float hi[4];
    _mm_store_ps(lo, lower);
    _mm_store_ps(hi, upper);
    const Vec2 r{shape.radius, shape.radius};
    return {Vec2{lo[0], lo[1]} - r, Vec2{hi[0], hi[1]} + r};
}

#else

Aabb computeAabb(const Polygon& shape, const Transform& xf) {
    Vec2 lower = transformPoint(xf, shape.vertices[0]);
    Vec2 upper = lower;
    for (int i = 1; i < shape.count; ++i) {
        Vec2 v = transformPoint(xf, shape.vertices[i]);
        lower = glm::min(lower, v);
        upper = glm::max(upper, v);
    }
    Vec2 r{shape.radius, shape.radius};
    return {lower - r, upper + r};
}

#endif

// A switch on the alternative, not std::visit: the write-back computes every awake shape's box
// each step.
Aabb computeAabb(const ShapeGeometry& shape, const Transform& xf) {
    switch (shape.index()) {
    case 0:
        return computeAabb(*std::get_if<Circle>(&shape), xf);
    case 1:
        return computeAabb(*std::get_if<Capsule>(&shape), xf);
    case 2:
        return computeAabb(*std::get_if<Segment>(&shape), xf);
    case 3:
        return computeAabb(*std::get_if<Polygon>(&shape), xf);
    default:
        return computeAabb(*std::get_if<ChainSegment>(&shape), xf);
    }
}

} // namespace e2d::physics
