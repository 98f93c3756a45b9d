// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/geometry.hpp>
#include <e2d/physics/id.hpp>
#include <e2d/physics/math.hpp>
#include <e2d/physics/query.hpp>

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

/// A geometric character mover: a capsule that is not a body of the world, moved by the game
/// through the world's shapes (cast the capsule, collide and slide along the planes it meets,
/// report what it stands on). The design follows Box2D v3.1's mover (b2World_CastMover,
/// b2World_CollideMover, b2SolvePlanes, b2ClipVector); the code is e2d's own.
///
/// STEP BY STEP
///   CharacterMover mover({.capsule = {{0, -0.5f}, {0, 0.5f}, 0.3f}, .position = {2, 1}});
///   // each fixed step, after world.step(dt):
///   velocity.y = mover.grounded() ? 0 : velocity.y + gravity * dt;   // your rules
///   MoveResult r = mover.move(world, (velocity + mover.groundVelocity()) * dt);
///   velocity = mover.clipVelocity(velocity);    // no speed piles up against walls
///
/// Jumping, coyote time (a jump still allowed a moment after the feet left the ground) and jump
/// buffering (a jump pressed just before landing happens on landing) are game rules: keep them
/// in the game's controller, fed by grounded() and groundVelocity(). The mover only moves.
namespace e2d::physics {

class World;

/// What a surface is to the mover, by its normal against CharacterMoverDef::up.
enum class MoverSurface : std::uint8_t {
    Ground,  ///< faces up within maxSlopeAngle: the mover stands on it
    Wall,    ///< anything between (walls and slopes too steep to stand on)
    Ceiling, ///< faces down within maxSlopeAngle
};

/// A surface the mover touches after a move() (within twice the skin).
struct MoverContact {
    ShapeId shape;
    BodyId body;
    Vec2 point{0.0f, 0.0f};  ///< on the shape's surface, metres
    Vec2 normal{0.0f, 0.0f}; ///< unit, from the shape towards the mover
    float separation = 0.0f; ///< gap between the surfaces, metres (negative: overlap)
    MoverSurface surface = MoverSurface::Wall;
};

/// Decides whether a shape blocks the mover (CharacterMoverDef::contactFilter).
using MoverContactFilter = std::function<bool(const MoverContact& contact)>;

/// How a CharacterMover is made. The constructor validates every field.
struct CharacterMoverDef {
    /// The character's shape, relative to its position, metres: a capsule (center1 == center2
    /// makes a disc), radius finite and > 0, centres finite. The round bottom slides over seams,
    /// and walks over a step whose edge it meets within maxSlopeAngle of up (lower than
    /// radius * (1 - cos(maxSlopeAngle)), 0.29 radius at 45 degrees); there is no separate
    /// step-up for higher ones. Default a 1.6 m tall capsule of radius 0.3 standing on its position
    /// minus 0.8 m: centres (0, -0.5) and (0, 0.5).
    Capsule capsule{{0.0f, -0.5f}, {0.0f, 0.5f}, 0.3f};
    /// Where the mover starts, metres, finite, within kHuge. Default (0, 0).
    Vec2 position{0.0f, 0.0f};
    /// The up direction (against gravity), unit length within 1e-3. Ground faces it, ceilings
    /// face away from it. Default (0, 1).
    Vec2 up{0.0f, 1.0f};
    /// The gap the mover keeps from surfaces (contact offset), metres, finite, in
    /// [0, capsule.radius]. Keeping clear of surfaces is what lets it slide along them without
    /// catching. Default 0.01.
    float skin = 0.01f;
    /// The steepest slope it stands on and walks up, radians, finite, in [0, pi/2). Steeper
    /// slopes are walls: it slides down them and cannot walk up them. Default pi/4 (45 degrees).
    float maxSlopeAngle = 0.78539816f;
    /// The most a move() pushes the mover out of shapes it overlaps (it started inside one, or
    /// something moved into it), metres, finite, > 0. A deeper overlap is resolved over several
    /// moves, so it never throws the mover (at 60 moves per second the default resolves up to
    /// 6 m/s). Default 0.1.
    float maxPushOut = 0.1f;
    /// While grounded and not moving up, a move() that ends with ground at most this far below
    /// its skin pulls the mover down onto it: it follows a slope or a step down
    /// instead of leaving the ground for a frame. Metres, finite, >= 0; 0 turns it off.
    /// Default 0.05.
    float groundSnapDistance = 0.05f;
    /// Which shapes block it (QueryFilter rules; sensors never do). Default everything. Shapes
    /// of dynamic bodies block it but never push it (a crate resting on its head does not press
    /// it into the floor); to push them, give the character a body (CharacterController does).
    QueryFilter filter{};
    /// A body whose shapes never block it (the mover's own body, if the game gives it one so
    /// that others see it; CharacterController does). Default none.
    BodyId ignoreBody{};
    /// Asked for each shape before it blocks the mover, with the contact as it would be
    /// reported (shape, body, point, normal from the shape to the mover, surface, and the
    /// separation: negative when overlapping, 0 for a shape met while moving); false lets the
    /// mover pass through. A one-way platform that holds what lands on it and lets through what
    /// jumps up into it: `return c.shape != platform || (c.surface == MoverSurface::Ground &&
    /// c.separation > -0.05f);`. Called from move(), outside any world lock. Default none:
    /// every shape the filter sees blocks.
    MoverContactFilter contactFilter{};
};

namespace detail {
/// One constraint of the plane solver run by CharacterMover::move() (mover_solver.cpp):
/// dot(normal, delta) >= need, enforced by moving along `direction`. Scratch, not API.
struct MoverConstraint {
    Vec2 normal{0.0f, 0.0f};
    Vec2 direction{0.0f, 0.0f};
    float need = 0.0f;
    float push = 0.0f;
};
} // namespace detail

/// What one move() did and what the mover touches afterwards.
struct MoveResult {
    Vec2 position{0.0f, 0.0f}; ///< where the mover is now, metres
    Vec2 translation{0.0f,
                     0.0f}; ///< how far it moved, metres (differs from the asked one when blocked)
    /// Standing on ground (a MoverSurface::Ground contact).
    bool grounded = false;
    /// The ground contact closest to facing straight up; meaningful while grounded.
    Vec2 groundNormal{0.0f, 0.0f};
    Vec2 groundPoint{0.0f, 0.0f};
    ShapeId groundShape{};
    BodyId groundBody{};
    /// Velocity of the ground's material at groundPoint, m/s (a moving platform's; zero for
    /// static ground). Add it to the next displacement to ride the platform.
    Vec2 groundVelocity{0.0f, 0.0f};
    /// Touching a wall (or a slope too steep to stand on); wallNormal is the first one's.
    bool touchingWall = false;
    Vec2 wallNormal{0.0f, 0.0f};
    /// Touching a ceiling; ceilingNormal is the first one's.
    bool touchingCeiling = false;
    Vec2 ceilingNormal{0.0f, 0.0f};
    /// How far the mover was pushed out of overlaps and back to its skin during this move,
    /// metres (at most maxPushOut).
    float pushedOut = 0.0f;
    /// Passes of the outer collide-solve-cast loop this move took (1 to kMaxMoverPasses).
    int passes = 0;
};

/// The most collide-solve-cast passes one move() runs. Each pass slides along the surfaces it
/// meets; a move into a corner needs two.
inline constexpr int kMaxMoverPasses = 5;

/// A character mover (see the namespace comment above). A value: it holds its def, position
/// and last contacts, not the world; any number of movers can share a world. move() only reads
/// the world (queries), so other bodies do not feel the mover unless the game gives it a body.
class CharacterMover {
public:
    /// Throws core::Error naming the invalid field of `def`
    /// ("physics::CharacterMover::CharacterMover(): def.skin must be ...").
    explicit CharacterMover(const CharacterMoverDef& def = {});

    /// Moves by `displacement` (metres, finite, within kHuge) as far as the world's shapes allow:
    /// it is cast along the way (it never passes through a wall, however thin or fast), slides
    /// along what it meets, climbs slopes up to maxSlopeAngle keeping its speed along the
    /// ground, and leaves overlaps by at most maxPushOut. Then it looks at what it touches
    /// (contacts(), grounded(), ...). Throws core::Error for a non-finite displacement.
    MoveResult move(const World& world, Vec2 displacement);

    /// `velocity` without the parts that push into the surfaces touched after the last move:
    /// the part into a wall or a ceiling along its normal, and the downward part (along up) on
    /// ground. Feed the game's velocity back through it so speed does not pile up against a
    /// wall or the floor. Give it relative to the ground (without groundVelocity()).
    [[nodiscard]] Vec2 clipVelocity(Vec2 velocity) const;

    /// Metres.
    [[nodiscard]] Vec2 position() const noexcept { return position_; }
    /// Teleports the mover (metres, finite, within kHuge); forgets the last contacts.
    void setPosition(Vec2 position);
    /// The last move()'s result (a default MoveResult at the start position before any).
    [[nodiscard]] const MoveResult& lastMove() const noexcept { return last_; }
    [[nodiscard]] bool grounded() const noexcept { return last_.grounded; }
    [[nodiscard]] Vec2 groundVelocity() const noexcept { return last_.groundVelocity; }
    /// What the mover touched after the last move(), in no particular order.
    [[nodiscard]] std::span<const MoverContact> contacts() const noexcept { return contacts_; }

    [[nodiscard]] const CharacterMoverDef& def() const noexcept { return def_; }
    /// The capsule placed at the current position, world metres.
    [[nodiscard]] Capsule worldCapsule() const;
    /// The body whose shapes never block the mover (CharacterMoverDef::ignoreBody).
    void setIgnoredBody(BodyId body) noexcept { def_.ignoreBody = body; }
    /// Replaces CharacterMoverDef::contactFilter (an empty function: every shape blocks).
    void setContactFilter(MoverContactFilter filter);

private:
    CharacterMoverDef def_;
    Vec2 position_{0.0f, 0.0f};
    MoveResult last_{};
    std::vector<MoverContact> contacts_;
    // Reused from move to move so that a move allocates nothing once warmed up.
    std::vector<MoverContact> planes_;
    std::vector<ShapeId> candidates_;
    std::vector<detail::MoverConstraint> constraints_;
    float cosMaxSlope_ = 0.0f;
};

} // namespace e2d::physics
