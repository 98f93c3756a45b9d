// SPDX-License-Identifier: MIT
#include "soft_step_stages.hpp"

#include <algorithm>

namespace e2d::physics::detail {

namespace {

// The smallest blocks of work: below them claiming a block costs about as much as running it.
constexpr int kMinGroupsPerBlock = 4;
constexpr int kMinBodiesPerBlock = 64;
// Blocks per worker and stage at most: enough that a worker slowed by the rest of the machine
// leaves little for the others to wait on at the end of each stage.
constexpr int kBlocksPerWorker = 8;

// Appends the stages of forEachSoftStepPass()'s passes.
struct StageList {
    std::vector<SoftStage>& out;
    const WideContacts& wide;
    int firstLevel;
    int endLevel;
    int bodyCount;
    bool restitutionToDo;
    int workers;

    void add(SoftStage stage, int minPerBlock) {
        const int items = stage.end - stage.begin;
        if (items <= 0) {
            return;
        }
        const int blocks =
            std::clamp((items + minPerBlock - 1) / minPerBlock, 1, kBlocksPerWorker * workers);
        stage.perBlock = (items + blocks - 1) / blocks;
        out.push_back(stage);
    }
    void addLevel(SoftStage stage, int level) {
        stage.begin = wide.levelStart[static_cast<std::size_t>(level)];
        stage.end = wide.levelStart[static_cast<std::size_t>(level) + 1];
        add(stage, kMinGroupsPerBlock);
    }

    void integrateVelocities(int /*subStep*/) {
        SoftStage stage{.kind = SoftStage::Kind::IntegrateVelocities};
        stage.end = bodyCount;
        add(stage, kMinBodiesPerBlock);
    }
    void warmStart() {
        for (int level = firstLevel; level < endLevel; ++level) {
            addLevel({.kind = SoftStage::Kind::WarmStart}, level);
        }
    }
    void solve(bool useBias, bool backward, bool reversePoints, bool /*joints: none*/) {
        const SoftStage stage{
            .kind = SoftStage::Kind::Solve, .useBias = useBias, .reversePoints = reversePoints};
        if (backward) {
            for (int level = endLevel; level-- > firstLevel;) {
                addLevel(stage, level);
            }
        } else {
            for (int level = firstLevel; level < endLevel; ++level) {
                addLevel(stage, level);
            }
        }
    }
    void integratePositions() {
        SoftStage stage{.kind = SoftStage::Kind::IntegratePositions};
        stage.end = bodyCount;
        add(stage, kMinBodiesPerBlock);
    }
    void restitution() {
        if (restitutionToDo) {
            out.push_back({.kind = SoftStage::Kind::Restitution, .begin = 0, .end = 1});
        }
    }
};

struct StageContext {
    const SolverStep& step;
    WideContacts& wide;
    std::span<const int> bodies;
    std::span<const WideRestitution> restitution;
    std::span<const SoftStage> stages;
    float h;
};

void runStage(int stageIndex, int block, int /*worker*/, void* context) {
    const StageContext& c = *static_cast<const StageContext*>(context);
    const SoftStage& stage = c.stages[static_cast<std::size_t>(stageIndex)];
    const int begin = stage.begin + block * stage.perBlock;
    const int end = std::min(begin + stage.perBlock, stage.end);
    const SolverDef& def = *c.step.def;
    auto bodies = [&] {
        return c.bodies.subspan(static_cast<std::size_t>(begin),
                                static_cast<std::size_t>(end - begin));
    };
    switch (stage.kind) {
    case SoftStage::Kind::IntegrateVelocities:
        integrateBlockVelocities(c.step.sims, c.step.states, bodies(), c.h, def.maxLinearSpeed);
        break;
    case SoftStage::Kind::WarmStart:
        warmStartWideGroups(c.wide, begin, end);
        break;
    case SoftStage::Kind::Solve:
        solveWideGroups(c.wide, begin, end, 1.0f / c.h, stage.useBias, def.contactPushMaxSpeed,
                        stage.reversePoints);
        break;
    case SoftStage::Kind::IntegratePositions:
        integrateBlockPositions(c.step.states, bodies(), c.h, def.maxLinearSpeed);
        break;
    case SoftStage::Kind::Restitution:
        applyRestitutionWide(c.wide, c.restitution, c.step.states, def.restitutionThreshold, c.h);
        break;
    }
}

} // namespace

void solveSoftStepStaged(const SolverStep& step, WideContacts& wide, int firstLevel, int endLevel,
                         std::span<const int> bodies, std::span<const WideRestitution> restitution,
                         Tasks& tasks, SoftStepStages& scratch) {
    scratch.stages.clear();
    StageList list{scratch.stages,
                   wide,
                   firstLevel,
                   endLevel,
                   static_cast<int>(bodies.size()),
                   !restitution.empty(),
                   tasks.workerCount()};
    forEachSoftStepPass(step, list);
    scratch.blockCounts.clear();
    for (const SoftStage& stage : scratch.stages) {
        scratch.blockCounts.push_back((stage.end - stage.begin + stage.perBlock - 1) /
                                      stage.perBlock);
    }
    scratch.runner.reset(scratch.blockCounts, tasks.workerCount());
    StageContext context{step,           wide,
                         bodies,         restitution,
                         scratch.stages, step.dt / static_cast<float>(step.def->subSteps)};
    // One piece per worker; each joins the stages where they are when it starts.
    tasks.parallelFor(tasks.workerCount(), 1, [&](int /*begin*/, int /*end*/, int worker) {
        scratch.runner.join(worker, runStage, &context);
    });
}

} // namespace e2d::physics::detail
