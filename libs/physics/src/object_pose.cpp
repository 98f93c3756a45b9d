// SPDX-License-Identifier: MIT
#include "object_pose.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace e2d::physics::detail {

Pose worldPose(const core::GameObject& object) {
    const glm::vec3 p = object.worldPosition();
    return {{p.x, p.y}, object.worldOrientation()};
}

void setWorldPose(core::GameObject& object, const Pose& pose) {
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

ShapeGeometry scaledGeometry(const ShapeGeometry& geometry, glm::vec2 scale) {
    if (scale.x == 1.0f && scale.y == 1.0f) {
        return geometry;
    }
    const float radiusScale = std::max(std::fabs(scale.x), std::fabs(scale.y));
    struct Scaler {
        glm::vec2 s;
        float r;
        ShapeGeometry operator()(const Circle& c) const { return Circle{c.center * s, c.radius * r}; }
        ShapeGeometry operator()(const Capsule& c) const {
            return Capsule{c.center1 * s, c.center2 * s, c.radius * r};
        }
        ShapeGeometry operator()(const Segment& g) const { return Segment{g.point1 * s, g.point2 * s}; }
        ShapeGeometry operator()(const ChainSegment& g) const {
            return ChainSegment{{g.segment.point1 * s, g.segment.point2 * s}, g.ghost1 * s,
                                g.ghost2 * s, g.hasGhost1, g.hasGhost2};
        }
        ShapeGeometry operator()(const Polygon& p) const {
            std::vector<Vec2> points(p.vertices.begin(), p.vertices.begin() + p.count);
            for (Vec2& v : points) {
                v *= s;
            }
            return makePolygon(points, p.radius * r);
        }
    };
    return std::visit(Scaler{scale, radiusScale}, geometry);
}

bool movedApart(const Pose& a, Vec2 position, float angle) {
    // A matrix round trip changes a coordinate by a few ulps; a hand-made move is far larger.
    const float tolerance = 1e-5f * (1.0f + std::fabs(a.position.x) + std::fabs(a.position.y));
    return std::fabs(a.position.x - position.x) > tolerance ||
           std::fabs(a.position.y - position.y) > tolerance || std::fabs(a.angle - angle) > 1e-5f;
}

} // namespace e2d::physics::detail
