// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/geometry.hpp>

#include <cstdint>

/// Contact manifolds: where two shapes touch (or will soon touch), for the solver.
namespace e2d::physics {

/// Which algorithm collides polygon pairs (and rounded polygons). Chosen per world.
enum class CollisionAlgorithm : std::uint8_t {
    Sat,    ///< separating axis test, reference-face clipping (default)
    GjkEpa, ///< GJK distance, EPA penetration, then the same clipping
};

/// One contact point.
struct ManifoldPoint {
    Vec2 point{0.0f, 0.0f};      ///< world point, midway between the two surfaces, metres
    Vec2 anchorA{0.0f, 0.0f};    ///< point relative to shape A's transform origin (world axes)
    Vec2 anchorB{0.0f, 0.0f};    ///< point relative to shape B's transform origin (world axes)
    float separation = 0.0f;     ///< negative when overlapping, metres
    float normalImpulse = 0.0f;  ///< solver's accumulated impulse, kept across steps
    float tangentImpulse = 0.0f; ///< solver's accumulated friction impulse
    std::uint16_t id = 0;        ///< feature id, stable across steps while the same features touch
    bool persisted = false;      ///< set by the world when `id` matched last step's manifold
};

/// Up to two contact points sharing one normal, which points from shape A to shape B.
struct Manifold {
    Vec2 normal{0.0f, 0.0f};
    ManifoldPoint points[2]{};
    int pointCount = 0;
};

/// Builds a feature id from the two features (vertex or edge indices) that made a point.
constexpr std::uint16_t makeFeatureId(int a, int b) {
    return static_cast<std::uint16_t>(((a & 0xFF) << 8) | (b & 0xFF));
}

/// Pair routines. Points farther apart than `margin` (metres, >= 0: the speculative distance)
/// are not reported; pointCount == 0 means no contact within the margin. The shapes are not
/// validated (this is the hot path): pass shapes that validate() accepts.
///
/// Polygon-capsule, segment-polygon and overlapping capsule axes go through collidePolygons()
/// with the capsule or segment as a 2-vertex polygon (rounded by the capsule's radius); a
/// segment is a capsule of radius 0 for the circle and capsule routines. Circle pairs report
/// id 0; capsule pairs use 0/1 for an end and 2 for the side; polygon pairs use vertex indices.
Manifold collideCircles(const Circle& a, const Transform& xfA, const Circle& b,
                        const Transform& xfB, float margin = kSpeculativeDistance);
Manifold collideCapsuleAndCircle(const Capsule& a, const Transform& xfA, const Circle& b,
                                 const Transform& xfB, float margin = kSpeculativeDistance);
Manifold collideCapsules(const Capsule& a, const Transform& xfA, const Capsule& b,
                         const Transform& xfB, float margin = kSpeculativeDistance);
Manifold collidePolygonAndCircle(const Polygon& a, const Transform& xfA, const Circle& b,
                                 const Transform& xfB, float margin = kSpeculativeDistance);
Manifold collidePolygonAndCapsule(const Polygon& a, const Transform& xfA, const Capsule& b,
                                  const Transform& xfB, float margin = kSpeculativeDistance);
/// SAT: best separating axis of both polygons, reference/incident faces, clipping.
Manifold collidePolygons(const Polygon& a, const Transform& xfA, const Polygon& b,
                         const Transform& xfB, float margin = kSpeculativeDistance);
/// GJK for the separated case, EPA for the overlapping one, then reference-face clipping.
Manifold collidePolygonsGjkEpa(const Polygon& a, const Transform& xfA, const Polygon& b,
                               const Transform& xfB, float margin = kSpeculativeDistance);
Manifold collideSegmentAndCircle(const Segment& a, const Transform& xfA, const Circle& b,
                                 const Transform& xfB, float margin = kSpeculativeDistance);
Manifold collideSegmentAndCapsule(const Segment& a, const Transform& xfA, const Capsule& b,
                                  const Transform& xfB, float margin = kSpeculativeDistance);
Manifold collideSegmentAndPolygon(const Segment& a, const Transform& xfA, const Polygon& b,
                                  const Transform& xfB, float margin = kSpeculativeDistance);

/// A chain segment against a circle, capsule or polygon: one-sided and smooth over the joints
/// between segments (see ChainSegment); nothing against a segment or chain segment. Polygon
/// faces are found by SAT whatever the world's algorithm.
Manifold collideChainSegment(const ChainSegment& a, const Transform& xfA, const ShapeGeometry& b,
                             const Transform& xfB, float margin = kSpeculativeDistance);

/// Any pair. The normal points from A to B whatever the order of the shape types; polygon
/// pairs use `algorithm`. Two segments never collide (pointCount == 0).
Manifold collide(const ShapeGeometry& a, const Transform& xfA, const ShapeGeometry& b,
                 const Transform& xfB, CollisionAlgorithm algorithm = CollisionAlgorithm::Sat,
                 float margin = kSpeculativeDistance);

} // namespace e2d::physics
