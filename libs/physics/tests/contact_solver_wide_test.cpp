// SPDX-License-Identifier: MIT
// The level schedule and the wide soft-step contact passes: solving level by level, four or
// eight constraints at a time, must give exactly what the scalar passes give in constraint order.
#include "../src/body_solver.hpp"
#include "../src/constraint_graph.hpp"
#include "../src/contact_solver.hpp"
#include "../src/contact_solver_wide.hpp"
#include "world_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <map>
#include <set>
#include <vector>

namespace e2d::physics::detail {
namespace {

TEST(ConstraintLevels, EachConstraintGoesOneAboveItsBodiesLastLevel) {
    ConstraintLevels levels;
    levels.reset(4);
    // Body chain 0-1-2-3, then each end against the ground (-1).
    EXPECT_EQ(levels.assign(0, 1), 0);
    EXPECT_EQ(levels.assign(1, 2), 1);   // after (0,1) on body 1
    EXPECT_EQ(levels.assign(2, 3), 2);   // after (1,2) on body 2
    EXPECT_EQ(levels.assign(0, -1), 1);  // after (0,1) on body 0
    EXPECT_EQ(levels.assign(3, -1), 3);  // after (2,3) on body 3
    EXPECT_EQ(levels.assign(-1, -1), 0); // nothing to wait for
    const std::vector<int> expected{2, 2, 1, 1};
    EXPECT_EQ(levels.counts(), expected);
    EXPECT_EQ(levels.levelCount(), 4);

    levels.reset(2);
    EXPECT_EQ(levels.levelCount(), 0);
    EXPECT_EQ(levels.assign(1, 0), 0);
}

TEST(ConstraintColors, AColumnIsTwoColoursAndTheGroundNeverTakesColourZero) {
    using Colors = ConstraintColors;
    Colors colors;
    colors.reset(20);
    // A column on the ground (-1), in contact order: the ground contact first, then each box on
    // the one below.
    EXPECT_EQ(colors.assign(-1, 0), 1); // a static side skips colour 0
    for (int i = 0; i + 1 < 20; ++i) {
        EXPECT_EQ(colors.assign(i, i + 1), i % 2) << "contact " << i;
    }
    EXPECT_EQ(colors.assign(-1, -1), 0); // nothing moves

    // A body with more moving contacts than the colours of moving pairs: the rest overflow to
    // levels after the colours, one after another on that body; its static contacts still get
    // the colours kept for them.
    colors.reset(40);
    const int movingColors = Colors::kColorCount - Colors::kStaticOnlyColors;
    for (int i = 1; i <= movingColors; ++i) {
        EXPECT_EQ(colors.assign(0, i), i - 1);
    }
    EXPECT_EQ(colors.assign(0, movingColors + 1), Colors::kColorCount);
    EXPECT_EQ(colors.assign(movingColors + 2, 0), Colors::kColorCount + 1);
    EXPECT_EQ(colors.assign(0, -1), movingColors);
    EXPECT_EQ(colors.assign(-1, 1), 1); // body 1 has colour 0 only
}

TEST(ConstraintColors, AColoursConstraintsShareNoMovingBody) {
    test::Random rng(7);
    ConstraintColors colors;
    for (int round = 0; round < 20; ++round) {
        const int bodies = 2 + rng.below(60);
        colors.reset(bodies);
        std::map<int, std::set<int>> bodiesOf; // colour -> moving bodies
        for (int k = 0; k < 300; ++k) {
            const int a = rng.below(4) == 0 ? -1 : rng.below(bodies);
            int b = rng.below(bodies);
            b = b == a ? -1 : b;
            const int color = colors.assign(a, b);
            if (a < 0 || b < 0) {
                EXPECT_NE(color, 0) << "a static side never takes colour 0";
            } else {
                EXPECT_TRUE(color < ConstraintColors::kColorCount -
                                        ConstraintColors::kStaticOnlyColors ||
                            color >= ConstraintColors::kColorCount)
                    << "moving pairs leave the static-only colours, got " << color;
            }
            for (int side : {a, b}) {
                if (side >= 0) {
                    EXPECT_TRUE(bodiesOf[color].insert(side).second)
                        << "body " << side << " twice in colour " << color;
                }
            }
        }
    }
}

// What prepareContact() was given for one constraint.
struct PrepareInput {
    Manifold manifold;
    ContactBodyView a;
    ContactBodyView b;
    float friction = 0.0f;
    Softness softness;
};

struct Problem {
    // The softness of contacts against a rigid side (no mass, no inertia: a static side too)
    // and of the others, the world's pick (softnessFor()).
    Softness dynamic;
    Softness vsStatic;
    std::vector<ContactConstraint> constraints;
    std::vector<BodyState> states;
    std::vector<PrepareInput> inputs; // per constraint
};

// A random pile: bodies with random velocities and motion since the step began, contacts
// between random pairs (some against a static side, some speculative) of one or two points
// (maxPoints 1: one each, as circles make).
Problem randomProblem(std::uint32_t seed, int bodyCount, int contactCount, float h,
                      int maxPoints = 2) {
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
    p.dynamic = dynamic;
    p.vsStatic = vsStatic;
    for (int k = 0; k < contactCount; ++k) {
        int a = rng.below(bodyCount);
        int b = rng.below(bodyCount - 1);
        b = b >= a ? b + 1 : b;
        bool staticA = rng.below(5) == 0;
        Manifold m;
        float angle = rng.uniform(0.0f, 6.2831853f);
        m.normal = {std::cos(angle), std::sin(angle)};
        m.pointCount = 1 + rng.below(2);
        m.pointCount = std::min(m.pointCount, maxPoints);
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
        const PrepareInput& in = p.inputs.emplace_back(
            PrepareInput{m, va, vb, rng.uniform(0.1f, 1.0f), staticA ? vsStatic : dynamic});
        prepareContact(c, in.manifold, in.a, in.b, {in.friction, 0.0f, 0.0f}, in.softness);
    }
    return p;
}

// The constraints by level: each one's level in constraint order and the slots of each level
// (levelStart), level order within (order: the constraint of each slot).
struct Schedule {
    std::vector<int> levelStart;
    std::vector<int> order;
    int levelCount = 0;
};

Schedule scheduleOf(const Problem& p) {
    ConstraintLevels levels;
    levels.reset(static_cast<int>(p.states.size()));
    std::vector<int> levelOf;
    for (const ContactConstraint& c : p.constraints) {
        levelOf.push_back(levels.assign(c.indexA, c.indexB));
    }
    Schedule s;
    s.levelCount = levels.levelCount();
    s.levelStart.assign(static_cast<std::size_t>(s.levelCount) + 1, 0);
    for (int k = 0; k < s.levelCount; ++k) {
        s.levelStart[static_cast<std::size_t>(k) + 1] =
            s.levelStart[static_cast<std::size_t>(k)] +
            levels.counts()[static_cast<std::size_t>(k)];
    }
    std::vector<int> next(s.levelStart.begin(), s.levelStart.end() - 1);
    s.order.resize(p.constraints.size());
    for (std::size_t k = 0; k < levelOf.size(); ++k) {
        s.order[static_cast<std::size_t>(next[static_cast<std::size_t>(levelOf[k])]++)] =
            static_cast<int>(k);
    }
    return s;
}

void expectSame(const Problem& scalar, const Problem& wide) {
    ASSERT_EQ(scalar.states.size(), wide.states.size());
    for (std::size_t i = 0; i < scalar.states.size(); ++i) {
        EXPECT_EQ(scalar.states[i].linearVelocity.x, wide.states[i].linearVelocity.x)
            << "body " << i;
        EXPECT_EQ(scalar.states[i].linearVelocity.y, wide.states[i].linearVelocity.y)
            << "body " << i;
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

template <int N>
bool onePointLanes(const WideConstraintT<N>& g) {
    return g.twoPointLanes == 0;
}

// Random piles (randomProblem(seed, 40, 150, h, maxPoints)) solved by the scalar passes and by
// the wide ones at every lane width: the same bits.
void expectWideMatchesScalar(std::uint32_t seed, int maxPoints) {
    constexpr float kH = 1.0f / 240.0f;
    constexpr float kPushMaxSpeed = 3.0f;
    {
        Problem scalar = randomProblem(seed, 40, 150, kH, maxPoints);
        Problem wide = scalar;

        // Reference: the soft step's sub-step four times (warm start, a biased sweep forward,
        // the bodies moved, two relax sweeps backward), the last two with each constraint's
        // points in reverse (all four orders the soft step uses). The wide passes keep the
        // separations a relax sweep finds for the sweeps up to the next biased one: moving the
        // bodies in between checks that they are worked out again where they changed.
        constexpr float kMaxSpeed = 100.0f;
        for (int round = 0; round < 4; ++round) {
            bool reversePoints = round >= 2;
            warmStartContacts(scalar.constraints, scalar.states);
            solveContacts(scalar.constraints, scalar.states, 1.0f / kH, true, kPushMaxSpeed, false,
                          reversePoints);
            integratePositions(scalar.states, kH, kMaxSpeed);
            for (int relax = 0; relax < 2; ++relax) {
                solveContacts(scalar.constraints, scalar.states, 1.0f / kH, false, kPushMaxSpeed,
                              true, reversePoints);
            }
        }

        // The same by level, several at a time.
        const Schedule schedule = scheduleOf(wide);
        const std::vector<int>& levelStart = schedule.levelStart;
        const std::vector<int>& order = schedule.order;
        // A body in a random pile of 40 takes part in several contacts: several levels, and
        // levels that do not fill a multiple of four lanes.
        EXPECT_GT(schedule.levelCount, 3);
        const Problem unsolved = wide;
        // Four lanes everywhere; eight where the CPU has AVX2.
        for (int lanes : {4, 8}) {
            if (lanes > bestWideLanes()) {
                continue;
            }
            wide = unsolved;
            WideContacts packed;
            packed.dynamic = wide.dynamic;
            packed.vsStatic = wide.vsStatic;
            prepareWide(packed, wide.constraints, order, levelStart, lanes, wide.states);
            ASSERT_EQ(packed.lanes, lanes);
            // Groups of one-point lanes (only those) take their own passes.
            int onePointGroups = 0;
            for (const auto& g : packed.constraints4) {
                onePointGroups += onePointLanes(g) ? 1 : 0;
            }
            for (const auto& g : packed.constraints8) {
                onePointGroups += onePointLanes(g) ? 1 : 0;
            }
            if (maxPoints == 1) {
                EXPECT_EQ(onePointGroups, static_cast<int>(packed.constraints4.size() +
                                                           packed.constraints8.size()));
            } else {
                EXPECT_LT(onePointGroups, static_cast<int>(packed.constraints4.size() +
                                                           packed.constraints8.size()));
            }
            for (int round = 0; round < 4; ++round) {
                bool reversePoints = round >= 2;
                warmStartWide(packed);
                solveWide(packed, 1.0f / kH, true, kPushMaxSpeed, false, reversePoints);
                integratePositions(wide.states, kH, kMaxSpeed);
                for (int relax = 0; relax < 2; ++relax) {
                    solveWide(packed, 1.0f / kH, false, kPushMaxSpeed, true, reversePoints);
                }
            }
            storeWide(packed, wide.constraints, order, levelStart);

            SCOPED_TRACE(seed);
            SCOPED_TRACE(lanes);
            expectSame(scalar, wide);
        }
        // And the solve did something: impulses changed from the warm-start values.
        int changed = 0;
        Problem initial = randomProblem(seed, 40, 150, kH, maxPoints);
        for (std::size_t k = 0; k < initial.constraints.size(); ++k) {
            changed += initial.constraints[k].points[0].normalImpulse !=
                               wide.constraints[k].points[0].normalImpulse
                           ? 1
                           : 0;
        }
        EXPECT_GT(changed, 100);
    }
}

TEST(WideContactSolver, MatchesTheScalarPassesBitForBit) {
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        expectWideMatchesScalar(seed, 2);
    }
}

// Every lane with one point (a pile of circles): the groups skip the second point.
TEST(WideContactSolver, OnePointGroupsMatchTheScalarPassesBitForBit) {
    for (std::uint32_t seed : {7u, 8u}) {
        expectWideMatchesScalar(seed, 1);
    }
}

template <int N>
const std::vector<WideConstraintT<N>>& groupsOf(const WideContacts& wide) {
    if constexpr (N == 8) {
        return wide.constraints8;
    } else {
        return wide.constraints4;
    }
}

template <int N>
std::vector<WideConstraintT<N>>& groupsOf(WideContacts& wide) {
    if constexpr (N == 8) {
        return wide.constraints8;
    } else {
        return wide.constraints4;
    }
}

template <int N>
std::vector<WideImpactT<N>>& impactsOf(WideContacts& wide) {
    if constexpr (N == 8) {
        return wide.impacts8;
    } else {
        return wide.impacts4;
    }
}

// The softness the world gives a contact between `a` and `b`.
Softness softnessFor(const Problem& p, const ContactBodyView& a, const ContactBodyView& b) {
    auto rigid = [](const ContactBodyView& v) {
        return v.invMass.x == 0.0f && v.invMass.y == 0.0f && v.invInertia == 0.0f;
    };
    return rigid(a) || rigid(b) ? p.vsStatic : p.dynamic;
}

// The groups prepareWideGroup() makes from gathered lanes, byte for byte the ones
// prepareContact() and packWideLane() make one constraint at a time, and the lanes it finds
// pushed apart, isPushedApart()'s; counts those (pushed) and the others with a point deeper
// than the slop (held: their load explains it).
template <int N>
void expectSameGroups(const Problem& p, const Schedule& schedule, int& pushed, int& held) {
    std::vector<BodyState> states = p.states;
    WideContacts reference;
    reference.dynamic = p.dynamic;
    reference.vsStatic = p.vsStatic;
    prepareWide(reference, p.constraints, schedule.order, schedule.levelStart, N, states);
    WideContacts gathered;
    gathered.dynamic = p.dynamic;
    gathered.vsStatic = p.vsStatic;
    layoutWide(gathered, schedule.levelStart, N);
    // Whatever an earlier step left in the groups: prepareWideGroup() writes every byte the
    // comparison below reads.
    for (WideConstraintT<N>& g : groupsOf<N>(gathered)) {
        std::memset(static_cast<void*>(&g), 0x5A, offsetof(WideConstraintT<N>, bodyA));
        g.twoPointLanes = 0x5A;
        g.unseenLanes[0] = 0x5A;
        g.unseenLanes[1] = 0x5A;
        g.blockLanes = 0x5A;
        g.rigidLanes = 0x5A;
        g.padLanes = 0x5A;
    }
    for (WideImpactT<N>& im : impactsOf<N>(gathered)) {
        std::memset(static_cast<void*>(&im), 0x5A, sizeof im);
    }
    ASSERT_EQ(reference.lanes, N);
    ASSERT_EQ(gathered.lanes, N);
    int groups = 0;
    for (int level = 0; level < schedule.levelCount; ++level) {
        const int first = schedule.levelStart[static_cast<std::size_t>(level)];
        const int end = schedule.levelStart[static_cast<std::size_t>(level) + 1];
        int g = gathered.levelStart[static_cast<std::size_t>(level)];
        for (int slot = first; slot < end; slot += N, ++g) {
            WideGatherT<N> in;
            int pushedLanes = 0;
            for (int lane = 0; lane < N; ++lane) {
                if (slot + lane < end) {
                    const PrepareInput& pi = p.inputs[static_cast<std::size_t>(
                        schedule.order[static_cast<std::size_t>(slot + lane)])];
                    const Softness picked = softnessFor(p, pi.a, pi.b);
                    ASSERT_EQ(std::memcmp(&pi.softness, &picked, sizeof picked), 0);
                    // The views' rows; their velocities are the states'.
                    in.manifold[lane] = &pi.manifold;
                    in.offsetA[lane] = &pi.a.centerOffset.x;
                    in.offsetB[lane] = &pi.b.centerOffset.x;
                    in.massA[lane] = &pi.a.invMass.x;
                    in.massB[lane] = &pi.b.invMass.x;
                    in.indexA[lane] = pi.a.stateIndex;
                    in.indexB[lane] = pi.b.stateIndex;
                    in.friction[lane] = pi.friction;
                    const Manifold& m = pi.manifold;
                    if (isPushedApart(m, pi.a, pi.b, pi.softness)) {
                        pushedLanes |= 1 << lane;
                        ++pushed;
                    } else if (m.points[0].separation < -kLinearSlop ||
                               (m.pointCount > 1 && m.points[1].separation < -kLinearSlop)) {
                        ++held;
                    }
                } else {
                    in.clearLane(lane);
                }
            }
            EXPECT_EQ(prepareWideGroup(gathered, g, in, states), pushedLanes) << "group " << g;
            ++groups;
        }
    }
    const std::vector<WideConstraintT<N>>& expected = groupsOf<N>(reference);
    const std::vector<WideConstraintT<N>>& actual = groupsOf<N>(gathered);
    ASSERT_EQ(static_cast<int>(actual.size()), groups);
    ASSERT_EQ(expected.size(), actual.size());
    // Byte for byte up to the body addresses, which are the same states or each group's own pad.
    using Group = WideConstraintT<N>;
    for (std::size_t g = 0; g < expected.size(); ++g) {
        const Group& e = expected[g];
        const Group& a = actual[g];
        EXPECT_EQ(std::memcmp(&e, &a, offsetof(Group, bodyA)), 0) << "group " << g;
        EXPECT_EQ(e.twoPointLanes, a.twoPointLanes) << "group " << g;
        EXPECT_EQ(e.unseenLanes[0], a.unseenLanes[0]) << "group " << g;
        EXPECT_EQ(e.unseenLanes[1], a.unseenLanes[1]) << "group " << g;
        EXPECT_EQ(e.blockLanes, a.blockLanes) << "group " << g;
        EXPECT_EQ(e.rigidLanes, a.rigidLanes) << "group " << g;
        EXPECT_EQ(e.padLanes, a.padLanes) << "group " << g;
        const WideImpactT<N>& ei = impactsOf<N>(reference)[g];
        const WideImpactT<N>& ai = impactsOf<N>(gathered)[g];
        EXPECT_EQ(std::memcmp(&ei, &ai, offsetof(WideImpactT<N>, pad)), 0) << "group " << g;
        // A pad in use is at rest, as the passes reset it.
        if (a.padLanes != 0) {
            EXPECT_EQ(std::memcmp(&ei.pad, &ai.pad, sizeof ai.pad), 0) << "group " << g;
        }
        for (int lane = 0; lane < N; ++lane) {
            for (auto side : {&Group::bodyA, &Group::bodyB}) {
                const BodyState* want = (e.*side)[lane];
                const BodyState* got = (a.*side)[lane];
                if (want == &ei.pad) {
                    EXPECT_EQ(got, &ai.pad) << "group " << g << " lane " << lane;
                    EXPECT_NE((a.padLanes >> lane) & 1, 0) << "group " << g << " lane " << lane;
                } else {
                    EXPECT_EQ(got, want) << "group " << g << " lane " << lane;
                    EXPECT_TRUE(want >= states.data() && want < states.data() + states.size());
                }
            }
        }
    }
}

TEST(WideContactSolver, PreparesGroupsAsPrepareContactDoes) {
    constexpr float kH = 1.0f / 240.0f;
    for (std::uint32_t seed : {4u, 5u, 6u}) {
        Problem p = randomProblem(seed, 40, 150, kH);
        // Cases the random pile rarely makes: a 2-point manifold with both points at one
        // place (K singular: no block), a point exactly at the touching separation, a body that
        // cannot move at all against a static side (no effective mass), a rigid side.
        PrepareInput& twin = p.inputs[0];
        twin.manifold.pointCount = 2;
        twin.manifold.points[1] = twin.manifold.points[0];
        p.inputs[1].manifold.points[0].separation = kTouchingSeparation;
        PrepareInput& stuck = p.inputs[2];
        stuck.a = ContactBodyView{};
        stuck.b.invMass = {0.0f, 0.0f};
        stuck.b.invInertia = 0.0f;
        p.inputs[3].a.invInertia = 0.0f;
        // A pinned speck (position locked, tiny inertia) deep inside a body 1e16 times
        // heavier: the rounding term of the effective masses (kLeverRounding2) is what counts
        // there, one point with its normal through the speck's centre, one beside it.
        for (std::size_t k : {4u, 5u}) {
            PrepareInput& speck = p.inputs[k];
            speck.a.invMass = {0.0f, 0.0f};
            speck.a.invInertia = 2.4e13f;
            speck.b.invMass = {1.0e-9f, 1.0e-9f};
            speck.b.invInertia = 2.3e-15f;
            Manifold& m = speck.manifold;
            m.pointCount = k == 4 ? 1 : 2;
            m.points[0].anchorA = -180.0f * m.normal;
            m.points[0].anchorB = -400.0f * m.normal;
            m.points[1].anchorA = m.points[0].anchorA + 0.001f * rightPerp(m.normal);
            m.points[1].anchorB = m.points[0].anchorB + 0.001f * rightPerp(m.normal);
        }
        // A body that cannot translate, 2.7e15 kg m^2 of inertia, against a static side at two
        // points: K ~ 1e-21..1e-18 and det K underflows (kMinBlockDeterminant): no block.
        PrepareInput& giant = p.inputs[6];
        giant.a = ContactBodyView{};
        giant.b.invMass = {0.0f, 0.0f};
        giant.b.invInertia = 3.75e-16f;
        giant.manifold.pointCount = 2;
        giant.manifold.normal = {0.0f, 1.0f};
        giant.manifold.points[0].anchorB = {0.0034f, -445.0f};
        giant.manifold.points[1].anchorB = {-0.062f, -445.0f};
        // A rigid moving side (no mass, no inertia): the static softness.
        p.inputs[7].b.invMass = {0.0f, 0.0f};
        p.inputs[7].b.invInertia = 0.0f;
        // A side locked on y that cannot turn, against a static side, its normal a billionth
        // of a radian off y (one point, then two): K is that component squared, and the
        // impulse stopping the normal velocity would throw the body along x at a billion times
        // the closing speed; lockedAxisFloor() holds it to kMaxContactGain times.
        for (std::size_t k : {8u, 9u}) {
            PrepareInput& locked = p.inputs[k];
            locked.a = ContactBodyView{};
            locked.b.invMass = {3.0e-9f, 0.0f};
            locked.b.invInertia = 0.0f;
            locked.manifold.normal = {3.7e-9f, -1.0f};
            locked.manifold.pointCount = k == 8 ? 1 : 2;
            locked.manifold.points[0].anchorB = {-115.0f, 3.4f};
            locked.manifold.points[1].anchorB = {-120.0f, 3.4f};
        }
        for (std::size_t k = 0; k < 10; ++k) {
            PrepareInput& in = p.inputs[k];
            in.softness = softnessFor(p, in.a, in.b);
            prepareContact(p.constraints[k], in.manifold, in.a, in.b, {in.friction, 0.0f, 0.0f},
                           in.softness);
        }
        ASSERT_FALSE(p.constraints[0].blockSolve);
        ASSERT_EQ(p.constraints[2].points[0].normalMass, 0.0f);
        ASSERT_LT(p.constraints[4].points[0].normalMass, 1.0e-5f);
        ASSERT_FALSE(p.constraints[6].blockSolve);
        for (std::size_t k : {8u, 9u}) {
            const ContactConstraint& c = p.constraints[k];
            // What the velocity along x gains per m/s of normal velocity stopped.
            const float gain = c.points[0].normalMass * c.invMassB.x * c.normal.x;
            ASSERT_GT(gain, 0.0f);
            ASSERT_LE(gain, kMaxContactGain);
            ASSERT_FALSE(c.blockSolve);
        }
        const Schedule schedule = scheduleOf(p);
        SCOPED_TRACE(seed);
        int pushed = 0;
        int held = 0;
        expectSameGroups<4>(p, schedule, pushed, held);
        if (bestWideLanes() >= 8) {
            expectSameGroups<8>(p, schedule, pushed, held);
        }
        // Both answers of isPushedApart()'s second test come up.
        EXPECT_GT(pushed, 0);
        EXPECT_GT(held, 0);
    }
}

// Groups whose lanes have one point each (a pile of circles) skip the second point: packed as
// prepareContact() packs a missing point, whatever the manifolds hold there.
TEST(WideContactSolver, PreparesOnePointGroupsAsPrepareContactDoes) {
    constexpr float kH = 1.0f / 240.0f;
    Problem p = randomProblem(9u, 40, 150, kH, 1);
    for (std::size_t k = 0; k < p.inputs.size(); ++k) {
        PrepareInput& in = p.inputs[k];
        ASSERT_EQ(in.manifold.pointCount, 1);
        in.manifold.points[1] = in.manifold.points[0];
    }
    const Schedule schedule = scheduleOf(p);
    int pushed = 0;
    int held = 0;
    expectSameGroups<4>(p, schedule, pushed, held);
    if (bestWideLanes() >= 8) {
        expectSameGroups<8>(p, schedule, pushed, held);
    }
}

} // namespace
} // namespace e2d::physics::detail
