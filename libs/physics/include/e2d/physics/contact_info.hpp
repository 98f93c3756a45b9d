// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec2.hpp>

#include <array>

namespace e2d::core {
class Component;
class GameObject;
} // namespace e2d::core

namespace e2d::physics {

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

/// What the physics components tell an object about a contact. Plain data; valid only during
/// the call that receives it.
struct ContactInfo {
    static constexpr int kMaxPoints = 2;

    /// The first `pointCount` entries are valid (0 for exit events and most triggers).
    std::array<ContactPoint, kMaxPoints> points{};
    int pointCount = 0;
    /// The object on the other side of the contact (nullptr if it has none).
    core::GameObject* other = nullptr;
    /// The other object's collider component: a Collider, or the CharacterController of a
    /// character (nullptr if it has none).
    core::Component* otherCollider = nullptr;
};

// The events PhysicsSystem delivers after each step to the components of the two objects
// involved (GameObject::dispatch). Take them with core::Handles:
//
//     class Crate : public core::Component, public core::Handles<physics::CollisionEnter> {
//         void on(const physics::CollisionEnter& hit) override { ... hit.other ... }
//     };

/// The object's collider started touching another (solid) collider.
struct CollisionEnter : ContactInfo {};
/// The object's collider stopped touching another collider (no points).
struct CollisionExit : ContactInfo {};
/// A trigger (sensor) and another collider started to overlap; both objects receive it.
struct TriggerEnter : ContactInfo {};
/// They stopped overlapping; both objects receive it.
struct TriggerExit : ContactInfo {};

} // namespace e2d::physics
