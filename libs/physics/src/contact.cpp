// SPDX-License-Identifier: MIT
// Contacts: created from new broad-phase pairs, destroyed when the fat boxes part or a shape
// goes, updated by the narrow phase (carrying impulses by feature id) with begin/end and
// sensor events.
#include "contact_solver_wide.hpp"
#include "manifold_circles.hpp"
#include "prefetch.hpp"
#include "world_impl.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <new>
#include <variant>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

namespace e2d::physics {

using detail::kNullIndex;

namespace {

int sideOf(const detail::Contact& c, int bodyIndex) { return c.bodyA == bodyIndex ? 0 : 1; }

constexpr std::size_t kPolygonIndex = static_cast<std::size_t>(ShapeType::Polygon);
constexpr std::size_t kCircleIndex = static_cast<std::size_t>(ShapeType::Circle);

// The circle of a shape known to be one (Contact::circles): std::get_if's test of the
// variant's index, and its load from another cache line of the shape, are left out.
const Circle& knownCircle(const detail::Shape& s) {
    if (s.geometry.index() != kCircleIndex) {
        __builtin_unreachable();
    }
    return *std::get_if<Circle>(&s.geometry);
}

// ContactLinks::proxyKeyA, proxyKeyB and Contact::circles from the contact's shapes.
void copyShapes(detail::Contact& c, detail::ContactLinks& l, const detail::Shape& a,
                const detail::Shape& b) {
    l.proxyKeyA = a.proxyKey;
    l.proxyKeyB = b.proxyKey;
    c.circles = a.geometry.index() == kCircleIndex && b.geometry.index() == kCircleIndex;
}

} // namespace

void World::Impl::createContact(int shapeA, int shapeB) {
    detail::Simulation& s = sim;
    int ci;
    if (!s.freeContacts.empty()) {
        ci = s.freeContacts.back();
        s.freeContacts.pop_back();
    } else {
        ci = static_cast<int>(s.contacts.size());
        s.contacts.emplace_back();
        s.contactLinks.emplace_back();
    }
    const detail::Shape& a = shape(shapeA);
    const detail::Shape& b = shape(shapeB);
    detail::Contact& c = s.contacts[static_cast<std::size_t>(ci)];
    detail::ContactLinks& l = s.contactLinks[static_cast<std::size_t>(ci)];
    c = detail::Contact{};
    l = detail::ContactLinks{};
    l.shapeA = shapeA;
    l.shapeB = shapeB;
    c.bodyA = a.body;
    c.bodyB = b.body;
    copyShapes(c, l, a, b);
    l.idA = shapeId(shapeA);
    l.idB = shapeId(shapeB);
    c.sensor = a.isSensor || b.isSensor;
    c.friction = detail::mixFriction(s.def, a.friction, b.friction);
    c.restitution = detail::mixRestitution(s.def, a.restitution, b.restitution);
    c.rollingResistance = std::max(a.rollingResistance, b.rollingResistance);
    c.touchEvents =
        c.sensor ? a.sensorEvents && b.sensorEvents : a.contactEvents && b.contactEvents;
    c.hitEvents = a.hitEvents && b.hitEvents;
    c.alive = true;
    for (int side = 0; side < 2; ++side) {
        detail::BodyMotion& m = body(side == 0 ? c.bodyA : c.bodyB).motion;
        l.prev[side] = kNullIndex;
        l.next[side] = m.contactHead;
        if (m.contactHead != kNullIndex) {
            const auto head = static_cast<std::size_t>(m.contactHead);
            s.contactLinks[head].prev[sideOf(s.contacts[head], side == 0 ? c.bodyA : c.bodyB)] = ci;
        }
        m.contactHead = ci;
    }
    ++s.contactCount;
}

void World::Impl::copyContactShapes() {
    for (std::size_t i = 0; i < sim.contacts.size(); ++i) {
        detail::Contact& c = sim.contacts[i];
        detail::ContactLinks& l = sim.contactLinks[i];
        if (c.alive) {
            copyShapes(c, l, shape(l.shapeA), shape(l.shapeB));
        }
    }
}

void World::Impl::destroyContact(int contactIndex, bool reportEnd) {
    detail::Simulation& s = sim;
    detail::Contact& c = s.contacts[static_cast<std::size_t>(contactIndex)];
    const detail::ContactLinks& l = s.contactLinks[static_cast<std::size_t>(contactIndex)];
    if (reportEnd && c.touching && c.touchEvents) {
        if (c.sensor) {
            bool aIsSensor = shape(l.shapeA).isSensor;
            (s.inStep ? s.sensorEndEvents : s.pendingSensorEndEvents)
                .push_back(aIsSensor ? SensorEndTouchEvent{l.idA, l.idB}
                                     : SensorEndTouchEvent{l.idB, l.idA});
        } else {
            (s.inStep ? s.endEvents : s.pendingEndEvents).push_back({l.idA, l.idB});
        }
    }
    for (int side = 0; side < 2; ++side) {
        int bodyIndex = side == 0 ? c.bodyA : c.bodyB;
        if (l.prev[side] != kNullIndex) {
            const auto p = static_cast<std::size_t>(l.prev[side]);
            s.contactLinks[p].next[sideOf(s.contacts[p], bodyIndex)] = l.next[side];
        } else {
            body(bodyIndex).motion.contactHead = l.next[side];
        }
        if (l.next[side] != kNullIndex) {
            const auto n = static_cast<std::size_t>(l.next[side]);
            s.contactLinks[n].prev[sideOf(s.contacts[n], bodyIndex)] = l.prev[side];
        }
    }
    c.alive = false;
    s.freeContacts.push_back(contactIndex);
    --s.contactCount;
}

void World::Impl::destroyContacts(int shapeIndex) {
    int bodyIndex = shape(shapeIndex).body;
    int ci = body(bodyIndex).motion.contactHead;
    while (ci != kNullIndex) {
        const detail::Contact& c = sim.contacts[static_cast<std::size_t>(ci)];
        const detail::ContactLinks& l = sim.contactLinks[static_cast<std::size_t>(ci)];
        int next = l.next[sideOf(c, bodyIndex)];
        if (l.shapeA == shapeIndex || l.shapeB == shapeIndex) {
            int other = c.bodyA == bodyIndex ? c.bodyB : c.bodyA;
            // Whatever rested on this shape must notice it is gone.
            if (c.touching) {
                wakeBody(other);
            }
            broadPhase.removePair(static_cast<std::uint64_t>(l.shapeA),
                                  static_cast<std::uint64_t>(l.shapeB));
            destroyContact(ci, true);
        }
        ci = next;
    }
}

namespace {

// A contact's two bodies, as the narrow phase reads them, and its shapes (only looked at when
// the manifold is not recycled: the links and the shape array).
struct ContactSides {
    const detail::ContactLinks& links;
    const detail::Shape* shapes;
    const detail::Body& ba;
    const detail::Body& bb;

    const detail::Shape& shapeA() const { return shapes[links.shapeA]; }
    const detail::Shape& shapeB() const { return shapes[links.shapeB]; }
};

// Recycling is for pairs of polygons and segments, whose routine (SAT or GJK/EPA and clipping)
// is the expensive one. Circle and capsule routines cost less than the recycling's bookkeeping,
// and a rolling round shape's contact point is on no material point of it (a recycled one
// drifts under the shape and tilts its support). Chain segments are one-sided and hand a body
// over to the next segment, which a recycled manifold would not see.
bool isRecyclable(const ShapeGeometry& g) {
    const ShapeType type = typeOf(g);
    return type == ShapeType::Polygon || type == ShapeType::Segment;
}

// SolverDef::contactRecycleDistance, capped at the speculative distance; 0 in classic mode
// (see its doc).
float effectiveRecycleDistance(const SolverDef& def, float speculativeDistance) {
    return def.mode == SolverMode::Classic
               ? 0.0f
               : std::min(def.contactRecycleDistance, speculativeDistance);
}

// The farthest a point of the body's shapes is from its origin, metres.
float extentFromOrigin(const detail::Body& b) {
    return length(b.motion.localCenter) + b.motion.maxExtent;
}

// Notes the manifold just computed for bodies at xfA and xfB, in the bodies' frames.
void recordOrigin(detail::ManifoldOrigin& o, const Manifold& m, const detail::Body& ba,
                  const detail::Body& bb) {
    const Transform& xfA = ba.transform;
    const Transform& xfB = bb.transform;
    o.setFrames(invRotate(xfB.q, xfA.p - xfB.p), invMulTransforms(xfA, xfB));
    o.extentA = extentFromOrigin(ba);
    o.extentB = extentFromOrigin(bb);
    o.normalInA = invRotate(xfA.q, m.normal);
    for (int i = 0; i < m.pointCount; ++i) {
        const ManifoldPoint& mp = m.points[i];
        const Vec2 half = (0.5f * mp.separation) * m.normal;
        o.surfaceA[i] = invRotate(xfA.q, mp.anchorA - half);
        o.surfaceB[i] = invRotate(xfB.q, mp.anchorB + half);
    }
}

#if defined(__SSE2__)

// The recycle path is most of a resting pile's narrow phase, so it is written for SSE2: the
// motion bound with its three 2-vectors' x and y components in two registers, the move with
// two points a register. Every lane does the scalar code's operations (below) on the same
// operands in the same order (x - y as x + (-y), a + b as b + a; no FMA on the SSE2
// baseline), so the results are bit for bit the scalar ones. Both functions load the two
// transforms whole; inlined together, they share the loads.

static_assert(sizeof(Transform) == 4 * sizeof(float), "Transform is p.x p.y q.c q.s");

// (p.x, p.y, q.c, q.s).
inline __m128 loadTransform(const Transform& xf) { return _mm_loadu_ps(&xf.p.x); }
// (x, y, 0, 0) from two adjacent floats.
inline __m128 loadLow(const float* xy) {
    return _mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(xy));
}
template <int i0, int i1, int i2, int i3>
inline __m128 lanes(__m128 v) {
    return _mm_shuffle_ps(v, v, _MM_SHUFFLE(i3, i2, i1, i0));
}
// (x0, y0, x1, y1) -> (y0, x0, y1, x1).
inline __m128 swapHalves(__m128 v) { return lanes<1, 0, 3, 2>(v); }
// Flips the sign of lanes 0 and 2.
inline __m128 negateEven(__m128 v) { return _mm_xor_ps(v, _mm_setr_ps(-0.0f, 0.0f, -0.0f, 0.0f)); }
inline void storeLow(Vec2& to, __m128 v) { _mm_storel_pi(reinterpret_cast<__m64*>(&to.x), v); }
inline void storeHigh(Vec2& to, __m128 v) { _mm_storeh_pi(reinterpret_cast<__m64*>(&to.x), v); }

// How far any point of one body has moved relative to the other since the origin was noted, at
// most: the translation of one body's origin in the other's frame plus the chord the relative
// rotation turns the farthest point through (the smaller bound of the two ways round).
// Computed in the lanes of ManifoldOrigin::frame's rows (A's origin in B's frame, B's origin in
// A's frame, B's rotation in A's frame; lane 3 unused): x rows c u + s v, y rows c v - s u.
inline float motionSince(const detail::ManifoldOrigin& o, const Transform& xfA,
                         const Transform& xfB) {
    const __m128 a = loadTransform(xfA);
    const __m128 b = loadTransform(xfB);
    const __m128 p = _mm_unpacklo_ps(a, b);                         // pAx pBx pAy pBy
    const __m128 q = _mm_unpackhi_ps(a, b);                         // cA cB sA sB
    const __m128 d = _mm_sub_ps(p, lanes<1, 0, 3, 2>(p));           // x: pA - pB, pB - pA; y: same
    const __m128 u = _mm_shuffle_ps(d, q, _MM_SHUFFLE(3, 1, 1, 0)); // dx(A-B) dx(B-A) cB
    const __m128 v = _mm_shuffle_ps(d, q, _MM_SHUFFLE(3, 3, 3, 2)); // dy(A-B) dy(B-A) sB
    const __m128 c = lanes<1, 0, 0, 0>(q);                          // cB cA cA
    const __m128 s = lanes<3, 2, 2, 2>(q);                          // sB sA sA
    const __m128 x =
        _mm_sub_ps(_mm_add_ps(_mm_mul_ps(c, u), _mm_mul_ps(s, v)), _mm_loadu_ps(o.frame));
    const __m128 y =
        _mm_sub_ps(_mm_sub_ps(_mm_mul_ps(c, v), _mm_mul_ps(s, u)), _mm_loadu_ps(o.frame + 3));
    // |A moved in B|, |B moved in A|, the chord; then + chord (extentA, extentB). std::min(b, a)
    // is minss(a, b), which keeps the second on a tie or a NaN as std::min does.
    const __m128 lengths = _mm_sqrt_ps(_mm_add_ps(_mm_mul_ps(x, x), _mm_mul_ps(y, y)));
    const __m128 bounds =
        _mm_add_ps(lengths, _mm_mul_ps(lanes<2, 2, 2, 2>(lengths), loadLow(&o.extentA)));
    return _mm_cvtss_f32(_mm_min_ss(bounds, lanes<1, 1, 1, 1>(bounds)));
}

// The noted manifold moved with the bodies: each point's two surface points where the bodies
// now carry them, the point midway, the separation along the normal (which turns with A).
// Impulses and feature ids stay. Both points are moved in one register.
inline void recycleManifold(Manifold& m, const detail::ManifoldOrigin& o, const Transform& xfA,
                            const Transform& xfB) {
    const __m128 a = loadTransform(xfA);
    const __m128 b = loadTransform(xfB);
    // rotate(q, v) = c v + (-s, s) (v.y, v.x).
    const __m128 cA = lanes<2, 2, 2, 2>(a);
    const __m128 sA = negateEven(lanes<3, 3, 3, 3>(a));
    const __m128 cB = lanes<2, 2, 2, 2>(b);
    const __m128 sB = negateEven(lanes<3, 3, 3, 3>(b));
    const __m128 normalInA = loadLow(&o.normalInA.x);
    const __m128 normal =
        _mm_add_ps(_mm_mul_ps(cA, normalInA), _mm_mul_ps(sA, swapHalves(normalInA)));
    storeLow(m.normal, normal);
    // Read once: the stores below may alias it as far as the compiler knows.
    const int pointCount = m.pointCount;
    if (pointCount == 0) {
        return;
    }
    const __m128 pA = _mm_movelh_ps(a, a);
    const __m128 offset = _mm_sub_ps(_mm_movelh_ps(b, b), pA);
    const __m128 surfaceA = _mm_loadu_ps(&o.surfaceA[0].x);
    const __m128 surfaceB = _mm_loadu_ps(&o.surfaceB[0].x);
    const __m128 onA = _mm_add_ps(_mm_mul_ps(cA, surfaceA), _mm_mul_ps(sA, swapHalves(surfaceA)));
    const __m128 onB = _mm_add_ps(_mm_mul_ps(cB, surfaceB), _mm_mul_ps(sB, swapHalves(surfaceB)));
    const __m128 gap = _mm_sub_ps(_mm_add_ps(offset, onB), onA);
    const __m128 anchorA = _mm_add_ps(onA, _mm_mul_ps(_mm_set1_ps(0.5f), gap));
    const __m128 anchorB = _mm_sub_ps(anchorA, offset);
    const __m128 point = _mm_add_ps(pA, anchorA);
    const __m128 products = _mm_mul_ps(gap, _mm_movelh_ps(normal, normal));
    const __m128 separation = _mm_add_ps(products, swapHalves(products)); // lanes 0 and 2
    ManifoldPoint& p0 = m.points[0];
    storeLow(p0.point, point);
    storeLow(p0.anchorA, anchorA);
    storeLow(p0.anchorB, anchorB);
    _mm_store_ss(&p0.separation, separation);
    p0.persisted = true;
    if (pointCount == 2) {
        ManifoldPoint& p1 = m.points[1];
        storeHigh(p1.point, point);
        storeHigh(p1.anchorA, anchorA);
        storeHigh(p1.anchorB, anchorB);
        _mm_store_ss(&p1.separation, _mm_movehl_ps(separation, separation));
        p1.persisted = true;
    }
}

#else

// How far any point of one body has moved relative to the other since the origin was noted, at
// most: the translation of one body's origin in the other's frame plus the chord the relative
// rotation turns the farthest point through (the smaller bound of the two ways round).
float motionSince(const detail::ManifoldOrigin& o, const Transform& xfA, const Transform& xfB) {
    const Transform bInA = invMulTransforms(xfA, xfB);
    const Vec2 aInB = invRotate(xfB.q, xfA.p - xfB.p);
    const Transform bInA0 = o.bInA();
    const float chord = length(Vec2{bInA.q.c - bInA0.q.c, bInA.q.s - bInA0.q.s});
    return std::min(length(bInA.p - bInA0.p) + chord * o.extentB,
                    length(aInB - o.aInB()) + chord * o.extentA);
}

// The noted manifold moved with the bodies: each point's two surface points where the bodies
// now carry them, the point midway, the separation along the normal (which turns with A).
// Impulses and feature ids stay.
void recycleManifold(Manifold& m, const detail::ManifoldOrigin& o, const Transform& xfA,
                     const Transform& xfB) {
    m.normal = rotate(xfA.q, o.normalInA);
    const Vec2 offset = xfB.p - xfA.p;
    for (int i = 0; i < m.pointCount; ++i) {
        ManifoldPoint& mp = m.points[i];
        const Vec2 a = rotate(xfA.q, o.surfaceA[i]);
        const Vec2 gap = offset + rotate(xfB.q, o.surfaceB[i]) - a;
        mp.anchorA = a + 0.5f * gap;
        mp.anchorB = mp.anchorA - offset;
        mp.point = xfA.p + mp.anchorA;
        mp.separation = dot(gap, m.normal);
        mp.persisted = true;
    }
}

#endif

// What collideContact() found: whether the manifold has points, and whether it was recycled.
enum Collided : unsigned char { kNoPoints = 0, kPoints = 1, kRecycled = 2 };

// How fast the pair can close, at most (m/s): the relative speed of the origins plus each
// body's fastest turning point.
inline float closingSpeed(const detail::Body& ba, const detail::Body& bb) {
    const Vec2 v = bb.linearVelocity - ba.linearVelocity;
#if defined(__SSE2__)
    // length(v) with sqrtss itself: std::sqrt's check for a negative argument (for errno),
    // a compare and a branch around it, goes. (The square in every lane: _mm_set_ss's zeroed
    // upper lanes cost GCC a round trip through a general register.)
    const float speed = _mm_cvtss_f32(_mm_sqrt_ss(_mm_set1_ps(v.x * v.x + v.y * v.y)));
#else
    const float speed = length(v);
#endif
    return speed + std::abs(ba.angularVelocity) * ba.motion.maxExtent +
           std::abs(bb.angularVelocity) * bb.motion.maxExtent;
}

// Speculative margin: the fixed one plus how far the pair can close in one step, so a fast
// approach is caught before it overlaps (bounded, as a huge margin would stop bodies against
// points they would have passed).
inline float speculativeMargin(float speculativeDistance, float dt, float closing) {
    return std::min(speculativeDistance + dt * closing, 4.0f * kAabbMargin);
}

// Last step's impulses of one point by feature id (-1: no point), kept aside so that the new
// manifold can be built in place, without a 92-byte copy.
struct OldPoint {
    int id;
    float normalImpulse;
    float tangentImpulse;
};
struct OldPoints {
    OldPoint p0;
    OldPoint p1;
};

inline OldPoints oldPoints(const Manifold& old) {
    return {{old.pointCount > 0 ? old.points[0].id : -1, old.points[0].normalImpulse,
             old.points[0].tangentImpulse},
            {old.pointCount > 1 ? old.points[1].id : -1, old.points[1].normalImpulse,
             old.points[1].tangentImpulse}};
}

// Impulses carry over from the first old point with the same id.
inline void carryImpulses(Manifold& m, const OldPoints& old) {
    for (int i = 0; i < m.pointCount; ++i) {
        ManifoldPoint& mp = m.points[i];
        const OldPoint* match = mp.id == old.p0.id   ? &old.p0
                                : mp.id == old.p1.id ? &old.p1
                                                     : nullptr;
        mp.normalImpulse = match != nullptr ? match->normalImpulse : 0.0f;
        mp.tangentImpulse = match != nullptr ? match->tangentImpulse : 0.0f;
        mp.persisted = match != nullptr;
    }
}

#if defined(__SSE2__)

// collideContact() for two circles with no noted origin (circle pairs are never recycled): the
// old impulses are only looked at for circles within the margin, and nothing else is.
[[gnu::always_inline]] inline unsigned collideCircleContact(detail::Contact& c, const Circle& a,
                                                            const Circle& b, const detail::Body& ba,
                                                            const detail::Body& bb,
                                                            float speculativeDistance, float dt) {
    const detail::CircleGapSse2 gap = detail::circleGapSse2(a, ba.transform, b, bb.transform);
    if (gap.beyond(speculativeMargin(speculativeDistance, dt, closingSpeed(ba, bb)))) {
        detail::storeNoManifoldSse2(c.manifold);
        return kNoPoints;
    }
    const OldPoints old = oldPoints(c.manifold);
    detail::storeCircleManifoldSse2(gap, a, c.manifold);
    carryImpulses(c.manifold, old);
    return kPoints;
}

#endif

// Whether a sensor contact's shapes overlap (a sensor keeps no manifold).
bool sensorOverlaps(const ContactSides& sides, CollisionAlgorithm collisionAlgorithm) {
    const Manifold m = collide(sides.shapeA().geometry, sides.ba.transform, sides.shapeB().geometry,
                               sides.bb.transform, collisionAlgorithm, 0.0f);
    return m.pointCount > 0;
}

// World::Impl::updateManifold() of a solid (not sensor) contact on sides already looked up:
// forced inline into the parallel pass's loop, which has just read them (the call and the
// second lookup cost about 30 instructions a contact).
[[gnu::always_inline]] inline unsigned collideContact(detail::Contact& c, const ContactSides& sides,
                                                      CollisionAlgorithm collisionAlgorithm,
                                                      float speculativeDistance,
                                                      float recycleDistance, float dt) {
    const detail::Body& ba = sides.ba;
    const detail::Body& bb = sides.bb;
    // Recycling: the old manifold moved with the bodies while they, with this step's motion at
    // the current speeds, stay within the distance of where the routine last saw them. Most of
    // a resting pile's contacts end here, without a look at their shapes.
    detail::ManifoldOrigin& origin = c.origin;
    float closing;
    if (c.originValid) {
        closing = closingSpeed(ba, bb);
        if (recycleDistance > 0.0f &&
            motionSince(origin, ba.transform, bb.transform) + dt * closing <= recycleDistance) {
            const unsigned points = c.manifold.pointCount > 0 ? kPoints : kNoPoints;
            recycleManifold(c.manifold, origin, ba.transform, bb.transform);
            return kRecycled | points;
        }
        c.originValid = false;
    } else {
        const detail::Shape& sa = sides.shapeA();
        const detail::Shape& sb = sides.shapeB();
#if defined(__SSE2__)
        if (c.circles) {
            return collideCircleContact(c, knownCircle(sa), knownCircle(sb), ba, bb,
                                        speculativeDistance, dt);
        }
#endif
        closing = closingSpeed(ba, bb);
    }
    const detail::Shape& sa = sides.shapeA();
    const detail::Shape& sb = sides.shapeB();
    const float margin = speculativeMargin(speculativeDistance, dt, closing);
    const OldPoints old = oldPoints(c.manifold);
    const std::size_t type = sa.geometry.index();
    const bool sameType = type == sb.geometry.index();
    // Polygon pairs (most of a box scene) and circle pairs (most of a ball pit) call their
    // routine directly, skipping collide()'s dispatch on both geometries (about 30
    // instructions a circle pair). The routine's result initialises c.manifold directly.
    Manifold& m = *::new (&c.manifold) Manifold(
        sameType && type == kPolygonIndex && collisionAlgorithm == CollisionAlgorithm::Sat
            ? collidePolygons(*std::get_if<Polygon>(&sa.geometry), ba.transform,
                              *std::get_if<Polygon>(&sb.geometry), bb.transform, margin)
        : sameType && type == kCircleIndex
            ? collideCircles(*std::get_if<Circle>(&sa.geometry), ba.transform,
                             *std::get_if<Circle>(&sb.geometry), bb.transform, margin)
            : collide(sa.geometry, ba.transform, sb.geometry, bb.transform, collisionAlgorithm,
                      margin));
    carryImpulses(m, old);
    if (recycleDistance > 0.0f && isRecyclable(sa.geometry) && isRecyclable(sb.geometry)) {
        recordOrigin(origin, m, ba, bb);
        c.originValid = true;
    }
    return m.pointCount > 0 ? kPoints : kNoPoints;
}

// What the narrow phase's first pass found of a contact for its second (see
// World::Impl::updateContacts()).
enum NarrowUpdate : unsigned char { kApart, kAsleep, kTouching, kApartNow };

constexpr int kBlock = detail::Simulation::kNarrowBlock;
// How far ahead the first pass asks for a contact's bodies and shapes (where it does).
constexpr int kPrefetchAhead = 6;
// What the first pass reads of a body: the fields up to BodyMotion::awake (see Body).
constexpr std::size_t kBodyBytesRead =
    offsetof(detail::Body, motion) + offsetof(detail::BodyMotion, awake) + sizeof(bool);
static_assert(offsetof(detail::Body, type) < kBodyBytesRead &&
                  offsetof(detail::BodyMotion, maxExtent) < offsetof(detail::BodyMotion, awake),
              "the body fields the narrow phase reads come first (Body)");

// The narrow phase's first pass (World::Impl::updateContacts()): the arrays it reads and
// writes and the step's settings.
struct NarrowPass {
    detail::Contact* contacts;
    const detail::ContactLinks* links;
    unsigned char* updates; // per contact slot in `serial`: a NarrowUpdate
    detail::Simulation::TouchingContact* touchingSlots;
    int* serialSlots;
    detail::Simulation::NarrowBlock* blocks;
    const detail::Shape* shapeSlots;
    const detail::Body* bodySlots;
    const detail::BroadPhase* broadPhase;
    CollisionAlgorithm algorithm;
    float speculative;
    float stepDt;
    float recycleDistance;
    int contactSlots;
    // With the pre-solve hook set, every update goes through the second pass (the hook is
    // called there, in contact order, and sees the others as they were).
    bool serialAll;
    // The fat-box test (about 26 instructions a contact) only where a fat box changed since it
    // last ran: in a resting pile, no proxy moves for many steps.
    bool testBoxes;
};

// The first pass over blocks [firstBlock, endBlock), with prefetches if kPrefetch (a separate
// loop without them: the test for them was 3 instructions a contact). `p` is taken by value
// and its fields read into locals: each contact's store to `updates` (a char, which may alias
// anything) made the compiler load them from memory again for every contact.
template <bool kPrefetch>
[[gnu::always_inline]] inline void narrowPass(const NarrowPass p, int firstBlock, int endBlock) {
    using TouchingContact = detail::Simulation::TouchingContact;
    detail::Contact* const contacts = p.contacts;
    const detail::ContactLinks* const links = p.links;
    unsigned char* const updates = p.updates;
    TouchingContact* const touchingSlots = p.touchingSlots;
    int* const serialSlots = p.serialSlots;
    detail::Simulation::NarrowBlock* const blocks = p.blocks;
    const detail::Shape* const shapeSlots = p.shapeSlots;
    const detail::Body* const bodySlots = p.bodySlots;
    const detail::BroadPhase& bp = *p.broadPhase;
    const CollisionAlgorithm algorithm = p.algorithm;
    const float speculative = p.speculative;
    const float stepDt = p.stepDt;
    const float recycleDistance = p.recycleDistance;
    const bool serialAll = p.serialAll;
    const bool testBoxes = p.testBoxes;
    const int prefetchEnd = std::min(endBlock * kBlock, p.contactSlots);
    for (int b = firstBlock; b < endBlock; ++b) {
        const int begin = b * kBlock;
        const int end = std::min(begin + kBlock, p.contactSlots);
        TouchingContact* touching = touchingSlots + begin;
        int* serial = serialSlots + begin;
        detail::Simulation::NarrowBlock counts;
        for (int ci = begin; ci < end; ++ci) {
            if constexpr (kPrefetch) {
                if (ci + kPrefetchAhead < prefetchEnd) {
                    const detail::Contact& ahead = contacts[ci + kPrefetchAhead];
                    if (ahead.alive) {
                        detail::prefetchFirst<kBodyBytesRead>(bodySlots + ahead.bodyA);
                        detail::prefetchFirst<kBodyBytesRead>(bodySlots + ahead.bodyB);
                        // A manifold moved with its bodies reads no shape.
                        if (!ahead.originValid) {
                            const detail::ContactLinks& l = links[ci + kPrefetchAhead];
                            detail::prefetchObject(shapeSlots + l.shapeA);
                            detail::prefetchObject(shapeSlots + l.shapeB);
                        }
                    }
                }
            }
            detail::Contact& c = contacts[ci];
            if (!c.alive) {
                continue;
            }
            unsigned char update;
            const detail::Body& ba = bodySlots[c.bodyA];
            const detail::Body& bb = bodySlots[c.bodyB];
            if (testBoxes && !bp.fatAabbsOverlapLive(links[ci].proxyKeyA, links[ci].proxyKeyB)) {
                update = kApart;
            } else if (!ba.motion.awake && !bb.motion.awake) {
                // Settled unless an earlier contact wakes a side in the second pass.
                if (c.touching && !c.sensor && c.enabled) {
                    *touching++ = {ci, c.bodyA, c.bodyB, c.rollingResistance};
                }
                update = kAsleep;
            } else if (c.sensor) {
                // Overlap only: no manifold is kept and no body woken.
                const bool nowTouching = sensorOverlaps({links[ci], shapeSlots, ba, bb}, algorithm);
                ++counts.manifoldUpdates;
                if (serialAll || (nowTouching != c.touching && c.touchEvents)) {
                    update = nowTouching ? kTouching : kApartNow;
                } else {
                    c.touching = nowTouching;
                    continue;
                }
            } else {
                const unsigned collided =
                    collideContact(c, {links[ci], shapeSlots, ba, bb}, algorithm, speculative,
                                   recycleDistance, stepDt);
                ++counts.manifoldUpdates;
                counts.manifoldsRecycled += (collided & kRecycled) != 0 ? 1 : 0;
                const bool nowTouching = (collided & kPoints) != 0;
                // Something awake touching a sleeping body that can wake.
                const bool awakeA = ba.motion.awake;
                const bool wakes = nowTouching && awakeA != bb.motion.awake &&
                                   (awakeA ? bb : ba).type != BodyType::Static;
                if (serialAll || wakes || (nowTouching != c.touching && c.touchEvents)) {
                    update = nowTouching ? kTouching : kApartNow;
                } else {
                    // Stored only when they change: a store dirties the contact's last
                    // cache line (its origin and flags), which a recycled manifold leaves
                    // clean, and so adds a line's write-back per contact.
                    if (c.touching != nowTouching) {
                        c.touching = nowTouching;
                    }
                    if (!c.enabled) {
                        c.enabled = true;
                    }
                    if (nowTouching) {
                        *touching++ = {ci, c.bodyA, c.bodyB, c.rollingResistance};
                    }
                    continue;
                }
            }
            updates[ci] = update;
            *serial++ = ci;
        }
        counts.touching = static_cast<int>(touching - (touchingSlots + begin));
        counts.serial = static_cast<int>(serial - (serialSlots + begin));
        blocks[b] = counts;
    }
}
template <bool kPrefetch>
void narrowPassSse2(const NarrowPass& p, int firstBlock, int endBlock) {
    narrowPass<kPrefetch>(p, firstBlock, endBlock);
}
#if defined(E2D_HAS_WIDE8)
template <bool kPrefetch>
__attribute__((target("avx2"))) void narrowPassAvx2(const NarrowPass& p, int firstBlock,
                                                    int endBlock) {
    narrowPass<kPrefetch>(p, firstBlock, endBlock);
}
#endif

} // namespace

// The narrow phase of one contact whose bodies are not both asleep: its new manifold (kept, with
// impulses carried over by feature id; a sensor's is not kept) and whether it touches. Reads the
// contact's shapes and bodies only, so contacts are updated on several workers at once.
bool World::Impl::updateManifold(detail::Contact& c, const detail::ContactLinks& links,
                                 float dt) const {
    const ContactSides sides{links, shapes.data(), body(c.bodyA), body(c.bodyB)};
    if (c.sensor) {
        return sensorOverlaps(sides, collisionAlgorithm);
    }
    return (collideContact(c, sides, collisionAlgorithm, speculativeDistance,
                           effectiveRecycleDistance(sim.def, speculativeDistance), dt) &
            kPoints) != 0;
}

void World::Impl::updateContacts(float dt) {
    detail::Simulation& s = sim;
    // Pair finding on several workers unless the game's pair filter is set (its code is
    // called from the stepping thread only; shouldPair() alone only reads).
    broadPhase.updatePairs(
        [this](std::uint64_t a, std::uint64_t b) {
            return shouldPair(static_cast<int>(a), static_cast<int>(b));
        },
        [this](std::uint64_t ud) { return pairQueryMask(static_cast<int>(ud)); },
        hooks.pairFilter ? nullptr : &tasks);
    for (const detail::ProxyPair& p : broadPhase.newPairs()) {
        createContact(static_cast<int>(p.userDataA), static_cast<int>(p.userDataB));
    }

    // The narrow phase in two passes. The first updates each contact on its own (on several
    // workers): whether the fat boxes parted, and the new manifold of every contact with an
    // awake side. A contact whose update nothing else sees (no event, no hook, no body to wake)
    // is settled there; the others are noted for the second pass, which goes through them in
    // contact order, alone: ends, events, the pre-solve hook and waking, which other contacts
    // see. A contact whose bodies were both asleep in the first pass and that an earlier contact
    // woke is updated there, as it would have been in one pass in contact order. Settling a
    // contact early changes nothing the second pass reads: waking only follows contacts to
    // sleeping bodies, and a contact the first pass updated had an awake side.
    using TouchingContact = detail::Simulation::TouchingContact;
    const int contactSlots = static_cast<int>(s.contacts.size());
    const int blockCount = (contactSlots + kBlock - 1) / kBlock;
    s.contactUpdates.resize(static_cast<std::size_t>(contactSlots));
    s.blockTouching.resize(static_cast<std::size_t>(contactSlots));
    s.blockSerial.resize(static_cast<std::size_t>(contactSlots));
    s.narrowBlocks.resize(static_cast<std::size_t>(blockCount));
    // Each contact reads two bodies and (unless its manifold is recycled) two shapes scattered
    // over the body and shape arrays: where these are larger than a core's own cache, they are
    // fetched a few contacts ahead (many_pyramids: about -6 % narrow-phase time). Where they
    // fit, the prefetches only cost their instructions (47 a contact when this was measured,
    // about 20 since only a body's first line or two are asked for; falling_circles_1000: -5 %
    // instructions a step and faster without them, and still so with the contact arrays counted
    // in the sizes), so they are left out.
    const bool prefetch =
        shapes.size() * sizeof(detail::Shape) + bodies.size() * sizeof(detail::Body) >
        detail::kPrefetchBytes;
    const NarrowPass pass{s.contacts.data(),
                          s.contactLinks.data(),
                          s.contactUpdates.data(),
                          s.blockTouching.data(),
                          s.blockSerial.data(),
                          s.narrowBlocks.data(),
                          shapes.data(),
                          bodies.data(),
                          &broadPhase,
                          collisionAlgorithm,
                          speculativeDistance,
                          dt,
                          effectiveRecycleDistance(s.def, speculativeDistance),
                          contactSlots,
                          static_cast<bool>(hooks.preSolve),
                          broadPhase.fatBoxChanges() != s.fatBoxChangesTested};
    s.fatBoxChangesTested = broadPhase.fatBoxChanges();
    // The same loop compiled for AVX2 where the solver may use eight lanes (the CPU has them and
    // WorldDef::simdLanes allows them; VEX encodings: about 12 % fewer instructions, no register
    // copies; the same operations, so the same bits, and no FMA).
#if defined(E2D_HAS_WIDE8)
    const bool avx2 = std::min(detail::bestWideLanes(), s.simdLanes) == 8;
#else
    const bool avx2 = false;
#endif
    auto updateBlocks = [&](int firstBlock, int endBlock, int /*worker*/) {
#if defined(E2D_HAS_WIDE8)
        if (avx2) {
            (prefetch ? narrowPassAvx2<true> : narrowPassAvx2<false>)(pass, firstBlock, endBlock);
            return;
        }
#endif
        (void)avx2;
        (prefetch ? narrowPassSse2<true> : narrowPassSse2<false>)(pass, firstBlock, endBlock);
    };
    // A block is 64 contacts of 25 (circles) to 55 ns (boxes).
    tasks.parallelFor(blockCount, tasks.minRange(30 * kBlock), updateBlocks);

    // The touching solid contacts, in contact order, as they are after the narrow phase: what
    // the solver makes constraints of (without streaming the whole contact array again). Each
    // block's settled ones, with the contacts of the second pass in between. (Cleared below
    // where it is rebuilt by appending: resized in place, last step's entries are not built
    // anew before they are overwritten.)
    auto listTouching = [&](int ci, const detail::Contact& c) {
        if (c.touching && !c.sensor && c.enabled) {
            s.touchingContacts.push_back({ci, c.bodyA, c.bodyB, c.rollingResistance});
        }
    };
    // The second pass's work on one contact; whether it woke a body.
    auto finishContact = [&](int ci, unsigned char update) {
        detail::Contact& c = s.contacts[static_cast<std::size_t>(ci)];
        const detail::ContactLinks& l = s.contactLinks[static_cast<std::size_t>(ci)];
        if (update == kApart) {
            broadPhase.removePair(static_cast<std::uint64_t>(l.shapeA),
                                  static_cast<std::uint64_t>(l.shapeB));
            destroyContact(ci, true);
            return false;
        }
        const bool awakeA = body(c.bodyA).motion.awake;
        const bool awakeB = body(c.bodyB).motion.awake;
        if (update == kAsleep) {
            // Woken by an earlier one.
            update = updateManifold(c, l, dt) ? kTouching : kApartNow;
            ++s.counters.manifoldUpdates;
        }
        const bool wasTouching = c.touching;
        c.touching = update == kTouching;
        if (c.sensor) {
            if (c.touching != wasTouching && c.touchEvents) {
                bool aIsSensor = shape(l.shapeA).isSensor;
                ShapeId sensorId = aIsSensor ? l.idA : l.idB;
                ShapeId visitorId = aIsSensor ? l.idB : l.idA;
                if (c.touching) {
                    s.sensorBeginEvents.push_back({sensorId, visitorId});
                } else {
                    s.sensorEndEvents.push_back({sensorId, visitorId});
                }
            }
            return false;
        }
        if (c.touching && !wasTouching && c.touchEvents) {
            s.beginEvents.push_back({l.idA, l.idB, c.manifold});
        } else if (!c.touching && wasTouching && c.touchEvents) {
            s.endEvents.push_back({l.idA, l.idB});
        }
        if (hooks.preSolve) {
            if (c.touching) {
                CallbackLock lock(*this, "step", "pre-solve");
                c.enabled = hooks.preSolve(l.idA, l.idB, c.manifold);
            } else {
                c.enabled = true;
            }
            if (!c.enabled) {
                // Nothing was solved: no impulse to warm start the next step with.
                for (int i = 0; i < c.manifold.pointCount; ++i) {
                    c.manifold.points[i].normalImpulse = 0.0f;
                    c.manifold.points[i].tangentImpulse = 0.0f;
                }
            }
        } else {
            c.enabled = true;
        }
        bool woke = false;
        if (c.touching && awakeA != awakeB) {
            // Something awake touches a sleeping island: it wakes (static bodies never do).
            wakeBody(awakeA ? c.bodyB : c.bodyA);
            woke = true;
        }
        listTouching(ci, c);
        return woke;
    };
    // With nothing for the second pass (a settled scene), the blocks' lists are just put one
    // after the other, on the workers: where each block's goes first, here.
    std::vector<int>& touchingStart = s.narrowTouchingStart;
    touchingStart.resize(static_cast<std::size_t>(blockCount) + 1);
    touchingStart[0] = 0;
    bool anySerial = false;
    for (int b = 0; b < blockCount; ++b) {
        const detail::Simulation::NarrowBlock& block = s.narrowBlocks[static_cast<std::size_t>(b)];
        s.counters.manifoldUpdates += block.manifoldUpdates;
        s.counters.manifoldsRecycled += block.manifoldsRecycled;
        anySerial = anySerial || block.serial > 0;
        touchingStart[static_cast<std::size_t>(b) + 1] =
            touchingStart[static_cast<std::size_t>(b)] + block.touching;
    }
    if (!anySerial) {
        s.touchingContacts.resize(static_cast<std::size_t>(touchingStart.back()));
        auto copyBlocks = [&](int firstBlock, int endBlock, int /*worker*/) {
            for (int b = firstBlock; b < endBlock; ++b) {
                const auto at = static_cast<std::size_t>(b);
                std::copy_n(s.blockTouching.begin() + b * kBlock,
                            touchingStart[at + 1] - touchingStart[at],
                            s.touchingContacts.begin() + touchingStart[at]);
            }
        };
        // A block's list is about 50 ns.
        tasks.parallelFor(blockCount, tasks.minRange(50), copyBlocks);
        return;
    }
    s.touchingContacts.clear();
    // Until a body wakes here, every contact found asleep stays as it was.
    bool anyWoken = false;
    for (int b = 0; b < blockCount; ++b) {
        const detail::Simulation::NarrowBlock& block = s.narrowBlocks[static_cast<std::size_t>(b)];
        const TouchingContact* settled = s.blockTouching.data() + b * kBlock;
        const TouchingContact* const settledEnd = settled + block.touching;
        const int* const serial = s.blockSerial.data() + b * kBlock;
        for (int k = 0; k < block.serial; ++k) {
            const int ci = serial[k];
            const unsigned char update = s.contactUpdates[static_cast<std::size_t>(ci)];
            if (update == kAsleep) {
                const detail::Contact& c = s.contacts[static_cast<std::size_t>(ci)];
                if (!anyWoken || (!body(c.bodyA).motion.awake && !body(c.bodyB).motion.awake)) {
                    continue; // nothing moved, the manifold still holds
                }
            }
            const TouchingContact* before = settled;
            while (before != settledEnd && before->contact < ci) {
                ++before;
            }
            s.touchingContacts.insert(s.touchingContacts.end(), settled, before);
            // A woken contact's entry from when it was asleep: the update lists it anew.
            settled = before != settledEnd && before->contact == ci ? before + 1 : before;
            anyWoken = finishContact(ci, update) || anyWoken;
        }
        s.touchingContacts.insert(s.touchingContacts.end(), settled, settledEnd);
    }
}

} // namespace e2d::physics
