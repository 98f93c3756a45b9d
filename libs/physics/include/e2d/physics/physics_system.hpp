// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/system.hpp>
#include <e2d/physics/id.hpp>
#include <e2d/physics/query.hpp>
#include <e2d/physics/world.hpp>

#include <cstdint>
#include <optional>
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
/// events are dispatched as CollisionEnter/Exit and TriggerEnter/Exit (contact_info.hpp) to the objects of both
/// shapes, with ContactInfo normals pointing away from the receiving object.
/// On a scene change (clear()) the world is emptied.
///
/// Units. The World runs in metres; game objects live in world units, `unitsPerMetre()` of
/// them to a metre (default 1: a world unit is a metre). Everything the components take and
/// give is in world units, converted here in one place: object positions, collider geometry,
/// Rigidbody velocities (units/s), forces (kg*units/s^2) and impulses (kg*units/s), torques
/// and angular impulses (kg*units^2/s^2, kg*units^2/s), JointComponent anchors, lengths and
/// forces, contact points and separations in ContactInfo, and the ray casts below.
/// Angles are radians, masses kg and densities kg/m^2 whatever the scale (so a scene and the
/// same scene drawn 100 times larger at 100 units per metre weigh and move alike). The
/// WorldDef and whatever is done through world() directly stay in metres: toMetres() and
/// toUnits() convert.
///
/// Event callbacks may change the world through world(): create, move or destroy bodies and
/// shapes (events are dispatched from a copy, after the step). A Rigidbody's or static
/// Collider's body destroyed through the world is noticed at the start of the next
/// fixedUpdate(): the components then have no body and no shapes (Rigidbody::body() and
/// Collider::shape() are null) and the object keeps its last pose. Calling fixedUpdate() from
/// inside an event callback throws core::Error.
class PhysicsSystem : public core::System {
public:
    /// `def` is in metres (gravity m/s^2). `unitsPerMetre`: world units per metre, finite and
    /// > 0, default 1. Throws core::Error naming the invalid field of `def` (see World) or the
    /// invalid scale.
    explicit PhysicsSystem(const WorldDef& def = {}, float unitsPerMetre = 1.0f);
    ~PhysicsSystem() override;
    PhysicsSystem(const PhysicsSystem&) = delete;
    PhysicsSystem& operator=(const PhysicsSystem&) = delete;

    [[nodiscard]] World& world() noexcept { return world_; }
    [[nodiscard]] const World& world() const noexcept { return world_; }

    /// World units per metre (see the class comment).
    [[nodiscard]] float unitsPerMetre() const noexcept { return unitsPerMetre_; }
    /// A point or vector in world units (or per second) as metres (per second).
    [[nodiscard]] Vec2 toMetres(Vec2 units) const noexcept { return units / unitsPerMetre_; }
    [[nodiscard]] float toMetres(float units) const noexcept { return units / unitsPerMetre_; }
    /// A point or vector in metres (or per second) as world units (per second).
    [[nodiscard]] Vec2 toUnits(Vec2 metres) const noexcept { return metres * unitsPerMetre_; }
    [[nodiscard]] float toUnits(float metres) const noexcept { return metres * unitsPerMetre_; }

    /// World::castRayClosest() in world units: `origin` and `translation` are world units, and
    /// so is the result's point (normal and fraction need no scale).
    [[nodiscard]] std::optional<RayResult> castRayClosest(Vec2 origin, Vec2 translation,
                                                          const QueryFilter& filter = {}) const;
    /// World::castRayAll() in world units.
    [[nodiscard]] std::vector<RayResult> castRayAll(Vec2 origin, Vec2 translation,
                                                    const QueryFilter& filter = {}) const;

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
    float unitsPerMetre_ = 1.0f;
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
