// SPDX-License-Identifier: MIT
// World snapshots on every shipped scenario, in both solver modes: step N, save, step M (hash A
// and the state's bytes); restore into the same world and into a new one, step M: the same
// hash and the same bytes. Any state a snapshot leaves out that the step reads (a warm-start
// impulse, a sleep timer, a tree node, a pair's slot) shows up here as a different hash.
#include "scenario_parser.hpp"
#include "world_test_util.hpp"

#include <e2d/physics/world.hpp>
#include <e2d/scenes/e2d_builder.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace e2d::validation {
namespace {

namespace ph = e2d::physics;

// Long enough for contacts, warm starts and (in the resting scenes) sleep timers to build up.
constexpr int kStepsBefore = 90;
constexpr int kStepsAfter = 60;
// The big pyramids (1 275 and 5 050 bodies) cost most of the test: fewer steps, and the largest
// in the soft step only (its classic run shows nothing the small scenes do not).
constexpr std::size_t kLargeScene = 1000;
constexpr std::size_t kHugeScene = 3000;

std::vector<std::string> shippedScenarios() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(E2D_VALIDATION_SCENARIOS_DIR)) {
        if (entry.path().extension() == ".json") {
            names.push_back(entry.path().stem().string());
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

void stepWorld(ph::World& world, float timeStep, int steps) {
    for (int i = 0; i < steps; ++i) {
        world.step(timeStep);
    }
}

class SnapshotRoundTrip : public testing::TestWithParam<std::string> {};

TEST_P(SnapshotRoundTrip, StepsOnBitForBit) {
    const Scenario scenario =
        loadScenario(std::filesystem::path(E2D_VALIDATION_SCENARIOS_DIR) / (GetParam() + ".json"));
    const std::size_t bodies = scenario.scene.bodies.size();
    const int before = bodies > kLargeScene ? kStepsBefore / 3 : kStepsBefore;
    const int after = bodies > kLargeScene ? kStepsAfter / 3 : kStepsAfter;
    for (ph::SolverMode mode : {ph::SolverMode::SoftStep, ph::SolverMode::Classic}) {
        if (mode == ph::SolverMode::Classic && bodies > kHugeScene) {
            continue;
        }
        SCOPED_TRACE(mode == ph::SolverMode::SoftStep ? "soft step" : "classic");
        ph::WorldDef def;
        def.solver.mode = mode;
        scenes::E2dScene scene = scenes::buildE2d(scenario.scene, def);
        const float dt = scene.timeStep;
        stepWorld(scene.world, dt, before);
        const std::vector<std::uint8_t> snapshot = scene.world.saveSnapshot();
        stepWorld(scene.world, dt, after);
        const std::uint64_t expected = ph::test::stateHash(scene.world, scene.bodies);
        const std::vector<std::uint8_t> expectedBytes = scene.world.saveSnapshot();

        scene.world.restoreSnapshot(snapshot);
        stepWorld(scene.world, dt, after);
        EXPECT_EQ(ph::test::stateHash(scene.world, scene.bodies), expected) << "same world";
        EXPECT_TRUE(scene.world.saveSnapshot() == expectedBytes) << "same world";

        ph::World fresh;
        fresh.restoreSnapshot(snapshot);
        stepWorld(fresh, dt, after);
        EXPECT_EQ(ph::test::stateHash(fresh, scene.bodies), expected) << "new world";
        EXPECT_TRUE(fresh.saveSnapshot() == expectedBytes) << "new world";
    }
}

INSTANTIATE_TEST_SUITE_P(Shipped, SnapshotRoundTrip, testing::ValuesIn(shippedScenarios()),
                         [](const testing::TestParamInfo<std::string>& param) {
                             return param.param;
                         });

} // namespace
} // namespace e2d::validation
