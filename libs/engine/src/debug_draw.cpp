// SPDX-License-Identifier: MIT
#include "debug_draw.hpp"

#include <e2d/physics/world.hpp>
#include <e2d/render/camera.hpp>
#include <e2d/render/drawer.hpp>

#include <glm/vec4.hpp>

#include <array>
#include <cmath>
#include <type_traits>

namespace e2d::engine::detail {

namespace {

glm::vec4 color(const float (&c)[4]) { return {c[0], c[1], c[2], c[3]}; }

} // namespace

int drawPhysics(const physics::World& world, const render::Camera& camera, double unitsPerMetre,
                render::Drawer& drawer) {
    const float upm = static_cast<float>(unitsPerMetre);
    const render::Rect view = camera.visibleWorldBounds();
    if (!std::isfinite(view.min.x) || !std::isfinite(view.size.x) || upm <= 0.0f) {
        return 0;
    }
    physics::Aabb box{view.min / upm, view.max() / upm};
    physics::QueryFilter filter;
    filter.includeSensors = true;
    const std::vector<physics::ShapeId> shapes = world.overlapAabb(box, filter);
    const auto toWorld = [upm](physics::Vec2 metres) { return glm::vec2(metres) * upm; };

    for (const physics::ShapeId shape : shapes) {
        const physics::BodyId body = world.shapeBody(shape);
        const physics::Transform xf = world.transform(body);
        glm::vec4 c = color(DebugDrawColors::kStatic);
        switch (world.bodyType(body)) {
        case physics::BodyType::Dynamic:
            c = color(world.isAwake(body) ? DebugDrawColors::kDynamic : DebugDrawColors::kSleeping);
            break;
        case physics::BodyType::Kinematic:
            c = color(DebugDrawColors::kKinematic);
            break;
        case physics::BodyType::Static:
            break;
        }
        if (world.isSensor(shape)) {
            c = color(DebugDrawColors::kSensor);
        }
        const auto point = [&](physics::Vec2 local) {
            return toWorld(physics::transformPoint(xf, local));
        };
        std::visit(
            [&](const auto& g) {
                using T = std::decay_t<decltype(g)>;
                if constexpr (std::is_same_v<T, physics::Circle>) {
                    const glm::vec2 centre = point(g.center);
                    drawer.circle(centre, g.radius * upm, c, 2.0f);
                    // A radius shows the rotation.
                    drawer.line(centre, centre + toWorld(physics::rotate(xf.q, {g.radius, 0.0f})),
                                c, 2.0f);
                } else if constexpr (std::is_same_v<T, physics::Capsule>) {
                    const glm::vec2 a = point(g.center1);
                    const glm::vec2 b = point(g.center2);
                    const float r = g.radius * upm;
                    drawer.circle(a, r, c, 2.0f);
                    drawer.circle(b, r, c, 2.0f);
                    const glm::vec2 d = b - a;
                    const float length = std::sqrt(d.x * d.x + d.y * d.y);
                    if (length > 0.0f) {
                        const glm::vec2 n{-d.y / length * r, d.x / length * r};
                        drawer.line(a + n, b + n, c, 2.0f);
                        drawer.line(a - n, b - n, c, 2.0f);
                    }
                } else if constexpr (std::is_same_v<T, physics::Segment>) {
                    drawer.line(point(g.point1), point(g.point2), c, 2.0f);
                } else if constexpr (std::is_same_v<T, physics::ChainSegment>) {
                    // A one-sided segment: a tick from its middle towards the solid side's
                    // outside (the right-hand side walking from point1 to point2).
                    const glm::vec2 a = point(g.segment.point1);
                    const glm::vec2 b = point(g.segment.point2);
                    drawer.line(a, b, c, 2.0f);
                    const glm::vec2 d = b - a;
                    const float length = std::sqrt(d.x * d.x + d.y * d.y);
                    if (length > 0.0f) {
                        const glm::vec2 mid = 0.5f * (a + b);
                        drawer.line(mid, mid + glm::vec2{d.y, -d.x} / length * 8.0f, c, 1.0f);
                    }
                } else {
                    std::array<glm::vec2, physics::kMaxPolygonVertices> points{};
                    for (int i = 0; i < g.count; ++i) {
                        points[static_cast<std::size_t>(i)] =
                            point(g.vertices[static_cast<std::size_t>(i)]);
                    }
                    drawer.polygon(std::span<const glm::vec2>(points.data(),
                                                              static_cast<std::size_t>(g.count)),
                                   c, 2.0f);
                }
            },
            world.shapeGeometry(shape));
        const physics::Aabb aabb = world.shapeAabb(shape);
        drawer.rect(toWorld(aabb.lower), toWorld(aabb.upper), color(DebugDrawColors::kAabb), 1.0f);
    }

    // Joints: origin A - anchor A - anchor B - origin B, dots on the anchors, the axis of a
    // prismatic or wheel joint. Every joint, whether or not its bodies are in view (a line
    // between two bodies outside the view may cross it).
    const float pixel = 1.0f / camera.pixelsPerUnit().x;
    const glm::vec4 jointColour = color(DebugDrawColors::kJoint);
    for (const physics::JointDebugData& joint : world.jointDebugData()) {
        const glm::vec2 originA = toWorld(joint.originA);
        const glm::vec2 originB = toWorld(joint.originB);
        const glm::vec2 anchorA = toWorld(joint.anchorA);
        const glm::vec2 anchorB = toWorld(joint.anchorB);
        drawer.line(originA, anchorA, jointColour, 2.0f);
        drawer.line(anchorA, anchorB, jointColour, 2.0f);
        drawer.line(anchorB, originB, jointColour, 2.0f);
        drawer.fillCircle(anchorA, 3.0f * pixel, jointColour);
        drawer.fillCircle(anchorB, 3.0f * pixel, jointColour);
        if (joint.axis != physics::Vec2{0.0f, 0.0f}) {
            const glm::vec2 axis{joint.axis};
            const float lower = joint.limitEnabled ? joint.lower * upm : -30.0f * pixel;
            const float upper = joint.limitEnabled ? joint.upper * upm : 30.0f * pixel;
            drawer.line(anchorA + axis * lower, anchorA + axis * upper, jointColour, 1.0f);
        }
    }

    // Contact points (4 px dots) and normals (20 px long, from shape A to shape B).
    world.forEachTouchingContact([&](const physics::ContactData& contact) {
        if (contact.manifold == nullptr) {
            return;
        }
        const physics::Manifold& m = *contact.manifold;
        for (int i = 0; i < m.pointCount; ++i) {
            const glm::vec2 p = toWorld(m.points[i].point);
            drawer.fillCircle(p, 4.0f * pixel, color(DebugDrawColors::kContact));
            drawer.line(p, p + glm::vec2(m.normal) * (20.0f * pixel),
                        color(DebugDrawColors::kNormal), 2.0f);
        }
    });
    return static_cast<int>(shapes.size());
}

} // namespace e2d::engine::detail
