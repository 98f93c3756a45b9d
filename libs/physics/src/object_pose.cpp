// SPDX-License-Identifier: MIT
#include "object_pose.hpp"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

#include <e2d/core/error.hpp>
#include <e2d/physics/constants.hpp>

#include <algorithm>
#include <cmath>
#include <string>
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
    const glm::vec4 local = glm::inverse(parent->worldTransform()) *
                            glm::vec4(pose.position.x, pose.position.y, 0.0f, 1.0f);
    object.setPosition(glm::vec3(local.x, local.y, z));
    object.setOrientation(pose.angle - parent->worldOrientation());
}

namespace {

glm::mat2 linearPart(const glm::mat4& m) { return {m[0][0], m[0][1], m[1][0], m[1][1]}; }

} // namespace

glm::mat2 worldScale(const core::GameObject& object) {
    // The world matrix's basis vectors carry the scale of the object and all its parents.
    const glm::mat4& m = object.worldTransform();
    return {std::hypot(m[0][0], m[0][1]), 0.0f, 0.0f, std::hypot(m[1][0], m[1][1])};
}

void relativePlacement(const core::GameObject& body, const core::GameObject& descendant,
                       glm::mat2& linear, glm::vec2& offset) {
    // The chain of local transforms from below `body` down to `descendant`.
    linear = glm::mat2(1.0f);
    offset = glm::vec2(0.0f);
    for (const core::GameObject* o = &descendant; o != &body && o != nullptr; o = o->parent()) {
        const glm::mat4& local = o->localTransform();
        const glm::mat2 l = linearPart(local);
        offset = l * offset + glm::vec2(local[3][0], local[3][1]);
        linear = l * linear;
    }
    // Then into the body object's rigid frame: its world rotation taken off its world linear
    // part leaves its (and its ancestors') scale.
    const float angle = body.worldOrientation();
    const float c = std::cos(angle);
    const float s = std::sin(angle);
    const glm::mat2 unrotate{c, -s, s, c};
    const glm::mat2 scale = unrotate * linearPart(body.worldTransform());
    linear = scale * linear;
    offset = scale * offset;
}

ShapeGeometry placedGeometry(const ShapeGeometry& geometry, const glm::mat2& linear,
                             glm::vec2 offset, float unitsPerMetre) {
    if (linear == glm::mat2(1.0f) && offset == glm::vec2(0.0f) && unitsPerMetre == 1.0f) {
        return geometry;
    }
    const float radiusScale = std::max(glm::length(linear[0]), glm::length(linear[1]));
    // Mapped, then divided by the units per metre (a division keeps whole multiples exact).
    struct Mapper {
        glm::mat2 m;
        glm::vec2 o;
        float r;
        float upm;
        [[nodiscard]] Vec2 p(Vec2 v) const { return (m * v + o) / upm; }
        [[nodiscard]] float l(float radius) const { return radius * r / upm; }
        ShapeGeometry operator()(const Circle& c) const { return Circle{p(c.center), l(c.radius)}; }
        ShapeGeometry operator()(const Capsule& c) const {
            return Capsule{p(c.center1), p(c.center2), l(c.radius)};
        }
        ShapeGeometry operator()(const Segment& g) const {
            return Segment{p(g.point1), p(g.point2)};
        }
        ShapeGeometry operator()(const ChainSegment& g) const {
            return ChainSegment{{p(g.segment.point1), p(g.segment.point2)},
                                p(g.ghost1),
                                p(g.ghost2),
                                g.hasGhost1,
                                g.hasGhost2};
        }
        ShapeGeometry operator()(const Polygon& poly) const {
            std::vector<Vec2> points(poly.vertices.begin(), poly.vertices.begin() + poly.count);
            for (Vec2& v : points) {
                v = p(v);
            }
            return makePolygon(points, l(poly.radius));
        }
    };
    ShapeGeometry placed = std::visit(Mapper{linear, offset, radiusScale, unitsPerMetre}, geometry);
    validate(placed, "physics::Collider");
    // A round shape shrunk below the linear slop is as degenerate as a polygon would be.
    const float radius = std::holds_alternative<Circle>(placed) ? std::get<Circle>(placed).radius
                         : std::holds_alternative<Capsule>(placed)
                             ? std::get<Capsule>(placed).radius
                             : kLinearSlop;
    if (!(radius >= kLinearSlop)) {
        throw core::Error("physics::Collider: the scaled radius " + std::to_string(radius) +
                          " m is below the linear slop");
    }
    return placed;
}

bool movedApart(const Pose& a, Vec2 position, float angle) {
    // A matrix round trip changes a coordinate by a few ulps; a hand-made move is far larger.
    const float tolerance = 1e-5f * (1.0f + std::fabs(a.position.x) + std::fabs(a.position.y));
    return std::fabs(a.position.x - position.x) > tolerance ||
           std::fabs(a.position.y - position.y) > tolerance || std::fabs(a.angle - angle) > 1e-5f;
}

bool placementsDiffer(const glm::mat2& linearA, glm::vec2 offsetA, const glm::mat2& linearB,
                      glm::vec2 offsetB) {
    const auto differ = [](float a, float b) {
        return !(std::fabs(a - b) <= 1e-5f * (1.0f + std::fabs(a)));
    };
    return differ(linearA[0][0], linearB[0][0]) || differ(linearA[0][1], linearB[0][1]) ||
           differ(linearA[1][0], linearB[1][0]) || differ(linearA[1][1], linearB[1][1]) ||
           differ(offsetA.x, offsetB.x) || differ(offsetA.y, offsetB.y);
}

} // namespace e2d::physics::detail
