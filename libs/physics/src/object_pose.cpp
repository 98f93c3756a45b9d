// SPDX-License-Identifier: MIT
#include "object_pose.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace e2d::physics::detail {

Pose worldPose(const core::GameObject& object, float unitsPerMetre) {
    const glm::vec3 p = object.worldPosition();
    // A division, not a product with the reciprocal: whole multiples of the scale come out exact.
    return {Vec2{p.x, p.y} / unitsPerMetre, object.worldOrientation()};
}

void setWorldPose(core::GameObject& object, const Pose& metres, float unitsPerMetre) {
    const Pose pose{metres.position * unitsPerMetre, metres.angle};
    const core::GameObject* parent = object.parent();
    const float z = object.position().z;
    if (parent == nullptr) {
        object.setPosition(glm::vec3(pose.position.x, pose.position.y, z));
        object.setOrientation(pose.angle);
        return;
    }
    // The parent's world matrix may scale; its inverse takes the world point into its frame.
    const glm::vec4 local =
        glm::inverse(parent->worldTransform()) * glm::vec4(pose.position.x, pose.position.y, 0.0f, 1.0f);
    object.setPosition(glm::vec3(local.x, local.y, z));
    object.setOrientation(pose.angle - parent->worldOrientation());
}

ShapeGeometry scaledGeometry(const ShapeGeometry& geometry, glm::vec2 scale, float unitsPerMetre) {
    if (scale.x == 1.0f && scale.y == 1.0f && unitsPerMetre == 1.0f) {
        return geometry;
    }
    const float radiusScale = std::max(std::fabs(scale.x), std::fabs(scale.y));
    // Scaled, then divided by the units per metre (a division keeps whole multiples exact).
    struct Scaler {
        glm::vec2 s;
        float r;
        float upm;
        [[nodiscard]] Vec2 p(Vec2 v) const { return v * s / upm; }
        [[nodiscard]] float l(float radius) const { return radius * r / upm; }
        ShapeGeometry operator()(const Circle& c) const { return Circle{p(c.center), l(c.radius)}; }
        ShapeGeometry operator()(const Capsule& c) const {
            return Capsule{p(c.center1), p(c.center2), l(c.radius)};
        }
        ShapeGeometry operator()(const Segment& g) const { return Segment{p(g.point1), p(g.point2)}; }
        ShapeGeometry operator()(const ChainSegment& g) const {
            return ChainSegment{{p(g.segment.point1), p(g.segment.point2)}, p(g.ghost1),
                                p(g.ghost2), g.hasGhost1, g.hasGhost2};
        }
        ShapeGeometry operator()(const Polygon& poly) const {
            std::vector<Vec2> points(poly.vertices.begin(), poly.vertices.begin() + poly.count);
            for (Vec2& v : points) {
                v = p(v);
            }
            return makePolygon(points, l(poly.radius));
        }
    };
    return std::visit(Scaler{scale, radiusScale, unitsPerMetre}, geometry);
}

bool movedApart(const Pose& a, Vec2 position, float angle) {
    // A matrix round trip changes a coordinate by a few ulps; a hand-made move is far larger.
    const float tolerance = 1e-5f * (1.0f + std::fabs(a.position.x) + std::fabs(a.position.y));
    return std::fabs(a.position.x - position.x) > tolerance ||
           std::fabs(a.position.y - position.y) > tolerance || std::fabs(a.angle - angle) > 1e-5f;
}

} // namespace e2d::physics::detail
