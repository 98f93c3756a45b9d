// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/component.hpp>
#include <e2d/physics/id.hpp>
#include <e2d/physics/math.hpp>
#include <e2d/physics/types.hpp>

namespace e2d::physics {

class PhysicsSystem;

/// How a Rigidbody starts. Every field can be changed later through the component.
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
    /// Initial velocity, m/s and rad/s. Default 0.
    Vec2 linearVelocity{0.0f, 0.0f};
    float angularVelocity = 0.0f;
};

/// Makes its GameObject a body of the PhysicsSystem's world: the object's position and
/// orientation follow the body after every fixed step. Unique per object. Mass and inertia come
/// from the object's Colliders' densities. The body is created when the object enters the scene
/// (or, if added later, when the component is attached) and destroyed with the component; its
/// Colliders move onto it, and back onto static bodies of their own when it goes.
class Rigidbody : public core::Component {
public:
    static constexpr bool kUnique = true;

    /// `system` must outlive the component. Throws core::Error for a non-finite or negative
    /// field of `def`, or a static type.
    Rigidbody(PhysicsSystem& system, const RigidbodyDef& def = {});
    ~Rigidbody() override;

    /// The body, null before the object entered the scene, after the component went, or once
    /// the PhysicsSystem noticed the body was destroyed through the World.
    [[nodiscard]] BodyId body() const noexcept { return body_; }
    [[nodiscard]] PhysicsSystem& system() const noexcept { return system_; }

    [[nodiscard]] Vec2 linearVelocity() const;
    void setLinearVelocity(Vec2 velocity);
    [[nodiscard]] float angularVelocity() const;
    void setAngularVelocity(float velocity);
    /// kg, from the colliders' densities.
    [[nodiscard]] float mass() const;
    [[nodiscard]] float gravityScale() const;
    void setGravityScale(float scale);
    void setFreezeRotation(bool freeze);
    void setFreezePosition(bool x, bool y);

    /// Force at the centre of mass (N), applied during the next fixed step.
    void applyForce(Vec2 force);
    /// Force at a world point (N, m).
    void applyForceAtPoint(Vec2 force, Vec2 point);
    void applyTorque(float torque);
    /// Impulse at the centre of mass (N*s): changes the velocity at once.
    void applyLinearImpulse(Vec2 impulse);
    void applyImpulseAtPoint(Vec2 impulse, Vec2 point);
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

    PhysicsSystem& system_;
    RigidbodyDef def_;
    BodyId body_{};
    // What the last fixed step wrote to the object, to tell a hand-made move from our own.
    glm::vec2 writtenPosition_{0.0f, 0.0f};
    float writtenAngle_ = 0.0f;
    bool leaving_ = false; // inside onTerminate
};

} // namespace e2d::physics
