// SPDX-License-Identifier: MIT
#include "broad_phase.hpp"
#include "slot_array.hpp"

#include <e2d/core/error.hpp>

#include <e2d/physics/constants.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <set>
#include <utility>
#include <vector>

using e2d::physics::Aabb;
using e2d::physics::BodyType;
using e2d::physics::kAabbMargin;
using e2d::physics::Vec2;
using e2d::physics::detail::BroadPhase;
using e2d::physics::detail::ProxyPair;

namespace {

float uniform(std::mt19937& rng, float lo, float hi) {
    const double u = static_cast<double>(rng()) / 4294967296.0;
    return lo + static_cast<float>(u) * (hi - lo);
}

bool overlap(const Aabb& a, const Aabb& b) {
    return a.lower.x <= b.upper.x && b.lower.x <= a.upper.x && a.lower.y <= b.upper.y &&
           b.lower.y <= a.upper.y;
}

bool holds(const Aabb& outer, const Aabb& inner) {
    return outer.lower.x <= inner.lower.x && outer.lower.y <= inner.lower.y &&
           inner.upper.x <= outer.upper.x && inner.upper.y <= outer.upper.y;
}

using PairSetT = std::set<std::pair<std::uint64_t, std::uint64_t>>;

PairSetT pairsOf(const BroadPhase& bp) {
    PairSetT out;
    bp.forEachPair([&](const ProxyPair& p) {
        EXPECT_LT(p.userDataA, p.userDataB);
        out.insert({p.userDataA, p.userDataB});
    });
    return out;
}

bool mayTouch(BodyType a, BodyType b) {
    // Only pairs with a dynamic body are looked for.
    return a == BodyType::Dynamic || b == BodyType::Dynamic;
}

struct Box {
    Vec2 center;
    Vec2 half;
    Vec2 velocity;
    BodyType type;
    int key;
    [[nodiscard]] Aabb aabb() const { return {center - half, center + half}; }
};

// A deterministic filter of the kind the World applies: shapes whose indices are both
// multiples of 5 never touch.
bool testFilter(std::uint64_t a, std::uint64_t b) { return !(a % 5 == 0 && b % 5 == 0); }

// Categories and masks of the random scene's proxies (userData i): one of three categories,
// and a mask that leaves one out (every fourth proxy takes all).
std::uint64_t categoryOf(std::uint64_t i) { return std::uint64_t{1} << (i % 3); }
std::uint64_t maskOf(std::uint64_t i) {
    return i % 4 == 0 ? ~std::uint64_t{0} : ~categoryOf(i + 1);
}
bool maskFilter(std::uint64_t a, std::uint64_t b) {
    return testFilter(a, b) && (maskOf(a) & categoryOf(b)) != 0 && (maskOf(b) & categoryOf(a)) != 0;
}

} // namespace

TEST(BroadPhase, ProxyKeysPackIdAndType) {
    using namespace e2d::physics::detail;
    static_assert(proxyIdOf(makeProxyKey(12345, BodyType::Kinematic)) == 12345);
    static_assert(proxyTypeOf(makeProxyKey(12345, BodyType::Kinematic)) == BodyType::Kinematic);
    static_assert(makePairKey(3, 9) == makePairKey(9, 3));
    static_assert(pairKeyLow(makePairKey(9, 3)) == 3 && pairKeyHigh(makePairKey(9, 3)) == 9);
}

TEST(BroadPhase, FattensMovingProxiesOnly) {
    BroadPhase bp;
    const Aabb tight{{0, 0}, {1, 1}};
    const int s = bp.createProxy(tight, BodyType::Static, 1, 0);
    const int d = bp.createProxy(tight, BodyType::Dynamic, 1, 1);
    EXPECT_EQ(bp.fatAabb(s).lower, tight.lower);
    EXPECT_EQ(bp.fatAabb(s).upper, tight.upper);
    EXPECT_EQ(bp.fatAabb(d).lower, (Vec2{-kAabbMargin, -kAabbMargin}));
    EXPECT_EQ(bp.fatAabb(d).upper, (Vec2{1 + kAabbMargin, 1 + kAabbMargin}));
    EXPECT_EQ(bp.userData(d), 1u);
    EXPECT_EQ(bp.proxyCount(), 2);
    EXPECT_EQ(bp.moveCount(), 2); // new proxies are buffered

    bp.updatePairs([](std::uint64_t, std::uint64_t) { return true; });
    EXPECT_EQ(bp.moveCount(), 0);
    ASSERT_EQ(bp.newPairs().size(), 1u);
    EXPECT_EQ(bp.newPairs()[0].userDataA, 0u);
    EXPECT_EQ(bp.newPairs()[0].userDataB, 1u);
    EXPECT_EQ(bp.newPairs()[0].proxyKeyA, s);
    EXPECT_EQ(bp.newPairs()[0].proxyKeyB, d);

    // Moving within the margin touches nothing.
    const float m = 0.5f * kAabbMargin;
    EXPECT_FALSE(bp.moveProxy(d, {{m, m}, {1 + m, 1 + m}}));
    EXPECT_EQ(bp.moveCount(), 0);
    // Leaving it refattens around the new box.
    EXPECT_TRUE(bp.moveProxy(d, {{3, 0}, {4, 1}}));
    EXPECT_EQ(bp.moveCount(), 1);
    EXPECT_EQ(bp.fatAabb(d).lower.x, 3 - kAabbMargin);
    EXPECT_EQ(bp.fatAabb(d).upper.x, 4 + kAabbMargin);
}

TEST(BroadPhase, AMovingProxysFatBoxReachesTwoDisplacementsAhead) {
    BroadPhase bp;
    const int d = bp.createProxy({{0, 0}, {1, 1}}, BodyType::Dynamic, 1, 0);
    bp.updatePairs([](std::uint64_t, std::uint64_t) { return true; });
    // Moving right by 0.3 m a step: the box swept over the next step leaves the fat box, which
    // is rebuilt two displacements long to the right and the margin elsewhere.
    const Vec2 v{0.3f, 0.0f};
    EXPECT_TRUE(bp.moveProxy(d, {{0.3f, 0}, {1.3f, 1}}, v));
    const Aabb fat = bp.fatAabb(d);
    EXPECT_FLOAT_EQ(fat.lower.x, 0.3f - kAabbMargin);
    EXPECT_FLOAT_EQ(fat.upper.x, 1.3f + 2.0f * 0.3f + kAabbMargin);
    EXPECT_FLOAT_EQ(fat.lower.y, -kAabbMargin);
    EXPECT_FLOAT_EQ(fat.upper.y, 1 + kAabbMargin);
    bp.updatePairs([](std::uint64_t, std::uint64_t) { return true; });
    // The next steps stay inside it (their box swept one step ahead included) without touching
    // the tree, until the swept box would reach past it.
    int steps = 0;
    for (float x = 0.6f; bp.moveCount() == 0 && steps < 10; x += 0.3f, ++steps) {
        const Aabb box{{x, 0}, {x + 1, 1}};
        const bool moved = bp.moveProxy(d, box, v);
        EXPECT_EQ(moved, box.upper.x + v.x > fat.upper.x) << x;
    }
    EXPECT_EQ(steps, 2); // 0.6 inside; 0.9 + 1 + 0.3 is past 1.3 + 0.6 + 0.1
    EXPECT_TRUE(holds(bp.fatAabb(d), {{0.9f, 0}, {2.2f, 1}}));
}

TEST(BroadPhase, AFatBoxFarLargerThanNeededIsShrunk) {
    BroadPhase bp;
    const int d = bp.createProxy({{0, 0}, {1, 1}}, BodyType::Dynamic, 1, 0);
    // Fast to the right, then stopped inside the stretched box.
    EXPECT_TRUE(bp.moveProxy(d, {{0, 0}, {1, 1}}, {1.0f, 0.0f}));
    EXPECT_FLOAT_EQ(bp.fatAabb(d).upper.x, 1 + 2.0f + kAabbMargin);
    bp.updatePairs([](std::uint64_t, std::uint64_t) { return true; });
    EXPECT_TRUE(bp.moveProxy(d, {{0.1f, 0}, {1.1f, 1}}, {0.0f, 0.0f}));
    EXPECT_FLOAT_EQ(bp.fatAabb(d).upper.x, 1.1f + kAabbMargin);
    // No more than four margins wider than it needs: kept.
    bp.updatePairs([](std::uint64_t, std::uint64_t) { return true; });
    EXPECT_TRUE(bp.moveProxy(d, {{0.2f, 0}, {1.2f, 1}}, {0.09f, 0.0f}));
    const Aabb stretched = bp.fatAabb(d);
    EXPECT_FALSE(bp.moveProxy(d, {{0.25f, 0}, {1.25f, 1}}, {0.0f, 0.0f}));
    EXPECT_EQ(bp.fatAabb(d).upper.x, stretched.upper.x);
    EXPECT_EQ(bp.moveCount(), 1);
}

TEST(BroadPhase, NothingMovedMeansNoQueryAndNoNewPairs) {
    BroadPhase bp;
    for (int i = 0; i < 20; ++i) {
        const float x = static_cast<float>(i) * 0.5f;
        bp.createProxy({{x, 0}, {x + 1, 1}}, i % 2 == 0 ? BodyType::Dynamic : BodyType::Static, 1,
                       static_cast<std::uint64_t>(i));
    }
    bp.updatePairs([](std::uint64_t, std::uint64_t) { return true; });
    EXPECT_GT(bp.lastQueryCount(), 0);
    EXPECT_GT(bp.newPairs().size(), 0u);
    const int pairs = bp.pairCount();

    bp.updatePairs([](std::uint64_t, std::uint64_t) {
        ADD_FAILURE() << "filter called with nothing moved";
        return true;
    });
    EXPECT_EQ(bp.lastQueryCount(), 0);
    EXPECT_TRUE(bp.newPairs().empty());
    EXPECT_EQ(bp.pairCount(), pairs);
}

TEST(BroadPhase, NeverPairsStaticWithStaticNorKinematicWithoutDynamic) {
    BroadPhase bp;
    const Aabb box{{0, 0}, {1, 1}};
    bp.createProxy(box, BodyType::Static, 1, 0);
    bp.createProxy(box, BodyType::Static, 1, 1);
    bp.createProxy(box, BodyType::Kinematic, 1, 2);
    bp.createProxy(box, BodyType::Kinematic, 1, 3);
    std::vector<std::pair<std::uint64_t, std::uint64_t>> asked;
    bp.updatePairs([&](std::uint64_t a, std::uint64_t b) {
        asked.emplace_back(a, b);
        return true;
    });
    EXPECT_TRUE(asked.empty());
    EXPECT_EQ(bp.pairCount(), 0);

    const int d = bp.createProxy(box, BodyType::Dynamic, 1, 4);
    bp.updatePairs([&](std::uint64_t a, std::uint64_t b) {
        asked.emplace_back(a, b);
        return true;
    });
    // The dynamic box pairs with all four, once each, lower userData first.
    const std::vector<std::pair<std::uint64_t, std::uint64_t>> expected{
        {0, 4}, {1, 4}, {2, 4}, {3, 4}};
    std::sort(asked.begin(), asked.end());
    EXPECT_EQ(asked, expected);
    ASSERT_EQ(bp.newPairs().size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(bp.newPairs()[i].userDataA, expected[i].first);
        EXPECT_EQ(bp.newPairs()[i].userDataB, expected[i].second);
        EXPECT_EQ(bp.newPairs()[i].proxyKeyB, d);
    }

    // Destroying the dynamic proxy removes its pairs.
    bp.destroyProxy(d);
    EXPECT_EQ(bp.pairCount(), 0);
    EXPECT_FALSE(bp.containsPair(0, 4));
}

TEST(BroadPhase, FilterIsHonouredAndRemovedPairsComeBackOnlyAfterAMove) {
    BroadPhase bp;
    const Aabb box{{0, 0}, {1, 1}};
    const int a = bp.createProxy(box, BodyType::Dynamic, 1, 10);
    bp.createProxy(box, BodyType::Dynamic, 1, 20);
    bp.createProxy(box, BodyType::Dynamic, 1, 30);
    bp.updatePairs([](std::uint64_t x, std::uint64_t y) { return !(x == 10 && y == 20); });
    EXPECT_FALSE(bp.containsPair(10, 20));
    EXPECT_TRUE(bp.containsPair(20, 10) == false);
    EXPECT_TRUE(bp.containsPair(10, 30));
    EXPECT_TRUE(bp.containsPair(30, 20));
    EXPECT_EQ(bp.pairCount(), 2);

    EXPECT_TRUE(bp.removePair(30, 10));
    EXPECT_FALSE(bp.removePair(30, 10));
    bp.updatePairs([](std::uint64_t, std::uint64_t) { return true; });
    EXPECT_FALSE(bp.containsPair(10, 30)); // nothing moved, nothing found

    bp.bufferMove(a);
    bp.updatePairs([](std::uint64_t, std::uint64_t) { return true; });
    EXPECT_TRUE(bp.containsPair(10, 30));
    EXPECT_TRUE(bp.containsPair(10, 20)); // the filter lets it through now
    EXPECT_EQ(bp.newPairs().size(), 2u);
}

TEST(BroadPhase, RandomSceneMatchesBruteForce) {
    std::mt19937 rng(2024);
    BroadPhase bp;
    std::vector<Box> boxes;
    const float world = 30.0f;
    for (int i = 0; i < 400; ++i) {
        Box b{};
        const int kind = i % 10;
        b.type = kind < 3 ? BodyType::Static : (kind < 4 ? BodyType::Kinematic : BodyType::Dynamic);
        b.center = {uniform(rng, -world, world), uniform(rng, -world, world)};
        b.half = {uniform(rng, 0.2f, 1.5f), uniform(rng, 0.2f, 1.5f)};
        if (b.type != BodyType::Static) {
            b.velocity = {uniform(rng, -0.3f, 0.3f), uniform(rng, -0.3f, 0.3f)};
        }
        boxes.push_back(b);
    }
    auto create = [&](std::size_t i) {
        boxes[i].key = bp.createProxy(boxes[i].aabb(), boxes[i].type, categoryOf(i), i);
    };
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        create(i);
    }

    std::vector<bool> alive(boxes.size(), true);
    std::size_t totalNew = 0;
    for (int frame = 0; frame < 120; ++frame) {
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            Box& b = boxes[i];
            if (!alive[i] || b.type == BodyType::Static) {
                continue;
            }
            b.center += b.velocity;
            if (std::abs(b.center.x) > world) {
                b.velocity.x = -b.velocity.x;
            }
            if (std::abs(b.center.y) > world) {
                b.velocity.y = -b.velocity.y;
            }
            // Every other one tells its displacement (its fat box stretches along it).
            bp.moveProxy(b.key, b.aabb(), i % 2 == 0 ? b.velocity : Vec2{0.0f, 0.0f});
        }
        // Now and then a shape is destroyed and another comes back.
        if (frame % 10 == 5) {
            const std::size_t i = rng() % boxes.size();
            if (alive[i]) {
                bp.destroyProxy(boxes[i].key);
                alive[i] = false;
            } else {
                create(i);
                alive[i] = true;
            }
        }
        // A static body is teleported once in a while: its pairs must be found too.
        if (frame % 7 == 3) {
            for (std::size_t i = 0; i < boxes.size(); ++i) {
                if (alive[i] && boxes[i].type == BodyType::Static) {
                    boxes[i].center = {uniform(rng, -world, world), uniform(rng, -world, world)};
                    bp.moveProxy(boxes[i].key, boxes[i].aabb());
                    break;
                }
            }
        }

        const PairSetT before = pairsOf(bp);
        // The queries look at the categories in each moved proxy's mask only.
        bp.updatePairs(maskFilter, maskOf);
        // New pairs: sorted, unique, not in the set before.
        const auto fresh = bp.newPairs();
        totalNew += fresh.size();
        for (std::size_t k = 0; k < fresh.size(); ++k) {
            ASSERT_EQ(before.count({fresh[k].userDataA, fresh[k].userDataB}), 0u);
            if (k > 0) {
                ASSERT_TRUE(fresh[k - 1].userDataA < fresh[k].userDataA ||
                            (fresh[k - 1].userDataA == fresh[k].userDataA &&
                             fresh[k - 1].userDataB < fresh[k].userDataB));
            }
        }
        bp.prunePairs();

        PairSetT expected;
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            if (!alive[i]) {
                continue;
            }
            // The fat box holds the tight one.
            const Aabb fat = bp.fatAabb(boxes[i].key);
            ASSERT_TRUE(holds(fat, boxes[i].aabb()));
            if (boxes[i].type == BodyType::Static) {
                ASSERT_EQ(fat.lower, boxes[i].aabb().lower);
            }
            for (std::size_t j = i + 1; j < boxes.size(); ++j) {
                if (alive[j] && mayTouch(boxes[i].type, boxes[j].type) &&
                    overlap(fat, bp.fatAabb(boxes[j].key)) && maskFilter(i, j)) {
                    expected.insert({i, j});
                }
            }
        }
        ASSERT_EQ(pairsOf(bp), expected) << "frame " << frame;
        ASSERT_EQ(bp.pairCount(), static_cast<int>(expected.size()));
    }
    EXPECT_GT(totalNew, 200u); // the scene really produces pairs over time
    for (int t = 0; t < 3; ++t) {
        EXPECT_TRUE(bp.tree(static_cast<BodyType>(t)).validate());
    }
}

TEST(BroadPhase, SameInputsGiveTheSamePairsInTheSameOrder) {
    auto run = [] {
        std::mt19937 rng(5);
        BroadPhase bp;
        std::vector<int> keys;
        std::vector<Vec2> pos;
        for (int i = 0; i < 200; ++i) {
            pos.push_back({uniform(rng, -10, 10), uniform(rng, -10, 10)});
            keys.push_back(bp.createProxy({pos.back(), pos.back() + Vec2{1, 1}},
                                          i % 4 == 0 ? BodyType::Static : BodyType::Dynamic, 1,
                                          static_cast<std::uint64_t>(i)));
        }
        std::vector<std::uint64_t> trace;
        for (int frame = 0; frame < 30; ++frame) {
            for (std::size_t i = 0; i < keys.size(); ++i) {
                if (i % 4 != 0) {
                    pos[i] += Vec2{uniform(rng, -0.2f, 0.2f), uniform(rng, -0.2f, 0.2f)};
                    bp.moveProxy(keys[i], {pos[i], pos[i] + Vec2{1, 1}});
                }
            }
            bp.updatePairs([](std::uint64_t, std::uint64_t) { return true; });
            for (const ProxyPair& p : bp.newPairs()) {
                trace.push_back(p.userDataA << 32 | p.userDataB);
            }
            bp.prunePairs();
            bp.forEachPair(
                [&](const ProxyPair& p) { trace.push_back(p.userDataA << 32 | p.userDataB); });
        }
        return trace;
    };
    const auto first = run();
    EXPECT_GT(first.size(), 1000u);
    EXPECT_EQ(first, run());
}

// A grid of proxies swinging about their cells, most of them reinserted near where they were
// (DynamicTree::moveProxy()'s local path): the tree stays valid and about as tight as a fresh
// build of the same boxes, frame after frame.
TEST(BroadPhase, TheTreeStaysTightWhileProxiesMove) {
    std::mt19937 rng(8);
    BroadPhase bp;
    constexpr int kSide = 50;
    std::vector<int> keys;
    std::vector<Vec2> base;
    std::vector<float> phase;
    for (int i = 0; i < kSide * kSide; ++i) {
        base.push_back({static_cast<float>(i % kSide), static_cast<float>(i / kSide)});
        phase.push_back(uniform(rng, 0.0f, 6.28f));
        keys.push_back(bp.createProxy({base.back(), base.back() + Vec2{0.7f, 0.7f}},
                                      BodyType::Dynamic, 1, static_cast<std::uint64_t>(i)));
    }
    auto accept = [](std::uint64_t, std::uint64_t) { return true; };
    bp.updatePairs(accept);
    int moved = 0;
    for (int frame = 1; frame <= 60; ++frame) {
        for (std::size_t i = 0; i < keys.size(); ++i) {
            const float t = 0.1f * static_cast<float>(frame) + phase[i];
            const Vec2 p = base[i] + Vec2{0.3f * std::sin(t), 0.3f * std::cos(t)};
            moved += bp.moveProxy(keys[i], {p, p + Vec2{0.7f, 0.7f}}) ? 1 : 0;
        }
        bp.updatePairs(accept);
        bp.prunePairs();
        const auto& tree = bp.tree(BodyType::Dynamic);
        ASSERT_TRUE(tree.validate()) << "frame " << frame;
        e2d::physics::DynamicTree fresh = tree;
        fresh.rebuild();
        ASSERT_LE(tree.areaRatio(), 1.25f * fresh.areaRatio()) << "frame " << frame;
    }
    EXPECT_GT(moved, 60 * kSide * kSide / 10); // the motion really leaves the fat boxes
}

TEST(BroadPhase, RejectsBadInput) {
    BroadPhase bp;
    EXPECT_THROW(bp.createProxy({{0, 0}, {1, 1}}, BodyType::Dynamic, 1, std::uint64_t{1} << 32),
                 e2d::core::Error);
    EXPECT_THROW(bp.destroyProxy(7), e2d::core::Error);
    EXPECT_THROW(bp.moveProxy(-1, {{0, 0}, {1, 1}}), e2d::core::Error);
    const int key = bp.createProxy({{0, 0}, {1, 1}}, BodyType::Dynamic, 1, 0);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(bp.moveProxy(key, {{nan, 0}, {1, 1}}), e2d::core::Error);
    EXPECT_EQ(bp.moveCount(), 1);
    EXPECT_TRUE(bp.tree(BodyType::Dynamic).validate());
}

// The World's slot storage: contents survive growth on the heap, the move to a mapping past
// 256 KiB and the mapping's growth; new slots are value-initialised; moving hands the block over.
TEST(SlotArray, KeepsItsContentsThroughEveryKindOfGrowth) {
    struct Slot {
        int value = 7;
        double weight = 0.5;
        char pad[100] = {};
    };
    e2d::physics::detail::SlotArray<Slot> slots;
    EXPECT_TRUE(slots.empty());
    constexpr std::size_t kCount = 20000; // 2.2 MB: heap, then mapped, then remapped
    for (std::size_t i = 0; i < kCount; ++i) {
        Slot& s = slots.emplace_back();
        ASSERT_EQ(s.value, 7) << i;
        ASSERT_EQ(s.weight, 0.5) << i;
        s.value = static_cast<int>(i);
        s.pad[99] = static_cast<char>(i & 0x7F);
        ASSERT_GE(slots.capacity(), slots.size());
    }
    ASSERT_EQ(slots.size(), kCount);
    for (std::size_t i = 0; i < kCount; ++i) {
        ASSERT_EQ(slots[i].value, static_cast<int>(i));
        ASSERT_EQ(slots[i].pad[99], static_cast<char>(i & 0x7F));
    }
    e2d::physics::detail::SlotArray<Slot> moved(std::move(slots));
    EXPECT_EQ(moved.size(), kCount);
    EXPECT_EQ(moved[kCount - 1].value, static_cast<int>(kCount - 1));
    e2d::physics::detail::SlotArray<Slot> assigned;
    assigned.reserve(10);
    assigned = std::move(moved);
    EXPECT_EQ(assigned.size(), kCount);
    EXPECT_EQ(assigned[12345].value, 12345);
    // reserve() beyond the size keeps the contents too.
    assigned.reserve(3 * kCount);
    EXPECT_GE(assigned.capacity(), 3 * kCount);
    EXPECT_EQ(assigned[kCount / 2].value, static_cast<int>(kCount / 2));
}
