// SPDX-License-Identifier: MIT
#include "plan.hpp"
#include "runner.hpp"
#include "scenario_parser.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace e2d::validation {
namespace {

Scenario shipped(const std::string& name) {
    return loadScenario(std::filesystem::path(E2D_VALIDATION_SCENARIOS_DIR) / (name + ".json"));
}

const CheckResult* findCheck(const RunResult& r, const std::string& kind) {
    for (const CheckResult& c : r.checks) {
        if (c.kind == kind) {
            return &c;
        }
    }
    return nullptr;
}

RunSpec box2d(int velocity, int position) {
    RunSpec spec;
    spec.config.engine = "box2d";
    spec.config.velocityIterations = velocity;
    spec.config.positionIterations = position;
    return spec;
}

// The stacking checks must be able to fail: Box2D with a single velocity and position
// iteration cannot hold a 20-box stack or a 20-row pyramid, and the checks must say so, while
// Box2D's defaults hold both.
TEST(BrokenSettings, OneIterationFailsTheStackingChecks) {
    for (const char* name : {"stack_20", "pyramid_20"}) {
        SCOPED_TRACE(name);
        const Scenario s = shipped(name);
        const RunResult good = runOne(s, box2d(8, 3));
        EXPECT_TRUE(good.passed);
        EXPECT_TRUE(good.failure.empty()) << good.failure;
        const RunResult broken = runOne(s, box2d(1, 1));
        EXPECT_FALSE(broken.passed);
        const CheckResult* standing = findCheck(broken, "standing");
        ASSERT_NE(standing, nullptr);
        EXPECT_FALSE(standing->passed);
        EXPECT_GT(broken.normalizedError, 1.0);
    }
}

RunSpec e2d(const std::string& solver, int subSteps, int velocity, int position) {
    RunSpec spec;
    spec.config.engine = "e2d";
    spec.config.solver = solver;
    spec.config.subSteps = subSteps;
    spec.config.velocityIterations = velocity;
    spec.config.positionIterations = position;
    return spec;
}

// The same for e2d: one sub-step (soft step) drops a 20-box stack, one velocity and position
// iteration (classic) a 10-box stack, which the defaults hold. (Classic at its defaults does
// not hold 20 boxes: the report shows it.)
TEST(BrokenSettings, E2dWithOneSubStepOrOneIterationFailsTheStack) {
    const struct {
        const char* scenario;
        RunSpec good;
        RunSpec broken;
    } cases[] = {{"stack_20", e2d("soft", 4, 8, 3), e2d("soft", 1, 8, 3)},
                 {"stack_10", e2d("classic", 4, 8, 3), e2d("classic", 4, 1, 1)}};
    for (const auto& c : cases) {
        SCOPED_TRACE(c.good.config.solver);
        const Scenario s = shipped(c.scenario);
        const RunResult good = runOne(s, c.good);
        EXPECT_TRUE(good.passed) << good.failure;
        const RunResult broken = runOne(s, c.broken);
        EXPECT_FALSE(broken.passed);
        const CheckResult* standing = findCheck(broken, "standing");
        ASSERT_NE(standing, nullptr);
        EXPECT_FALSE(standing->passed);
    }
}

TEST(Runner, RecordsMetricsOfABaselineRun) {
    const Scenario s = shipped("stack_5");
    const RunResult r = runOne(s, box2d(8, 3));
    EXPECT_EQ(r.steps, 300); // 5 s at 60 Hz
    EXPECT_EQ(r.bodies, 6);
    ASSERT_TRUE(r.metrics.topDrift.has_value());
    EXPECT_LT(*r.metrics.topDrift, 0.05f);
    ASSERT_TRUE(r.metrics.standing.has_value());
    EXPECT_TRUE(*r.metrics.standing);
    EXPECT_GT(r.metrics.msMedian, 0.0);
    EXPECT_GE(r.metrics.msP95, r.metrics.msMedian);
    // A resting stack in Box2D falls asleep (b2_timeToSleep is 0.5 s).
    ASSERT_TRUE(r.metrics.timeToSleep.has_value());
    EXPECT_LT(*r.metrics.timeToSleep, 4.0f);
    EXPECT_FALSE(r.series.empty());
}

TEST(Runner, AnUnavailableEngineIsAFailedRunNotACrash) {
    const Scenario s = shipped("stack_5");
    RunSpec spec;
    spec.config.engine = "nonexistent";
    const RunResult r = runOne(s, spec);
    EXPECT_FALSE(r.passed);
    EXPECT_NE(r.failure.find("nonexistent"), std::string::npos);
}

TEST(Plan, BaselineSweepAndFeatures) {
    std::vector<Scenario> scenarios{shipped("stack_5"), shipped("pyramid_100")};
    ASSERT_FALSE(scenarios[1].sweep);
    const std::vector<RunSpec> plan = makePlan(scenarios, {"box2d"}, SweepLevel::Full, true);
    int baselines = 0;
    int sweeps = 0;
    int features = 0;
    for (const RunSpec& r : plan) {
        baselines += r.role == RunRole::Baseline ? 1 : 0;
        sweeps += r.role == RunRole::Sweep ? 1 : 0;
        features += r.role == RunRole::Feature ? 1 : 0;
        if (r.scenario == 1 && r.role == RunRole::Sweep) {
            // pyramid_100 is not swept; it only gets the reference run for the scaling plot.
            EXPECT_EQ(r.variant, "vel 8, pos 3");
        }
        EXPECT_TRUE(r.scenario == 0 || r.role != RunRole::Feature);
    }
    EXPECT_EQ(baselines, 2);
    // Six sweep points of stack_5 (sleeping off, so (8, 3) is not the baseline) and the
    // reference of pyramid_100; ccd and warm starting switched off.
    EXPECT_EQ(sweeps, 6 + 1);
    EXPECT_EQ(features, 2);
    for (const RunSpec& r : plan) {
        EXPECT_EQ(r.config.sleeping, r.role == RunRole::Baseline);
    }
}

TEST(Runner, ParallelResultsComeBackInPlanOrder) {
    std::vector<Scenario> scenarios{shipped("drop_e050"), shipped("elastic_impact")};
    const std::vector<RunSpec> plan = makePlan(scenarios, {"box2d"}, SweepLevel::Quick, false);
    int calls = 0;
    const std::vector<RunResult> results =
        runPlan(scenarios, plan, 2, [&](int done, int total, const RunResult&) {
            ++calls;
            EXPECT_LE(done, total);
        });
    ASSERT_EQ(results.size(), plan.size());
    EXPECT_EQ(calls, static_cast<int>(plan.size()));
    for (std::size_t i = 0; i < plan.size(); ++i) {
        EXPECT_EQ(results[i].spec.scenario, plan[i].scenario);
        EXPECT_EQ(results[i].spec.variant, plan[i].variant);
    }
}

} // namespace
} // namespace e2d::validation
