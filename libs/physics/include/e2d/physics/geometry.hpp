// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/constants.hpp>
#include <e2d/physics/math.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <variant>

/// Convex shapes in their local frame, how to build them, and what they weigh.
///
/// Polygons are counter-clockwise (y up, normals point out); points given in either winding
/// are normalised to counter-clockwise.
namespace e2d::physics {

/// A solid disc.
struct Circle {
    Vec2 center{0.0f, 0.0f}; ///< local centre, metres
    float radius = 0.0f;     ///< metres, > 0
};

/// A segment with rounded ends: every point within `radius` of segment [center1, center2].
struct Capsule {
    Vec2 center1{0.0f, 0.0f}; ///< local centre of the first cap, metres
    Vec2 center2{0.0f, 0.0f}; ///< local centre of the second cap, metres
    float radius = 0.0f;      ///< metres, > 0
};

/// A line segment with no thickness (for static level geometry; it has no mass).
struct Segment {
    Vec2 point1{0.0f, 0.0f}; ///< metres
    Vec2 point2{0.0f, 0.0f}; ///< metres
};

/// One segment of a chain (World::createChain() makes them from a list of points): a one-sided
/// segment that knows its neighbours, so that a shape sliding along a chain glides over the
/// joints between segments instead of catching on them.
///
/// One-sided: only the front side collides, the side to the right of the direction
/// segment.point1 -> segment.point2 (normal rightPerp(point2 - point1)). A counter-clockwise
/// loop is therefore solid inside and hit from outside; a floor hit from above runs from right
/// to left. A shape whose centre is behind the segment does not touch it, and rays hit only the
/// front. The ghost points are the neighbouring chain points: ghost1 comes before point1 and
/// ghost2 after point2. Contact normals that belong to a neighbour's side or corner are left to
/// that neighbour. An end without a neighbour (hasGhost1/hasGhost2 false, the free ends of an
/// open chain) is round like a Segment's end. Like a Segment, it has no mass.
struct ChainSegment {
    Segment segment{};       ///< metres
    Vec2 ghost1{0.0f, 0.0f}; ///< the chain point before segment.point1, metres
    Vec2 ghost2{0.0f, 0.0f}; ///< the chain point after segment.point2, metres
    bool hasGhost1 = false;  ///< whether ghost1 is a neighbour. Default false.
    bool hasGhost2 = false;  ///< whether ghost2 is a neighbour. Default false.
};

/// A convex polygon of 3 to kMaxPolygonVertices vertices, counter-clockwise, optionally rounded
/// by `radius` (every point within `radius` of the core polygon). Build it with makePolygon()
/// or makeBox(), which validate; do not fill the fields by hand.
struct Polygon {
    std::array<Vec2, kMaxPolygonVertices> vertices{}; ///< counter-clockwise, local, metres
    std::array<Vec2, kMaxPolygonVertices> normals{};  ///< outward unit normal of edge i -> i+1
    Vec2 centroid{0.0f, 0.0f};                        ///< area centroid, local, metres
    float radius = 0.0f;                              ///< rounding radius, metres, >= 0
    int count = 0;                                    ///< number of vertices
};

/// The convex hull of a point cloud: counter-clockwise, no collinear or near-duplicate points.
struct Hull {
    std::array<Vec2, kMaxPolygonVertices> points{};
    int count = 0;
};

enum class ShapeType : std::uint8_t { Circle, Capsule, Segment, Polygon, ChainSegment };

/// Any one of the shapes; the variant index equals ShapeType.
using ShapeGeometry = std::variant<Circle, Capsule, Segment, Polygon, ChainSegment>;

inline ShapeType typeOf(const ShapeGeometry& g) { return static_cast<ShapeType>(g.index()); }

/// Mass, centre of mass and rotational inertia about the centre of mass.
struct MassData {
    float mass = 0.0f;              ///< kilograms
    Vec2 center{0.0f, 0.0f};        ///< local centre of mass, metres
    float rotationalInertia = 0.0f; ///< about `center`, kg*m^2
};

/// Ray (or translation) in a shape's local frame: from origin to origin + maxFraction * translation.
struct RayCastInput {
    Vec2 origin{0.0f, 0.0f};
    Vec2 translation{0.0f, 0.0f};
    float maxFraction = 1.0f;
};

/// Result of a ray or shape cast. `fraction` is along the input translation.
struct CastOutput {
    Vec2 normal{0.0f, 0.0f}; ///< surface normal at the hit
    Vec2 point{0.0f, 0.0f};  ///< hit point
    float fraction = 0.0f;
    int iterations = 0;
    bool hit = false;
};

/// Convex hull of `points`, welding points closer than kLinearSlop. Throws core::Error naming
/// the problem: fewer than 3 distinct points, all points collinear (zero area), a non-finite
/// coordinate, or more than kMaxPolygonVertices points on the hull.
/// Points within kLinearSlop of the line through their hull neighbours are dropped too. Any
/// winding in, counter-clockwise out. O(n log n) for n points spread out; points bunched
/// within kLinearSlop of each other in x cost more.
Hull computeHull(std::span<const Vec2> points);

/// A polygon from any point cloud (its convex hull), rounded by `radius` (>= 0). Throws core::Error.
Polygon makePolygon(std::span<const Vec2> points, float radius = 0.0f);
/// A polygon from a hull computeHull() returned.
Polygon makePolygon(const Hull& hull, float radius = 0.0f);
/// A box centred on the origin with half-extents hx, hy (> 0, metres). Throws core::Error.
Polygon makeBox(float hx, float hy);
/// A box with half-extents hx, hy, centred at `center` and rotated by `angle` radians.
Polygon makeOffsetBox(float hx, float hy, Vec2 center, float angle);
/// A box whose corners are rounded by `radius`; the outer half-extents are hx + radius, hy + radius.
Polygon makeRoundedBox(float hx, float hy, float radius);

/// Mass properties at `density` (kg/m^2, >= 0). Segments and chain segments have none. Exact for every shape,
/// rounded polygons included (core + edge strips + corner sectors). Throws core::Error for a
/// negative or non-finite density.
MassData computeMass(const Circle& shape, float density);
MassData computeMass(const Capsule& shape, float density);
MassData computeMass(const Polygon& shape, float density);
MassData computeMass(const ShapeGeometry& shape, float density);

/// The tight world box of a shape placed at `xf`.
Aabb computeAabb(const Circle& shape, const Transform& xf);
Aabb computeAabb(const Capsule& shape, const Transform& xf);
Aabb computeAabb(const Segment& shape, const Transform& xf);
Aabb computeAabb(const Polygon& shape, const Transform& xf);
Aabb computeAabb(const ChainSegment& shape, const Transform& xf);
Aabb computeAabb(const ShapeGeometry& shape, const Transform& xf);

/// Whether a local point is inside (or on) the shape. A segment or chain segment contains no
/// point.
bool testPoint(const Circle& shape, Vec2 localPoint);
bool testPoint(const Capsule& shape, Vec2 localPoint);
bool testPoint(const Segment& shape, Vec2 localPoint);
bool testPoint(const Polygon& shape, Vec2 localPoint);
bool testPoint(const ChainSegment& shape, Vec2 localPoint);
bool testPoint(const ShapeGeometry& shape, Vec2 localPoint);

/// Ray casts in the shape's local frame. A ray starting inside a solid shape does not hit it.
/// Segments are two-sided; a chain segment is hit only from its front (a ray going against
/// its normal). Rounded polygons and capsules are cast exactly (offset faces and
/// corner arcs). On a hit, `normal` is the outward surface normal, facing the ray; `iterations`
/// is 0 (no iterative method is used).
CastOutput rayCast(const RayCastInput& input, const Circle& shape);
CastOutput rayCast(const RayCastInput& input, const Capsule& shape);
CastOutput rayCast(const RayCastInput& input, const Segment& shape);
CastOutput rayCast(const RayCastInput& input, const Polygon& shape);
CastOutput rayCast(const RayCastInput& input, const ChainSegment& shape);
CastOutput rayCast(const RayCastInput& input, const ShapeGeometry& shape);

/// Throws core::Error unless every number in the shape is finite and sizes are valid.
/// `function` names the caller in the message. Coordinates and radii must be within kHuge;
/// circle and capsule radii > 0, polygon radius >= 0; polygons 3 to kMaxPolygonVertices
/// vertices, strictly convex, counter-clockwise, with unit normals. A capsule (or segment)
/// whose two points are closer than kLinearSlop is rejected, not turned into a circle: its
/// axis would be undefined, and a Circle says what is meant. A chain segment is checked like
/// a segment, and its ghost points (when present) must be finite and within kHuge.
void validate(const ShapeGeometry& shape, const char* function);

} // namespace e2d::physics
