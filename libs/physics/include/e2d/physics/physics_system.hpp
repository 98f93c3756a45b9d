// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/system.hpp>
#include <e2d/physics/character_mover.hpp>
#include <e2d/physics/id.hpp>
#include <e2d/physics/query.hpp>
#include <e2d/physics/world.hpp>

#include <cstdint>
#include <functional>
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

class CharacterController;
class Collider;
class Rigidbody;

/// The scene's physics at one moment (PhysicsSystem::saveSnapshot()): the World's state and
/// what the physics components keep beside it. A value: copy it, keep several (a rollback
/// buffer of the last seconds), restore any of them (PhysicsSystem::restoreSnapshot()) into
/// the running scene it was saved in.
class PhysicsSnapshot {
public:
    /// The World's part: World::saveSnapshot()'s bytes (metres; the format is described there).
    [[nodiscard]] const std::vector<std::uint8_t>& world() const noexcept { return world_; }

private:
    friend class PhysicsSystem;

    // A CharacterController's own state: its mover (position, last move, contacts), its last
    // result in world units and what it touched and overlapped, for enter/exit events.
    struct Character {
        const CharacterController* component = nullptr;
        CharacterMover mover;
        MoveResult last{};
        std::vector<ShapeId> touching;
        std::vector<ShapeId> sensors;
    };

    std::vector<std::uint8_t> world_;
    std::vector<Character> characters_;
};

/// Owns the World of a running game and connects it to game objects.
///
/// Each fixed step: colliders whose object was reparented, moved relative to its body or
/// rescaled are rebuilt (see Collider), game objects that were moved by hand since the last
/// step are teleported in the world (their bodies' transforms follow the object), kinematic
/// targets (Rigidbody::setTargetTransform()) set their bodies' velocities, the world steps,
/// every Rigidbody writes its body's position and angle back to its object (z and scale
/// untouched), and the step's events are dispatched as CollisionEnter/Exit and
/// TriggerEnter/Exit (contact_info.hpp) to the object of each collider (and to its Rigidbody's object too, when
/// the collider is on a child of it), with ContactInfo normals pointing away from the
/// receiving collider. On a scene change (clear()) the world is emptied.
///
/// Units. The World runs in metres; game objects live in world units, `unitsPerMetre()` of
/// them to a metre (default 1: a world unit is a metre). Everything the components take and
/// give is in world units, converted here in one place: object positions, collider geometry,
/// Rigidbody velocities (units/s), forces (kg*units/s^2) and impulses (kg*units/s), torques
/// and angular impulses (kg*units^2/s^2, kg*units^2/s), JointComponent anchors, lengths and
/// forces, contact points and separations in ContactInfo, and the queries below.
/// Angles are radians, masses kg and densities kg/m^2 whatever the scale (so a scene and the
/// same scene drawn 100 times larger at 100 units per metre weigh and move alike). The
/// WorldDef (gravity in m/s^2) and whatever is done through world() directly stay in metres:
/// toMetres() and toUnits() convert.
///
/// Contacts. A ContactInfo of CollisionEnter holds the manifold after the step that began
/// the touch (where the shapes are when the event arrives, not where the narrow phase found
/// them before solving): points in world units, separations in world units (about zero, or
/// slightly negative, for shapes resting on each other).
///
/// Event callbacks may change the world through world(): create, move or destroy bodies and
/// shapes (events are dispatched from a copy, after the step). A Rigidbody's or static
/// Collider's body destroyed through the world is noticed at the start of the next
/// fixedUpdate(): the components then have no body and no shapes (Rigidbody::body() and
/// Collider::shape() are null) and the object keeps its last pose. Calling fixedUpdate() from
/// inside an event callback throws core::Error. The system installs the World's pre-solve
/// callback while a Collider has a oneWay or preSolve rule; replacing it through world()
/// turns those rules off.
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

    /// Gravity, world units/s^2 (the World's m/s^2 times unitsPerMetre()).
    [[nodiscard]] Vec2 gravity() const { return toUnits(world_.gravity()); }
    /// World units/s^2, finite.
    void setGravity(Vec2 gravity) { world_.setGravity(toMetres(gravity)); }

    // Queries in world units: the World's (see there for the rules), with every point, length
    // and geometry in world units; ShapeIds are the colliders' (collider() finds them).

    /// World::castRayClosest(): `origin`, `translation` and the result's point in world units
    /// (normal and fraction need no scale).
    [[nodiscard]] std::optional<RayResult> castRayClosest(Vec2 origin, Vec2 translation,
                                                          const QueryFilter& filter = {}) const;
    /// World::castRayAll() in world units.
    [[nodiscard]] std::vector<RayResult> castRayAll(Vec2 origin, Vec2 translation,
                                                    const QueryFilter& filter = {}) const;
    /// World::castShape(): `geometry` (world units) at `position` (world units) turned by
    /// `angle`, moved by `translation` (world units); the result's point in world units.
    [[nodiscard]] std::optional<RayResult> castShape(const ShapeGeometry& geometry, Vec2 position,
                                                     float angle, Vec2 translation,
                                                     const QueryFilter& filter = {}) const;
    /// World::overlapPoint(): the shapes containing `point` (world units).
    [[nodiscard]] std::vector<ShapeId> overlapPoint(Vec2 point,
                                                    const QueryFilter& filter = {}) const;
    /// World::overlapAabb(): the shapes whose box overlaps `box` (world units).
    [[nodiscard]] std::vector<ShapeId> overlapAabb(const Aabb& box,
                                                   const QueryFilter& filter = {}) const;
    /// World::overlapShape(): the shapes `geometry` (world units) at `position` (world units)
    /// turned by `angle` overlaps.
    [[nodiscard]] std::vector<ShapeId> overlapShape(const ShapeGeometry& geometry, Vec2 position,
                                                    float angle,
                                                    const QueryFilter& filter = {}) const;

    /// The collider that owns `shape`, or nullptr (not a component's shape, or stale).
    [[nodiscard]] Collider* collider(ShapeId shape) const noexcept;

    /// The whole scene's physics now, to come back to with restoreSnapshot(): the World's
    /// state (World::saveSnapshot(): bodies, contacts and their warm starts, joints, sleep,
    /// the broad phase, the ids) and each CharacterController's (its mover's position and
    /// contacts, its last move, what it touches). Rigidbody, Collider and JointComponent keep
    /// nothing a snapshot needs: their ids stay valid across a restore. Throws core::Error
    /// from inside an event handler of this system.
    [[nodiscard]] PhysicsSnapshot saveSnapshot() const;
    /// Puts the scene's physics back as `snapshot` saved it: the World restored (a snapshot it
    /// refuses throws core::Error and changes nothing), then every Rigidbody's object and
    /// every static Collider's object moved to its body's restored pose, every
    /// CharacterController's state put back and its object moved there, all drawn there at
    /// once (no interpolation from where they were). The world's callbacks stay the system's.
    /// The last step's events are not dispatched again. Kinematic targets set for the coming
    /// step stay.
    ///
    /// For the scene the snapshot was saved in, with the same objects (a checkpoint, a
    /// rollback, replaying a bug): a component made after the save loses its body (as when a
    /// body is destroyed through world()), a body whose component went since comes back
    /// without one, and the game's own state (scores, timers, its objects) is the game's to
    /// save beside it. Throws core::Error from inside an event handler of this system.
    void restoreSnapshot(const PhysicsSnapshot& snapshot);

    void fixedUpdate(double step) override;
    void clear() override;

private:
    friend class CharacterController;
    friend class Collider;
    friend class Rigidbody;

    void registerCollider(Collider& collider);
    void unregisterCollider(Collider& collider) noexcept;
    void registerShape(ShapeId shape, Collider& collider);
    void unregisterShape(ShapeId shape) noexcept;
    void registerRigidbody(Rigidbody& body);
    void unregisterRigidbody(Rigidbody& body) noexcept;
    void registerStaticCollider(Collider& collider);
    void unregisterStaticCollider(Collider& collider) noexcept;
    void registerCharacter(CharacterController& character);
    void unregisterCharacter(CharacterController& character) noexcept;
    /// Throws core::Error naming `function` while events are being dispatched.
    void requireNotDispatching(const char* function) const;
    /// Colliders riding on `body`.
    [[nodiscard]] std::vector<Collider*> collidersOn(const Rigidbody* body) const;
    /// Attaches again every collider `which` picks.
    void reattachColliders(const std::function<bool(const Collider&)>& which);
    /// Installs or removes the World's pre-solve callback as colliders with rules come and go.
    void updatePreSolve();
    [[nodiscard]] bool preSolve(ShapeId a, ShapeId b, const Manifold& manifold) const;

    void forgetDestroyedBodies();
    void syncColliders();
    void pullMovedObjects(float step);
    void pushBodyTransforms();
    void dispatchEvents();

    struct ColliderSlot {
        ShapeId shape{};
        Collider* collider = nullptr;
    };

    WorldDef def_;
    float unitsPerMetre_ = 1.0f;
    World world_;
    std::vector<Collider*> allColliders_; // every initialized collider, shape or not
    std::vector<ColliderSlot> colliders_; // indexed by ShapeId::index1 - 1
    std::vector<Rigidbody*> rigidbodies_;
    std::vector<Collider*> staticColliders_;       // colliders with a static body of their own
    std::vector<CharacterController*> characters_; // in a scene (onInitialize to onTerminate)
    int ruledColliders_ = 0;                       // colliders with oneWay or preSolve
    bool preSolveInstalled_ = false;
    // The last step's events, copied before dispatch (capacity reused from step to step).
    std::vector<ContactBeginTouchEvent> beginEvents_;
    std::vector<ContactEndTouchEvent> endEvents_;
    std::vector<SensorBeginTouchEvent> sensorBeginEvents_;
    std::vector<SensorEndTouchEvent> sensorEndEvents_;
    bool dispatching_ = false;
};

} // namespace e2d::physics
