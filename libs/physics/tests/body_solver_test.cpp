// SPDX-License-Identifier: MIT
// The integration loops take four bodies a register where the target has SSE2, and eight where
// the machine has AVX2: every body must come out as the one-body (scalar) loop leaves it, bit
// for bit, the rare paths (a speed over the cap, a non-finite value, a body already held still,
// a rotation that does not normalise) mixed into groups of ordinary bodies included, and groups
// of ordinary bodies alone (which take the lanes' own path).
#include "../src/body_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

namespace e2d::physics::detail {
namespace {

constexpr float kH = 1.0f / 240.0f;
constexpr float kMaxSpeed = 400.0f;

struct Bodies {
    std::vector<BodySim> sims;
    std::vector<BodyState> states;
};

// Mostly ordinary bodies; every `rareEvery`-th one takes one of the rare cases.
Bodies makeBodies(int count, unsigned seed, int rareEvery = 7) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    Bodies b;
    for (int i = 0; i < count; ++i) {
        BodySim sim;
        sim.velocityStep = {0.01f * unit(random), -0.04f + 0.01f * unit(random)};
        sim.angularVelocityStep = 0.01f * unit(random);
        sim.linearDampingFactor = i % 3 == 0 ? 1.0f : 1.0f / (1.0f + 0.1f * (1.0f + unit(random)));
        sim.angularDampingFactor = i % 5 == 0 ? 1.0f : 1.0f / (1.0f + 0.2f * (1.0f + unit(random)));
        BodyState st;
        st.linearVelocity = {10.0f * unit(random), 10.0f * unit(random)};
        st.angularVelocity = 20.0f * unit(random);
        st.deltaPosition = {0.1f * unit(random), 0.1f * unit(random)};
        const float angle = 3.0f * unit(random);
        st.deltaRotation = {std::cos(angle), std::sin(angle)};
        switch (i % rareEvery == rareEvery - 1 ? (i / rareEvery) % 7 : -1) {
        case 0:
            st.linearVelocity = {900.0f, -700.0f}; // over the speed cap
            break;
        case 1:
            st.angularVelocity = 1e6f; // over the turn cap (clamped in the lanes too)
            break;
        case 2:
            st.linearVelocity.x = std::numeric_limits<float>::quiet_NaN();
            break;
        case 3:
            sim.velocityStep.y = std::numeric_limits<float>::infinity();
            break;
        case 4:
            st.flags = kNonFinite;
            break;
        case 5:
            st.deltaRotation = {0.0f, 0.0f}; // does not normalise
            st.angularVelocity = 0.0f;
            break;
        case 6:
            st.linearVelocity = {3e19f, 3e19f}; // its square overflows
            break;
        default:
            break;
        }
        b.sims.push_back(sim);
        b.states.push_back(st);
    }
    return b;
}

void expectSameStates(const std::vector<BodyState>& got, const std::vector<BodyState>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        EXPECT_EQ(std::memcmp(&got[i], &want[i], sizeof(BodyState)), 0)
            << "body " << i << ": v (" << got[i].linearVelocity.x << ", " << got[i].linearVelocity.y
            << ") w " << got[i].angularVelocity << ", want (" << want[i].linearVelocity.x << ", "
            << want[i].linearVelocity.y << ") w " << want[i].angularVelocity;
    }
}

TEST(BodySolver, IntegrationLoopsMatchOneBodyAtATime) {
    // Every seventh body rare: no group of eight is free of one. Every 40th: most groups are.
    for (const auto& [count, rareEvery] : {std::pair{1, 7},
                                           {3, 7},
                                           {4, 7},
                                           {7, 7},
                                           {8, 7},
                                           {50, 7},
                                           {101, 7},
                                           {8, 40},
                                           {13, 40},
                                           {203, 40}}) {
        Bodies all = makeBodies(count, static_cast<unsigned>(count), rareEvery);
        Bodies alone = all;
        for (int subStep = 0; subStep < 4; ++subStep) {
            integrateVelocities(std::span<const BodySim>(all.sims), all.states, kH, kMaxSpeed);
            integratePositions(all.states, kH, kMaxSpeed);
            for (std::size_t i = 0; i < alone.states.size(); ++i) {
                integrateVelocities(std::span<const BodySim>(&alone.sims[i], 1),
                                    std::span<BodyState>(&alone.states[i], 1), kH, kMaxSpeed);
                integratePositions(std::span<BodyState>(&alone.states[i], 1), kH, kMaxSpeed);
            }
            expectSameStates(all.states, alone.states);
        }
    }
}

TEST(BodySolver, IndexedIntegrationLoopsMatchOneBodyAtATime) {
    // A block's bodies: a subset of the states, in any order.
    Bodies all = makeBodies(120, 5, 11);
    Bodies alone = all;
    std::vector<int> indices;
    for (int i = 0; i < 120; i += 1 + i % 3) {
        indices.push_back(i);
    }
    std::shuffle(indices.begin(), indices.end(), std::mt19937(9));
    for (int subStep = 0; subStep < 4; ++subStep) {
        integrateVelocities(std::span<const BodySim>(all.sims), all.states, indices, kH, kMaxSpeed);
        integratePositions(all.states, indices, kH, kMaxSpeed);
        for (int i : indices) {
            const std::span<const int> one(&i, 1);
            integrateVelocities(std::span<const BodySim>(alone.sims), alone.states, one, kH,
                                kMaxSpeed);
            integratePositions(alone.states, one, kH, kMaxSpeed);
        }
        expectSameStates(all.states, alone.states);
    }
}

TEST(BodySolver, BlockIntegrationMatchesTheIndexedLoops) {
    // A block's bodies in increasing order: one run of the arrays (read in place), and the same
    // with one body left out, which is no run (through the indices). The bodies outside the
    // block must stay as they were either way.
    std::vector<int> run;
    for (int i = 10; i < 61; ++i) {
        run.push_back(i);
    }
    std::vector<int> gapped = run;
    gapped.erase(gapped.begin() + 20);
    for (const std::vector<int>* indices : {&run, &gapped}) {
        Bodies block = makeBodies(80, 3, 9);
        Bodies indexed = block;
        for (int subStep = 0; subStep < 4; ++subStep) {
            integrateBlockVelocities(block.sims, block.states, *indices, kH, kMaxSpeed);
            integrateBlockPositions(block.states, *indices, kH, kMaxSpeed);
            integrateVelocities(std::span<const BodySim>(indexed.sims), indexed.states, *indices,
                                kH, kMaxSpeed);
            integratePositions(indexed.states, *indices, kH, kMaxSpeed);
            expectSameStates(block.states, indexed.states);
        }
    }
}

TEST(BodySolver, FinalizePositionsMatchesOneBodyAtATime) {
    // Four bodies a register where the target has SSE2, eight with AVX2: each must end as the
    // one-body call leaves it, bit for bit, a rotation that does not normalise (zero) included,
    // flagged kIsFast exactly when movedFast() says so.
    for (int count : {1, 4, 7, 13, 8, 21}) {
        Bodies all = makeBodies(count, static_cast<unsigned>(100 + count));
        std::mt19937 random(static_cast<unsigned>(count));
        std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
        for (std::size_t i = 0; i < all.sims.size(); ++i) {
            BodySim& sim = all.sims[i];
            sim.center0 = {100.0f * unit(random), 50.0f * unit(random)};
            const float angle = 3.0f * unit(random);
            sim.rotation0 = {std::cos(angle), std::sin(angle)};
            sim.localCenter =
                i % 3 == 0 ? Vec2{0.0f, 0.0f} : Vec2{0.5f * unit(random), 0.5f * unit(random)};
            // Shapes from 0.05 to 0.5 m across: some bodies move fast (deltaPosition up to 0.1 m
            // a step), most do not; one in five is a bullet.
            sim.minExtent = 0.05f + 0.2f * (1.0f + unit(random));
            sim.maxExtent = sim.minExtent + 0.1f * (1.0f + unit(random));
            sim.flags = i % 5 == 4 ? std::uint32_t{kIsBullet} : 0u;
        }
        if (count > 2) {
            all.states[2].deltaRotation = {0.0f, 0.0f}; // stays unnormalised
        }
        Bodies alone = all;
        const bool sweeps = finalizePositions(all.sims, all.states);
        bool sweepsAlone = false;
        for (std::size_t i = 0; i < alone.sims.size(); ++i) {
            sweepsAlone = finalizePositions(std::span<BodySim>(&alone.sims[i], 1),
                                            std::span<const BodyState>(&alone.states[i], 1)) ||
                          sweepsAlone;
        }
        EXPECT_EQ(sweeps, sweepsAlone) << count << " bodies";
        int fast = 0;
        for (std::size_t i = 0; i < all.sims.size(); ++i) {
            const BodySim& sim = all.sims[i];
            const bool moved = movedFast(sim.center - sim.center0, all.states[i].deltaRotation.s,
                                         sim.maxExtent, sim.minExtent);
            EXPECT_EQ((sim.flags & kIsFast) != 0, moved) << "body " << i << " of " << count;
            fast += moved ? 1 : 0;
        }
        if (count >= 8) {
            EXPECT_GT(fast, 0) << "no fast body among " << count;
            EXPECT_LT(fast, count) << "no slow body among " << count;
        }
        for (std::size_t i = 0; i < all.sims.size(); ++i) {
            EXPECT_EQ(std::memcmp(&all.sims[i], &alone.sims[i], sizeof(BodySim)), 0)
                << "body " << i << " of " << count << ": p (" << all.sims[i].transform.p.x << ", "
                << all.sims[i].transform.p.y << "), want (" << alone.sims[i].transform.p.x << ", "
                << alone.sims[i].transform.p.y << ")";
        }
    }
}

} // namespace
} // namespace e2d::physics::detail
