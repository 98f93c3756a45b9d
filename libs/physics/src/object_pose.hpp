// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/game_object.hpp>
#include <e2d/physics/geometry.hpp>
#include <e2d/physics/math.hpp>

#include <glm/mat2x2.hpp>

namespace e2d::physics::detail {

/// A game object's place in the world, as physics sees it (x, y and the angle).
struct Pose {
    Vec2 position{0.0f, 0.0f};
    float angle = 0.0f;
};

/// The object's world pose in physics metres: its world position divided by `unitsPerMetre`.
Pose worldPose(const core::GameObject& object, float unitsPerMetre);

/// Places the object at `pose` (metres), i.e. at `pose.position * unitsPerMetre` world units,
/// whatever its parent, keeping its z.
void setWorldPose(core::GameObject& object, const Pose& pose, float unitsPerMetre);

/// The magnitudes of the object's world scale per axis (its own and its ancestors'), as a
/// diagonal matrix: how a collider's geometry is scaled on its own object's body.
glm::mat2 worldScale(const core::GameObject& object);

/// How `descendant`'s frame sits in the rigid frame (position and orientation, no scale) of
/// its ancestor `body`: body frame point = linear * descendant point + offset (world units).
/// Computed down the hierarchy from `body`, so large world coordinates add no rounding.
void relativePlacement(const core::GameObject& body, const core::GameObject& descendant,
                       glm::mat2& linear, glm::vec2& offset);

/// `geometry` (world units, in its object's frame) mapped by `linear` and `offset` into the
/// body's frame and divided by `unitsPerMetre` (a circle's or a capsule's radius scaled by
/// the longer of linear's columns). Throws core::Error when the result is not a valid shape
/// (degenerate: too small, a circle or capsule radius below kLinearSlop, or non-finite).
ShapeGeometry placedGeometry(const ShapeGeometry& geometry, const glm::mat2& linear,
                             glm::vec2 offset, float unitsPerMetre);

/// Whether two poses differ by more than float noise from a round trip through a matrix.
bool movedApart(const Pose& a, Vec2 position, float angle);

/// Whether two placements differ by more than float noise.
bool placementsDiffer(const glm::mat2& linearA, glm::vec2 offsetA, const glm::mat2& linearB,
                      glm::vec2 offsetB);

} // namespace e2d::physics::detail
