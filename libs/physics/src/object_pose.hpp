// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/game_object.hpp>
#include <e2d/physics/geometry.hpp>
#include <e2d/physics/math.hpp>

namespace e2d::physics::detail {

/// A game object's place in the world, as physics sees it (x, y and the angle).
struct Pose {
    Vec2 position{0.0f, 0.0f};
    float angle = 0.0f;
};

/// The object's world pose in physics metres: its world position divided by `unitsPerMetre`.
Pose worldPose(const core::GameObject& object, float unitsPerMetre);

/// Puts the object at `pose` in world space, whatever its parent, keeping its z.
/// Places the object at `pose` (metres), i.e. at `pose.position * unitsPerMetre` world units.
void setWorldPose(core::GameObject& object, const Pose& pose, float unitsPerMetre);

/// The geometry scaled by the object's world scale (a circle's or a capsule's radius by the
/// larger factor). Throws core::Error if the result is not a valid shape.
/// `geometry` (world units, object-local) scaled by `scale` and divided by `unitsPerMetre`.
ShapeGeometry scaledGeometry(const ShapeGeometry& geometry, glm::vec2 scale, float unitsPerMetre);

/// Whether two poses differ by more than float noise from a round trip through a matrix.
bool movedApart(const Pose& a, Vec2 position, float angle);

} // namespace e2d::physics::detail
