// SPDX-License-Identifier: MIT
#include <e2d/core/game_object_id.hpp>
#include <e2d/core/id.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <type_traits>
#include <vector>

namespace e2d::core {
namespace {

struct ThingTag;
struct OtherTag;
using ThingId = Id<ThingTag, std::uint16_t, std::uint16_t>;
using OtherId = Id<OtherTag, std::uint16_t, std::uint16_t>;
using PlainId = Id<ThingTag>;
using NeverReusedId = Id<ThingTag, NoGeneration>;

// Sizes the libraries' ids rely on (their headers check their own).
static_assert(sizeof(ThingId) == 8);
static_assert(sizeof(PlainId) == 8);
static_assert(sizeof(NeverReusedId) == 4);
static_assert(sizeof(GameObjectId) == 12);
static_assert(std::is_trivially_copyable_v<ThingId>);
// Ids of different pools are different types.
static_assert(!std::is_convertible_v<ThingId, OtherId>);
static_assert(!std::is_same_v<ThingId, OtherId>);
static_assert(ThingId::kHasGeneration && !NeverReusedId::kHasGeneration);

// A pool as the libraries keep one: a generation per slot, bumped when the object goes.
struct Pool {
    struct Slot {
        std::uint16_t generation = 1;
        bool alive = false;
    };
    std::vector<Slot> slots;
    std::uint16_t tag = 7;

    ThingId create() {
        slots.push_back({1, true});
        return ThingId::forSlot(static_cast<std::uint32_t>(slots.size() - 1), 1, tag);
    }
    void destroy(ThingId id) {
        Slot& slot = slots[id.index()];
        slot.alive = false;
        slot.generation = nextGeneration(slot.generation);
    }
    ThingId reuse(std::uint32_t index) {
        slots[index].alive = true;
        return ThingId::forSlot(index, slots[index].generation, tag);
    }
    [[nodiscard]] std::optional<std::uint32_t> find(ThingId id) const {
        return findSlot(
            id, slots.size(),
            [this](std::uint32_t i) {
                return slots[i].alive ? slots[i].generation : std::uint16_t{0};
            },
            tag);
    }
};

TEST(Id, ValueInitialisedIsNullAndEqualToOtherNulls) {
    EXPECT_TRUE(ThingId{}.isNull());
    EXPECT_TRUE(NeverReusedId{}.isNull());
    EXPECT_TRUE(GameObjectId{}.isNull());
    EXPECT_EQ(ThingId{}, ThingId{});
    EXPECT_FALSE(ThingId::forSlot(0, 1, 7).isNull());
}

TEST(Id, ForSlotStoresIndexPlusOneAndEqualityComparesEveryField) {
    const ThingId id = ThingId::forSlot(4, 9, 3);
    EXPECT_EQ(id.index1, 5u);
    EXPECT_EQ(id.index(), 4u);
    EXPECT_EQ(id.generation, 9u);
    EXPECT_EQ(id.owner, 3u);
    EXPECT_EQ(id, (ThingId{5, 9, 3}));
    EXPECT_NE(id, (ThingId{6, 9, 3}));
    EXPECT_NE(id, (ThingId{5, 10, 3}));
    EXPECT_NE(id, (ThingId{5, 9, 4}));
    EXPECT_EQ(NeverReusedId::forSlot(2), NeverReusedId{3});
}

TEST(Id, NextGenerationSkipsZeroOnWrapAround) {
    EXPECT_EQ(nextGeneration(std::uint16_t{1}), 2u);
    EXPECT_EQ(nextGeneration(std::uint16_t{65534}), 65535u);
    EXPECT_EQ(nextGeneration(std::uint16_t{65535}), 1u);
    EXPECT_EQ(nextGeneration(std::uint32_t{0xffffffffu}), 1u);
    EXPECT_EQ(nextGeneration(std::uint8_t{255}), 1u);
    static_assert(std::is_same_v<decltype(nextGeneration(std::uint16_t{1})), std::uint16_t>);

    // Every generation from 1 comes once before the first comes back: 65 535 reuses.
    std::uint16_t generation = 1;
    int steps = 0;
    do {
        generation = nextGeneration(generation);
        ASSERT_NE(generation, 0u);
        ++steps;
    } while (generation != 1);
    EXPECT_EQ(steps, 65535);
}

TEST(Id, FindSlotRefusesNullOutOfRangeForeignAndStaleIds) {
    Pool pool;
    const ThingId a = pool.create();
    const ThingId b = pool.create();
    EXPECT_EQ(pool.find(a), 0u);
    EXPECT_EQ(pool.find(b), 1u);

    EXPECT_EQ(pool.find(ThingId{}), std::nullopt);
    EXPECT_EQ(pool.find(ThingId{3, 1, pool.tag}), std::nullopt); // past the end
    EXPECT_EQ(pool.find(ThingId{1, 1, 8}), std::nullopt);        // another pool's
    EXPECT_EQ(pool.find(ThingId{1, 0, pool.tag}), std::nullopt); // generation 0 is never live

    pool.destroy(a);
    EXPECT_EQ(pool.find(a), std::nullopt); // freed
    const ThingId again = pool.reuse(0);
    EXPECT_EQ(again.index(), a.index());
    EXPECT_NE(again, a);
    EXPECT_EQ(pool.find(a), std::nullopt); // reused: the old id stays stale
    EXPECT_EQ(pool.find(again), 0u);
}

TEST(Id, StaleIdMatchesAgainOnlyAfterTheGenerationWrapsAround) {
    Pool pool;
    const ThingId first = pool.create();
    ThingId current = first;
    for (int reuse = 1; reuse < 65535; ++reuse) {
        pool.destroy(current);
        current = pool.reuse(0);
        ASSERT_NE(current.generation, 0u);
        ASSERT_EQ(pool.find(first), std::nullopt) << "after " << reuse << " reuses";
    }
    // The 65 535th reuse hands out generation 1 again: the documented limit of 16 bits.
    pool.destroy(current);
    current = pool.reuse(0);
    EXPECT_EQ(current, first);
}

TEST(Id, SlotOfChecksRangeAndOwnerOnly) {
    EXPECT_EQ(slotOf(NeverReusedId{}, 4), std::nullopt);
    EXPECT_EQ(slotOf(NeverReusedId{4}, 4), 3u);
    EXPECT_EQ(slotOf(NeverReusedId{5}, 4), std::nullopt);
    EXPECT_EQ(slotOf(ThingId{1, 5, 2}, 1, 2), 0u); // the generation is not looked at
    EXPECT_EQ(slotOf(ThingId{1, 5, 2}, 1, 3), std::nullopt);
}

} // namespace
} // namespace e2d::core
