// SPDX-License-Identifier: MIT
#pragma once

namespace e2d::physics {
class World;
}
namespace e2d::render {
class Camera;
class Drawer;
} // namespace e2d::render

namespace e2d::engine::detail {

/// Colours of the physics debug draw (RGBA in [0, 1]).
struct DebugDrawColors {
    static constexpr float kDynamic[4] = {0.95f, 0.75f, 0.2f, 1.0f};  ///< awake dynamic bodies
    static constexpr float kSleeping[4] = {0.55f, 0.55f, 0.55f, 1.0f}; ///< sleeping ones
    static constexpr float kStatic[4] = {0.3f, 0.9f, 0.35f, 1.0f};
    static constexpr float kKinematic[4] = {0.35f, 0.6f, 1.0f, 1.0f};
    static constexpr float kSensor[4] = {0.9f, 0.3f, 0.9f, 1.0f};
    static constexpr float kAabb[4] = {1.0f, 0.2f, 0.2f, 0.6f};
    static constexpr float kContact[4] = {1.0f, 0.1f, 0.1f, 1.0f};
    static constexpr float kNormal[4] = {1.0f, 1.0f, 1.0f, 1.0f};
};

/// Draws the shapes (outlines, by body type), their AABBs, the touching contact points and
/// their normals of every shape visible through `camera`, in world units
/// (`unitsPerMetre` world units per metre). Returns the number of shapes drawn.
int drawPhysics(const physics::World& world, const render::Camera& camera, double unitsPerMetre,
                render::Drawer& drawer);

} // namespace e2d::engine::detail
