// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/constants.hpp>
#include <e2d/physics/id.hpp>
#include <e2d/physics/math.hpp>

#include <cstdint>
#include <variant>

/// Joints: constraints between two bodies of a World.
///
/// Making and naming one. Fill one of the def structs below (each field's unit, default and
/// valid range are documented at the field) and pass it to World::createJoint(), which checks
/// every field and throws core::Error naming the type, the field and the value
/// ("physics::World::createJoint(): revolute def.lowerAngle must be <= def.upperAngle, got 1 >
/// -1"). Its two bodies must be live bodies of that world, different, at least one dynamic. The
/// JointId it returns is generation-checked and carries its world's tag like BodyId and ShapeId:
/// a stale id, or one from another world, throws on use (World::isValid() tells beforehand).
/// World::joint(id) gives a Joint view (views.hpp) with the functions below as members;
/// Body::createJoint() and Body::joints() do the same from a body.
///
/// Lifetime. A joint lives until World::destroyJoint() or until either of its bodies is
/// destroyed (World::destroyBody() destroys the body's joints first). Making or destroying a
/// joint wakes both bodies. Neither may be called inside a query's or hook's callback (see
/// World); reading joints and changing motors, limits and springs there is allowed.
///
/// Collisions. Unless the def's collideConnected is true, the two bodies' shapes do not collide
/// with each other while the joint lives (a contact between them ends when it is made).
///
/// Reading it. World::jointReactionForce() and jointReactionTorque(): what the joint applied
/// to body B during the last step (N, N*m; a game breaks a joint above a threshold).
/// World::jointValue(): a revolute joint's angle, a prismatic or wheel joint's translation, a
/// distance joint's length. World::jointAnchorA()/jointAnchorB(), jointBodyA()/jointBodyB(),
/// jointType(), jointUserData(), bodyJoints(). World::jointDebugData(): every joint's picture
/// for a debug renderer.
///
/// Changing it. World::enableJointMotor(), setJointMotorSpeed(), setJointMaxMotorForce(),
/// enableJointLimit(), setJointLimits(), setJointSpring(), setMouseJointTarget(),
/// setMotorJointOffsets() (each says which types it takes and throws for the others); each
/// wakes the bodies.
///
/// Game objects. JointComponent (joint_component.hpp) makes a joint between its object's
/// Rigidbody and another object's (or the world) from any of these defs.
///
/// Solving. Every joint is solved with the contacts in both solver modes: in the soft step,
/// sub-stepped, warm started and relaxed like the contacts (before them in each pass), per
/// block on the wide solver, bit-identical from run to run; in classic mode, in the velocity
/// iterations and then the position iterations (Box2D 2.4's recipe). Jointed bodies are one
/// island: they sleep and wake together (a mouse joint does not keep its body awake).
///
/// Springs are given as a frequency (hertz) and a damping ratio, as in Box2D v3: a spring of
/// `hertz` f acting on an effective mass m has stiffness k = m (2 pi f)^2: for a body held by a
/// static one at its centre of mass, m is the body's mass; an angular spring's m is the bodies' effective
/// rotational inertia about their centres of mass (1 / (1 / I_A + 1 / I_B)), wherever the anchor.
/// The rigid parts of a joint (a revolute's shared point, a limit reached) are themselves stiff
/// springs in the soft step, of 60 Hz at the sub-step rate: a joint carrying force F between
/// effective masses m stretches by F / (m (2 pi 60)^2) (0.07 mm for F / m = 10 m/s^2), so a
/// long heavy chain stretches a little; classic mode's position iterations stretch it less.
/// A zero hertz spring has no stiffness (with damping 0 it does nothing).
///
/// Anchors are in each body's local frame (metres from the body origin). Angles are radians,
/// counter-clockwise; a joint's angle is the angle of body B relative to body A minus the def's
/// referenceAngle, followed continuously through whole turns.
namespace e2d::physics {

/// Kind of joint.
enum class JointType : std::uint8_t {
    Distance,
    Motor,
    Mouse,
    Prismatic,
    Revolute,
    Weld,
    Wheel,
};

/// Number of JointType values.
inline constexpr int kJointTypeCount = 7;

/// Keeps two anchor points at a distance: a rigid rod (neither spring nor limit), a spring
/// (enableSpring), or a rope (enableLimit alone: free between minLength and maxLength).
struct DistanceJointDef {
    /// The two bodies, different, live. Default null.
    BodyId bodyA{};
    BodyId bodyB{};
    /// Anchor on body A / B, local metres, finite. Default (0, 0).
    Vec2 localAnchorA{0.0f, 0.0f};
    Vec2 localAnchorB{0.0f, 0.0f};
    /// Rest length, metres, finite, >= kLinearSlop (0.005 m). Default 1.
    float length = 1.0f;
    /// The length is a spring (hertz, dampingRatio) instead of rigid. Default false.
    bool enableSpring = false;
    /// Spring frequency, hertz, finite, >= 0. Default 0 (no stiffness: a rope within limits).
    float hertz = 0.0f;
    /// Spring damping ratio (1 is critical), finite, >= 0. Default 0.
    float dampingRatio = 0.0f;
    /// Enforce minLength <= length <= maxLength (metres, finite, 0 <= minLength <= maxLength;
    /// a minLength below kLinearSlop acts as kLinearSlop). The joint is then not rigid: without
    /// a spring it is a rope (or a rod that may also shorten). Default false, 0, kHuge.
    bool enableLimit = false;
    float minLength = 0.0f;
    float maxLength = kHuge;
    /// A motor along the length of a non-rigid joint, driving its rate of change to motorSpeed
    /// (m/s, finite) with at most maxMotorForce (N, finite, >= 0). Default off, 0, 0.
    bool enableMotor = false;
    float maxMotorForce = 0.0f;
    float motorSpeed = 0.0f;
    /// Whether the two bodies' shapes collide with each other. Default false.
    bool collideConnected = false;
    /// Anything the application wants to find the joint's owner by. Default 0.
    std::uint64_t userData = 0;
};

/// Drives body B towards a pose relative to body A (B's origin at linearOffset in A's frame,
/// B's angle at A's plus angularOffset) with a capped force and torque: a top-down character
/// on a moving platform, a body following another.
struct MotorJointDef {
    BodyId bodyA{};
    BodyId bodyB{};
    /// Target position of B's origin in A's frame, metres, finite. Default (0, 0).
    Vec2 linearOffset{0.0f, 0.0f};
    /// Target angle of B relative to A, radians, finite. Default 0.
    float angularOffset = 0.0f;
    /// Largest force, N, finite, >= 0. Default 1.
    float maxForce = 1.0f;
    /// Largest torque, N*m, finite, >= 0. Default 1.
    float maxTorque = 1.0f;
    /// Fraction of the pose error corrected per second times the step rate, in [0, 1].
    /// Default 0.3.
    float correctionFactor = 0.3f;
    bool collideConnected = false;
    std::uint64_t userData = 0;
};

/// Pulls a point of body B towards a world target with a soft spring of capped force (dragging
/// a body with the mouse). Body A is only a reference (usually a static ground body).
struct MouseJointDef {
    BodyId bodyA{};
    BodyId bodyB{};
    /// The world target, metres, finite. Default (0, 0).
    Vec2 target{0.0f, 0.0f};
    /// The point of B pulled, local metres, finite. Default (0, 0) (B's origin).
    Vec2 localAnchorB{0.0f, 0.0f};
    /// Spring frequency, hertz, finite, > 0. Default 5.
    float hertz = 5.0f;
    /// Damping ratio, finite, >= 0. Default 0.7.
    float dampingRatio = 0.7f;
    /// Largest pulling force, N, finite, >= 0 (typically a multiple of the body's weight).
    /// Default 1000.
    float maxForce = 1000.0f;
    bool collideConnected = false;
    std::uint64_t userData = 0;
};

/// Lets body B slide along an axis fixed in body A, without rotating relative to it (a piston,
/// an elevator, a sliding door), with limits, a motor and a spring along the axis.
struct PrismaticJointDef {
    BodyId bodyA{};
    BodyId bodyB{};
    Vec2 localAnchorA{0.0f, 0.0f};
    Vec2 localAnchorB{0.0f, 0.0f};
    /// The axis in A's frame, finite, non-zero (normalised on creation). Default (1, 0).
    Vec2 localAxisA{1.0f, 0.0f};
    /// B's angle minus A's in the rest pose, radians, finite. Default 0.
    float referenceAngle = 0.0f;
    /// A spring pulling the translation to 0. Default false, 0 Hz, ratio 0.
    bool enableSpring = false;
    float hertz = 0.0f;
    float dampingRatio = 0.0f;
    /// Translation limits along the axis, metres, finite, lower <= upper. Default off, 0, 0.
    bool enableLimit = false;
    float lowerTranslation = 0.0f;
    float upperTranslation = 0.0f;
    /// Motor: drives the translation speed to motorSpeed (m/s, finite) with at most
    /// maxMotorForce (N, finite, >= 0). Default off, 0, 0.
    bool enableMotor = false;
    float maxMotorForce = 0.0f;
    float motorSpeed = 0.0f;
    bool collideConnected = false;
    std::uint64_t userData = 0;
};

/// Pins an anchor of body B to an anchor of body A, letting them turn about it (a hinge, a door,
/// a ragdoll's shoulder), with angle limits, a motor and an angular spring.
struct RevoluteJointDef {
    BodyId bodyA{};
    BodyId bodyB{};
    Vec2 localAnchorA{0.0f, 0.0f};
    Vec2 localAnchorB{0.0f, 0.0f};
    /// B's angle minus A's when the joint angle is 0, radians, finite. Default 0.
    float referenceAngle = 0.0f;
    /// An angular spring pulling the joint angle to 0. Default false, 0 Hz, ratio 0.
    bool enableSpring = false;
    float hertz = 0.0f;
    float dampingRatio = 0.0f;
    /// Joint angle limits, radians, finite, lower <= upper. Default off, 0, 0.
    bool enableLimit = false;
    float lowerAngle = 0.0f;
    float upperAngle = 0.0f;
    /// Motor: drives the joint's angular speed to motorSpeed (rad/s, finite) with at most
    /// maxMotorTorque (N*m, finite, >= 0). Default off, 0, 0.
    bool enableMotor = false;
    float maxMotorTorque = 0.0f;
    float motorSpeed = 0.0f;
    bool collideConnected = false;
    std::uint64_t userData = 0;
};

/// Glues body B to body A at their current relative pose, rigidly (hertz 0) or through linear
/// and angular springs.
struct WeldJointDef {
    BodyId bodyA{};
    BodyId bodyB{};
    Vec2 localAnchorA{0.0f, 0.0f};
    Vec2 localAnchorB{0.0f, 0.0f};
    /// B's angle minus A's, radians, finite. Default 0.
    float referenceAngle = 0.0f;
    /// Linear and angular stiffness, hertz, finite, >= 0; 0 is rigid. Default 0.
    float linearHertz = 0.0f;
    float angularHertz = 0.0f;
    /// Damping ratios of the soft parts, finite, >= 0. Default 1.
    float linearDampingRatio = 1.0f;
    float angularDampingRatio = 1.0f;
    bool collideConnected = false;
    std::uint64_t userData = 0;
};

/// A wheel: body B's anchor slides along an axis fixed in body A (the suspension, with a spring
/// and limits) and B turns freely about it (with a motor: the drive).
struct WheelJointDef {
    BodyId bodyA{};
    BodyId bodyB{};
    Vec2 localAnchorA{0.0f, 0.0f};
    Vec2 localAnchorB{0.0f, 0.0f};
    /// The suspension axis in A's frame, finite, non-zero (normalised). Default (0, 1).
    Vec2 localAxisA{0.0f, 1.0f};
    /// Suspension spring along the axis, pulling the translation to 0. Default true, 1 Hz,
    /// ratio 0.7. A wheel of a body of mass m at rest under gravity g along the axis sits
    /// m g / k below its anchor, k = m_eff (2 pi hertz)^2.
    bool enableSpring = true;
    float hertz = 1.0f;
    float dampingRatio = 0.7f;
    /// Translation limits along the axis, metres, finite, lower <= upper. Default off, 0, 0.
    bool enableLimit = false;
    float lowerTranslation = 0.0f;
    float upperTranslation = 0.0f;
    /// Drive: B's angular speed relative to A towards motorSpeed (rad/s, finite) with at most
    /// maxMotorTorque (N*m, finite, >= 0). Default off, 0, 0.
    bool enableMotor = false;
    float maxMotorTorque = 0.0f;
    float motorSpeed = 0.0f;
    bool collideConnected = false;
    std::uint64_t userData = 0;
};

/// Any joint's def.
using JointDef = std::variant<DistanceJointDef, MotorJointDef, MouseJointDef, PrismaticJointDef,
                              RevoluteJointDef, WeldJointDef, WheelJointDef>;

/// What a debug renderer draws for one joint (World::jointDebugData()), world metres: the
/// lines originA - anchorA - anchorB - originB (Box2D's picture of a joint), and for a
/// prismatic or wheel joint its axis through anchorA, from lower to upper when limited.
struct JointDebugData {
    JointId id{};
    JointType type = JointType::Distance;
    /// The bodies' origins.
    Vec2 originA{0.0f, 0.0f};
    Vec2 originB{0.0f, 0.0f};
    /// World::jointAnchorA() and jointAnchorB() (a mouse joint's A anchor is its target).
    Vec2 anchorA{0.0f, 0.0f};
    Vec2 anchorB{0.0f, 0.0f};
    /// Prismatic and wheel: the unit axis in world axes; (0, 0) for other types.
    Vec2 axis{0.0f, 0.0f};
    /// Whether limits are on, and them: lengths (distance), translations along `axis` from
    /// anchorA (prismatic, wheel), angles (revolute). 0 when off.
    bool limitEnabled = false;
    float lower = 0.0f;
    float upper = 0.0f;
};

/// The type a def creates.
JointType jointTypeOf(const JointDef& def);

/// The type's name ("revolute", ...).
const char* jointTypeName(JointType type);

} // namespace e2d::physics
