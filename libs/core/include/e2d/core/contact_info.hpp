// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec2.hpp>

#include <array>

namespace e2d::core {

class Component;
class GameObject;

/// One point of contact between two colliders, in world space and world units (the physics
/// system converts from its metres), as the shapes are after the fixed step that reported it.
struct ContactPoint {
    /// Where the colliders touch.
    glm::vec2 point{0.0f};
    /// Unit normal pointing away from the object receiving the event, towards `other`.
    glm::vec2 normal{0.0f};
    /// Signed distance along the normal, world units; negative means overlap (about zero for
    /// shapes resting on each other).
    float separation = 0.0f;
};

/// What the physics components hand to onCollisionEnter/Exit and onTriggerEnter/Exit.
/// Plain data; valid only during the call.
struct ContactInfo {
    static constexpr int kMaxPoints = 2;

    /// The first `pointCount` entries are valid (0 for exit events and most triggers).
    std::array<ContactPoint, kMaxPoints> points{};
    int pointCount = 0;
    /// The object on the other side of the contact (nullptr if it has none).
    GameObject* other = nullptr;
    /// The other object's collider component (nullptr if it has none).
    Component* otherCollider = nullptr;
};

} // namespace e2d::core
