// SPDX-License-Identifier: MIT
#include <e2d/physics/geometry.hpp>

#include "shape_detail.hpp"

namespace e2d::physics {

bool testPoint(const Circle& shape, Vec2 localPoint) {
    return distanceSquared(shape.center, localPoint) <= shape.radius * shape.radius;
}

bool testPoint(const Capsule& shape, Vec2 localPoint) {
    Vec2 closest = detail::closestPointOnSegment(shape.center1, shape.center2, localPoint);
    return distanceSquared(closest, localPoint) <= shape.radius * shape.radius;
}

bool testPoint(const Segment&, Vec2) { return false; }

bool testPoint(const ChainSegment&, Vec2) { return false; }

bool testPoint(const Polygon& shape, Vec2 localPoint) {
    float maxSeparation = -kHuge;
    for (int i = 0; i < shape.count; ++i) {
        float s = dot(shape.normals[i], localPoint - shape.vertices[i]);
        maxSeparation = s > maxSeparation ? s : maxSeparation;
    }
    if (maxSeparation <= 0.0f) {
        return true;
    }
    if (maxSeparation > shape.radius) {
        return false;
    }
    // Outside the core but within the radius of its faces: near a vertex the face separation
    // underestimates the distance, so measure the distance to the boundary itself.
    float rr = shape.radius * shape.radius;
    for (int i = 0; i < shape.count; ++i) {
        Vec2 a = shape.vertices[i];
        Vec2 b = shape.vertices[i + 1 < shape.count ? i + 1 : 0];
        if (distanceSquared(detail::closestPointOnSegment(a, b, localPoint), localPoint) <= rr) {
            return true;
        }
    }
    return false;
}

bool testPoint(const ShapeGeometry& shape, Vec2 localPoint) {
    return std::visit([&](const auto& s) { return testPoint(s, localPoint); }, shape);
}

} // namespace e2d::physics
