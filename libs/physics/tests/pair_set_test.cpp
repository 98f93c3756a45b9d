// SPDX-License-Identifier: MIT
#include "pair_set.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>

using e2d::physics::detail::makePairKey;
using e2d::physics::detail::PairEntry;
using e2d::physics::detail::PairSet;

TEST(PairSet, InsertFindErase) {
    PairSet set;
    EXPECT_EQ(set.size(), 0);
    EXPECT_FALSE(set.contains(makePairKey(1, 2)));
    EXPECT_TRUE(set.insert({makePairKey(1, 2), 4, 8}));
    EXPECT_FALSE(set.insert({makePairKey(2, 1), 5, 9})); // same unordered pair
    ASSERT_NE(set.find(makePairKey(2, 1)), nullptr);
    EXPECT_EQ(set.find(makePairKey(2, 1))->proxyKeyA, 4); // the first insertion stays
    EXPECT_EQ(set.size(), 1);
    PairEntry removed;
    EXPECT_TRUE(set.erase(makePairKey(1, 2), &removed));
    EXPECT_EQ(removed.proxyKeyB, 8);
    EXPECT_FALSE(set.erase(makePairKey(1, 2)));
    EXPECT_EQ(set.size(), 0);
}

// Random churn against std::set: exercises growth and backward-shift deletion through long
// probe runs (ids from a small range make many pairs, and the table stays near its load limit).
TEST(PairSet, MatchesStdSetUnderChurn) {
    std::mt19937 rng(11);
    PairSet set;
    std::set<std::uint64_t> reference;
    for (int op = 0; op < 60000; ++op) {
        const std::uint64_t a = rng() % 300;
        std::uint64_t b = rng() % 300;
        if (a == b) {
            b = (b + 1) % 300;
        }
        const std::uint64_t key = makePairKey(a, b);
        if (rng() % 3 != 0) {
            EXPECT_EQ(set.insert({key, 0, 0}), reference.insert(key).second);
        } else {
            EXPECT_EQ(set.erase(key), reference.erase(key) == 1);
        }
        if (op % 10000 == 0) {
            // Every key in the reference is reachable, and nothing else is stored.
            for (std::uint64_t k : reference) {
                ASSERT_TRUE(set.contains(k));
            }
            std::size_t count = 0;
            set.forEach([&](const PairEntry& e) {
                ++count;
                EXPECT_EQ(reference.count(e.key), 1u);
            });
            ASSERT_EQ(count, reference.size());
        }
    }
    EXPECT_EQ(set.size(), static_cast<int>(reference.size()));
    EXPECT_GT(set.size(), 10000); // the churn really filled the table
    set.clear();
    EXPECT_EQ(set.size(), 0);
    EXPECT_FALSE(set.contains(makePairKey(1, 2)));
}
