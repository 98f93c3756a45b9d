// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

namespace e2d::core {

/// A handle to a game object of one scene: slot index plus generation.
///
/// The value-initialised id (generation 0) is null. When an object is destroyed its slot's
/// generation changes, so `Scene::find()` with an old id returns nullptr instead of a
/// dangling or reused object.
struct GameObjectId {
    std::uint32_t index = 0;
    std::uint32_t generation = 0;

    /// False for the null id. A non-null id may still be stale; ask the scene.
    [[nodiscard]] constexpr bool isNull() const noexcept { return generation == 0; }
    friend constexpr bool operator==(GameObjectId, GameObjectId) noexcept = default;
};

} // namespace e2d::core
