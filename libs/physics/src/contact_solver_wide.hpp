// SPDX-License-Identifier: MIT
#pragma once

#include "contact_solver.hpp"
#include "solver_body.hpp"

#include <cstdint>
#include <span>
#include <vector>

// The soft-step contact passes four constraints at a time. Mirrors warmStartContacts() and
// solveContacts() in contact_solver.cpp operation for operation, over the constraints by level
// (ConstraintLevels): a level's constraints share no moving body, so solving four of them at
// once gives bit for bit what solving them one after another does, and level order is the
// same sweep as constraint order. Rolling resistance is not handled here (the world uses the
// scalar functions when a contact has it).
//
// The lanes are GCC/Clang vector extensions: SSE on x86-64, NEON on ARM64, and plain scalar
// code (same operations, same results) wherever the target has no SIMD.
namespace e2d::physics::detail {

using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));

inline constexpr int kLanes = 4;

struct WidePoint {
    Float4 anchorAx, anchorAy, anchorBx, anchorBy;
    Float4 baseSeparation;
    Float4 relativeVelocity;
    Float4 normalImpulse, tangentImpulse, maxNormalImpulse;
    Float4 normalMass, tangentMass;
    Float4 impactGap;
    Int4 impactSeen; // all bits set when seen
};

struct WideConstraint {
    int indexA[kLanes]; // BodyState index, -1: static (or an empty lane)
    int indexB[kLanes];
    Float4 normalX, normalY;
    Float4 invMassAx, invMassAy, invMassBx, invMassBy;
    Float4 invInertiaA, invInertiaB;
    Float4 friction;
    Float4 biasRate, massScale, impulseScale;
    WidePoint points[2];
};

// The packed constraints of one step.
struct WideContacts {
    std::vector<WideConstraint> constraints;
    // Packed constraints of level k: [levelStart[k], levelStart[k + 1]).
    std::vector<int> levelStart;
};

// Sizes `wide` for the levels (levelStart as below) and empties the lanes past each level's
// last constraint; packWideLane() then fills the others.
void layoutWide(WideContacts& wide, std::span<const int> levelStart);
// Puts constraint `c` in lane `lane` of `w`.
void packWideLane(WideConstraint& w, int lane, const ContactConstraint& c);

// Packs the constraints of each level, constraints[levelOrder[levelStart[k] ..
// levelStart[k + 1])], into groups of four (the last group of a level padded with empty lanes).
void prepareWide(WideContacts& wide, std::span<const ContactConstraint> constraints,
                 std::span<const int> levelOrder, std::span<const int> levelStart);
// Copies impulses and the impact bookkeeping back to the constraints.
void storeWide(const WideContacts& wide, std::span<ContactConstraint> constraints,
               std::span<const int> levelOrder, std::span<const int> levelStart);

// warmStartContacts() and solveContacts() over every packed constraint, level after level
// (backward: last level first; reversePoints: each constraint's points last to first).
void warmStartWide(const WideContacts& wide, std::span<BodyState> states);
void solveWide(WideContacts& wide, std::span<BodyState> states, float invH, bool useBias,
               float pushMaxSpeed, bool backward, bool reversePoints);

} // namespace e2d::physics::detail
