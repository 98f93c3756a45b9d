// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/component.hpp>
#include <e2d/core/game_object_id.hpp>
#include <e2d/physics/id.hpp>
#include <e2d/physics/joint.hpp>
#include <e2d/physics/math.hpp>

namespace e2d::physics {

class PhysicsSystem;

/// What a JointComponent makes.
struct JointComponentDef {
    /// The joint, any of joint.hpp's defs, validated as World::createJoint() does (errors name
    /// its fields as `def.joint.<field>`). Its bodyA and bodyB are ignored: body A is the
    /// connected object's Rigidbody (or a static anchor), body B this object's Rigidbody. Anchors are in each body's own frame (world units from
    /// the object's position, unrotated). Lengths, translations, offsets, targets and linear
    /// motor speeds are in world units (per second), forces in kg*units/s^2 and torques in
    /// kg*units^2/s^2; the system divides them by its unitsPerMetre() (squared for torques)
    /// for World::createJoint(), so at the default 1 unit per metre they are metres and
    /// newtons. Angles, frequencies and ratios have no scale. Default: a revolute joint at both
    /// origins.
    JointDef joint = RevoluteJointDef{};
    /// The object to connect to. With a Rigidbody: its body. Without one (a wall, the ground):
    /// a static anchor at the object's world pose when the joint is made (it does not follow
    /// the object afterwards), so localAnchorA is in the object's frame. Null (default): a
    /// static anchor at the world origin, so localAnchorA is a world point.
    core::GameObjectId connectedObject{};
};

/// Connects its GameObject's Rigidbody to another object (its Rigidbody, or the place of an
/// object without one) or to the world with a joint, so a scene builds a rope, a door or a car from components without touching ids.
/// Not unique: an object may have several.
///
/// The joint is made when the object enters the scene (or when the component is attached
/// later): both Rigidbodies' bodies are created then if they do not exist yet. It goes when the
/// component goes, and with either Rigidbody (World destroys a body's joints): isConnected()
/// then turns false, and the component does not make it again. Everything else about the joint
/// is reached through world() and joint() (motor speeds, limits, springs, reactions).
class JointComponent : public core::Component {
public:
    /// The PhysicsSystem is found through the scene when the object enters it, like
    /// Rigidbody's. Throws core::Error for an invalid def, naming the field
    /// (`def.joint.lowerAngle`) and the value as given; the def is checked again in metres
    /// when the joint is made (a length below the linear slop at that scale).
    explicit JointComponent(const JointComponentDef& def = {});
    /// With an explicit system, which must outlive the component.
    JointComponent(PhysicsSystem& system, const JointComponentDef& def = {});
    ~JointComponent() override;

    /// The joint, null before the object entered the scene or after it went.
    [[nodiscard]] JointId joint() const noexcept { return joint_; }
    /// Whether the joint exists: made, and neither the component nor a Rigidbody went since.
    [[nodiscard]] bool isConnected() const;
    /// The system given or found through the scene; core::Error when there is none.
    [[nodiscard]] PhysicsSystem& system() const;
    [[nodiscard]] const JointComponentDef& def() const noexcept { return def_; }

    /// The force on this object's body during the last fixed step, kg*units/s^2 (N at 1 unit
    /// per metre), world axes (see World::jointReactionForce()); zero when not connected.
    [[nodiscard]] Vec2 reactionForce() const;
    /// The torque on this object's body during the last fixed step, kg*units^2/s^2 (N*m at 1
    /// unit per metre); zero when not connected.
    [[nodiscard]] float reactionTorque() const;
    /// Destroys the joint now (a game breaking it above a force); the bodies stay.
    void disconnect();

    void onInitialize() override;
    void onTerminate() override;

private:
    /// def_.joint in metres, checked (the error names `function`).
    [[nodiscard]] JointDef validateInMetres(const char* function) const;

    mutable PhysicsSystem* system_ = nullptr; // found through the scene when not given
    JointComponentDef def_;
    JointId joint_{};
    BodyId anchor_{}; // the static anchor made for an object without a Rigidbody, or the world
};

} // namespace e2d::physics
