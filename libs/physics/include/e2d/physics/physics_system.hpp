// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/system.hpp>
#include <e2d/physics/id.hpp>
#include <e2d/physics/world.hpp>

#include <cstdint>
#include <vector>

namespace e2d::core {
class Component;
class GameObject;
} // namespace e2d::core

/// The scene-graph side of the physics library: a core::System that owns a World and steps it
/// at the loop's fixed rate, and the Rigidbody and Collider components that attach game objects
/// to it. Nothing here is needed to use World on its own.
namespace e2d::physics {

class Collider;
class Rigidbody;

/// Owns the World of a running game and connects it to game objects.
///
/// Each fixed step: game objects that were moved by hand since the last step are teleported in
/// the world (their bodies' transforms follow the object), the world steps, every Rigidbody writes
/// its body's position and angle back to its object (z and scale untouched), and the step's
/// events are dispatched as onCollisionEnter/Exit and onTriggerEnter/Exit to the objects of both
/// shapes, with core::ContactInfo normals pointing away from the receiving object.
/// On a scene change (clear()) the world is emptied.
///
/// Event callbacks may change the world through world(): create, move or destroy bodies and
/// shapes (events are dispatched from a copy, after the step). A Rigidbody's or static
/// Collider's body destroyed through the world is noticed at the start of the next
/// fixedUpdate(): the components then have no body and no shapes (Rigidbody::body() and
/// Collider::shape() are null) and the object keeps its last pose. Calling fixedUpdate() from
/// inside an event callback throws core::Error.
class PhysicsSystem : public core::System {
public:
    /// Throws core::Error naming the invalid field of `def` (see World).
    explicit PhysicsSystem(const WorldDef& def = {});
    ~PhysicsSystem() override;
    PhysicsSystem(const PhysicsSystem&) = delete;
    PhysicsSystem& operator=(const PhysicsSystem&) = delete;

    [[nodiscard]] World& world() noexcept { return world_; }
    [[nodiscard]] const World& world() const noexcept { return world_; }

    /// The collider that owns `shape`, or nullptr (not a component's shape, or stale).
    [[nodiscard]] Collider* collider(ShapeId shape) const noexcept;

    void fixedUpdate(double step) override;
    void clear() override;

private:
    friend class Collider;
    friend class Rigidbody;

    void registerCollider(ShapeId shape, Collider& collider);
    void unregisterCollider(ShapeId shape) noexcept;
    void registerRigidbody(Rigidbody& body);
    void unregisterRigidbody(Rigidbody& body) noexcept;
    void registerStaticCollider(Collider& collider);
    void unregisterStaticCollider(Collider& collider) noexcept;

    void forgetDestroyedBodies();
    void pullMovedObjects();
    void pushBodyTransforms();
    void dispatchEvents();

    struct ColliderSlot {
        ShapeId shape{};
        Collider* collider = nullptr;
    };

    WorldDef def_;
    World world_;
    std::vector<ColliderSlot> colliders_; // indexed by ShapeId::index1 - 1
    std::vector<Rigidbody*> rigidbodies_;
    std::vector<Collider*> staticColliders_; // colliders with a static body of their own
    // The last step's events, copied before dispatch (capacity reused from step to step).
    std::vector<ContactBeginTouchEvent> beginEvents_;
    std::vector<ContactEndTouchEvent> endEvents_;
    std::vector<SensorBeginTouchEvent> sensorBeginEvents_;
    std::vector<SensorEndTouchEvent> sensorEndEvents_;
    bool dispatching_ = false;
};

} // namespace e2d::physics
