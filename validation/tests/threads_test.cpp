// SPDX-License-Identifier: MIT
// Every shipped scenario, joints and contacts alike, steps bit for bit the same with 1, 2, 3 and
// 8 workers (physics::WorldDef::workerCount) on the SSE2 (4 lanes) and AVX2 (8 lanes) solver
// paths, with each joint solver, a large pyramid's single island solved by all workers together
// included. Short runs: at most 30 steps, fewer for big scenes.
#include "scenario_parser.hpp"

#include <e2d/physics/world.hpp>
#include <e2d/scenes/e2d_builder.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace e2d::validation {
namespace {

namespace ph = e2d::physics;

// FNV-1a over the bits of every body's transform and velocities after every step. `staged`
// (when given) counts the constraints all workers solved together (StepCounters).
std::uint64_t runHash(const Scenario& scenario, int workers, int lanes, ph::JointSolver joints,
                      int steps, int* staged = nullptr) {
    ph::WorldDef def;
    def.tag = 3;
    def.workerCount = workers;
    def.minSplitWork = 0; // every stage split: what the hashes compare
    def.simdLanes = lanes;
    def.solver.jointSolver = joints;
    scenes::E2dScene scene = scenes::buildE2d(scenario.scene, def);
    std::uint64_t h = 1469598103934665603ull;
    auto add = [&h](float x) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, &x, sizeof bits);
        h = (h ^ bits) * 1099511628211ull;
    };
    for (int i = 0; i < steps; ++i) {
        scene.step();
        if (staged != nullptr) {
            *staged += scene.world.stepCounters().stagedConstraints;
        }
        for (ph::BodyId id : scene.bodies) {
            const ph::Transform xf = scene.world.transform(id);
            const ph::Vec2 v = scene.world.linearVelocity(id);
            for (float x :
                 {xf.p.x, xf.p.y, xf.q.c, xf.q.s, v.x, v.y, scene.world.angularVelocity(id)}) {
                add(x);
            }
        }
    }
    return h;
}

std::vector<std::filesystem::path> scenarioFiles() {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(E2D_VALIDATION_SCENARIOS_DIR)) {
        if (entry.path().extension() == ".json") {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

TEST(Threads, EveryScenarioStepsTheSameForEveryWorkerCountAndSimdWidth) {
    const std::vector<std::filesystem::path> files = scenarioFiles();
    ASSERT_GE(files.size(), 40u);
    for (const std::filesystem::path& file : files) {
        const Scenario scenario = loadScenario(file);
        // About 10 000 body steps each, between 5 and 30 steps (CI's budget).
        const int bodies = std::max(static_cast<int>(scenario.scene.bodies.size()), 1);
        const int steps = std::clamp(10000 / bodies, 5, 30);
        std::vector<ph::JointSolver> jointSolvers{ph::JointSolver::Soft};
        if (!scenario.scene.joints.empty()) {
            jointSolvers.push_back(ph::JointSolver::Direct);
        }
        for (ph::JointSolver joints : jointSolvers) {
            const std::uint64_t reference = runHash(scenario, 1, 8, joints, steps);
            for (int lanes : {4, 8}) {
                for (int workers : {1, 2, 3, 8}) {
                    if (workers == 1 && lanes == 8) {
                        continue;
                    }
                    int staged = 0;
                    EXPECT_EQ(runHash(scenario, workers, lanes, joints, steps, &staged), reference)
                        << scenario.name << ": " << workers << " workers, " << lanes
                        << " lanes, joint solver " << static_cast<int>(joints);
                    // The large pyramids are one island each, which the workers solve together.
                    if ((scenario.name == "pyramid_50" || scenario.name == "pyramid_100") &&
                        workers > 1) {
                        EXPECT_GT(staged, 0) << scenario.name << ": " << workers << " workers";
                    }
                }
            }
        }
    }
}

} // namespace
} // namespace e2d::validation
