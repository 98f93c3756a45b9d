// SPDX-License-Identifier: MIT
// Plain hinges four or eight at a time: packing them into groups, their warm start and solve
// (joint_point_kernel.inl, once per lane width), and their impulses back to the joints.
#include "joint_solver.hpp"
#include "wide_lanes.hpp"

#include <cstring>

namespace e2d::physics::detail {

namespace {

// A lane's prepared fields: the joint's first cache line only (the layout's indices and slot
// stay as packed).
template <int N>
__attribute__((always_inline)) inline void refreshLane(PointJointLanes<N>& q, int lane,
                                                       const Joint& j) {
    q.invInertiaA[lane] = j.invInertiaA;
    q.invInertiaB[lane] = j.invInertiaB;
    q.invMassAx[lane] = j.invMassA.x;
    q.invMassAy[lane] = j.invMassA.y;
    q.invMassBx[lane] = j.invMassB.x;
    q.invMassBy[lane] = j.invMassB.y;
    q.anchorAx[lane] = j.anchorA.x;
    q.anchorAy[lane] = j.anchorA.y;
    q.anchorBx[lane] = j.anchorB.x;
    q.anchorBy[lane] = j.anchorB.y;
    q.deltaCenterX[lane] = j.deltaCenter.x;
    q.deltaCenterY[lane] = j.deltaCenter.y;
    q.impulseX[lane] = j.linearImpulse.x;
    q.impulseY[lane] = j.linearImpulse.y;
}

template <int N>
void packLane(PointJointLanes<N>& q, int lane, const Joint& j, int slot) {
    q.indexA[lane] = j.indexA;
    q.indexB[lane] = j.indexB;
    q.slot[lane] = slot;
    refreshLane(q, lane, j);
}

template <int N>
void refreshGroups(std::span<PointJointLanes<N>> groups, std::span<const Joint> joints) {
    for (PointJointLanes<N>& q : groups) {
        for (int lane = 0; lane < N; ++lane) {
            if (q.slot[lane] >= 0) {
                refreshLane(q, lane, joints[static_cast<std::size_t>(q.slot[lane])]);
            }
        }
    }
}

template <int N>
void storeGroups(std::span<const PointJointLanes<N>> groups, std::span<Joint> joints, float invH) {
    for (const PointJointLanes<N>& q : groups) {
        for (int lane = 0; lane < N; ++lane) {
            if (q.slot[lane] >= 0) {
                Joint& j = joints[static_cast<std::size_t>(q.slot[lane])];
                j.linearImpulse = {q.impulseX[lane], q.impulseY[lane]};
                // No frame needed: a revolute joint's force is its point impulse.
                j.reactionForce = invH * j.linearImpulse;
                // A plain hinge has no spring, motor or limit, and prepareJoint() zeroed their
                // impulses: no torque (and no read of the joint's second cache line).
                j.reactionTorque = 0.0f;
            }
        }
    }
}

} // namespace

void packJointPasses(std::span<const Joint> joints, std::span<const int> slots,
                     std::span<const int> levels, bool quadsAllowed, PointJointGroups& groups,
                     std::vector<int>& entries) {
    const std::size_t n = slots.size();
    // Direct (quadsAllowed false): only the loopy groups' hinges, which the direct solve leaves.
    auto grouped = [&](const Joint& j) { return isPointJoint(j) && (quadsAllowed || j.loopy); };
    std::size_t first = 0;
    while (first < n) {
        std::size_t end = first + 1;
        while (end < n && levels[end] == levels[first]) {
            ++end;
        }
        // The level's plain hinges in groups, then its other joints: eights while five or more
        // are left (with eight lanes), then fours. A lone hinge left over (a chain's levels
        // hold one joint each) is cheaper solved alone than in a group of padding.
        int points = 0;
        for (std::size_t k = first; k < end; ++k) {
            points += grouped(joints[static_cast<std::size_t>(slots[k])]) ? 1 : 0;
        }
        int left = points;
        int lane = 0;
        int width = 0; // the open group's
        int packed = 0;
        for (std::size_t k = first; k < end && left > 0; ++k) {
            const int s = slots[k];
            const Joint& j = joints[static_cast<std::size_t>(s)];
            if (!grouped(j)) {
                continue;
            }
            if (lane == width) {
                if (left == 1) {
                    break;
                }
                width = groups.lanes == 8 && left >= 5 ? 8 : 4;
                lane = 0;
                if (width == 8) {
                    entries.push_back(PointJointGroups::octetEntry(groups.octets.size()));
                    groups.octets.emplace_back();
                } else {
                    entries.push_back(PointJointGroups::quadEntry(groups.quads.size()));
                    groups.quads.emplace_back();
                }
            }
            if (width == 8) {
                packLane(groups.octets.back(), lane++, j, s);
            } else {
                packLane(groups.quads.back(), lane++, j, s);
            }
            --left;
            ++packed;
        }
        int seen = 0;
        // A level of plain hinges only, all in groups (a joint grid's), has no other entries.
        const bool allPacked = static_cast<std::size_t>(packed) == end - first;
        for (std::size_t k = first; k < end && !allPacked; ++k) {
            const int s = slots[k];
            if (!grouped(joints[static_cast<std::size_t>(s)]) || seen++ >= packed) {
                entries.push_back(s);
            }
        }
        first = end;
    }
}

void refreshPointJointGroups(PointJointGroups& groups, std::span<const Joint> joints) {
    refreshGroups<4>(groups.quads, joints);
    refreshGroups<8>(groups.octets, joints);
}

void storePointJointGroups(const PointJointGroups& groups, std::span<Joint> joints, float invH) {
    storeGroups<4>(groups.quads, joints, invH);
    storeGroups<8>(groups.octets, joints, invH);
}

int bestPointJointLanes() {
#if defined(E2D_HAS_WIDE8)
    return __builtin_cpu_supports("avx2") ? 8 : 4;
#else
    return 4;
#endif
}

namespace lanes4 {
namespace {
#define E2D_WIDE_FN inline
#include "joint_point_kernel.inl"
#undef E2D_WIDE_FN
} // namespace
} // namespace lanes4

void warmStartPointQuad(PointJointQuad& q, std::span<BodyState> states) {
    lanes4::warmStartHinges(q, states);
}

void solvePointQuad(PointJointQuad& q, std::span<BodyState> states, const Softness& soft) {
    lanes4::solveHinges(q, states, soft);
}

#if defined(E2D_HAS_WIDE8)

namespace lanes8 {
namespace {
#define E2D_WIDE_FN E2D_AVX2_FN
#include "joint_point_kernel.inl"
#undef E2D_WIDE_FN
} // namespace
} // namespace lanes8

__attribute__((target("avx2"))) void warmStartPointOctet(PointJointOctet& q,
                                                         std::span<BodyState> states) {
    lanes8::warmStartHinges(q, states);
}

__attribute__((target("avx2"))) void
solvePointOctet(PointJointOctet& q, std::span<BodyState> states, const Softness& soft) {
    lanes8::solveHinges(q, states, soft);
}

#else

// No eight lanes on this target (bestPointJointLanes() is 4): an octet is two quads' passes,
// lane by lane.
namespace {

PointJointQuad half(const PointJointOctet& q, int h) {
    PointJointQuad r;
    for (int lane = 0; lane < 4; ++lane) {
        const int from = 4 * h + lane;
        r.indexA[lane] = q.indexA[from];
        r.indexB[lane] = q.indexB[from];
        r.slot[lane] = q.slot[from];
        r.invInertiaA[lane] = q.invInertiaA[from];
        r.invInertiaB[lane] = q.invInertiaB[from];
        r.invMassAx[lane] = q.invMassAx[from];
        r.invMassAy[lane] = q.invMassAy[from];
        r.invMassBx[lane] = q.invMassBx[from];
        r.invMassBy[lane] = q.invMassBy[from];
        r.anchorAx[lane] = q.anchorAx[from];
        r.anchorAy[lane] = q.anchorAy[from];
        r.anchorBx[lane] = q.anchorBx[from];
        r.anchorBy[lane] = q.anchorBy[from];
        r.deltaCenterX[lane] = q.deltaCenterX[from];
        r.deltaCenterY[lane] = q.deltaCenterY[from];
        r.impulseX[lane] = q.impulseX[from];
        r.impulseY[lane] = q.impulseY[from];
    }
    return r;
}

} // namespace

void warmStartPointOctet(PointJointOctet& q, std::span<BodyState> states) {
    for (int h = 0; h < 2; ++h) {
        PointJointQuad r = half(q, h);
        warmStartPointQuad(r, states);
    }
}

void solvePointOctet(PointJointOctet& q, std::span<BodyState> states, const Softness& soft) {
    for (int h = 0; h < 2; ++h) {
        PointJointQuad r = half(q, h);
        solvePointQuad(r, states, soft);
        std::memcpy(q.impulseX + 4 * h, r.impulseX, sizeof r.impulseX);
        std::memcpy(q.impulseY + 4 * h, r.impulseY, sizeof r.impulseY);
    }
}

#endif

} // namespace e2d::physics::detail
