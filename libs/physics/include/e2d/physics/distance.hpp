// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/constants.hpp>
#include <e2d/physics/geometry.hpp>
#include <e2d/physics/math.hpp>

#include <array>
#include <cstdint>
#include <span>

/// Distance queries between convex shapes seen as point clouds with a radius: GJK distance,
/// EPA penetration and shape casts. Every shape type reduces to a ShapeProxy.
namespace e2d::physics {

/// The most GJK iterations shapeDistance() runs. For two proxies of at most kMaxPolygonVertices
/// points GJK ends well before (it stops when a support point repeats, which bounds it by the
/// number of point pairs); the cap guards against floating-point cycling.
inline constexpr int kMaxGjkIterations = 20;
/// GJK also stops when a new support point brings the simplex closer to the origin by less than
/// this fraction of the coordinates' magnitude (rounding noise; e.g. duplicated points). The
/// reported distance is then within about that much of the exact one.
inline constexpr float kGjkRelativeTolerance = 1.0e-6f;
/// The most EPA iterations penetration() runs (the Minkowski difference of two proxies has at
/// most 2 * kMaxPolygonVertices vertices, so a polytope that grows by one vertex per iteration
/// is complete before this).
inline constexpr int kMaxEpaIterations = 2 * kMaxPolygonVertices + 4;
/// EPA stops when a new support point lies less than this beyond the closest polytope edge,
/// metres. The reported depth is within this of the exact depth.
inline constexpr float kEpaTolerance = 1.0e-5f;
/// The most conservative-advancement steps shapeCast() runs.
inline constexpr int kMaxShapeCastIterations = 30;
/// shapeCast() reports a hit when the (rounded) shapes are closer than this, metres.
inline constexpr float kShapeCastTolerance = 0.1f * kLinearSlop;

/// A convex shape as the convex hull of up to kMaxPolygonVertices points, rounded by `radius`.
struct ShapeProxy {
    std::array<Vec2, kMaxPolygonVertices> points{}; ///< local, metres
    int count = 0;                                  ///< number of points, 1..kMaxPolygonVertices
    float radius = 0.0f;                            ///< rounding radius, metres, >= 0
};

/// A proxy of the given points (1..kMaxPolygonVertices, finite and within kHuge; duplicates
/// are allowed) and radius (finite, 0..kHuge). Throws core::Error naming the bad count or value.
ShapeProxy makeProxy(std::span<const Vec2> points, float radius);
/// Proxies of the shapes, in their local frame (a circle is one point, a capsule or segment two).
ShapeProxy makeProxy(const Polygon& polygon);
ShapeProxy makeProxy(const Circle& circle);
ShapeProxy makeProxy(const Capsule& capsule);
ShapeProxy makeProxy(const Segment& segment);
/// The chain segment's segment (a proxy has no sides).
ShapeProxy makeProxy(const ChainSegment& segment);
ShapeProxy makeProxy(const ShapeGeometry& shape);

/// Warm-start data for shapeDistance(): the support point indices of the last simplex. Zero
/// initialised means "no cache". Keep one per shape pair across steps; it only speeds GJK up,
/// the answer is the same with or without it.
struct SimplexCache {
    std::uint8_t indexA[3]{}; ///< proxy A point indices
    std::uint8_t indexB[3]{}; ///< proxy B point indices
    std::uint8_t count = 0;   ///< number of valid entries, 0..3
};

/// Two placed proxies.
struct DistanceInput {
    ShapeProxy proxyA;
    ShapeProxy proxyB;
    Transform transformA{};
    Transform transformB{};
    bool useRadii = true; ///< measure between the rounded shapes (true) or the core point hulls
};

/// Result of shapeDistance(). Points and normal are in world coordinates.
struct DistanceOutput {
    Vec2 pointA{0.0f, 0.0f}; ///< closest point on A, metres
    Vec2 pointB{0.0f, 0.0f}; ///< closest point on B, metres
    /// Unit vector from A to B along the closest points; (0, 0) when the core hulls overlap
    /// or touch (distance of the cores below ~1e-6 m), where no direction is defined.
    Vec2 normal{0.0f, 0.0f};
    float distance = 0.0f; ///< metres, >= 0; 0 when overlapping
    int iterations = 0;    ///< GJK iterations run
    int simplexCount = 0;  ///< 1 or 2 when separated, 3 when the core hulls overlap
};

/// Closest points of two convex proxies by GJK (2D simplex with Voronoi-region reduction).
/// Runs at most kMaxGjkIterations; ends when a support point repeats, when progress falls
/// below kGjkRelativeTolerance, or when the simplex encloses the origin (overlap). Never returns
/// NaN for finite input, whatever the degeneracy (duplicated points, collinear supports,
/// one-point proxies, identical shapes at the same place). `cache` may be
/// null; if given it warm-starts the search and is updated.
/// With useRadii, rounded shapes whose cores are closer than the sum of radii overlap: distance
/// 0 and pointA == pointB in the middle of the overlap.
DistanceOutput shapeDistance(const DistanceInput& input, SimplexCache* cache = nullptr);

/// Result of penetration(). Points and normal are in world coordinates.
struct PenetrationOutput {
    Vec2 normal{0.0f, 0.0f}; ///< unit, from A to B: moving B by depth * normal separates them
    Vec2 pointA{0.0f, 0.0f}; ///< deepest point of A inside B (on A's surface), metres
    Vec2 pointB{0.0f, 0.0f}; ///< deepest point of B inside A (on B's surface), metres
    /// Penetration depth, metres (with radii when useRadii). Negative when the shapes are in
    /// fact separated: then -depth is their distance and the other fields are GJK's.
    float depth = 0.0f;
    int iterations = 0;    ///< GJK plus EPA iterations
    bool converged = true; ///< false when EPA hit kMaxEpaIterations or the polytope degenerated
};

/// Minimum translation separating two proxies: GJK first, then EPA (expanding polytope) on the
/// Minkowski difference when the cores overlap. Accurate to kEpaTolerance. When the Minkowski
/// difference has no area (two collinear segments, points) the answer falls back to the axis
/// perpendicular to it, or to +x for two points, with converged == false. Never returns NaN for
/// finite input.
PenetrationOutput penetration(const DistanceInput& input);

/// Cast of proxy B along `translationB` against proxy A (A still).
struct ShapeCastPairInput {
    ShapeProxy proxyA;
    ShapeProxy proxyB;
    Transform transformA{};
    Transform transformB{};
    Vec2 translationB{0.0f, 0.0f}; ///< world translation of B over the cast, metres
    float maxFraction = 1.0f;      ///< fraction of the translation to cast, in [0, 1]
};

/// First contact of B moving by fraction * translationB with A, by conservative advancement
/// (each step moves B by the current GJK distance divided by the approach speed along the
/// normal, so it never passes the contact). The shapes touch when their rounded surfaces are
/// closer than kShapeCastTolerance. Output (world): `point` on the surface of A, `normal` from A
/// to B at the contact; `hit` with `fraction` 0 when they touch or overlap at the start (the
/// normal is then (0, 0) if even the core hulls overlap); no hit when they move apart, do not
/// meet before maxFraction, or after kMaxShapeCastIterations (grazing approaches converge
/// slowly; `fraction` then tells how far B is known to move freely).
CastOutput shapeCast(const ShapeCastPairInput& input);

} // namespace e2d::physics
