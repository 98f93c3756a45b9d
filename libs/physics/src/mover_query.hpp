// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/character_mover.hpp>
#include <e2d/physics/world.hpp>

#include <vector>

// The two world queries a CharacterMover is made of (Box2D v3.1 calls them b2World_CollideMover
// and b2World_CastMover): the planes of the shapes near the capsule, and how far the capsule
// may travel.
namespace e2d::physics::detail {

/// What both queries need to know about the mover.
struct MoverQuery {
    const World* world = nullptr;
    Capsule capsule{}; ///< relative to the position, metres
    float skin = 0.0f; ///< metres
    QueryFilter filter{};
    BodyId ignoreBody{};
    Vec2 up{0.0f, 1.0f};
    float cosMaxSlope = 0.0f;
    const MoverContactFilter* contactFilter = nullptr;
};

/// Ground, wall or ceiling, by the normal against up.
MoverSurface surfaceOf(const MoverQuery& query, Vec2 normal);

/// Fills `planes` (cleared first) with one contact per shape whose surface is within `reach`
/// of the capsule placed at `position` (separation <= reach; overlaps have a negative one).
/// Shapes the contact filter refuses are left out. `candidates` is scratch.
void collideMover(const MoverQuery& query, Vec2 position, float reach,
                  std::vector<MoverContact>& planes, std::vector<ShapeId>& candidates);

/// The fraction of `translation` the capsule at `position` may travel keeping `skin` away from
/// every shape it is clear of, and getting no deeper into those it is already within `skin` of
/// (so it slides along a surface it touches; Box2D calls this encroachment). Shapes whose core
/// it already overlaps do not stop it (the planes push it out). `candidates` is scratch.
float castMover(const MoverQuery& query, Vec2 position, Vec2 translation,
                std::vector<ShapeId>& candidates);

} // namespace e2d::physics::detail
