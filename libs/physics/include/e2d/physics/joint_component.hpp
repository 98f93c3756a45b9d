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
    /// The joint, any of joint.hpp's defs, validated as World::createJoint() does. Its bodyA
    /// and bodyB are ignored: body A is the connected object's Rigidbody (or a static anchor),
    /// body B this object's Rigidbody. Anchors are in each body's own frame (world units from
    /// the object's position, unrotated). Lengths, translations, offsets, targets and linear
    /// motor speeds are in world units (per second), forces in kg*units/s^2 and torques in
    /// kg*units^2/s^2; the system divides them by its unitsPerMetre() (squared for torques)
    /// for World::createJoint(), so at the default 1 unit per metre they are metres and
    /// newtons. Angles, frequencies and ratios have no scale. Default: a revolute joint at both
    /// origins.
    JointDef joint = RevoluteJointDef{};
    /// The object to connect to; it must have a Rigidbody. Null (default): a static anchor
    /// fixed in the world at the world origin, so localAnchorA is a world point.
    core::GameObjectId connectedObject{};
};

/// Connects its GameObject's Rigidbody to another object's Rigidbody (or to the world) with a
/// joint, so a scene builds a rope, a door or a car from components without touching ids.
/// Not unique: an object may have several.
///
/// The joint is made when the object enters the scene (or when the component is attached
/// later): both Rigidbodies' bodies are created then if they do not exist yet. It goes when the
/// component goes, and with either Rigidbody (World destroys a body's joints): isConnected()
/// then turns false, and the component does not make it again. Everything else about the joint
/// is reached through world() and joint() (motor speeds, limits, springs, reactions).
class JointComponent : public core::Component {
public:
    /// `system` must outlive the component. Throws core::Error for an invalid def (as
    /// World::createJoint() does, checked on attach: the field, and the value).
    JointComponent(PhysicsSystem& system, const JointComponentDef& def = {});
    ~JointComponent() override;

    /// The joint, null before the object entered the scene or after it went.
    [[nodiscard]] JointId joint() const noexcept { return joint_; }
    /// Whether the joint exists: made, and neither the component nor a Rigidbody went since.
    [[nodiscard]] bool isConnected() const;
    [[nodiscard]] PhysicsSystem& system() const noexcept { return system_; }
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
    PhysicsSystem& system_;
    JointComponentDef def_;
    JointDef metres_; // def_.joint in metres, for the World
    JointId joint_{};
    BodyId anchor_{}; // the static anchor made for a null connectedObject
};

} // namespace e2d::physics
