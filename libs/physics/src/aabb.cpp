// SPDX-License-Identifier: MIT
#include <e2d/physics/geometry.hpp>

#include <glm/common.hpp>

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

Aabb computeAabb(const ShapeGeometry& shape, const Transform& xf) {
    return std::visit([&](const auto& s) { return computeAabb(s, xf); }, shape);
}

} // namespace e2d::physics
