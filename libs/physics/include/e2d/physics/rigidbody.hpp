// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/component.hpp>
#include <e2d/physics/id.hpp>
#include <e2d/physics/math.hpp>
#include <e2d/physics/types.hpp>

namespace e2d::physics {

class PhysicsSystem;

/// How a Rigidbody starts. Every field can be changed later through the component. Lengths are
/// world units (the PhysicsSystem's unitsPerMetre() of them make a metre; see PhysicsSystem).
struct RigidbodyDef {
    /// Dynamic (forces and contacts move it) or kinematic (only its velocity does). Default
    /// dynamic. A static body is a Collider without a Rigidbody.
    BodyType type = BodyType::Dynamic;
    /// Multiplies the world's gravity for this body. Default 1.
    float gravityScale = 1.0f;
    /// 1/s, >= 0. Default 0.
    float linearDamping = 0.0f;
    /// 1/s, >= 0. Default 0.
    float angularDamping = 0.0f;
    /// The body never rotates. Default false.
    bool freezeRotation = false;
    /// The body never moves along world x / world y. Default false.
    bool freezePositionX = false;
    bool freezePositionY = false;
    /// Continuous collision against everything (not only static shapes). Default false.
    bool bullet = false;
    /// Initial velocity, world units/s and rad/s. Default 0.
    Vec2 linearVelocity{0.0f, 0.0f};
    float angularVelocity = 0.0f;
};

/// Makes its GameObject a body of the PhysicsSystem's world: the object's position and
/// orientation follow the body after every fixed step. Unique per object. Mass and inertia come
/// from the object's Colliders' densities. The body is created when the object enters the scene
/// (or, if added later, when the component is attached) and destroyed with the component; its
/// Colliders move onto it, and back onto static bodies of their own when it goes.
///
/// Units are the scene's: positions and points in world units, velocities in units/s, forces
/// in kg*units/s^2, impulses in kg*units/s, torques in kg*units^2/s^2 and angular impulses in
/// kg*units^2/s (at the default 1 unit per metre: metres, N, N*s, N*m). The PhysicsSystem
/// converts them to the World's metres.
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

    /// World units/s.
    [[nodiscard]] Vec2 linearVelocity() const;
    void setLinearVelocity(Vec2 velocity);
    /// rad/s.
    [[nodiscard]] float angularVelocity() const;
    void setAngularVelocity(float velocity);
    /// kg, from the colliders' densities.
    [[nodiscard]] float mass() const;
    [[nodiscard]] float gravityScale() const;
    void setGravityScale(float scale);
    void setFreezeRotation(bool freeze);
    void setFreezePosition(bool x, bool y);

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

    /// Creates the body now if the object is in the scene and it does not exist yet.
    BodyId ensureBody();
    BodyId requireBody(const char* function) const;

    PhysicsSystem& sys() const;

    mutable PhysicsSystem* system_ = nullptr; // found through the scene when not given
    RigidbodyDef def_;
    BodyId body_{};
    // What the last fixed step wrote to the object, to tell a hand-made move from our own.
    glm::vec2 writtenPosition_{0.0f, 0.0f};
    float writtenAngle_ = 0.0f;
    bool leaving_ = false; // inside onTerminate
};

} // namespace e2d::physics
