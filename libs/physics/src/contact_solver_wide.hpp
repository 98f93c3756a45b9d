// SPDX-License-Identifier: MIT
#pragma once

#include "contact_solver.hpp"
#include "solver_body.hpp"
#include "wide_lanes.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

// The soft-step contact passes several constraints at a time. Mirrors warmStartContacts() and
// solveContacts() in contact_solver.cpp operation for operation, over the constraints by level
// (the world's levels are colours, ConstraintColors; ConstraintLevels gives the levels of the
// sequential sweep): a level's constraints share no moving body, so solving several of them at
// once gives bit for bit what solving them one after another in level order does. Rolling
// resistance is not handled here (the world uses the scalar functions when a contact has it).
//
// The lanes are GCC/Clang vector extensions. Four lanes everywhere (SSE2 on x86-64, NEON on
// ARM64, plain scalar code where the target has no SIMD); eight on x86-64 CPUs with AVX2,
// chosen at run time (the build sets no -march). Multiplies and adds stay separate
// instructions (no FMA), so every lane width gives the scalar results.
namespace e2d::physics::detail {

// Aligned to the vector size by hand: without AVX enabled GCC aligns a 32-byte vector to 16
// only, while the AVX2 code assumes 32. Every member is a whole number of vectors, so the
// layout is the same either way.
template <int N>
struct alignas(4 * N) WidePointT {
    using F = typename WideLanes<N>::F;
    using I = typename WideLanes<N>::I;
    F anchorAx, anchorAy, anchorBx, anchorBy;
    F baseSeparation;
    F normalImpulse, tangentImpulse, maxNormalImpulse;
    F normalMass, tangentMass;
};

// What a group's passes rarely touch, kept apart from the groups (WideContacts::impacts4 and
// impacts8, indexed like the groups) so that the passes do not stream it:
// - the impact bookkeeping (ContactConstraintPoint's relativeVelocity, impactGap and
//   impactSeen), per point: the store, restitution and hit code read it, the passes only while
//   a lane has a point not yet seen (WideConstraintT::unseenLanes), which is rare once a pile
//   has settled;
// - the pad, where the lanes of a static side or an empty lane read and write their body
//   (WideConstraintT::bodyA and bodyB): only groups with such lanes touch it
//   (WideConstraintT::padLanes), a pile's few ground contacts and each level's last group.
template <int N>
struct alignas(4 * N) WideImpactT {
    using F = typename WideLanes<N>::F;
    using I = typename WideLanes<N>::I;
    F relativeVelocity[2];
    F impactGap[2];
    I impactSeen[2]; // all bits set when seen
    mutable BodyState pad;
};

// Aligned to cache lines: a group of eight is twenty lines, of four ten.
template <int N>
struct alignas(64) WideConstraintT {
    using F = typename WideLanes<N>::F;
    using I = typename WideLanes<N>::I;
    F normalX, normalY;
    F invMassAx, invMassAy, invMassBx, invMassBy;
    F invInertiaA, invInertiaB;
    F friction;
    // The block matrix K of a 2-point manifold (ContactConstraint's blockK) and 1 / det K: the
    // passes work K's inverse out from them as prepareBlock() does, bit for bit (a few
    // multiplies a group cost less than streaming two more vectors). Lanes outside blockLanes
    // hold K = identity.
    F k11, k12, k22, invDet;
    WidePointT<N> points[2];
    // Where each lane reads and writes its bodies this step (bodiesAt()), set with the rest so
    // that the passes do not work the addresses out again: a state in the step's array, or the
    // group's pad (WideImpactT::pad) for a static side and an empty lane (the only record of
    // the lane's bodies: a lane's state index is its address's distance from the array's
    // start). Each pass resets the pad before it reads the lanes (it may write there), so a
    // static side always reads a resting state.
    BodyState* bodyA[N];
    BodyState* bodyB[N];
    // The points' separations as a relax pass (useBias false) found them, for the passes up
    // to the next biased one to use instead of working them out again. Positions only change
    // in integratePositions(), and the soft step's sub-step (forEachSoftStepPass()) runs its
    // biased passes, then integratePositions(), then its relax passes: from a relax pass to
    // the next biased pass nothing moves. So a relax pass sets separationsKnown, the passes
    // after it use the separations, and the first biased pass that does clears it (the
    // passes that follow it may come after integratePositions()); prepareGroup() and
    // packWideLane() clear it too. Warm starts do not touch it.
    F separation[2];
    int separationsKnown;
    // The lanes with a second point, lane k in bit k: the passes pick their kernel with one
    // test of memory (zero: every lane has at most one point).
    int twoPointLanes;
    // Per point, the lanes whose point is not seen yet (not all bits of the group's
    // WideImpactT::impactSeen), lane k in bit k: zero, the passes skip the impact bookkeeping
    // without reading it.
    int unseenLanes[2];
    // The lanes of well-conditioned 2-point manifolds, which take the block solve
    // (ContactConstraint::blockSolve), and the empty lanes too (their block gives zero
    // impulses, and a group of block constraints then never runs the point-by-point solve as
    // well); lane k in bit k.
    int blockLanes;
    // The lanes against a rigid side (no mass, no inertia: a static side too), whose softness
    // is WideContacts::vsStatic; the others' is WideContacts::dynamic.
    int rigidLanes;
    // The lanes with a side at the pad (a static side or an empty lane): zero, the passes do
    // not touch the pad.
    int padLanes;
};

static_assert(sizeof(WidePointT<8>) % 32 == 0 && sizeof(WideConstraintT<8>) % 32 == 0 &&
                  sizeof(WideImpactT<8>) % 32 == 0 && offsetof(WideConstraintT<8>, normalX) == 0,
              "wide constraints must be whole vectors");
// What the passes stream per group of eight contacts: the large piles are bound by memory
// (reading 512 more bytes a group in the warm start alone slowed a base-100 pyramid by 8 %),
// so what the passes can work out cheaply or rarely read is not kept here (1 504 bytes before
// the softness, the block inverse, the block lanes and the pad came out).
static_assert(sizeof(WideConstraintT<8>) == 1280 && sizeof(WideConstraintT<4>) % 64 == 0,
              "the wide constraint's size changed");

// The packed constraints of one step, `lanes` constraints per group.
struct WideContacts {
    int lanes = 4;
    // The lanes' softness (the world's choice, as makeContactSoftness() gives it): vsStatic on a
    // group's rigidLanes, dynamic on the others.
    Softness dynamic;
    Softness vsStatic;
    std::vector<WideConstraintT<4>> constraints4; // lanes == 4
    std::vector<WideConstraintT<8>> constraints8; // lanes == 8
    // Each group's impact bookkeeping, at the group's index.
    std::vector<WideImpactT<4>> impacts4; // lanes == 4
    std::vector<WideImpactT<8>> impacts8; // lanes == 8
    // Packed groups of level k: [levelStart[k], levelStart[k + 1]).
    std::vector<int> levelStart;
};

// The widest lane count this CPU runs: 8 with AVX2 (x86-64), else 4.
int bestWideLanes();

// Sizes `wide` for the levels (levelStart as below), `lanes` (4 or 8) constraints per group,
// and empties the lanes past each level's last constraint; packWideLane() then fills the
// others.
void layoutWide(WideContacts& wide, std::span<const int> levelStart, int lanes);
// Puts constraint `c`, the `at`-th of level `level`, in its lane; its bodies are in `states`.
// Its softness must be the world's choice: wide.vsStatic against a rigid side (no mass, no
// inertia), else wide.dynamic (the lane records which).
void packWideLane(WideContacts& wide, int level, int at, const ContactConstraint& c,
                  std::span<BodyState> states);

// The manifold of an empty lane: no points.
inline const Manifold kEmptyManifold{};

// Where prepareWideGroup() reads what prepareContact() reads for N constraints, one per lane:
// the manifold itself, and each side's ContactBodyView as a ContactBodyRow (its velocity, masses
// and centre offset), read whole as two rows of four floats, so that a group's lanes are
// gathered with a few loads and shuffles instead of copied field by field. A static side's row
// holds its centre offset and zeros. Empty lanes: kEmptyManifold, a zero row and index -1.
template <int N>
struct WideGatherT {
    const Manifold* manifold[N];
    const ContactBodyRow* sideA[N];
    const ContactBodyRow* sideB[N];
    int indexA[N]; // ContactBodyView::stateIndex
    int indexB[N];
    float friction[N];
    // Room for the rows of static sides, lane k's A side at 2 k, its B side at 2 k + 1 (the
    // caller's to fill; kept with the lanes so that each group does not initialise its own).
    ContactBodyRow staticSides[2 * N];

    // An empty lane: no bodies, no points; it packs as ContactConstraint{} does.
    void clearLane(int lane) {
        static constexpr ContactBodyRow kNoBody{};
        manifold[lane] = &kEmptyManifold;
        sideA[lane] = &kNoBody;
        sideB[lane] = &kNoBody;
        indexA[lane] = -1;
        indexB[lane] = -1;
        friction[lane] = 0.0f;
    }
};

// Prepares and packs the group of constraints `group` from the lanes of `in` (see
// WideGatherT), bit for bit what prepareContact() and packWideLane() give one at a time, all
// lanes at once; the lanes' softness is the world's choice between wide.dynamic and
// wide.vsStatic (vsStatic where a side is rigid: no mass, no inertia). Their bodies are in
// `states` (the array the passes then run on; the build reads their rows, not the states). The
// lane count must be wide.lanes. Returns the lanes isPushedApart() holds pushed apart (on the
// lane's softness), lane k in bit k.
int prepareWideGroup(WideContacts& wide, int group, const WideGatherT<4>& in,
                     std::span<BodyState> states);
int prepareWideGroup(WideContacts& wide, int group, const WideGatherT<8>& in,
                     std::span<BodyState> states);

// Packs the constraints of each level, constraints[levelOrder[levelStart[k] ..
// levelStart[k + 1])], into groups of `lanes` (the last group of a level padded with empty
// lanes); their bodies are in `states`, their softness wide.dynamic or wide.vsStatic (set
// them first; see packWideLane()).
void prepareWide(WideContacts& wide, std::span<const ContactConstraint> constraints,
                 std::span<const int> levelOrder, std::span<const int> levelStart, int lanes,
                 std::span<BodyState> states);
// Copies impulses and the impact bookkeeping back to the constraints.
void storeWide(const WideContacts& wide, std::span<ContactConstraint> constraints,
               std::span<const int> levelOrder, std::span<const int> levelStart);

// A packed constraint with restitution, in the order applyRestitution() visits them (constraint
// order): where it sits (the `at`-th of level `level`) and what the lanes do not keep.
struct WideRestitution {
    int level = 0;
    int at = 0;
    int pointCount = 0;
    float restitution = 0.0f;
    float pressAcceleration = 0.0f;
    int constraint = 0; // its place in constraint order
};

// applyRestitution() on the listed packed constraints, in list order.
void applyRestitutionWide(WideContacts& wide, std::span<const WideRestitution> list,
                          std::span<BodyState> states, float threshold, float h);

// What a lane that may hit leaves for the world's hit events, per point: whether a point was
// pushed on (maxNormalImpulse > 0) while approaching faster than the store's hit threshold
// (-relativeVelocity). The other lanes (a resting pile: every lane) skip it.
struct WideLaneHit {
    float relativeVelocity[2];
    float maxNormalImpulse[2];
};

// Stores what the step leaves in each packed constraint of levels [firstLevel, endLevel): its
// impulses go to its manifold, manifoldOf(slot) (a Manifold&, the one it was prepared from,
// for next step's warm start; its points only), and hit(slot, manifold, WideLaneHit) is
// called for the lanes that may hit, slot being the constraint's place in level order (level
// k holds slots [levelStart[k], levelStart[k + 1])), in slot order. hitThreshold: the
// approach speed above which a lane may hit.
template <class ManifoldOf, class Hit>
void storeWideImpulses(const WideContacts& wide, std::span<const int> levelStart, int firstLevel,
                       int endLevel, float hitThreshold, ManifoldOf&& manifoldOf, Hit&& hit);

// warmStartContacts() and solveContacts() over every packed constraint, level after level
// (backward: last level first; reversePoints: each constraint's points last to first), on the
// states the groups were prepared with (their bodies' addresses are in the groups). The passes
// keep the separations a relax pass finds for the passes up to the next biased one
// (WideConstraintT::separation): between a relax pass and the next biased pass over the same
// groups the bodies' positions must not change, and between an integratePositions() and the
// next relax pass there must be a biased pass, as in forEachSoftStepPass().
void warmStartWide(const WideContacts& wide);
void solveWide(WideContacts& wide, float invH, bool useBias, float pushMaxSpeed, bool backward,
               bool reversePoints);
// The same over levels [firstLevel, endLevel) only.
void warmStartWide(const WideContacts& wide, int firstLevel, int endLevel);
void solveWide(WideContacts& wide, int firstLevel, int endLevel, float invH, bool useBias,
               float pushMaxSpeed, bool backward, bool reversePoints);

// The same over the groups [groupBegin, groupEnd) of level `level` only.
template <class ManifoldOf, class Hit>
void storeWideImpulsesOfGroups(const WideContacts& wide, std::span<const int> levelStart, int level,
                               int groupBegin, int groupEnd, float hitThreshold,
                               ManifoldOf&& manifoldOf, Hit&& hit);

// warmStartWide() and solveWide() over the packed groups [groupBegin, groupEnd) of one level
// (its constraints share no moving body: any part of a level may run while another worker
// runs another part).
void warmStartWideGroups(const WideContacts& wide, int groupBegin, int groupEnd);
void solveWideGroups(WideContacts& wide, int groupBegin, int groupEnd, float invH, bool useBias,
                     float pushMaxSpeed, bool reversePoints);

// The lanes of `group` whose points may hit: pushed on (maxNormalImpulse > 0) while
// approaching faster than `threshold` (-relativeVelocity > threshold); lane k in bit k.
int hitLanes(const WideConstraintT<4>& group, const WideImpactT<4>& impact, float threshold);
int hitLanes(const WideConstraintT<8>& group, const WideImpactT<8>& impact, float threshold);

namespace wide_detail {

// Stores group g's lanes, the first holding slot `first`, up to slot `end`.
template <int N, class ManifoldOf, class Hit>
[[gnu::always_inline]] inline void storeGroup(const std::vector<WideConstraintT<N>>& groups,
                                              const std::vector<WideImpactT<N>>& impacts, int g,
                                              int first, int end, float hitThreshold,
                                              ManifoldOf& manifoldOf, Hit& hit) {
    const WideConstraintT<N>& w = groups[static_cast<std::size_t>(g)];
    const WideImpactT<N>& impact = impacts[static_cast<std::size_t>(g)];
    // The world's test for a hit, on all lanes at once (missing points have no impulse).
    const int mayHit = hitLanes(w, impact, hitThreshold);
    const int used = std::min(N, end - first);
    for (int lane = 0; lane < used; ++lane) {
        Manifold& m = manifoldOf(first + lane);
        for (int i = 0; i < m.pointCount; ++i) {
            m.points[i].normalImpulse = w.points[i].normalImpulse[lane];
            m.points[i].tangentImpulse = w.points[i].tangentImpulse[lane];
        }
        if (((mayHit >> lane) & 1) != 0) {
            WideLaneHit h;
            for (int i = 0; i < 2; ++i) {
                h.relativeVelocity[i] = impact.relativeVelocity[i][lane];
                h.maxNormalImpulse[i] = w.points[i].maxNormalImpulse[lane];
            }
            hit(first + lane, static_cast<const Manifold&>(m), h);
        }
    }
}

} // namespace wide_detail

template <class ManifoldOf, class Hit>
void storeWideImpulsesOfGroups(const WideContacts& wide, std::span<const int> levelStart, int level,
                               int groupBegin, int groupEnd, float hitThreshold,
                               ManifoldOf&& manifoldOf, Hit&& hit) {
    const auto at = static_cast<std::size_t>(level);
    const int end = levelStart[at + 1];
    auto run = [&](const auto& groups, const auto& impacts, auto lanes) {
        constexpr int N = decltype(lanes)::value;
        for (int g = groupBegin; g < groupEnd; ++g) {
            wide_detail::storeGroup<N>(groups, impacts, g,
                                       levelStart[at] + (g - wide.levelStart[at]) * N, end,
                                       hitThreshold, manifoldOf, hit);
        }
    };
    if (wide.lanes == 8) {
        run(wide.constraints8, wide.impacts8, std::integral_constant<int, 8>{});
    } else {
        run(wide.constraints4, wide.impacts4, std::integral_constant<int, 4>{});
    }
}

template <class ManifoldOf, class Hit>
void storeWideImpulses(const WideContacts& wide, std::span<const int> levelStart, int firstLevel,
                       int endLevel, float hitThreshold, ManifoldOf&& manifoldOf, Hit&& hit) {
    for (int level = firstLevel; level < endLevel; ++level) {
        const auto at = static_cast<std::size_t>(level);
        storeWideImpulsesOfGroups(wide, levelStart, level, wide.levelStart[at],
                                  wide.levelStart[at + 1], hitThreshold, manifoldOf, hit);
    }
}

} // namespace e2d::physics::detail
