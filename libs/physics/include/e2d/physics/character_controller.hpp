// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/component.hpp>
#include <e2d/core/mask.hpp>
#include <e2d/physics/character_mover.hpp>
#include <e2d/physics/id.hpp>

#include <functional>
#include <optional>
#include <vector>

namespace e2d::physics {

class PhysicsSystem;

/// How a CharacterController is made. Lengths are world units (the PhysicsSystem's
/// unitsPerMetre() of them make a metre), angles radians.
struct CharacterControllerDef {
    /// The character's capsule in the object's frame, world units (centre1 == centre2 makes a
    /// disc; radius > 0). Not scaled by the object's scale. Default centres (0, -0.5) and
    /// (0, 0.5), radius 0.3: a 1.6 m character at 1 unit per metre; give your own at other
    /// scales.
    Capsule capsule{{0.0f, -0.5f}, {0.0f, 0.5f}, 0.3f};
    /// The gap kept from surfaces, world units, in [0, capsule.radius]. Default 0.01.
    float skin = 0.01f;
    /// The steepest walkable slope, radians, in [0, pi/2). Default pi/4 (45 degrees).
    float maxSlopeAngle = 0.78539816f;
    /// The most one move() pushes out of an overlap, world units, > 0. Default 0.1.
    float maxPushOut = 0.1f;
    /// Ground this close below (world units, >= 0) is followed down slopes and steps while
    /// grounded and not moving up; 0 turns it off. Default 0.05.
    float groundSnapDistance = 0.05f;
    /// The up direction, unit. Default (0, 1).
    Vec2 up{0.0f, 1.0f};
    /// What the character is (its body's category) and what blocks it. Defaults: the first mask
    /// bit; everything.
    core::Mask category{1};
    core::Mask mask = core::Mask::all();
    /// Give the character a kinematic body carrying its capsule, teleported with it at each
    /// move(), so that the rest of the world sees it: dynamic bodies collide with it and rest on
    /// it, ray casts and queries find it. Sensors are found by move() itself either way (see
    /// the class comment). Default true.
    bool hasBody = true;
    /// See CharacterMoverDef::contactFilter (one-way platforms); its contact's point and
    /// separation are in metres. Default none.
    MoverContactFilter contactFilter{};
};

/// A character moved by the game, not by forces: Unity's CharacterController, on e2d's
/// CharacterMover. Call move() with this step's displacement (world units) from the object's
/// own fixedUpdate(): the object goes as far as the world's shapes allow, sliding along walls,
/// walking up slopes up to maxSlopeAngle, never passing through anything, and isGrounded(),
/// groundVelocity() and lastMove() say what it touches afterwards. Unique per object; do not
/// give the object a Rigidbody too (they would both move it). Colliders on the same object
/// never block its character.
///
/// The game owns the rules: gravity, jumping, and the forgiving ones players expect, coyote
/// time (a jump still starts for a moment, ~0.1 s, after running off an edge: remember when
/// isGrounded() was last true) and jump buffering (a jump pressed ~0.1 s before landing happens
/// on landing: remember when it was pressed). A typical fixed step:
///
///     velocity.x = input * runSpeed;
///     velocity.y = controller.isGrounded() ? 0 : velocity.y - gravity * dt;
///     if (jumpWanted && (controller.isGrounded() || coyoteLeft > 0)) velocity.y = jumpSpeed;
///     controller.move((velocity + controller.groundVelocity()) * dt);  // rides platforms
///     velocity = controller.clipVelocity(velocity);                     // no speed into walls
///
/// The object is moved at once (its world position; its angle is left alone, the capsule does
/// not turn). Moving the object by hand teleports the character there at the next move().
///
/// Events, from move(), to both objects (as PhysicsSystem does for bodies): CollisionEnter
/// when the character starts touching a solid shape (a wall, the ground, a crate; one point,
/// normal pointing away from the receiver, world units) and CollisionExit when it stops;
/// TriggerEnter/Exit when its capsule starts/stops overlapping a sensor Collider, whatever
/// the sensor's body type. Its own body reports no contact or sensor events through the
/// PhysicsSystem (they would name no Collider for it).
class CharacterController : public core::Component {
public:
    static constexpr bool kUnique = true;

    /// The PhysicsSystem is found through the scene when the object enters it. Throws
    /// core::Error naming the invalid field of `def`
    /// ("physics::CharacterController::CharacterController(): def.skin must be ...").
    explicit CharacterController(const CharacterControllerDef& def = {});
    ~CharacterController() override;

    /// Moves the object by `motion` (world units, finite) as far as the world allows and
    /// returns what happened, in world units. Throws core::Error before the object is in a scene.
    const MoveResult& move(Vec2 motion);

    /// Whether the last move() ended on ground (a surface within maxSlopeAngle of up).
    [[nodiscard]] bool isGrounded() const noexcept { return last_.grounded; }
    /// The ground's velocity under the character after the last move(), world units/s: add it
    /// to the displacement to ride a moving platform.
    [[nodiscard]] Vec2 groundVelocity() const noexcept { return last_.groundVelocity; }
    /// The last move()'s result in world units (positions, points, translation, ground velocity
    /// and pushedOut scaled; normals as they are).
    [[nodiscard]] const MoveResult& lastMove() const noexcept { return last_; }
    /// CharacterMover::clipVelocity(): `velocity` (world units/s, relative to the ground)
    /// without the parts into the walls, ceilings and ground it touches.
    [[nodiscard]] Vec2 clipVelocity(Vec2 velocity) const;

    /// The kinematic body carrying the capsule (null without def.hasBody, before the object is
    /// in a scene, or after the component went) and its shape.
    [[nodiscard]] BodyId body() const noexcept { return body_; }
    [[nodiscard]] ShapeId shape() const noexcept { return shape_; }
    /// The mover underneath, in metres (for what the component does not forward). Throws
    /// core::Error before the object is in a scene.
    [[nodiscard]] CharacterMover& mover();
    [[nodiscard]] const CharacterControllerDef& def() const noexcept { return def_; }

    void onInitialize() override;
    void onTerminate() override;

private:
    friend class PhysicsSystem;

    PhysicsSystem& sys() const;
    template <class Event>
    void tellBoth(ShapeId shape, const MoverContact* contact);
    void dispatchContactEvents();
    void dispatchSensorEvents();

    CharacterControllerDef def_;
    mutable PhysicsSystem* system_ = nullptr;
    std::optional<CharacterMover> mover_;
    MoveResult last_{};
    BodyId body_{};
    ShapeId shape_{};
    Vec2 writtenPosition_{0.0f, 0.0f}; // metres, where move() last put the object
    // What the character touched and overlapped after the previous move, for enter/exit events.
    std::vector<ShapeId> touching_;
    std::vector<ShapeId> sensors_;
    std::vector<ShapeId> scratch_;
};

} // namespace e2d::physics
