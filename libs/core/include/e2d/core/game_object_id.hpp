// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/id.hpp>

#include <cstdint>

namespace e2d::core {

struct GameObjectIdTag;

/// A handle to a game object of one scene (12 bytes; see id.hpp): slot index + 1, generation
/// and the tag of the scene that created the object (see Scene::tag()).
///
/// The value-initialised id is null. When an object is destroyed its slot's generation changes,
/// so `Scene::find()` with an old id returns nullptr instead of a dangling or reused object.
/// Generations start again in every scene, so an id kept from a previous scene is refused by
/// the next one by its scene tag, like a stale id.
using GameObjectId = Id<GameObjectIdTag, std::uint32_t, std::uint32_t>;

} // namespace e2d::core
