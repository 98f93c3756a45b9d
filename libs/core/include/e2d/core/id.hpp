// SPDX-License-Identifier: MIT
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>

/// Handles: small values that name a slot of a pool (a body of a physics::World, a sprite of a
/// render::Renderer, a game object of a core::Scene) instead of pointing into it. Every library's
/// id is an alias of core::Id; its pool finds the slot with findSlot() (or slotOf() when its
/// slots are never reused) and changes a slot's generation with nextGeneration() when the slot's
/// object goes, so a kept id is refused (stale) instead of reaching the next object.
///
///     struct BodyIdTag;
///     using BodyId = core::Id<BodyIdTag, std::uint16_t, std::uint16_t>; // 8 bytes
namespace e2d::core {

/// The `Generation` of an Id whose pool never reuses a slot (a mixer's sounds, an action map's
/// actions): the id has no generation (no storage, always equal).
struct NoGeneration {
    friend constexpr bool operator==(NoGeneration, NoGeneration) noexcept = default;
};

/// The `Owner` of an Id that carries no owner tag (no storage, always equal).
struct NoOwner {
    friend constexpr bool operator==(NoOwner, NoOwner) noexcept = default;
};

/// A handle to slot `index1 - 1` of one pool. The value-initialised id (`{}`) is null.
///
/// - `Tag`: any type, only there so that the ids of different pools are different types (a
///   ShapeId is not accepted where a BodyId is expected). It need not be complete.
/// - `Generation`: an unsigned integer, the slot's generation when the id was handed out (the
///   pool moves it on with nextGeneration() when the object goes, and never hands out 0), or
///   NoGeneration.
/// - `Owner`: an unsigned integer, the tag of the pool that handed the id out (a world's, a
///   scene's; never 0 for a live pool), so an id given to another pool is refused like a stale
///   one; or NoOwner.
///
/// Ids are equal when all their fields are. Fields of NoGeneration and NoOwner take no space:
/// `Id<T>` (16-bit generation, no owner) is 8 bytes, `Id<T, NoGeneration>` 4.
template <class Tag, class Generation = std::uint16_t, class Owner = NoOwner>
struct Id {
    static_assert(std::same_as<Generation, NoGeneration> || std::unsigned_integral<Generation>,
                  "core::Id: Generation must be an unsigned integer or core::NoGeneration");
    static_assert(std::same_as<Owner, NoOwner> || std::unsigned_integral<Owner>,
                  "core::Id: Owner must be an unsigned integer or core::NoOwner");

    using GenerationType = Generation;
    using OwnerType = Owner;
    /// Whether the id carries a generation (its pool reuses slots).
    static constexpr bool kHasGeneration = !std::same_as<Generation, NoGeneration>;

    std::uint32_t index1 = 0;                      ///< slot index + 1; 0 means null
    [[no_unique_address]] Generation generation{}; ///< the slot's generation when handed out
    [[no_unique_address]] Owner owner{};           ///< the tag of the pool that handed it out

    /// The id of slot `index` (0-based) as its pool hands it out.
    [[nodiscard]] static constexpr Id forSlot(std::uint32_t index, Generation generation = {},
                                              Owner owner = {}) noexcept {
        return Id{index + 1, generation, owner};
    }
    /// True for the null id. A non-null id may still be stale: ask its pool.
    [[nodiscard]] constexpr bool isNull() const noexcept { return index1 == 0; }
    /// The slot index (`index1 - 1`); wraps to 0xffffffff for the null id.
    [[nodiscard]] constexpr std::uint32_t index() const noexcept { return index1 - 1; }

    friend constexpr bool operator==(Id, Id) noexcept = default;
};

/// The generation a slot takes when its object goes: one more, skipping 0 on wrap-around, so
/// 0 is never the generation of a live slot (a pool may mark its free slots with 0, see
/// findSlot()). After 2^bits - 1 reuses of one slot an old id matches again: 65 535 for a
/// 16-bit generation.
template <std::unsigned_integral G>
[[nodiscard]] constexpr G nextGeneration(G generation) noexcept {
    const G next = static_cast<G>(generation + 1u);
    return next == 0 ? G{1} : next;
}

/// The slot index `id` names in a pool of `slotCount` slots whose tag is `owner`, or
/// std::nullopt for the null id, an index past the end or an id of another owner. The slot may
/// be free or reused: for a pool that reuses slots, use findSlot().
template <class Tag, class G, class O>
[[nodiscard]] constexpr std::optional<std::uint32_t>
slotOf(Id<Tag, G, O> id, std::size_t slotCount, std::type_identity_t<O> owner = {}) noexcept {
    // The null id's index wraps to 0xffffffff, past the end of any pool an id can address.
    const std::uint32_t index = id.index();
    if (index >= slotCount || !(id.owner == owner)) {
        return std::nullopt;
    }
    return index;
}

/// The slot index `id` names in a pool of `slotCount` slots whose tag is `owner`, or
/// std::nullopt when the id is null, past the end, of another owner or stale.
/// `liveGeneration(index)`, called only for an index in range, gives the slot's generation
/// while it holds an object and 0 while it is free (0 is never live, see nextGeneration()):
///
///     core::findSlot(id, voices.size(), [&](std::uint32_t i) { return voices[i].busy ? voices[i].generation : 0u; })
template <class Tag, class G, class O, class LiveGeneration>
requires(!std::same_as<G, NoGeneration>)
    [[nodiscard]] constexpr std::optional<std::uint32_t> findSlot(
        Id<Tag, G, O> id, std::size_t slotCount, LiveGeneration&& liveGeneration,
        std::type_identity_t<O> owner = {}) {
    const std::optional<std::uint32_t> index = slotOf(id, slotCount, owner);
    if (!index || static_cast<G>(liveGeneration(*index)) != id.generation || id.generation == 0) {
        return std::nullopt;
    }
    return index;
}

} // namespace e2d::core
