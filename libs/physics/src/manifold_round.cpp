// SPDX-License-Identifier: MIT
#include <e2d/physics/manifold.hpp>

#include "manifold_circles.hpp"
#include "manifold_detail.hpp"
#include "shape_detail.hpp"
#include "sse_lanes.hpp"

#include <bit>
#include <cfloat>
#include <cstddef>
#include <cstdint>
#include <cstring>

// E2D_PHYSICS_SCALAR_ROUND forces the portable face search on SSE2 machines, so that the two
// paths can be compared (they must return bit-identical manifolds).
#if defined(__SSE2__) && !defined(E2D_PHYSICS_SCALAR_ROUND)
#define E2D_ROUND_SSE2 1
#include <emmintrin.h>
#else
#define E2D_ROUND_SSE2 0
#endif

namespace e2d::physics {
namespace {

// Feature code for "the side of a capsule" in capsule ids; vertices are 0 and 1.
constexpr int kCapsuleSide = 2;
// Closest points offset along a capsule's axis by no more than this (metres) make a side
// contact with up to two points, for the reason given at detail::kFaceOffset.
constexpr float kCapsuleFaceOffset = detail::kFaceOffset;

// The one-point result of the circle routines, id 0. Everything after the first point's
// separation is zero (impulses, id, flag, the whole second point); cleared as one block,
// padding included, it is four stores instead of one per field.
inline Manifold onePoint(Vec2 normal, Vec2 point, Vec2 anchorA, Vec2 anchorB, float separation) {
    Manifold m;
    constexpr std::size_t zeroFrom =
        offsetof(Manifold, points) + offsetof(ManifoldPoint, normalImpulse);
    std::memset(reinterpret_cast<unsigned char*>(&m) + zeroFrom, 0,
                offsetof(Manifold, pointCount) - zeroFrom);
    m.normal = normal;
    m.points[0].point = point;
    m.points[0].anchorA = anchorA;
    m.points[0].anchorB = anchorB;
    m.points[0].separation = separation;
    m.pointCount = 1;
    return m;
}

// One point between two round features: cores at pA and pB (A's frame) `distance` apart along
// unit `normal`, radii rA and rB.
detail::LocalManifold singlePoint(Vec2 pA, Vec2 pB, Vec2 normal, float distance, float rA, float rB,
                                  std::uint16_t id) {
    detail::LocalManifold m;
    m.normal = normal;
    m.points[0] = 0.5f * ((pA + rA * normal) + (pB - rB * normal));
    m.separations[0] = distance - rA - rB;
    m.ids[0] = id;
    m.count = 1;
    return m;
}

// Clips incident segment [q1, q2] to the extent of reference segment p1 + [0, len] * u, with
// `normal` pointing from the reference to the incident segment. Fails (returns false) when the
// segments barely overlap along u, in which case a single closest-point contact is better.
bool clipToReference(Vec2 p1, Vec2 u, float len, Vec2 normal, Vec2 q1, Vec2 q2, float r1, float r2,
                     float margin, detail::LocalManifold& m, int (&incidentIds)[2]) {
    float a1 = dot(q1 - p1, u);
    float a2 = dot(q2 - p1, u);
    float span = a2 - a1;
    if (std::fabs(span) < kLinearSlop) {
        return false;
    }
    float s0 = -a1 / span;
    float s1 = (len - a1) / span;
    float lo = std::fmax(0.0f, std::fmin(s0, s1));
    float hi = std::fmin(1.0f, std::fmax(s0, s1));
    if ((hi - lo) * std::fabs(span) < kLinearSlop) {
        return false;
    }
    m.normal = normal;
    m.count = 0;
    const float params[2] = {lo, hi};
    for (int k = 0; k < 2; ++k) {
        Vec2 q = q1 + params[k] * (q2 - q1);
        float core = dot(q - p1, normal);
        float separation = core - r1 - r2;
        if (separation > margin) {
            continue;
        }
        m.points[m.count] = q + (0.5f * (r1 - r2 - core)) * normal;
        m.separations[m.count] = separation;
        m.ids[m.count] = static_cast<std::uint16_t>(incidentIds[k]);
        ++m.count;
    }
    return true;
}

#if E2D_ROUND_SSE2

struct FaceSeparation {
    int face;
    float separation;
};

using detail::sse::padLanes;
using detail::sse::splat;

inline __m128 maxAcrossLanes(__m128 v) {
    v = _mm_max_ps(_mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 3, 0, 1)), v);
    return _mm_max_ps(_mm_shuffle_ps(v, v, _MM_SHUFFLE(1, 0, 3, 2)), v);
}

// max_i dot(n_i, c - v_i) over the polygon's faces, four faces per register (G registers: 1 up
// to 4 faces, 2 up to 8), and the first face reaching it. Each lane does the scalar loop's
// subtractions, products and sum (no FMA), so the face and the value are bit-identical to it.
template <int G>
inline FaceSeparation maxFaceSeparation(const Polygon& a, __m128 cx, __m128 cy) {
    const float* v = &a.vertices[0].x;
    const float* n = &a.normals[0].x;
    __m128 s[G];
    for (int g = 0; g < G; ++g) {
        const __m128 vlo = _mm_loadu_ps(v + 8 * g);     // x0 y0 x1 y1
        const __m128 vhi = _mm_loadu_ps(v + 8 * g + 4); // x2 y2 x3 y3
        const __m128 nlo = _mm_loadu_ps(n + 8 * g);
        const __m128 nhi = _mm_loadu_ps(n + 8 * g + 4);
        const __m128 dx = _mm_sub_ps(cx, _mm_shuffle_ps(vlo, vhi, _MM_SHUFFLE(2, 0, 2, 0)));
        const __m128 dy = _mm_sub_ps(cy, _mm_shuffle_ps(vlo, vhi, _MM_SHUFFLE(3, 1, 3, 1)));
        const __m128 nx = _mm_shuffle_ps(nlo, nhi, _MM_SHUFFLE(2, 0, 2, 0));
        const __m128 ny = _mm_shuffle_ps(nlo, nhi, _MM_SHUFFLE(3, 1, 3, 1));
        s[g] = _mm_add_ps(_mm_mul_ps(nx, dx), _mm_mul_ps(ny, dy));
    }
    // Padding the separations, not the inputs: one register instead of four.
    const int used = a.count - 4 * (G - 1);
    if (used < 4) {
        s[G - 1] = padLanes(s[G - 1], used);
    }
    // maxps returns its second operand on ties, so the lower faces go second: lane 0 ends with
    // the value of the first best face (the scalar loop's, down to the sign of a zero), and
    // every lane with the maximum.
    __m128 best = maxAcrossLanes(s[0]);
    if constexpr (G == 2) {
        best = _mm_max_ps(maxAcrossLanes(s[1]), best);
    }
    int mask = _mm_movemask_ps(_mm_cmpeq_ps(s[0], best));
    if constexpr (G == 2) {
        mask |= _mm_movemask_ps(_mm_cmpeq_ps(s[1], best)) << 4;
    }
    // A NaN (invalid shapes only) matches no lane: face 0, as the scalar loop.
    return {__builtin_ctz(static_cast<unsigned>(mask) | 0x100u) & 7, _mm_cvtss_f32(best)};
}

#endif

} // namespace

#if E2D_ROUND_SSE2

Manifold collideCircles(const Circle& a, const Transform& xfA, const Circle& b,
                        const Transform& xfB, float margin) {
    return detail::collideCirclesSse2(a, xfA, b, xfB, margin);
}

#else

Manifold collideCircles(const Circle& a, const Transform& xfA, const Circle& b,
                        const Transform& xfB, float margin) {
    // Centres relative to A's origin along world axes: no frame change is needed for two
    // circles, and the anchors come out directly. Centred circles (most) skip the rotations.
    Vec2 cA{0.0f, 0.0f};
    Vec2 cB = xfB.p - xfA.p;
    if (!detail::bothCentred(a, b)) {
        cA = rotate(xfA.q, a.center);
        cB = rotate(xfB.q, b.center) + cB;
    }
    const Vec2 d = cB - cA;
    const float radius = a.radius + b.radius;
    const float limit = radius + margin;
    const float distSq = lengthSquared(d);
    if (distSq > limit * limit) {
        return Manifold{};
    }
    const float dist = std::sqrt(distSq);
    // Concentric circles have no preferred direction; A's x axis is as good as any. Spelled
    // as the rotation's column: rotate(q, {1, 0}) costs multiplications by zero the compiler
    // may not drop (they could make -0 or NaN).
    Vec2 normal{xfA.q.c, xfA.q.s};
    if (dist > FLT_EPSILON) {
        // Two divisions, not a reciprocal and two products: shorter, correctly rounded, and
        // measured no slower (the divisions are independent).
        normal = d / dist;
    }
    // Midway between the surfaces: half the separation beyond A's surface. One scale of the
    // normal instead of moving both surface points.
    const float separation = dist - radius;
    const Vec2 anchorA = cA + (a.radius + 0.5f * separation) * normal;
    return onePoint(normal, anchorA + xfA.p, anchorA, anchorA + (xfA.p - xfB.p), separation);
}

#endif

Manifold collideCapsuleAndCircle(const Capsule& a, const Transform& xfA, const Circle& b,
                                 const Transform& xfB, float margin) {
    const Transform xf = invMulTransforms(xfA, xfB);
    const Vec2 pB = transformPoint(xf, b.center);
    const Vec2 pA = detail::closestPointOnSegment(a.center1, a.center2, pB);
    const float limit = a.radius + b.radius + margin;
    const float distSq = distanceSquared(pA, pB);
    if (distSq > limit * limit) {
        return Manifold{};
    }
    const float dist = std::sqrt(distSq);
    // A centre on the axis: push out sideways, the shortest way out of a capsule.
    const Vec2 normal =
        dist > FLT_EPSILON ? (pB - pA) / dist : normalize(leftPerp(a.center2 - a.center1));
    return detail::localToWorld(singlePoint(pA, pB, normal, dist, a.radius, b.radius, 0), xfA, xfB);
}

Manifold collideCapsules(const Capsule& a, const Transform& xfA, const Capsule& b,
                         const Transform& xfB, float margin) {
    const Transform xf = invMulTransforms(xfA, xfB);
    const Vec2 p1 = a.center1;
    const Vec2 p2 = a.center2;
    const Vec2 q1 = transformPoint(xf, b.center1);
    const Vec2 q2 = transformPoint(xf, b.center2);
    const float rA = a.radius;
    const float rB = b.radius;
    const float limit = rA + rB + margin;

    const detail::SegmentDistance sd = detail::segmentDistance(p1, p2, q1, q2);
    if (sd.distanceSquared > limit * limit) {
        return Manifold{};
    }
    const float dist = std::sqrt(sd.distanceSquared);
    if (dist < 0.1f * kLinearSlop) {
        // The axes cross or touch: no closest-point direction, so find the axis of least
        // penetration with SAT on the two segments (complete for non-parallel segments).
        return collidePolygons(detail::makeCapsulePolygon(a.center1, a.center2, rA), xfA,
                               detail::makeCapsulePolygon(b.center1, b.center2, rB), xfB, margin);
    }
    const Vec2 delta = sd.closest2 - sd.closest1;
    const Vec2 w = delta / dist;

    // When the closest points are level along one axis, the contact is on that
    // capsule's side (parallel or resting capsules): clip the other axis to it for up to two
    // points. Otherwise it is an end-to-end contact with one point.
    detail::LocalManifold m;
    const float lenA = distance(p1, p2);
    const float lenB = distance(q1, q2);
    const Vec2 uA = lenA > 0.0f ? (p2 - p1) / lenA : Vec2{0.0f, 0.0f};
    const Vec2 uB = lenB > 0.0f ? (q2 - q1) / lenB : Vec2{0.0f, 0.0f};
    if (lenA > 0.0f && std::fabs(dot(delta, uA)) <= kCapsuleFaceOffset) {
        Vec2 n = leftPerp(uA);
        n = dot(n, w) < 0.0f ? -n : n;
        int ids[2] = {makeFeatureId(kCapsuleSide, 0), makeFeatureId(kCapsuleSide, 1)};
        if (clipToReference(p1, uA, lenA, n, q1, q2, rA, rB, margin, m, ids)) {
            return detail::localToWorld(m, xfA, xfB);
        }
    }
    if (lenB > 0.0f && std::fabs(dot(delta, uB)) <= kCapsuleFaceOffset) {
        Vec2 n = leftPerp(uB);
        n = dot(n, w) > 0.0f ? -n : n; // from B towards A
        int ids[2] = {makeFeatureId(0, kCapsuleSide), makeFeatureId(1, kCapsuleSide)};
        if (clipToReference(q1, uB, lenB, n, p1, p2, rB, rA, margin, m, ids)) {
            m.normal = -m.normal;
            return detail::localToWorld(m, xfA, xfB);
        }
    }
    const int featureA = sd.fraction1 < 0.5f ? 0 : 1;
    const int featureB = sd.fraction2 < 0.5f ? 0 : 1;
    m = singlePoint(sd.closest1, sd.closest2, w, dist, rA, rB, makeFeatureId(featureA, featureB));
    return detail::localToWorld(m, xfA, xfB);
}

Manifold collidePolygonAndCircle(const Polygon& a, const Transform& xfA, const Circle& b,
                                 const Transform& xfB, float margin) {
    // Only the centre moves to A's frame: cheaper than composing the two transforms first.
    // Kept relative to A's origin along world axes too (cW): the contact point is found from it
    // in world axes directly, so no local point has to be rotated back.
#if E2D_ROUND_SSE2
    // rotate() and invRotate() two lanes at a time, with their products and sums (a - b as
    // a + -b, which is exact), so cW and c are bit-identical to the scalar path's.
    const __m128 tA = _mm_loadu_ps(&xfA.p.x); // pA.x pA.y cA sA
    const __m128 tB = _mm_loadu_ps(&xfB.p.x);
    const __m128 centre =
        _mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(&b.center.x)));
    const __m128 negX = _mm_setr_ps(-0.0f, 0.0f, -0.0f, 0.0f);
    const __m128 negY = _mm_setr_ps(0.0f, -0.0f, 0.0f, -0.0f);
    const __m128 cWv = _mm_add_ps(
        _mm_add_ps(_mm_mul_ps(_mm_shuffle_ps(tB, tB, _MM_SHUFFLE(3, 2, 3, 2)), splat<0>(centre)),
                   _mm_xor_ps(_mm_mul_ps(_mm_shuffle_ps(tB, tB, _MM_SHUFFLE(2, 3, 2, 3)),
                                         splat<1>(centre)),
                              negX)),
        _mm_sub_ps(tB, tA));
    const __m128 cv = _mm_add_ps(
        _mm_xor_ps(_mm_mul_ps(_mm_shuffle_ps(tA, tA, _MM_SHUFFLE(3, 2, 3, 2)), splat<0>(cWv)),
                   negY),
        _mm_mul_ps(_mm_shuffle_ps(tA, tA, _MM_SHUFFLE(2, 3, 2, 3)), splat<1>(cWv)));
    const Vec2 cW{_mm_cvtss_f32(cWv), _mm_cvtss_f32(splat<1>(cWv))};
#else
    const Vec2 cW = rotate(xfB.q, b.center) + (xfB.p - xfA.p);
    const Vec2 c = invRotate(xfA.q, cW);
#endif
    const float radius = a.radius + b.radius;
    const float limit = radius + margin;

    // The face that separates the centre the most; the closest feature is that face or one of
    // its two vertices.
    // Kept by selects, not a branch: which face wins is random from pair to pair.
#if E2D_ROUND_SSE2
    const __m128 cx = splat<0>(cv);
    const __m128 cy = splat<1>(cv);
    const FaceSeparation best =
        a.count > 4 ? maxFaceSeparation<2>(a, cx, cy) : maxFaceSeparation<1>(a, cx, cy);
    const int face = best.face;
    const float separation = best.separation;
#else
    int face = 0;
    float separation = -FLT_MAX;
    for (int i = 0; i < a.count; ++i) {
        const float s = dot(a.normals[i], c - a.vertices[i]);
        const bool better = s > separation;
        face = better ? i : face;
        separation = better ? s : separation;
    }
#endif
    if (separation > limit) {
        return Manifold{};
    }
    // Face region, or the centre inside the core: out through the face, `separation` deep.
    Vec2 n = a.normals[face];
    float dist = separation;
    if (separation > FLT_EPSILON) {
        const int next = face + 1 < a.count ? face + 1 : 0;
#if E2D_ROUND_SSE2
        // Both vertices in one register: lanes c - v1 | c - v2, each dotted with e = v2 - v1
        // (the scalar path's products and sum). dot(c - v2, e) is exactly -dot(v2 - c, e) (up
        // to the sign of a zero, which no comparison with 0 sees), so the tests match it.
        // Vec2 is only 4-byte aligned: _mm_loadl_epi64 reads through an unaligned type.
        const __m128 v12 = _mm_loadh_pi(_mm_castsi128_ps(_mm_loadl_epi64(
                                            reinterpret_cast<const __m128i*>(&a.vertices[face].x))),
                                        reinterpret_cast<const __m64*>(&a.vertices[next].x));
        const __m128 d = _mm_sub_ps(_mm_unpacklo_ps(cx, cy), v12);
        const __m128 e = _mm_sub_ps(_mm_movehl_ps(v12, v12), v12);
        const __m128 p = _mm_mul_ps(d, _mm_movelh_ps(e, e));
        const __m128 u = _mm_add_ps(p, _mm_shuffle_ps(p, p, _MM_SHUFFLE(2, 3, 0, 1)));
        // Lane 2 negated: both lanes then read "< 0: beyond this vertex".
        const int beyond =
            _mm_movemask_ps(_mm_cmplt_ps(_mm_xor_ps(u, _mm_setr_ps(0.0f, 0.0f, -0.0f, 0.0f)),
                                         _mm_setzero_ps())) &
            5;
        if (beyond != 0) {
            // Vertex region: the distance to the vertex, tested squared so that a pair beyond
            // the margin costs no square root.
            const __m128 wv = (beyond & 1) != 0 ? d : _mm_movehl_ps(d, d);
            const Vec2 w{_mm_cvtss_f32(wv), _mm_cvtss_f32(_mm_shuffle_ps(wv, wv, 1))};
#else
        const Vec2 v1 = a.vertices[face];
        const Vec2 v2 = a.vertices[next];
        const Vec2 e = v2 - v1;
        const float u1 = dot(c - v1, e);
        const float u2 = dot(v2 - c, e);
        if (u1 < 0.0f || u2 < 0.0f) {
            // Vertex region: the distance to the vertex, tested squared so that a pair beyond
            // the margin costs no square root.
            const Vec2 w = c - (u1 < 0.0f ? v1 : v2);
#endif
            const float distSq = lengthSquared(w);
            if (distSq > limit * limit) {
                return Manifold{};
            }
            dist = std::sqrt(distSq);
            n = w / dist;
        }
    }
    // The closest core point is the centre moved back `dist` along n; midway between the
    // surfaces is the centre moved back by B's radius and half the separation.
    const Vec2 normal = rotate(xfA.q, n);
    const float pointSeparation = dist - radius;
    const Vec2 anchorA = cW - (b.radius + 0.5f * pointSeparation) * normal;
    return onePoint(normal, anchorA + xfA.p, anchorA, anchorA + (xfA.p - xfB.p), pointSeparation);
}

Manifold collidePolygonAndCapsule(const Polygon& a, const Transform& xfA, const Capsule& b,
                                  const Transform& xfB, float margin) {
    return collidePolygons(a, xfA, detail::makeCapsulePolygon(b.center1, b.center2, b.radius), xfB,
                           margin);
}

Manifold collideSegmentAndCircle(const Segment& a, const Transform& xfA, const Circle& b,
                                 const Transform& xfB, float margin) {
    return collideCapsuleAndCircle(Capsule{a.point1, a.point2, 0.0f}, xfA, b, xfB, margin);
}

Manifold collideSegmentAndCapsule(const Segment& a, const Transform& xfA, const Capsule& b,
                                  const Transform& xfB, float margin) {
    return collideCapsules(Capsule{a.point1, a.point2, 0.0f}, xfA, b, xfB, margin);
}

Manifold collideSegmentAndPolygon(const Segment& a, const Transform& xfA, const Polygon& b,
                                  const Transform& xfB, float margin) {
    return collidePolygons(detail::makeCapsulePolygon(a.point1, a.point2, 0.0f), xfA, b, xfB,
                           margin);
}

} // namespace e2d::physics
