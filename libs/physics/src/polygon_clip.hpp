// SPDX-License-Identifier: MIT
#pragma once

#include "manifold_detail.hpp"

namespace e2d::physics::detail {

/// A polygon's collision data seen through pointers: lets the pair routines use a polygon in
/// place or a copy moved to another frame without building (and zeroing) a whole Polygon.
struct PolygonRef {
    const Vec2* vertices;
    const Vec2* normals;
    float radius;
    int count;
};

inline PolygonRef refOf(const Polygon& p) {
    return {p.vertices.data(), p.normals.data(), p.radius, p.count};
}

/// Up to kMaxPolygonVertices vertices and normals, left uninitialised until written: the
/// frame change of the pair routines fills only `count` of them.
struct PolygonScratch {
    Vec2 vertices[kMaxPolygonVertices];
    Vec2 normals[kMaxPolygonVertices];
};

/// Contact points of two polygons once the axis is known: the reference edge `edgeA` of `a`
/// and the incident edge `edgeB` of `b`, both polygons in the same frame (A's local frame).
/// `flip` swaps the roles (b holds the reference edge `edgeB`, a the incident edge `edgeA`).
/// Returns the points in that frame (normal from a to b, each point midway between the two
/// rounded surfaces). Points with separation > margin are dropped.
/// Shared by SAT and GJK/EPA so both algorithms clip the same way.
LocalManifold clipPolygons(PolygonRef a, PolygonRef b, int edgeA, int edgeB, bool flip,
                           float margin);

} // namespace e2d::physics::detail
