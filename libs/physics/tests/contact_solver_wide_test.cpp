// SPDX-License-Identifier: MIT
// The level schedule and the wide soft-step contact passes: solving level by level, four or
// eight constraints at a time, must give exactly what the scalar passes give in constraint order.
#include "../src/constraint_graph.hpp"
#include "../src/contact_solver.hpp"
#include "../src/contact_solver_wide.hpp"
#include "world_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace e2d::physics::detail {
namespace {

TEST(ConstraintLevels, EachConstraintGoesOneAboveItsBodiesLastLevel) {
    ConstraintLevels levels;
    levels.reset(4);
    // Body chain 0-1-2-3, then each end against the ground (-1).
    EXPECT_EQ(levels.assign(0, 1), 0);
    EXPECT_EQ(levels.assign(1, 2), 1); // after (0,1) on body 1
    EXPECT_EQ(levels.assign(2, 3), 2); // after (1,2) on body 2
    EXPECT_EQ(levels.assign(0, -1), 1); // after (0,1) on body 0
    EXPECT_EQ(levels.assign(3, -1), 3); // after (2,3) on body 3
    EXPECT_EQ(levels.assign(-1, -1), 0); // nothing to wait for
    const std::vector<int> expected{2, 2, 1, 1};
    EXPECT_EQ(levels.counts(), expected);
    EXPECT_EQ(levels.levelCount(), 4);

    levels.reset(2);
    EXPECT_EQ(levels.levelCount(), 0);
    EXPECT_EQ(levels.assign(1, 0), 0);
}

struct Problem {
    std::vector<ContactConstraint> constraints;
    std::vector<BodyState> states;
};

// A random pile: bodies with random velocities and motion since the step began, contacts
// between random pairs (some against a static side, some with one point, some speculative).
Problem randomProblem(std::uint32_t seed, int bodyCount, int contactCount, float h) {
    test::Random rng(seed);
    Problem p;
    std::vector<Vec2> invMass;
    std::vector<float> invInertia;
    for (int i = 0; i < bodyCount; ++i) {
        BodyState s;
        s.linearVelocity = {rng.uniform(-2.0f, 2.0f), rng.uniform(-2.0f, 2.0f)};
        s.angularVelocity = rng.uniform(-3.0f, 3.0f);
        s.deltaPosition = {rng.uniform(-0.01f, 0.01f), rng.uniform(-0.01f, 0.01f)};
        s.deltaRotation = Rot::fromAngle(rng.uniform(-0.02f, 0.02f));
        p.states.push_back(s);
        // One body in eight is locked on an axis, as lockX / lockY leave it.
        float m = rng.uniform(0.2f, 2.0f);
        int lock = rng.below(8);
        invMass.push_back({lock == 0 ? 0.0f : m, lock == 1 ? 0.0f : m});
        invInertia.push_back(rng.uniform(0.5f, 6.0f));
    }
    const Softness dynamic = makeSoftness(30.0f, 10.0f, h);
    const Softness vsStatic = makeSoftness(60.0f, 10.0f, h);
    for (int k = 0; k < contactCount; ++k) {
        int a = rng.below(bodyCount);
        int b = rng.below(bodyCount - 1);
        b = b >= a ? b + 1 : b;
        bool staticA = rng.below(5) == 0;
        Manifold m;
        float angle = rng.uniform(0.0f, 6.2831853f);
        m.normal = {std::cos(angle), std::sin(angle)};
        m.pointCount = 1 + rng.below(2);
        for (int i = 0; i < m.pointCount; ++i) {
            ManifoldPoint& mp = m.points[i];
            mp.anchorA = {rng.uniform(-0.5f, 0.5f), rng.uniform(-0.5f, 0.5f)};
            mp.anchorB = {rng.uniform(-0.5f, 0.5f), rng.uniform(-0.5f, 0.5f)};
            mp.separation = rng.uniform(-0.05f, 0.03f);
            mp.normalImpulse = rng.uniform(0.0f, 1.0f);
            mp.tangentImpulse = rng.uniform(-0.3f, 0.3f);
        }
        ContactBodyView va;
        ContactBodyView vb;
        if (!staticA) {
            va.invMass = invMass[static_cast<std::size_t>(a)];
            va.invInertia = invInertia[static_cast<std::size_t>(a)];
            va.linearVelocity = p.states[static_cast<std::size_t>(a)].linearVelocity;
            va.angularVelocity = p.states[static_cast<std::size_t>(a)].angularVelocity;
            va.stateIndex = a;
        }
        vb.invMass = invMass[static_cast<std::size_t>(b)];
        vb.invInertia = invInertia[static_cast<std::size_t>(b)];
        vb.linearVelocity = p.states[static_cast<std::size_t>(b)].linearVelocity;
        vb.angularVelocity = p.states[static_cast<std::size_t>(b)].angularVelocity;
        vb.stateIndex = b;
        ContactConstraint& c = p.constraints.emplace_back();
        prepareContact(c, m, va, vb, {rng.uniform(0.1f, 1.0f), 0.0f, 0.0f},
                       staticA ? vsStatic : dynamic);
    }
    return p;
}

void expectSame(const Problem& scalar, const Problem& wide) {
    ASSERT_EQ(scalar.states.size(), wide.states.size());
    for (std::size_t i = 0; i < scalar.states.size(); ++i) {
        EXPECT_EQ(scalar.states[i].linearVelocity.x, wide.states[i].linearVelocity.x) << "body " << i;
        EXPECT_EQ(scalar.states[i].linearVelocity.y, wide.states[i].linearVelocity.y) << "body " << i;
        EXPECT_EQ(scalar.states[i].angularVelocity, wide.states[i].angularVelocity) << "body " << i;
    }
    for (std::size_t k = 0; k < scalar.constraints.size(); ++k) {
        const ContactConstraint& s = scalar.constraints[k];
        const ContactConstraint& w = wide.constraints[k];
        for (int i = 0; i < s.pointCount; ++i) {
            EXPECT_EQ(s.points[i].normalImpulse, w.points[i].normalImpulse) << k << "/" << i;
            EXPECT_EQ(s.points[i].tangentImpulse, w.points[i].tangentImpulse) << k << "/" << i;
            EXPECT_EQ(s.points[i].maxNormalImpulse, w.points[i].maxNormalImpulse) << k << "/" << i;
            EXPECT_EQ(s.points[i].relativeVelocity, w.points[i].relativeVelocity) << k << "/" << i;
            EXPECT_EQ(s.points[i].impactSeen, w.points[i].impactSeen) << k << "/" << i;
            EXPECT_EQ(s.points[i].impactGap, w.points[i].impactGap) << k << "/" << i;
        }
    }
}

TEST(WideContactSolver, MatchesTheScalarPassesBitForBit) {
    constexpr float kH = 1.0f / 240.0f;
    constexpr float kPushMaxSpeed = 3.0f;
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        Problem scalar = randomProblem(seed, 40, 150, kH);
        Problem wide = scalar;

        // Reference: warm start, a biased sweep forward and a relax sweep backward, four times,
        // the last two with each constraint's points in reverse (all four orders the soft step
        // uses).
        for (int round = 0; round < 4; ++round) {
            bool reversePoints = round >= 2;
            warmStartContacts(scalar.constraints, scalar.states);
            solveContacts(scalar.constraints, scalar.states, 1.0f / kH, true, kPushMaxSpeed, false,
                          reversePoints);
            solveContacts(scalar.constraints, scalar.states, 1.0f / kH, false, kPushMaxSpeed, true,
                          reversePoints);
        }

        // The same by level, several at a time.
        ConstraintLevels levels;
        levels.reset(static_cast<int>(wide.states.size()));
        std::vector<int> levelOf;
        for (const ContactConstraint& c : wide.constraints) {
            levelOf.push_back(levels.assign(c.indexA, c.indexB));
        }
        std::vector<int> levelStart(static_cast<std::size_t>(levels.levelCount()) + 1, 0);
        for (int k = 0; k < levels.levelCount(); ++k) {
            levelStart[static_cast<std::size_t>(k) + 1] =
                levelStart[static_cast<std::size_t>(k)] + levels.counts()[static_cast<std::size_t>(k)];
        }
        // A body in a random pile of 40 takes part in several contacts: several levels, and
        // levels that do not fill a multiple of four lanes.
        EXPECT_GT(levels.levelCount(), 3);
        std::vector<int> next(levelStart.begin(), levelStart.end() - 1);
        std::vector<int> order(wide.constraints.size());
        for (std::size_t k = 0; k < levelOf.size(); ++k) {
            order[static_cast<std::size_t>(next[static_cast<std::size_t>(levelOf[k])]++)] =
                static_cast<int>(k);
        }
        const Problem unsolved = wide;
        // Four lanes everywhere; eight where the CPU has AVX2.
        for (int lanes : {4, 8}) {
            if (lanes > bestWideLanes()) {
                continue;
            }
            wide = unsolved;
            WideContacts packed;
            prepareWide(packed, wide.constraints, order, levelStart, lanes);
            ASSERT_EQ(packed.lanes, lanes);
            for (int round = 0; round < 4; ++round) {
                bool reversePoints = round >= 2;
                warmStartWide(packed, wide.states);
                solveWide(packed, wide.states, 1.0f / kH, true, kPushMaxSpeed, false, reversePoints);
                solveWide(packed, wide.states, 1.0f / kH, false, kPushMaxSpeed, true, reversePoints);
            }
            storeWide(packed, wide.constraints, order, levelStart);

            SCOPED_TRACE(seed);
            SCOPED_TRACE(lanes);
            expectSame(scalar, wide);
        }
        // And the solve did something: impulses changed from the warm-start values.
        int changed = 0;
        Problem initial = randomProblem(seed, 40, 150, kH);
        for (std::size_t k = 0; k < initial.constraints.size(); ++k) {
            changed += initial.constraints[k].points[0].normalImpulse !=
                               wide.constraints[k].points[0].normalImpulse
                           ? 1
                           : 0;
        }
        EXPECT_GT(changed, 100);
    }
}

} // namespace
} // namespace e2d::physics::detail
