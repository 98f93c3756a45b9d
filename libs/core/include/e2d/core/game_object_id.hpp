// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

namespace e2d::core {

/// A handle to a game object of one scene: slot index, generation and the scene's tag.
///
/// The value-initialised id (generation 0) is null. When an object is destroyed its slot's
/// generation changes, so `Scene::find()` with an old id returns nullptr instead of a
/// dangling or reused object. Generations start again in every scene, so the id also carries
/// the tag of the scene that handed it out (see Scene::tag()): an id kept from a previous
/// scene is refused by the next one like a stale id.
struct GameObjectId {
    std::uint32_t index = 0;
    std::uint32_t generation = 0;
    /// The tag of the scene that created the object (never 0 for a live object).
    std::uint32_t scene = 0;

    /// False for the null id. A non-null id may still be stale; ask the scene.
    [[nodiscard]] constexpr bool isNull() const noexcept { return generation == 0; }
    friend constexpr bool operator==(GameObjectId, GameObjectId) noexcept = default;
};

} // namespace e2d::core
