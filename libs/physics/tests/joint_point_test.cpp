// SPDX-License-Identifier: MIT
// Plain hinges solved four or eight at a time (PointJointLanes) against the revolute joint's
// own passes in slot order: the same bits.
#include "../src/joint_solver.hpp"

#include <e2d/physics/solver_def.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <random>
#include <vector>

namespace e2d::physics::detail {
namespace {

float uniform(std::mt19937& rng, float lo, float hi) {
    return lo + static_cast<float>(static_cast<double>(rng()) / 4294967296.0) * (hi - lo);
}

struct Scene {
    std::vector<BodyState> states;
    std::vector<Joint> joints;
};

// Bodies with random motion; joints between random pairs (a side may be fixed, -1), most of
// them plain hinges, some with a motor or a limit (solved one by one), prepared fields random.
Scene randomScene(std::uint32_t seed, int bodies, int jointCount) {
    std::mt19937 rng(seed);
    Scene s;
    for (int i = 0; i < bodies; ++i) {
        BodyState st;
        st.linearVelocity = {uniform(rng, -5, 5), uniform(rng, -5, 5)};
        st.angularVelocity = uniform(rng, -3, 3);
        st.flags = rng() & 7u;
        st.deltaPosition = {uniform(rng, -0.1f, 0.1f), uniform(rng, -0.1f, 0.1f)};
        st.deltaRotation = Rot::fromAngle(uniform(rng, -0.2f, 0.2f));
        s.states.push_back(st);
    }
    for (int k = 0; k < jointCount; ++k) {
        Joint j;
        j.type = JointType::Revolute;
        j.alive = true;
        int a = static_cast<int>(rng() % static_cast<std::uint32_t>(bodies + 1)) - 1;
        int b = static_cast<int>(rng() % static_cast<std::uint32_t>(bodies));
        if (a == b) {
            a = -1;
        }
        j.indexA = a;
        j.indexB = b;
        const float mA = a < 0 ? 0.0f : uniform(rng, 0.1f, 2.0f);
        const float mB = uniform(rng, 0.1f, 2.0f);
        j.invMassA = {mA, (rng() % 5 == 0) ? 0.0f : mA}; // a locked axis now and then
        j.invMassB = {mB, mB};
        j.invInertiaA = a < 0 ? 0.0f : uniform(rng, 0.0f, 3.0f);
        j.invInertiaB = uniform(rng, 0.0f, 3.0f);
        j.anchorA = {uniform(rng, -1, 1), uniform(rng, -1, 1)};
        j.anchorB = {uniform(rng, -1, 1), uniform(rng, -1, 1)};
        j.deltaCenter = {uniform(rng, -2, 2), uniform(rng, -2, 2)};
        j.linearImpulse = {uniform(rng, -0.5f, 0.5f), uniform(rng, -0.5f, 0.5f)};
        j.angularMass = 1.0f / (j.invInertiaA + j.invInertiaB + 1e-3f);
        j.axialMass = j.angularMass;
        if (rng() % 6 == 0) {
            j.enableMotor = true;
            j.motorSpeed = uniform(rng, -2, 2);
            j.maxMotorForce = uniform(rng, 0, 50);
            j.motorImpulse = uniform(rng, -0.1f, 0.1f);
        } else if (rng() % 6 == 0) {
            j.enableLimit = true;
            j.lower = uniform(rng, -1, 0);
            j.upper = uniform(rng, 0, 1);
            j.angle0 = uniform(rng, -1.2f, 1.2f);
        }
        s.joints.push_back(j);
    }
    return s;
}

// Slot order in levels (a joint one above its bodies' last level), stably sorted by level.
void levelOrder(const Scene& s, std::vector<int>& slots, std::vector<int>& levels) {
    std::vector<int> last(s.states.size(), -1);
    std::vector<int> level(s.joints.size());
    for (std::size_t k = 0; k < s.joints.size(); ++k) {
        const Joint& j = s.joints[k];
        const int a = j.indexA < 0 ? -1 : last[static_cast<std::size_t>(j.indexA)];
        const int b = j.indexB < 0 ? -1 : last[static_cast<std::size_t>(j.indexB)];
        level[k] = std::max(a, b) + 1;
        if (j.indexA >= 0) {
            last[static_cast<std::size_t>(j.indexA)] = level[k];
        }
        if (j.indexB >= 0) {
            last[static_cast<std::size_t>(j.indexB)] = level[k];
        }
    }
    slots.resize(s.joints.size());
    for (std::size_t k = 0; k < slots.size(); ++k) {
        slots[k] = static_cast<int>(k);
    }
    std::stable_sort(slots.begin(), slots.end(), [&](int x, int y) {
        return level[static_cast<std::size_t>(x)] < level[static_cast<std::size_t>(y)];
    });
    levels.clear();
    for (int k : slots) {
        levels.push_back(level[static_cast<std::size_t>(k)]);
    }
}

// A soft step's joint passes: warm start, solve, two relaxations, twice.
void runPasses(Scene& s, PointJointGroups& groups, std::span<const int> order) {
    const float h = 1.0f / 240.0f;
    const JointStep step{
        h, 1.0f / h,
        makeSoftness(physics::SolverDef{}.jointHertz, physics::SolverDef{}.jointDampingRatio, h)};
    for (int sub = 0; sub < 2; ++sub) {
        warmStartJoints(s.joints, groups, order, s.states);
        solveJoints(s.joints, groups, order, s.states, step, true);
        solveJoints(s.joints, groups, order, s.states, step, false);
        solveJoints(s.joints, groups, order, s.states, step, false);
    }
}

// The slots of the lanes of the group that pass entry `entry` (< 0) names (-1: padding).
std::vector<int> groupSlots(const PointJointGroups& groups, int entry) {
    const auto index = static_cast<std::size_t>(~entry >> 1);
    if ((~entry & 1) != 0) {
        return {std::begin(groups.octets.at(index).slot), std::end(groups.octets.at(index).slot)};
    }
    return {std::begin(groups.quads.at(index).slot), std::end(groups.quads.at(index).slot)};
}

// Four lanes everywhere, eight where this CPU has them (bestPointJointLanes()).
std::vector<int> laneWidths() {
    std::vector<int> widths{4};
    if (bestPointJointLanes() == 8) {
        widths.push_back(8);
    }
    return widths;
}

void matchSlotOrder(int lanes) {
    for (std::uint32_t seed : {1u, 2u, 3u, 4u}) {
        SCOPED_TRACE(testing::Message() << lanes << " lanes, seed " << seed);
        Scene reference = randomScene(seed, 60, 150);
        Scene packed = reference;

        std::vector<int> slotOrder(reference.joints.size());
        for (std::size_t k = 0; k < slotOrder.size(); ++k) {
            slotOrder[k] = static_cast<int>(k);
        }
        PointJointGroups none;
        runPasses(reference, none, slotOrder);

        std::vector<int> slots;
        std::vector<int> levels;
        levelOrder(packed, slots, levels);
        PointJointGroups groups;
        groups.lanes = lanes;
        std::vector<int> entries;
        packJointPasses(packed.joints, slots, levels, true, groups, entries);
        // Eight lanes: octets, and quads for levels' last two to four hinges.
        EXPECT_FALSE(groups.quads.empty());
        EXPECT_EQ(groups.octets.empty(), lanes == 4);
        // Most joints went into groups; every joint is in exactly one entry or lane.
        std::vector<int> seen(packed.joints.size(), 0);
        int slotHinges = 0; // a level's lone leftover hinge stays a slot
        std::vector<bool> inQuad(packed.joints.size(), false);
        for (int e : entries) {
            if (e >= 0) {
                ++seen[static_cast<std::size_t>(e)];
                slotHinges += isPointJoint(packed.joints[static_cast<std::size_t>(e)]) ? 1 : 0;
            } else {
                for (int slot : groupSlots(groups, e)) {
                    if (slot >= 0) {
                        ++seen[static_cast<std::size_t>(slot)];
                        inQuad[static_cast<std::size_t>(slot)] = true;
                        EXPECT_TRUE(isPointJoint(packed.joints[static_cast<std::size_t>(slot)]));
                    }
                }
            }
        }
        EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
        EXPECT_LE(slotHinges, levels.back() + 1);
        EXPECT_GT(std::count(inQuad.begin(), inQuad.end(), true),
                  static_cast<long>(packed.joints.size() / 2));

        runPasses(packed, groups, entries);
        storePointJointGroups(groups, packed.joints, 240.0f);

        for (std::size_t i = 0; i < reference.states.size(); ++i) {
            EXPECT_EQ(std::memcmp(&reference.states[i], &packed.states[i], sizeof(BodyState)), 0)
                << "seed " << seed << " body " << i;
        }
        for (std::size_t k = 0; k < reference.joints.size(); ++k) {
            Joint& r = reference.joints[k];
            const Joint& p = packed.joints[k];
            if (inQuad[k]) {
                // The quads' reactions are storeJointReaction()'s.
                storeJointReaction(r, reference.states, 240.0f);
                EXPECT_EQ(std::memcmp(&r.reactionForce, &p.reactionForce, sizeof(Vec2)), 0)
                    << "joint " << k;
                EXPECT_EQ(r.reactionTorque, p.reactionTorque);
            }
            EXPECT_EQ(std::memcmp(&r.linearImpulse, &p.linearImpulse, sizeof(Vec2)), 0)
                << "seed " << seed << " joint " << k;
            EXPECT_EQ(r.motorImpulse, p.motorImpulse);
            EXPECT_EQ(r.lowerImpulse, p.lowerImpulse);
            EXPECT_EQ(r.upperImpulse, p.upperImpulse);
        }
        // The passes did something.
        const Scene before = randomScene(seed, 60, 150);
        int changed = 0;
        for (std::size_t i = 0; i < before.states.size(); ++i) {
            changed +=
                before.states[i].linearVelocity != reference.states[i].linearVelocity ? 1 : 0;
        }
        EXPECT_GT(changed, 50);
    }
}

} // namespace

TEST(PointJointQuads, MatchTheRevoluteJointsPassesInSlotOrderBitForBit) {
    for (int lanes : laneWidths()) {
        matchSlotOrder(lanes);
    }
}

// A level of n plain hinges goes into eights while five or more are left (eight lanes), then
// fours; a lone one left over stays a slot.
TEST(PointJointQuads, ALevelsHingesFillEightsThenFoursAndLeaveALoneOneAlone) {
    struct Expected {
        int octets, quads, slots;
    };
    for (int lanes : {4, 8}) {
        for (int n = 1; n <= 21; ++n) {
            SCOPED_TRACE(testing::Message() << lanes << " lanes, " << n << " hinges");
            Scene s;
            s.states.resize(static_cast<std::size_t>(2 * n));
            for (int k = 0; k < n; ++k) {
                Joint j;
                j.type = JointType::Revolute;
                j.indexA = 2 * k;
                j.indexB = 2 * k + 1;
                s.joints.push_back(j);
            }
            std::vector<int> slots;
            std::vector<int> levels;
            levelOrder(s, slots, levels);
            ASSERT_EQ(levels.back(), 0); // one level: the hinges share no body
            PointJointGroups groups;
            groups.lanes = lanes;
            std::vector<int> entries;
            packJointPasses(s.joints, slots, levels, true, groups, entries);
            // From first principles: eights while >= 5 are left (the last one padded), then
            // fours while >= 2 are left, a last single one alone.
            Expected want{0, 0, 0};
            int left = n;
            while (lanes == 8 && left >= 5) {
                ++want.octets;
                left -= std::min(left, 8);
            }
            while (left >= 2) {
                ++want.quads;
                left -= std::min(left, 4);
            }
            want.slots = left;
            EXPECT_EQ(static_cast<int>(groups.octets.size()), want.octets);
            EXPECT_EQ(static_cast<int>(groups.quads.size()), want.quads);
            EXPECT_EQ(static_cast<int>(std::count_if(entries.begin(), entries.end(),
                                                     [](int e) { return e >= 0; })),
                      want.slots);
            EXPECT_EQ(entries.size(), groups.size() + static_cast<std::size_t>(want.slots));
        }
    }
}

TEST(PointJointQuads, EightLanesWhereTheCpuHasAvx2) {
#if defined(__x86_64__)
    EXPECT_EQ(bestPointJointLanes(), __builtin_cpu_supports("avx2") ? 8 : 4);
#else
    EXPECT_EQ(bestPointJointLanes(), 4);
#endif
}

namespace {

TEST(PointJointQuads, WithoutQuadsThePassesAreTheSlotsInOrder) {
    Scene s = randomScene(9, 30, 60);
    std::vector<int> slots;
    std::vector<int> levels;
    levelOrder(s, slots, levels);
    for (int lanes : laneWidths()) {
        PointJointGroups groups;
        groups.lanes = lanes;
        std::vector<int> entries;
        packJointPasses(s.joints, slots, levels, false, groups, entries);
        EXPECT_EQ(groups.size(), 0u);
        EXPECT_EQ(entries, slots);
    }
}

} // namespace
} // namespace e2d::physics::detail
