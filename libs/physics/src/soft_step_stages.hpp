// SPDX-License-Identifier: MIT
#pragma once

#include "body_solver.hpp"
#include "task_pool.hpp"

#include <span>
#include <vector>

// The soft step of one large block of islands on several workers at once (Box2D v3's solver
// stages): each pass of solveSoftStepBlock() becomes one stage per level, or one over the
// block's bodies, cut into blocks of work that the workers claim; a stage starts once every
// block of the one before it has run (StageRunner).
namespace e2d::physics::detail {

// One stage: a pass over items [begin, end) in blocks of perBlock items. The items are the
// packed groups of one level (WarmStart, Solve) or places in the block's body list.
struct SoftStage {
    enum class Kind : unsigned char {
        IntegrateVelocities,
        WarmStart,
        Solve,
        IntegratePositions,
        Restitution, // one block: the list in constraint order
    };
    Kind kind = Kind::Solve;
    bool useBias = false; // Solve
    bool reversePoints = false;
    int begin = 0;
    int end = 0;
    int perBlock = 1;
};

// solveSoftStepStaged()'s arrays, reused step after step.
struct SoftStepStages {
    std::vector<SoftStage> stages;
    std::vector<int> blockCounts;
    StageRunner runner;
};

// solveSoftStepBlock() for a block without joints whose constraints change no rigid state's
// velocity (no two of a level's constraints then share a state they write), run by every
// worker of `tasks`: the integration passes over parts of `bodies`, each level's warm start and
// solve over parts of its groups (a level's constraints share no moving body), restitution on
// one worker. Each body and each constraint sees the same operations in the same order as in
// solveSoftStepBlock(), so the results are bit for bit the same for any worker count.
void solveSoftStepStaged(const SolverStep& step, WideContacts& wide, int firstLevel, int endLevel,
                         std::span<const int> bodies, std::span<const WideRestitution> restitution,
                         Tasks& tasks, SoftStepStages& scratch);

} // namespace e2d::physics::detail
