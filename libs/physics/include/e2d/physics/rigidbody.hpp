// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/component.hpp>
#include <e2d/physics/id.hpp>
#include <e2d/physics/math.hpp>
#include <e2d/physics/types.hpp>

#include <functional>
#include <optional>
#include <vector>

namespace e2d::physics {

class PhysicsSystem;

/// How a Rigidbody starts: BodyDef's fields under BodyDef's names, minus the pose (the
/// object's). Every field can be changed later through the component. Lengths are world units
/// (the PhysicsSystem's unitsPerMetre() of them make a metre; see PhysicsSystem).
struct RigidbodyDef {
    /// Dynamic (forces and contacts move it) or kinematic (only its velocity does, see
    /// Rigidbody::setTargetTransform()). Default dynamic, unlike BodyDef's static: a Rigidbody
    /// is what makes an object move (an object that only collides has a Collider and no
    /// Rigidbody, and is static), so the default is the body users add one for. Static is
    /// refused.
    BodyType type = BodyType::Dynamic;
    /// Initial velocity, world units/s, finite. Default 0.
    Vec2 linearVelocity{0.0f, 0.0f};
    /// Initial angular velocity, rad/s counter-clockwise, finite. Default 0.
    float angularVelocity = 0.0f;
    /// 1/s, finite, >= 0. Default 0.
    float linearDamping = 0.0f;
    /// 1/s, finite, >= 0. Default 0.
    float angularDamping = 0.0f;
    /// Multiplies the world's gravity for this body, finite. Default 1.
    float gravityScale = 1.0f;
    /// The body never rotates. Default false.
    bool fixedRotation = false;
    /// The body never moves along world x / world y. Default false.
    bool lockX = false;
    bool lockY = false;
    /// Continuous collision against everything (not only static shapes). Default false.
    bool isBullet = false;
    /// Whether the body may sleep (a player's body usually may not). Default true.
    bool enableSleep = true;
};

/// Makes its GameObject a body of the PhysicsSystem's world: the object's position and
/// orientation follow the body after every fixed step. Unique per object. Mass and inertia come
/// from the densities of the Colliders on the object and on its descendants that have no
/// Rigidbody of their own nearer (a compound body, see Collider). The body is created when the
/// object enters the scene (or, if added later, when the component is attached) and destroyed
/// with the component; its Colliders move onto it, and back onto static bodies of their own (or
/// onto the next Rigidbody up the hierarchy) when it goes.
///
/// Before the body exists (right after addComponent, until the start of the next frame), the
/// component can be used as if it did: setters change the def the body will be made with,
/// forces, impulses and a kinematic target wait and are applied when it is made, and getters
/// answer from the def (mass() is 0, there is no body to weigh yet). Once the body is gone
/// (the component was removed, or the body was destroyed through the World) they throw
/// core::Error.
///
/// Units are the scene's: positions and points in world units, velocities in units/s, forces
/// in kg*units/s^2, impulses in kg*units/s, torques in kg*units^2/s^2 and angular impulses in
/// kg*units^2/s (at 1 unit per metre: metres, N, N*s, N*m). The PhysicsSystem converts them to
/// the World's metres.
class Rigidbody : public core::Component {
public:
    static constexpr bool kUnique = true;

    /// The PhysicsSystem is found through the scene when the object enters it
    /// (`scene()->system<PhysicsSystem>()`, core::Error naming the type when there is none).
    /// Throws core::Error for a non-finite or negative field of `def`, or a static type.
    explicit Rigidbody(const RigidbodyDef& def = {});
    /// With an explicit system, which must outlive the component.
    Rigidbody(PhysicsSystem& system, const RigidbodyDef& def = {});
    ~Rigidbody() override;

    /// The body, null before the object entered the scene, after the component went, or once
    /// the PhysicsSystem noticed the body was destroyed through the World.
    [[nodiscard]] BodyId body() const noexcept { return body_; }
    /// The system given or found through the scene; core::Error when there is none (a
    /// def-only component whose object is not in a scene with a PhysicsSystem).
    [[nodiscard]] PhysicsSystem& system() const { return sys(); }
    /// The def the body was (or will be) made with, with the changes made through the setters
    /// before it was.
    [[nodiscard]] const RigidbodyDef& def() const noexcept { return def_; }

    [[nodiscard]] BodyType type() const;
    /// World units/s.
    [[nodiscard]] Vec2 linearVelocity() const;
    void setLinearVelocity(Vec2 velocity);
    /// rad/s.
    [[nodiscard]] float angularVelocity() const;
    void setAngularVelocity(float velocity);
    /// kg, from the colliders' densities; 0 before the body exists.
    [[nodiscard]] float mass() const;
    [[nodiscard]] float gravityScale() const;
    void setGravityScale(float scale);
    [[nodiscard]] bool isFixedRotation() const;
    void setFixedRotation(bool fixed);
    /// Per-axis locks of the centre of mass (world x and y).
    void setPositionLocks(bool lockX, bool lockY);
    void setBullet(bool bullet);
    void setSleepEnabled(bool enabled);

    /// Moves a kinematic (or dynamic) body so that its object reaches `position` (world units)
    /// and `angle` (radians) at the end of the next fixed step, with velocities that push and
    /// carry what touches it (World::setTargetTransform() with the step's time). Call it once
    /// per step (from fixedUpdate, or update: the last call before the step counts); the body
    /// keeps the velocity it was given until told otherwise. Throws core::Error for a static
    /// body or non-finite values.
    void setTargetTransform(Vec2 position, float angle);

    /// Force at the centre of mass (kg*units/s^2), applied during the next fixed step.
    void applyForce(Vec2 force);
    /// Force (kg*units/s^2) at a point (world units).
    void applyForceAtPoint(Vec2 force, Vec2 point);
    /// Torque, kg*units^2/s^2, applied during the next fixed step.
    void applyTorque(float torque);
    /// Impulse at the centre of mass (kg*units/s): changes the velocity at once.
    void applyLinearImpulse(Vec2 impulse);
    /// Impulse (kg*units/s) at a point (world units).
    void applyImpulseAtPoint(Vec2 impulse, Vec2 point);
    /// Angular impulse, kg*units^2/s.
    void applyAngularImpulse(float impulse);

    void onInitialize() override;
    void onTerminate() override;

private:
    friend class Collider;
    friend class JointComponent;
    friend class PhysicsSystem;

    enum class State { NotYet, Live, Gone };

    /// Creates the body now if the object is in the scene and it does not exist yet.
    BodyId ensureBody();
    /// Live: the body; NotYet: null (the caller queues); Gone: throws naming `function`.
    BodyId bodyOrQueue(const char* function) const;
    /// Runs `action` on the body now, or when it is made.
    void now(const char* function, std::function<void(Rigidbody&)> action);
    /// The pending kinematic target, applied by the system before the step of `timeStep`.
    void applyTarget(float timeStep);

    PhysicsSystem& sys() const;

    mutable PhysicsSystem* system_ = nullptr; // found through the scene when not given
    RigidbodyDef def_;
    BodyId body_{};
    State state_ = State::NotYet;
    std::vector<std::function<void(Rigidbody&)>> pending_; // until the body is made
    struct Target {
        Vec2 position{0.0f, 0.0f}; // world units
        float angle = 0.0f;
    };
    std::optional<Target> target_;
    // What the last fixed step wrote to the object, to tell a hand-made move from our own.
    glm::vec2 writtenPosition_{0.0f, 0.0f};
    float writtenAngle_ = 0.0f;
    bool leaving_ = false; // inside onTerminate
};

} // namespace e2d::physics
