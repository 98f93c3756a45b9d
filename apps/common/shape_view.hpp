// SPDX-License-Identifier: MIT
// ShapeView: draws the colliders of its game object as filled shapes with an outline, through
// the renderer's Drawer, every frame. Shared by the physics demos (apps/physics_polygons,
// apps/physics_materials), which show bodies as their shapes; the engine's physics debug draw
// (AABBs, contacts, normals) goes on top when it is switched on.
#pragma once

#include <e2d/core/component.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/engine/game_system.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/geometry.hpp>
#include <e2d/render/drawer.hpp>
#include <e2d/render/renderer.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <variant>
#include <vector>

namespace e2d::apps {

class ShapeView : public core::Component {
public:
    explicit ShapeView(glm::vec4 fill, glm::vec4 outline = {1.0f, 1.0f, 1.0f, 0.9f})
        : fill_(fill), outline_(outline) {}

    void setFill(glm::vec4 fill) noexcept { fill_ = fill; }

    void update(double dt) override {
        static_cast<void>(dt);
        auto& game = scene()->system<engine::GameSystem>();
        render::Drawer& draw = game.renderer().drawer();
        // Where the object is drawn this frame (between physics steps), as its sprites are.
        const glm::vec2 origin{gameObject()->renderPosition()};
        const float angle = gameObject()->renderOrientation();
        const float c = std::cos(angle);
        const float s = std::sin(angle);
        // Collider geometry is in the object's frame, in world units.
        auto toWorld = [&](glm::vec2 p) {
            return origin + glm::vec2{c * p.x - s * p.y, s * p.x + c * p.y};
        };

        for (const physics::Collider* collider : gameObject()->getComponents<physics::Collider>()) {
            const physics::ShapeGeometry& g = collider->geometry();
            if (const auto* circle = std::get_if<physics::Circle>(&g)) {
                const glm::vec2 centre = toWorld(circle->center);
                draw.fillCircle(centre, circle->radius, fill_);
                draw.circle(centre, circle->radius, outline_, 1.5f);
                // A spoke, so rolling shows.
                draw.line(centre, toWorld(circle->center + glm::vec2{circle->radius, 0.0f}),
                          outline_, 1.5f);
            } else if (const auto* polygon = std::get_if<physics::Polygon>(&g)) {
                points_.clear();
                for (int i = 0; i < polygon->count; ++i) {
                    points_.push_back(toWorld(polygon->vertices[static_cast<std::size_t>(i)]));
                }
                draw.fillPolygon(points_, fill_);
                draw.polygon(points_, outline_, 1.5f);
            } else if (const auto* segment = std::get_if<physics::Segment>(&g)) {
                draw.line(toWorld(segment->point1), toWorld(segment->point2), outline_, 2.0f);
            } else if (const auto* capsule = std::get_if<physics::Capsule>(&g)) {
                const glm::vec2 a = toWorld(capsule->center1);
                const glm::vec2 b = toWorld(capsule->center2);
                draw.fillCircle(a, capsule->radius, fill_);
                draw.fillCircle(b, capsule->radius, fill_);
                const glm::vec2 d = b - a;
                const float length = std::sqrt(d.x * d.x + d.y * d.y);
                if (length > 0.0f) {
                    const glm::vec2 n = glm::vec2{-d.y, d.x} * (capsule->radius / length);
                    const std::array<glm::vec2, 4> quad = {a + n, a - n, b - n, b + n};
                    draw.fillPolygon(quad, fill_);
                }
            }
        }
    }

private:
    glm::vec4 fill_;
    glm::vec4 outline_;
    std::vector<glm::vec2> points_;
};

/// A regular polygon of `sides` vertices (3..8) around the origin, circumradius `radius` metres.
inline physics::Polygon regularPolygon(int sides, float radius) {
    std::array<physics::Vec2, 8> points{};
    for (int i = 0; i < sides; ++i) {
        const float a =
            2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / static_cast<float>(sides) +
            std::numbers::pi_v<float> / 2.0f;
        points[static_cast<std::size_t>(i)] = {radius * std::cos(a), radius * std::sin(a)};
    }
    return physics::makePolygon(
        std::span<const physics::Vec2>(points.data(), static_cast<std::size_t>(sides)));
}

} // namespace e2d::apps
