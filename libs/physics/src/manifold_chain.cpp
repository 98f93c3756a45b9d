// SPDX-License-Identifier: MIT
// Chain segments against round shapes and polygons: one-sided, and aware of their neighbours
// (the ghost points), so that a shape sliding over the joint of two segments gets the face
// normal of the surface, not a side or corner normal of the segment ahead (which catches).
//
// The two-sided segment routines find the manifold; this file decides whether the chain
// segment keeps it. Every contact normal n (from the segment to the other shape) lies in the
// front half plane of the segment or is snapped into it. Direction d1 runs point1 -> point2,
// N = rightPerp(d1) is the front normal.
//   - n close to N (|n . d1| <= kFaceSine): a face contact, kept.
//   - n leaning back (n . d1 < 0): the corner at point1. With a neighbour there, that corner
//     belongs to the neighbour (it is its point2), so the contact is dropped; the neighbour's
//     face or corner contact carries the shape. Without one (a free end), kept, as a segment's.
//   - n leaning forward: the corner at point2, owned by this segment. Convex corner: normals
//     between N and the next segment's normal N2 are kept, normals beyond N2 belong to the next
//     segment's face and are dropped. Concave corner: the next segment's face covers the corner,
//     so the contact is snapped to this segment's face normal (clipped against the face).
// A collinear neighbour is a convex corner of zero angle: only N itself survives at the joint,
// which is what makes a chain floor smooth.
#include <e2d/physics/manifold.hpp>

#include "manifold_detail.hpp"
#include "shape_detail.hpp"

#include <cmath>

namespace e2d::physics {
namespace {

// Normals within this sine of the face normal are face contacts (about 0.06 degrees): only
// rounding noise of a true face normal, so a corner normal is never mistaken for one.
constexpr float kFaceSine = 1e-3f;

// Centre of a shape in its own frame: which side of a chain segment the shape is on.
Vec2 centerOf(const ShapeGeometry& g) {
    switch (typeOf(g)) {
    case ShapeType::Circle:
        return std::get<Circle>(g).center;
    case ShapeType::Capsule: {
        const Capsule& c = std::get<Capsule>(g);
        return 0.5f * (c.center1 + c.center2);
    }
    case ShapeType::Polygon:
        return std::get<Polygon>(g).centroid;
    default:
        return {0.0f, 0.0f};
    }
}

// The rounded polygon B (a polygon, or a capsule as a 2-vertex polygon) against the front face
// of segment [p1, p2] with unit normal `normal`, all in A's frame: B's edge facing the segment
// most, clipped to the segment's extent. Points beyond `margin` are dropped.
detail::LocalManifold clipToFace(Vec2 p1, Vec2 p2, Vec2 normal, const Polygon& b, float margin) {
    detail::LocalManifold m;
    m.normal = normal;
    m.count = 0;
    int incident = 0;
    float most = dot(b.normals[0], normal);
    for (int i = 1; i < b.count; ++i) {
        float d = dot(b.normals[static_cast<std::size_t>(i)], normal);
        if (d < most) {
            most = d;
            incident = i;
        }
    }
    const int i1 = incident;
    const int i2 = incident + 1 < b.count ? incident + 1 : 0;
    Vec2 q1 = b.vertices[static_cast<std::size_t>(i1)];
    Vec2 q2 = b.vertices[static_cast<std::size_t>(i2)];
    // Clip [q1, q2] to the slab between p1 and p2 along the segment.
    const Vec2 u = normalize(p2 - p1);
    const float len = dot(p2 - p1, u);
    float a1 = dot(q1 - p1, u);
    float a2 = dot(q2 - p1, u);
    float lo = 0.0f;
    float hi = 1.0f;
    if (a1 != a2) {
        float s0 = -a1 / (a2 - a1);
        float s1 = (len - a1) / (a2 - a1);
        lo = std::fmax(0.0f, std::fmin(s0, s1));
        hi = std::fmin(1.0f, std::fmax(s0, s1));
    } else if (a1 < 0.0f || a1 > len) {
        return m;
    }
    if (lo > hi) {
        return m;
    }
    const float params[2] = {lo, hi};
    const int ids[2] = {i1, i2};
    for (int k = 0; k < 2; ++k) {
        if (k == 1 && hi - lo <= 0.0f) {
            break;
        }
        Vec2 q = q1 + params[k] * (q2 - q1);
        float core = dot(q - p1, normal);
        float separation = core - b.radius;
        if (separation > margin) {
            continue;
        }
        m.points[m.count] = q - (b.radius + 0.5f * separation) * normal;
        m.separations[m.count] = separation;
        m.ids[m.count] = makeFeatureId(0, ids[k]);
        ++m.count;
    }
    return m;
}

// B as a rounded polygon in A's frame (for the snap to the face).
Polygon polygonInFrame(const ShapeGeometry& g, const Transform& bInA) {
    Polygon p;
    if (typeOf(g) == ShapeType::Capsule) {
        const Capsule& c = std::get<Capsule>(g);
        p = detail::makeCapsulePolygon(c.center1, c.center2, c.radius);
    } else {
        p = std::get<Polygon>(g);
    }
    for (int i = 0; i < p.count; ++i) {
        p.vertices[static_cast<std::size_t>(i)] =
            transformPoint(bInA, p.vertices[static_cast<std::size_t>(i)]);
        p.normals[static_cast<std::size_t>(i)] =
            rotate(bInA.q, p.normals[static_cast<std::size_t>(i)]);
    }
    p.centroid = transformPoint(bInA, p.centroid);
    return p;
}

} // namespace

Manifold collideChainSegment(const ChainSegment& a, const Transform& xfA, const ShapeGeometry& b,
                             const Transform& xfB, float margin) {
    const ShapeType tb = typeOf(b);
    if (tb == ShapeType::Segment || tb == ShapeType::ChainSegment) {
        return Manifold{}; // level geometry against level geometry: nothing to push apart
    }
    const Vec2 p1 = a.segment.point1;
    const Vec2 p2 = a.segment.point2;
    const Vec2 d1 = normalize(p2 - p1);
    const Vec2 normal = rightPerp(d1);
    const Transform bInA = invMulTransforms(xfA, xfB);
    const Vec2 center = transformPoint(bInA, centerOf(b));
    // One-sided: a shape whose centre is behind the segment passes through it.
    if (dot(center - p1, normal) < 0.0f) {
        return Manifold{};
    }

    if (tb == ShapeType::Circle) {
        // A circle's normal is the direction from its closest point on the segment, so the
        // corner regions are decided by where the centre is.
        const Vec2 e = p2 - p1;
        const float along = dot(center - p1, e);
        if (along <= 0.0f && a.hasGhost1) {
            return Manifold{}; // point1's corner belongs to the previous segment
        }
        if (along >= dot(e, e) && a.hasGhost2 && dot(center - p2, a.ghost2 - p2) > 0.0f) {
            return Manifold{}; // beyond the start of the next segment: its face holds the circle
        }
        return collideSegmentAndCircle(a.segment, xfA, std::get<Circle>(b), xfB, margin);
    }

    Manifold m = tb == ShapeType::Capsule
                     ? collideSegmentAndCapsule(a.segment, xfA, std::get<Capsule>(b), xfB, margin)
                     : collideSegmentAndPolygon(a.segment, xfA, std::get<Polygon>(b), xfB, margin);
    if (m.pointCount == 0) {
        return m;
    }
    const Vec2 n = invRotate(xfA.q, m.normal);
    const float lean = dot(n, d1);
    bool snap = dot(n, normal) < 0.0f; // pointing behind the face (deep overlap)
    if (!snap && std::fabs(lean) <= kFaceSine) {
        return m;
    }
    if (!snap && lean < 0.0f) {
        if (a.hasGhost1) {
            return Manifold{};
        }
        return m;
    }
    if (!snap) {
        if (!a.hasGhost2) {
            return m;
        }
        const Vec2 d2 = normalize(a.ghost2 - p2);
        const bool convex = cross(d1, d2) >= 0.0f;
        if (convex) {
            // Within the corner's cone the contact is this segment's; beyond the next
            // segment's normal it is that segment's face contact.
            if (dot(n, d2) > kFaceSine) {
                return Manifold{};
            }
            return m;
        }
        snap = true;
    }
    detail::LocalManifold local = clipToFace(p1, p2, normal, polygonInFrame(b, bInA), margin);
    return detail::localToWorld(local, xfA, xfB);
}

} // namespace e2d::physics
