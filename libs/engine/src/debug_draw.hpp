// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/engine/debug_colors.hpp>

namespace e2d::physics {
class World;
}
namespace e2d::render {
class Camera;
class Drawer;
} // namespace e2d::render

namespace e2d::engine::detail {

using engine::DebugDrawColors;

/// Draws the shapes (outlines, by body type), their AABBs, the touching contact points and
/// their normals of every shape visible through `camera`, and every joint, in world units
/// (`unitsPerMetre` world units per metre). Returns the number of shapes drawn.
int drawPhysics(const physics::World& world, const render::Camera& camera, double unitsPerMetre,
                render::Drawer& drawer);

} // namespace e2d::engine::detail
