// SPDX-License-Identifier: MIT
#include <e2d/physics/manifold.hpp>

#include "manifold_detail.hpp"
#include "polygon_clip.hpp"
#include "shape_detail.hpp"
#include "sse_lanes.hpp"

#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>

// E2D_PHYSICS_SCALAR_SAT forces the portable path on SSE2 machines, so that the two paths can
// be compared (they must return bit-identical manifolds).
#if defined(__SSE2__) && !defined(E2D_PHYSICS_SCALAR_SAT)
#define E2D_SAT_SSE2 1
#include <emmintrin.h>
#else
#define E2D_SAT_SSE2 0
#endif

namespace e2d::physics {
namespace {

using detail::kFaceOffset;
using detail::kFlipTolerance;
using detail::kSeparatedCores;
using detail::LocalManifold;
using detail::PolygonRef;

struct EdgeSeparation {
    int edge = 0;
    float separation = -FLT_MAX;
};

// Marks "no contact" in a LocalManifold without touching its points.
inline LocalManifold noContact() {
    LocalManifold m;
    m.count = 0;
    return m;
}

// Beyond this distance (metres) of A's first vertex from A's origin, the work moves to a
// frame at that vertex: coordinates relative to A's origin would lose precision (float ulp is
// 8e-6 m at 100 m). Below it, copying A to shift it costs more than it gains.
constexpr float kShiftSquared = 100.0f * 100.0f;

// Where the work happens: A's frame, moved to A's first vertex when that is far from A's
// origin (see kShiftSquared); `origin` is that vertex, to shift A and the results by.
struct WorkFrame {
    Transform frame;
    Vec2 origin;
    bool shift;
};

inline WorkFrame workFrameOf(const Polygon& a, const Transform& xfA) {
    WorkFrame w{xfA, a.vertices[0], lengthSquared(a.vertices[0]) > kShiftSquared};
    if (w.shift) [[unlikely]] {
        w.frame.p = transformPoint(xfA, w.origin);
    }
    return w;
}

// The manifold once the axis is known: `edge1` of poly1 (B when `flip`) is the reference face,
// `incident` the face of poly2 most anti-parallel to it, `separation` the reference face's.
// Shared by both search paths, so that they can differ only in how they find the axis.
// Forced inline: with four callers GCC kept it out of line, and the PolygonRefs and the result
// went through memory on every touching pair's critical path.
//
// `faceA` and `faceB` are each polygon's best face (the reference face is one of them).
[[gnu::always_inline]] inline LocalManifold
contactOnAxis(const PolygonRef& localA, const PolygonRef& localB, float margin,
              const EdgeSeparation& faceA, const EdgeSeparation& faceB, bool flip, int edge1,
              int incident, float separation) {
    const float radius = localA.radius + localB.radius;
    const float limit = margin + radius;
    const PolygonRef& poly1 = flip ? localB : localA;
    const PolygonRef& poly2 = flip ? localA : localB;
    if (separation > kSeparatedCores) [[unlikely]] {
        // Face separation only bounds the distance from below; near a corner the real gap is
        // larger, which matters for rounded polygons and for speculative points. The closest
        // points of the two edges tell a face contact from a vertex contact.
        const Vec2 normal1 = poly1.normals[edge1];
        const int i11 = edge1;
        const int i12 = i11 + 1 < poly1.count ? i11 + 1 : 0;
        const int i21 = incident;
        const int i22 = i21 + 1 < poly2.count ? i21 + 1 : 0;
        const detail::SegmentDistance sd = detail::segmentDistance(
            poly1.vertices[i11], poly1.vertices[i12], poly2.vertices[i21], poly2.vertices[i22]);
        if (sd.distanceSquared > limit * limit) {
            return noContact();
        }
        // distance >= separation > 0, so w is well defined.
        const float distance = std::sqrt(sd.distanceSquared);
        const Vec2 w = (sd.closest2 - sd.closest1) / distance;
        if (std::fabs(cross(normal1, sd.closest2 - sd.closest1)) > kFaceOffset) {
            Vec2 c1 = sd.closest1 + poly1.radius * w;
            Vec2 c2 = sd.closest2 - poly2.radius * w;
            int feature1 = sd.fraction1 < 0.5f ? i11 : i12;
            int feature2 = sd.fraction2 < 0.5f ? i21 : i22;
            // Zeroed: the unused second point would otherwise be copied uninitialised (GCC 12
            // at -O3 rightly warns). A vertex contact is the rare path; the stores cost nothing.
            LocalManifold m{};
            m.points[0] = 0.5f * (c1 + c2);
            m.separations[0] = distance - radius;
            m.ids[0] = flip ? makeFeatureId(feature2, feature1) : makeFeatureId(feature1, feature2);
            m.normal = flip ? -w : w;
            m.count = 1;
            return m;
        }
    } else if (detail::mayCrossAtCorners(localA, localB, faceA.edge, faceA.separation, faceB.edge,
                                         faceB.separation)) [[unlikely]] {
        const LocalManifold m =
            detail::crossingCorners(localA, localB, faceA.edge, faceB.edge, margin);
        if (m.count > 0) {
            return m;
        }
    }
    return detail::clipPolygons(localA, localB, flip ? incident : edge1, flip ? edge1 : incident,
                                flip, margin);
}

#if E2D_SAT_SSE2

// Both polygons four items to a register (x and y apart), so one instruction does the work of
// four faces. Each lane computes exactly what the scalar path computes for its face or vertex
// (the same products and sums in the same order, no FMA), so the results are bit-identical.

// Items 4g..4g+3 of an 8-slot array (vertices or normals) in lanes: G registers of each.
template <int G>
struct Lanes {
    __m128 x[G];
    __m128 y[G];
};

using detail::sse::padLanes;
using detail::sse::splat;

template <int G>
inline Lanes<G> loadLanes(const Vec2* items, int count) {
    Lanes<G> r;
    const float* f = &items[0].x;
    for (int g = 0; g < G; ++g) {
        const __m128 lo = _mm_loadu_ps(f + 8 * g);     // x0 y0 x1 y1
        const __m128 hi = _mm_loadu_ps(f + 8 * g + 4); // x2 y2 x3 y3
        r.x[g] = _mm_shuffle_ps(lo, hi, _MM_SHUFFLE(2, 0, 2, 0));
        r.y[g] = _mm_shuffle_ps(lo, hi, _MM_SHUFFLE(3, 1, 3, 1));
    }
    const int used = count - 4 * (G - 1);
    if (used < 4) {
        r.x[G - 1] = padLanes(r.x[G - 1], used);
        r.y[G - 1] = padLanes(r.y[G - 1], used);
    }
    return r;
}

// The lanes back in an 8-slot array of Vec2, for the scalar tail (clipping).
template <int G>
inline void storeLanes(const Lanes<G>& v, Vec2* items) {
    float* f = &items[0].x;
    for (int g = 0; g < G; ++g) {
        _mm_storeu_ps(f + 8 * g, _mm_unpacklo_ps(v.x[g], v.y[g]));
        _mm_storeu_ps(f + 8 * g + 4, _mm_unpackhi_ps(v.x[g], v.y[g]));
    }
}

// rotate(q, v): {c x - s y, s x + c y}, and transformPoint() adds t after.
template <int G>
inline Lanes<G> rotateLanes(const Lanes<G>& v, __m128 c, __m128 s) {
    Lanes<G> r;
    for (int g = 0; g < G; ++g) {
        r.x[g] = _mm_sub_ps(_mm_mul_ps(c, v.x[g]), _mm_mul_ps(s, v.y[g]));
        r.y[g] = _mm_add_ps(_mm_mul_ps(s, v.x[g]), _mm_mul_ps(c, v.y[g]));
    }
    return r;
}

// invMulTransforms(a, b) as p.x p.y q.c q.s in one register. Each lane does the scalar
// products and sums, reordered only where that is exact (c y + (-s) x for -s x + c y, and
// c s' + (-s) c' for c s' - s c'), so the transform is bit-identical to the scalar one.
inline __m128 invMulLanes(const Transform& a, const Transform& b) {
    static_assert(sizeof(Transform) == 16 && offsetof(Transform, q) == 8);
    const __m128 ta = _mm_loadu_ps(&a.p.x); // p.x p.y c s
    const __m128 tb = _mm_loadu_ps(&b.p.x);
    // b.p - a.p, then b.q unchanged (a's rotation lanes cleared).
    const __m128 v = _mm_sub_ps(tb, _mm_movelh_ps(ta, _mm_setzero_ps()));
    const __m128 c = splat<2>(ta);
    const __m128 signedS =
        _mm_xor_ps(splat<3>(ta), _mm_castsi128_ps(_mm_setr_epi32(0, INT32_MIN, 0, INT32_MIN)));
    return _mm_add_ps(_mm_mul_ps(c, v),
                      _mm_mul_ps(signedS, _mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 3, 0, 1))));
}

// dot(a_i, b_i) for every lane.
template <int G>
inline void dotLanes(const Lanes<G>& a, const Lanes<G>& b, __m128 (&out)[G]) {
    for (int g = 0; g < G; ++g) {
        out[g] = _mm_add_ps(_mm_mul_ps(a.x[g], b.x[g]), _mm_mul_ps(a.y[g], b.y[g]));
    }
}

// The lowest index whose lane equals `best` (every lane of `best` holds the extreme): what a
// scalar loop keeping only strict improvements returns. A NaN (invalid shapes) gives 0.
template <int G>
inline int firstEqual(const __m128 (&v)[G], __m128 best) {
    int mask = _mm_movemask_ps(_mm_cmpeq_ps(v[0], best));
    if constexpr (G == 2) {
        mask |= _mm_movemask_ps(_mm_cmpeq_ps(v[1], best)) << 4;
    }
    return __builtin_ctz(static_cast<unsigned>(mask) | 0x100u) & 7;
}

// The face of poly1 (normals `n`, dot(n_i, v_i) in `offset`) whose normal separates poly2's
// vertices `w` the most: separation_i = min_j dot(n_i, w_j) - dot(n_i, v_i), the first face
// with the largest. Faces are lanes, vertices are broadcast one by one: no horizontal step
// until the single one at the end.
template <int GF, int GP>
inline EdgeSeparation findMaxSeparation(const Lanes<GF>& n, const __m128 (&offset)[GF],
                                        const Lanes<GP>& w) {
    __m128 lowest[GF];
    for (int g = 0; g < GP; ++g) {
        const __m128 x0 = splat<0>(w.x[g]);
        const __m128 x1 = splat<1>(w.x[g]);
        const __m128 x2 = splat<2>(w.x[g]);
        const __m128 x3 = splat<3>(w.x[g]);
        const __m128 y0 = splat<0>(w.y[g]);
        const __m128 y1 = splat<1>(w.y[g]);
        const __m128 y2 = splat<2>(w.y[g]);
        const __m128 y3 = splat<3>(w.y[g]);
        for (int f = 0; f < GF; ++f) {
            const __m128 d0 = _mm_add_ps(_mm_mul_ps(n.x[f], x0), _mm_mul_ps(n.y[f], y0));
            const __m128 d1 = _mm_add_ps(_mm_mul_ps(n.x[f], x1), _mm_mul_ps(n.y[f], y1));
            const __m128 d2 = _mm_add_ps(_mm_mul_ps(n.x[f], x2), _mm_mul_ps(n.y[f], y2));
            const __m128 d3 = _mm_add_ps(_mm_mul_ps(n.x[f], x3), _mm_mul_ps(n.y[f], y3));
            const __m128 m = _mm_min_ps(_mm_min_ps(d0, d1), _mm_min_ps(d2, d3));
            lowest[f] = g == 0 ? m : _mm_min_ps(lowest[f], m);
        }
    }
    __m128 separation[GF];
    __m128 best = _mm_sub_ps(lowest[0], offset[0]);
    separation[0] = best;
    if constexpr (GF == 2) {
        separation[1] = _mm_sub_ps(lowest[1], offset[1]);
        best = _mm_max_ps(best, separation[1]);
    }
    best = _mm_max_ps(best, _mm_shuffle_ps(best, best, _MM_SHUFFLE(2, 3, 0, 1)));
    best = _mm_max_ps(best, _mm_shuffle_ps(best, best, _MM_SHUFFLE(1, 0, 3, 2)));
    return {firstEqual<GF>(separation, best), _mm_cvtss_f32(best)};
}

// The first face of `normals` most anti-parallel to `reference` (the incident face).
template <int G>
inline int findIncidentEdge(Vec2 reference, const Lanes<G>& normals) {
    const __m128 rx = _mm_set1_ps(reference.x);
    const __m128 ry = _mm_set1_ps(reference.y);
    __m128 d[G];
    for (int g = 0; g < G; ++g) {
        d[g] = _mm_add_ps(_mm_mul_ps(rx, normals.x[g]), _mm_mul_ps(ry, normals.y[g]));
    }
    __m128 best = d[0];
    if constexpr (G == 2) {
        best = _mm_min_ps(best, d[1]);
    }
    best = _mm_min_ps(best, _mm_shuffle_ps(best, best, _MM_SHUFFLE(2, 3, 0, 1)));
    best = _mm_min_ps(best, _mm_shuffle_ps(best, best, _MM_SHUFFLE(1, 0, 3, 2)));
    return firstEqual<G>(d, best);
}

// GA, GB: registers per coordinate for A and B (1 up to 4 vertices, 2 up to 8). Inlined into
// collidePolygons so that choosing the instance costs two compares, not a second call.
template <int GA, int GB>
[[gnu::always_inline]] inline Manifold collideLanes(const Polygon& a, const Transform& xfA,
                                                    const Polygon& b, const Transform& xfB,
                                                    float margin) {
    const auto [frame, origin, shift] = workFrameOf(a, xfA);
    // Work in A's frame: B's vertices are moved there first, its normals only once A's faces
    // found no separating axis, so separated pairs skip that work.
    const __m128 xf = invMulLanes(frame, xfB);
    const __m128 c = splat<2>(xf);
    const __m128 s = splat<3>(xf);
    Lanes<GB> vertsB = rotateLanes(loadLanes<GB>(b.vertices.data(), b.count), c, s);
    const __m128 tx = splat<0>(xf);
    const __m128 ty = splat<1>(xf);
    for (int g = 0; g < GB; ++g) {
        vertsB.x[g] = _mm_add_ps(vertsB.x[g], tx);
        vertsB.y[g] = _mm_add_ps(vertsB.y[g], ty);
    }
    Lanes<GA> vertsA = loadLanes<GA>(a.vertices.data(), a.count);
    if (shift) [[unlikely]] {
        const __m128 ox = _mm_set1_ps(origin.x);
        const __m128 oy = _mm_set1_ps(origin.y);
        for (int g = 0; g < GA; ++g) {
            vertsA.x[g] = _mm_sub_ps(vertsA.x[g], ox);
            vertsA.y[g] = _mm_sub_ps(vertsA.y[g], oy);
        }
    }
    const Lanes<GA> normalsA = loadLanes<GA>(a.normals.data(), a.count);
    __m128 offsetA[GA];
    dotLanes(normalsA, vertsA, offsetA);

    const float limit = margin + (a.radius + b.radius);
    const EdgeSeparation sepA = findMaxSeparation(normalsA, offsetA, vertsB);
    if (sepA.separation > limit) {
        return Manifold{};
    }
    const Lanes<GB> normalsB = rotateLanes(loadLanes<GB>(b.normals.data(), b.count), c, s);
    __m128 offsetB[GB];
    dotLanes(normalsB, vertsB, offsetB);
    const EdgeSeparation sepB = findMaxSeparation(normalsB, offsetB, vertsA);
    if (sepB.separation > limit) {
        return Manifold{};
    }

    // The tail works on arrays, as the GJK/EPA path does.
    detail::PolygonScratch movedB;
    storeLanes(vertsB, movedB.vertices);
    storeLanes(normalsB, movedB.normals);
    const PolygonRef localB{movedB.vertices, movedB.normals, b.radius, b.count};
    PolygonRef localA = detail::refOf(a);
    detail::PolygonScratch movedA;
    if (shift) [[unlikely]] {
        storeLanes(vertsA, movedA.vertices);
        localA.vertices = movedA.vertices;
    }
    const bool flip = sepB.separation > sepA.separation + kFlipTolerance;
    const int edge1 = flip ? sepB.edge : sepA.edge;
    const int incident = flip ? findIncidentEdge(movedB.normals[edge1], normalsA)
                              : findIncidentEdge(a.normals[edge1], normalsB);
    LocalManifold m = contactOnAxis(localA, localB, margin, sepA, sepB, flip, edge1, incident,
                                    flip ? sepB.separation : sepA.separation);
    if (shift) [[unlikely]] {
        for (int i = 0; i < m.count; ++i) {
            m.points[i] += origin;
        }
    }
    return detail::localToWorld(m, xfA, xfB);
}

#else

// The edge of poly1 whose normal separates poly2 the most (the least penetration). Every edge
// is tested and the best one kept by selects, not branches: which edge wins (or first
// separates a separated pair) is random from pair to pair, and stopping early at that edge
// cost a mispredicted branch per call, more than the edges it skipped.
//
// min_j dot(n, w_j - v) is computed as min_j dot(n, w_j) - dot(n, v): subtracting one number
// preserves the order of rounded values, so the same vertex is deepest, and the inner loop
// does two products and a sum per vertex, two vertices at a time on independent minima.
inline EdgeSeparation findMaxSeparation(PolygonRef poly1, PolygonRef poly2) {
    EdgeSeparation best;
    const Vec2* w = poly2.vertices;
    const int count2 = poly2.count;
    for (int i = 0; i < poly1.count; ++i) {
        const Vec2 n = poly1.normals[i];
        float min0 = FLT_MAX;
        float min1 = FLT_MAX;
        int j = 0;
        for (; j + 1 < count2; j += 2) {
            const float d0 = dot(n, w[j]);
            const float d1 = dot(n, w[j + 1]);
            min0 = d0 < min0 ? d0 : min0;
            min1 = d1 < min1 ? d1 : min1;
        }
        if (j < count2) {
            const float d0 = dot(n, w[j]);
            min0 = d0 < min0 ? d0 : min0;
        }
        const float si = (min1 < min0 ? min1 : min0) - dot(n, poly1.vertices[i]);
        const bool better = si > best.separation;
        best.edge = better ? i : best.edge;
        best.separation = better ? si : best.separation;
    }
    return best;
}

// The SAT manifold of two polygons given in one frame; each point is in that frame.
// `localB` (B moved to that frame) has its vertices ready; its normals are moved lazily by
// `moveNormals` once A's faces found no separating axis, so separated pairs skip that work.
template <class MoveNormals>
LocalManifold collideInFrame(PolygonRef localA, PolygonRef localB, float margin,
                             MoveNormals&& moveNormals) {
    const float limit = margin + (localA.radius + localB.radius);
    const EdgeSeparation sepA = findMaxSeparation(localA, localB);
    if (sepA.separation > limit) {
        return noContact();
    }
    moveNormals();
    const EdgeSeparation sepB = findMaxSeparation(localB, localA);
    if (sepB.separation > limit) {
        return noContact();
    }

    const bool flip = sepB.separation > sepA.separation + kFlipTolerance;
    const PolygonRef& poly1 = flip ? localB : localA;
    const PolygonRef& poly2 = flip ? localA : localB;
    const int edge1 = flip ? sepB.edge : sepA.edge;

    // The incident edge: the one of poly2 whose normal is most anti-parallel to the reference.
    const int incident = detail::firstMinDot(poly2.normals, poly2.count, poly1.normals[edge1]);
    return contactOnAxis(localA, localB, margin, sepA, sepB, flip, edge1, incident,
                         flip ? sepB.separation : sepA.separation);
}

#endif

} // namespace

Manifold collidePolygons(const Polygon& a, const Transform& xfA, const Polygon& b,
                         const Transform& xfB, float margin) {
#if E2D_SAT_SSE2
    if (a.count > 4) {
        return b.count > 4 ? collideLanes<2, 2>(a, xfA, b, xfB, margin)
                           : collideLanes<2, 1>(a, xfA, b, xfB, margin);
    }
    return b.count > 4 ? collideLanes<1, 2>(a, xfA, b, xfB, margin)
                       : collideLanes<1, 1>(a, xfA, b, xfB, margin);
#else
    // Work in A's frame: B is moved there once (its normals only when they are needed).
    const auto [frame, origin, shift] = workFrameOf(a, xfA);
    const Transform xf = invMulTransforms(frame, xfB);
    detail::PolygonScratch movedB;
    for (int i = 0; i < b.count; ++i) {
        movedB.vertices[i] = transformPoint(xf, b.vertices[i]);
    }
    auto moveNormals = [&] {
        for (int i = 0; i < b.count; ++i) {
            movedB.normals[i] = rotate(xf.q, b.normals[i]);
        }
    };
    const PolygonRef localB{movedB.vertices, movedB.normals, b.radius, b.count};
    PolygonRef localA = detail::refOf(a);
    detail::PolygonScratch movedA;
    if (shift) [[unlikely]] {
        for (int i = 0; i < a.count; ++i) {
            movedA.vertices[i] = a.vertices[i] - origin;
        }
        localA.vertices = movedA.vertices;
    }
    // One call site, so the compiler inlines collideInFrame: a call passing the two
    // PolygonRefs through the stack put a store and a reload on every pair's critical path.
    LocalManifold m = collideInFrame(localA, localB, margin, moveNormals);
    if (shift) [[unlikely]] {
        for (int i = 0; i < m.count; ++i) {
            m.points[i] += origin;
        }
    }
    return detail::localToWorld(m, xfA, xfB);
#endif
}

} // namespace e2d::physics
