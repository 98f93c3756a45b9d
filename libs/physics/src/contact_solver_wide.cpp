// SPDX-License-Identifier: MIT
#include "contact_solver_wide.hpp"

#include <bit>
#include <cstddef>
#include <cstdlib>
#include <cstring>

namespace e2d::physics::detail {

// The passes of each width, their helpers' names local to this file.
namespace lanes4 {
namespace {
#define E2D_WIDE_FN inline
#include "contact_solver_wide_kernel.inl"
#undef E2D_WIDE_FN
} // namespace
} // namespace lanes4

#if defined(E2D_HAS_WIDE8)
namespace lanes8 {
namespace {
#define E2D_WIDE_FN E2D_AVX2_FN
#include "contact_solver_wide_kernel.inl"
#undef E2D_WIDE_FN
} // namespace
} // namespace lanes8
#endif

namespace {

// `states`: where the constraint's bodies are (unused for static sides); `im`: the group's
// side data.
template <int N>
void packLane(WideConstraintT<N>& w, WideImpactT<N>& im, int lane, const ContactConstraint& c,
              BodyState* states) {
    const int bit = 1 << lane;
    w.bodyA[lane] = c.indexA >= 0 ? states + c.indexA : &im.pad;
    w.bodyB[lane] = c.indexB >= 0 ? states + c.indexB : &im.pad;
    const bool pad = c.indexA < 0 || c.indexB < 0;
    w.padLanes = pad ? (w.padLanes | bit) : (w.padLanes & ~bit);
    w.normalX[lane] = c.normal.x;
    w.normalY[lane] = c.normal.y;
    w.invMassAx[lane] = c.invMassA.x;
    w.invMassAy[lane] = c.invMassA.y;
    w.invMassBx[lane] = c.invMassB.x;
    w.invMassBy[lane] = c.invMassB.y;
    w.invInertiaA[lane] = c.invInertiaA;
    w.invInertiaB[lane] = c.invInertiaB;
    w.friction[lane] = c.friction;
    // The world's choice of softness (packWideLane()): vsStatic against a rigid side.
    const bool rigidLane =
        isRigidSide(c.invMassA, c.invInertiaA) || isRigidSide(c.invMassB, c.invInertiaB);
    w.rigidLanes = rigidLane ? (w.rigidLanes | bit) : (w.rigidLanes & ~bit);
    const BlockMatrix k = c.blockSolve ? c.blockK : BlockMatrix{1.0f, 0.0f, 1.0f};
    w.k11[lane] = k.a11;
    w.k12[lane] = k.a12;
    w.k22[lane] = k.a22;
    // prepareBlock()'s 1 / det K, whose products with K's entries are blockInvK.
    w.invDet[lane] = c.blockSolve ? c.blockInvDet : 1.0f;
    w.blockLanes = c.blockSolve ? (w.blockLanes | bit) : (w.blockLanes & ~bit);
    w.twoPointLanes = c.pointCount == 2 ? (w.twoPointLanes | bit) : (w.twoPointLanes & ~bit);
    w.separationsKnown = 0;
    for (int i = 0; i < 2; ++i) {
        // A missing second point has no mass: its impulses stay zero.
        const ContactConstraintPoint cp = i < c.pointCount ? c.points[i] : ContactConstraintPoint{};
        WidePointT<N>& wp = w.points[i];
        wp.anchorAx[lane] = cp.anchorA.x;
        wp.anchorAy[lane] = cp.anchorA.y;
        wp.anchorBx[lane] = cp.anchorB.x;
        wp.anchorBy[lane] = cp.anchorB.y;
        wp.baseSeparation[lane] = cp.baseSeparation;
        wp.normalImpulse[lane] = cp.normalImpulse;
        wp.tangentImpulse[lane] = cp.tangentImpulse;
        wp.maxNormalImpulse[lane] = cp.maxNormalImpulse;
        wp.normalMass[lane] = cp.normalMass;
        wp.tangentMass[lane] = cp.tangentMass;
        im.relativeVelocity[i][lane] = cp.relativeVelocity;
        im.impactGap[i][lane] = cp.impactGap;
        im.impactSeen[i][lane] = cp.impactSeen ? -1 : 0;
        w.unseenLanes[i] = cp.impactSeen ? (w.unseenLanes[i] & ~bit) : (w.unseenLanes[i] | bit);
    }
}

template <int N>
void layoutLanes(std::vector<WideConstraintT<N>>& groups, std::vector<WideImpactT<N>>& impacts,
                 std::vector<int>& wideStart, std::span<const int> levelStart) {
    const std::size_t levelCount = levelStart.empty() ? 0 : levelStart.size() - 1;
    wideStart.assign(levelCount + 1, 0);
    int count = 0;
    for (std::size_t k = 0; k < levelCount; ++k) {
        wideStart[k] = count;
        count += (levelStart[k + 1] - levelStart[k] + N - 1) / N;
    }
    wideStart[levelCount] = count;
    groups.resize(static_cast<std::size_t>(count));
    impacts.resize(static_cast<std::size_t>(count));
    // The lanes past a level's last constraint stay empty: no bodies, no mass, so every impulse
    // they compute is zero.
    for (std::size_t k = 0; k < levelCount; ++k) {
        const int inLevel = levelStart[k + 1] - levelStart[k];
        if (inLevel % N == 0) {
            continue;
        }
        const auto last = static_cast<std::size_t>(wideStart[k + 1] - 1);
        WideConstraintT<N>& w = groups[last];
        for (int lane = inLevel % N; lane < N; ++lane) {
            packLane(w, impacts[last], lane, ContactConstraint{}, nullptr);
            w.blockLanes |= 1 << lane;
        }
    }
}

template <int N>
void storeLanes(const std::vector<WideConstraintT<N>>& groups,
                const std::vector<WideImpactT<N>>& impacts, std::span<const int> wideStart,
                std::span<ContactConstraint> constraints, std::span<const int> levelOrder,
                std::span<const int> levelStart) {
    const std::size_t levelCount = levelStart.empty() ? 0 : levelStart.size() - 1;
    for (std::size_t k = 0; k < levelCount; ++k) {
        const int end = levelStart[k + 1];
        int g = wideStart[k];
        for (int first = levelStart[k]; first < end; first += N, ++g) {
            const WideConstraintT<N>& w = groups[static_cast<std::size_t>(g)];
            const WideImpactT<N>& im = impacts[static_cast<std::size_t>(g)];
            for (int lane = 0; lane < N && first + lane < end; ++lane) {
                ContactConstraint& c = constraints[static_cast<std::size_t>(
                    levelOrder[static_cast<std::size_t>(first + lane)])];
                for (int i = 0; i < c.pointCount; ++i) {
                    ContactConstraintPoint& cp = c.points[i];
                    const WidePointT<N>& wp = w.points[i];
                    cp.relativeVelocity = im.relativeVelocity[i][lane];
                    cp.normalImpulse = wp.normalImpulse[lane];
                    cp.tangentImpulse = wp.tangentImpulse[lane];
                    cp.maxNormalImpulse = wp.maxNormalImpulse[lane];
                    cp.impactGap = im.impactGap[i][lane];
                    cp.impactSeen = im.impactSeen[i][lane] != 0;
                }
            }
        }
    }
}

// The state index of a lane's side at `at` (packLane()): -1 at the pad (in `im`).
template <int N>
int stateIndexOf(const WideImpactT<N>& im, const BodyState* at, const BodyState* states) {
    return at == &im.pad ? -1 : static_cast<int>(at - states);
}

// `states`: the array the group was prepared on; `im`: the group's side data.
template <int N>
void unpackLane(const WideConstraintT<N>& w, const WideImpactT<N>& im, int lane,
                ContactConstraint& c, const BodyState* states) {
    c.indexA = stateIndexOf(im, w.bodyA[lane], states);
    c.indexB = stateIndexOf(im, w.bodyB[lane], states);
    c.normal = {w.normalX[lane], w.normalY[lane]};
    c.invMassA = {w.invMassAx[lane], w.invMassAy[lane]};
    c.invMassB = {w.invMassBx[lane], w.invMassBy[lane]};
    c.invInertiaA = w.invInertiaA[lane];
    c.invInertiaB = w.invInertiaB[lane];
    for (int i = 0; i < 2; ++i) {
        const WidePointT<N>& wp = w.points[i];
        ContactConstraintPoint& cp = c.points[i];
        cp.anchorA = {wp.anchorAx[lane], wp.anchorAy[lane]};
        cp.anchorB = {wp.anchorBx[lane], wp.anchorBy[lane]};
        cp.baseSeparation = wp.baseSeparation[lane];
        cp.relativeVelocity = im.relativeVelocity[i][lane];
        cp.normalImpulse = wp.normalImpulse[lane];
        cp.tangentImpulse = wp.tangentImpulse[lane];
        cp.maxNormalImpulse = wp.maxNormalImpulse[lane];
        cp.normalMass = wp.normalMass[lane];
        cp.tangentMass = wp.tangentMass[lane];
        cp.impactGap = im.impactGap[i][lane];
        cp.impactSeen = im.impactSeen[i][lane] != 0;
    }
}

template <int N>
void restituteLanes(std::vector<WideConstraintT<N>>& groups,
                    const std::vector<WideImpactT<N>>& impacts, std::span<const int> wideStart,
                    std::span<const WideRestitution> list, std::span<BodyState> states,
                    float threshold, float h) {
    for (const WideRestitution& r : list) {
        const auto g =
            static_cast<std::size_t>(wideStart[static_cast<std::size_t>(r.level)] + r.at / N);
        WideConstraintT<N>& w = groups[g];
        const int lane = r.at % N;
        // The scalar pass on a copy of the lane, so both paths run the same code.
        ContactConstraint c;
        unpackLane(w, impacts[g], lane, c, states.data());
        c.pointCount = r.pointCount;
        c.restitution = r.restitution;
        c.pressAcceleration = r.pressAcceleration;
        applyRestitution(std::span<ContactConstraint>(&c, 1), states, threshold, h);
        for (int i = 0; i < r.pointCount; ++i) {
            w.points[i].normalImpulse[lane] = c.points[i].normalImpulse;
            w.points[i].maxNormalImpulse[lane] = c.points[i].maxNormalImpulse;
        }
    }
}

} // namespace

void applyRestitutionWide(WideContacts& wide, std::span<const WideRestitution> list,
                          std::span<BodyState> states, float threshold, float h) {
    if (wide.lanes == 8) {
        restituteLanes(wide.constraints8, wide.impacts8, wide.levelStart, list, states, threshold,
                       h);
    } else {
        restituteLanes(wide.constraints4, wide.impacts4, wide.levelStart, list, states, threshold,
                       h);
    }
}

int bestWideLanes() {
#if defined(E2D_HAS_WIDE8)
    return __builtin_cpu_supports("avx2") ? 8 : 4;
#else
    return 4;
#endif
}

void layoutWide(WideContacts& wide, std::span<const int> levelStart, int lanes) {
#if defined(E2D_HAS_WIDE8)
    wide.lanes = lanes == 8 ? 8 : 4;
#else
    (void)lanes;
    wide.lanes = 4;
#endif
    if (wide.lanes == 8) {
        layoutLanes(wide.constraints8, wide.impacts8, wide.levelStart, levelStart);
    } else {
        layoutLanes(wide.constraints4, wide.impacts4, wide.levelStart, levelStart);
    }
}

void packWideLane(WideContacts& wide, int level, int at, const ContactConstraint& c,
                  std::span<BodyState> states) {
    const int first = wide.levelStart[static_cast<std::size_t>(level)];
    if (wide.lanes == 8) {
        const auto g = static_cast<std::size_t>(first + at / 8);
        packLane(wide.constraints8[g], wide.impacts8[g], at % 8, c, states.data());
    } else {
        const auto g = static_cast<std::size_t>(first + at / 4);
        packLane(wide.constraints4[g], wide.impacts4[g], at % 4, c, states.data());
    }
}

int hitLanes(const WideConstraintT<4>& group, const WideImpactT<4>& impact, float threshold) {
    return lanes4::hitLanes(group, impact, threshold);
}

int hitLanes(const WideConstraintT<8>& group, const WideImpactT<8>& impact, float threshold) {
#if defined(E2D_HAS_WIDE8)
    return lanes8::hitLanes(group, impact, threshold);
#else
    (void)group; // unreachable, as prepareWideGroup() below
    (void)impact;
    (void)threshold;
    std::abort();
#endif
}

int prepareWideGroup(WideContacts& wide, int group, const WideGatherT<4>& in,
                     std::span<BodyState> states) {
    const auto g = static_cast<std::size_t>(group);
    return lanes4::prepareGroup(in, wide.constraints4[g], wide.impacts4[g], states.data(),
                                wide.dynamic, wide.vsStatic);
}

int prepareWideGroup(WideContacts& wide, int group, const WideGatherT<8>& in,
                     std::span<BodyState> states) {
#if defined(E2D_HAS_WIDE8)
    const auto g = static_cast<std::size_t>(group);
    return lanes8::prepareGroup(in, wide.constraints8[g], wide.impacts8[g], states.data(),
                                wide.dynamic, wide.vsStatic);
#else
    // Unreachable: without AVX2 kernels layoutWide() never makes eight-lane groups.
    (void)wide;
    (void)group;
    (void)in;
    (void)states;
    std::abort();
#endif
}

void prepareWide(WideContacts& wide, std::span<const ContactConstraint> constraints,
                 std::span<const int> levelOrder, std::span<const int> levelStart, int lanes,
                 std::span<BodyState> states) {
    layoutWide(wide, levelStart, lanes);
    const std::size_t levelCount = levelStart.empty() ? 0 : levelStart.size() - 1;
    for (std::size_t k = 0; k < levelCount; ++k) {
        for (int slot = levelStart[k]; slot < levelStart[k + 1]; ++slot) {
            packWideLane(
                wide, static_cast<int>(k), slot - levelStart[k],
                constraints[static_cast<std::size_t>(levelOrder[static_cast<std::size_t>(slot)])],
                states);
        }
    }
}

void storeWide(const WideContacts& wide, std::span<ContactConstraint> constraints,
               std::span<const int> levelOrder, std::span<const int> levelStart) {
    if (wide.lanes == 8) {
        storeLanes(wide.constraints8, wide.impacts8, wide.levelStart, constraints, levelOrder,
                   levelStart);
    } else {
        storeLanes(wide.constraints4, wide.impacts4, wide.levelStart, constraints, levelOrder,
                   levelStart);
    }
}

void warmStartWide(const WideContacts& wide) {
    warmStartWide(wide, 0, static_cast<int>(wide.levelStart.size()) - 1);
}

void solveWide(WideContacts& wide, float invH, bool useBias, float pushMaxSpeed, bool backward,
               bool reversePoints) {
    solveWide(wide, 0, static_cast<int>(wide.levelStart.size()) - 1, invH, useBias, pushMaxSpeed,
              backward, reversePoints);
}

namespace {

std::span<const int> levelRange(const WideContacts& wide, int firstLevel, int endLevel) {
    if (endLevel <= firstLevel) {
        return {};
    }
    return std::span<const int>(wide.levelStart)
        .subspan(static_cast<std::size_t>(firstLevel),
                 static_cast<std::size_t>(endLevel - firstLevel) + 1);
}

} // namespace

namespace {

// The kernels over the groups levels.front() .. levels.back() (backward: level by level, last
// level first). The groups hold their bodies' addresses (WideConstraintT::bodyA and bodyB, in
// the states they were prepared on), so the states are not passed on.
void warmStartLevels(const WideContacts& wide, std::span<const int> levels) {
#if defined(E2D_HAS_WIDE8)
    if (wide.lanes == 8) {
        lanes8::warmStartAll(wide.constraints8, wide.impacts8, levels);
        return;
    }
#endif
    lanes4::warmStartAll(wide.constraints4, wide.impacts4, levels);
}

void solveLevels(WideContacts& wide, std::span<const int> levels, float invH, bool useBias,
                 float pushMaxSpeed, bool backward, bool reversePoints) {
#if defined(E2D_HAS_WIDE8)
    if (wide.lanes == 8) {
        if (reversePoints) {
            lanes8::solveAll<true>(wide.constraints8, wide.impacts8, levels, invH, useBias,
                                   pushMaxSpeed, backward, wide.dynamic, wide.vsStatic);
        } else {
            lanes8::solveAll<false>(wide.constraints8, wide.impacts8, levels, invH, useBias,
                                    pushMaxSpeed, backward, wide.dynamic, wide.vsStatic);
        }
        return;
    }
#endif
    if (reversePoints) {
        lanes4::solveAll<true>(wide.constraints4, wide.impacts4, levels, invH, useBias,
                               pushMaxSpeed, backward, wide.dynamic, wide.vsStatic);
    } else {
        lanes4::solveAll<false>(wide.constraints4, wide.impacts4, levels, invH, useBias,
                                pushMaxSpeed, backward, wide.dynamic, wide.vsStatic);
    }
}

} // namespace

void warmStartWide(const WideContacts& wide, int firstLevel, int endLevel) {
    warmStartLevels(wide, levelRange(wide, firstLevel, endLevel));
}

void solveWide(WideContacts& wide, int firstLevel, int endLevel, float invH, bool useBias,
               float pushMaxSpeed, bool backward, bool reversePoints) {
    solveLevels(wide, levelRange(wide, firstLevel, endLevel), invH, useBias, pushMaxSpeed, backward,
                reversePoints);
}

void warmStartWideGroups(const WideContacts& wide, int groupBegin, int groupEnd) {
    const int groups[2] = {groupBegin, groupEnd};
    warmStartLevels(wide, groups);
}

void solveWideGroups(WideContacts& wide, int groupBegin, int groupEnd, float invH, bool useBias,
                     float pushMaxSpeed, bool reversePoints) {
    const int groups[2] = {groupBegin, groupEnd};
    solveLevels(wide, groups, invH, useBias, pushMaxSpeed, false, reversePoints);
}

} // namespace e2d::physics::detail
