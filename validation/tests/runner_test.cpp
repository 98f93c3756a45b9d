// SPDX-License-Identifier: MIT
#include "plan.hpp"
#include "runner.hpp"
#include "scenario_parser.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

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

// The same for e2d: one sub-step (soft step) sinks the awake 50-box column 2.7 m into its
// contacts (their stiffness is capped at a quarter of the sub-step rate, 15 Hz), one velocity
// and position iteration (classic) drops a 10-box stack, which the defaults hold. (Classic at
// its defaults does not hold 20 boxes: the report shows it. The soft step at one sub-step holds
// a 20-box stack upright since it solves each 2-point manifold as one two-row constraint; only
// its 5 cm contacts fail there.)
TEST(BrokenSettings, E2dWithOneSubStepOrOneIterationFailsTheStack) {
    const struct {
        const char* scenario;
        RunSpec good;
        RunSpec broken;
    } cases[] = {{"column_50_awake", e2d("soft", 4, 8, 3), e2d("soft", 1, 8, 3)},
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

// A dynamic box of 0.2 x 0.2 mm trips an assertion inside Box2D 2.4 (its area is below
// b2_epsilon): that run fails with the reason, and the process, e2d's runs and the report go on.
TEST(Runner, AScenarioBox2DCannotBuildFailsThatRunOnly) {
    const Scenario s = parseScenario(R"({"family": "hard", "duration": 0.5, "bodies": [
        {"type": "static", "position": [0, -1], "shape": {"type": "box", "halfExtents": [5, 1]}},
        {"position": [0, 0.0001], "tag": "speck", "shape": {"type": "box", "halfExtents": [0.0001, 0.0001]}}],
        "checks": [{"type": "maxSpeed", "limit": 5}]})",
                                     "speck");
    const RunResult box = runOne(s, box2d(8, 3));
    EXPECT_FALSE(box.passed);
    EXPECT_EQ(box.failure,
              "Box2D 2.4 cannot build this scene: body 1 (\"speck\"), shape 0: box area "
              "4e-08 m^2 is not above b2_epsilon (Box2D 2.4's ComputeMass asserts)");
    const RunResult ours = runOne(s, e2d("soft", 4, 8, 3));
    EXPECT_TRUE(ours.failure.empty()) << ours.failure;
    const std::vector<RunResult> all =
        runPlan({s}, makePlan({s}, {"box2d", "e2d"}, SweepLevel::None, false), 2, {});
    EXPECT_EQ(all.size(), 5u); // Box2D and e2d's four modes, each with its own result
}

// A blown-up measurement must fail its check, never pass because NaN compares false.
TEST(Runner, NonFiniteMeasurementsFailTheirChecks) {
    Recording rec;
    rec.timeStep = 0.5f;
    for (int k = 0; k < 3; ++k) {
        rec.kineticEnergy.push_back(1.0f);
        rec.momentum.emplace_back(0.0f);
        rec.maxSpeed.push_back(k == 1 ? std::numeric_limits<float>::quiet_NaN() : 1.0f);
        rec.penetration.push_back(0.0f);
        rec.allAsleep.push_back(false);
        Sample sample;
        sample.position = {0.0f, k == 2 ? std::numeric_limits<float>::infinity() : 1.0f};
        rec.tagged["ball"].push_back(sample);
    }
    Check speed;
    speed.kind = CheckKind::MaxSpeed;
    speed.limit = 5.0f;
    const CheckResult s = evaluate(speed, rec, 10.0f);
    EXPECT_FALSE(s.passed);
    EXPECT_EQ(s.detail, "non-finite state at t = 0.5 s");
    EXPECT_TRUE(evaluateFinite(speed, rec, 10.0f).passed); // what NaN alone would have said

    Check bounds;
    bounds.kind = CheckKind::Bounds;
    bounds.body = "ball";
    bounds.lower = {-1.0f, -1.0f};
    bounds.upper = {1.0f, 2.0f};
    const CheckResult b = evaluate(bounds, rec, 10.0f);
    EXPECT_FALSE(b.passed);
    EXPECT_EQ(b.detail, "non-finite state at t = 1 s");
}

// A body launched at 1e30 m/s: whatever each engine does with it, the checks must not pass on a
// non-finite number.
TEST(Runner, AnAbsurdVelocityNeverPassesOnInfinity) {
    const Scenario s = parseScenario(R"({"family": "hard", "duration": 0.2, "gravity": [0, 0],
        "bodies": [{"position": [0, 0], "linearVelocity": [1e30, 1e30], "tag": "ball",
                    "shape": {"type": "circle", "radius": 0.5}}],
        "checks": [{"type": "maxSpeed", "limit": 1000}]})",
                                     "absurd");
    for (const RunSpec& spec : {box2d(8, 3), e2d("soft", 4, 8, 3)}) {
        SCOPED_TRACE(spec.config.engine);
        const RunResult r = runOne(s, spec);
        EXPECT_FALSE(r.passed);
        EXPECT_TRUE(std::isfinite(r.normalizedError));
    }
}

TEST(Runner, LongRunsReportTheirProgress) {
    const Scenario s = shipped("drop_e050");
    std::vector<int> seen;
    const RunResult r = runOne(
        s, box2d(8, 3),
        [&](const RunSpec&, int step, int steps, double seconds) {
            EXPECT_EQ(steps, r.steps == 0 ? steps : r.steps);
            EXPECT_GE(seconds, 0.0);
            seen.push_back(step);
        },
        0.0);
    ASSERT_FALSE(seen.empty());
    EXPECT_EQ(seen.front(), 0); // the world is built
    EXPECT_EQ(seen.back(), r.steps);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
}

// A free box of 1 kg in zero gravity: a constant force F for t seconds moves it F t^2 / (2 m)
// (semi-implicit Euler over n steps of dt: F dt^2 n (n + 1) / 2, within 2% at 60 steps); an
// impulse J at t0 moves it J (T - t0) / m by T. Both engines, both pushes.
TEST(Runner, ForcesAndImpulsesMoveBodiesAsNewtonSays) {
    const Scenario s = parseScenario(R"({"family": "hard", "duration": 1, "gravity": [0, 0],
        "bodies": [
          {"position": [0, 0], "tag": "pulled", "force": [2, 0],
           "shape": {"type": "box", "halfExtents": [0.5, 0.5], "density": 1}},
          {"position": [0, 5], "tag": "kicked", "impulses": [{"time": 0.5, "impulse": [0, 3]}],
           "shape": {"type": "box", "halfExtents": [0.5, 0.5], "density": 1}}],
        "checks": [{"type": "moves", "body": "pulled", "distance": 0.9, "direction": [1, 0]},
                   {"type": "moves", "body": "kicked", "distance": 1.4, "direction": [0, 1]}]})",
                                     "pushes");
    for (const RunSpec& spec : {box2d(8, 3), e2d("soft", 4, 8, 3), e2d("classic", 4, 8, 3)}) {
        SCOPED_TRACE(spec.config.family());
        const RunResult r = runOne(s, spec);
        ASSERT_TRUE(r.failure.empty()) << r.failure;
        ASSERT_EQ(r.checks.size(), 2u);
        EXPECT_NEAR(r.checks[0].measured, 0.5 * 2.0 * 1.0, 0.02);
        // Applied before the step that starts at 0.5 s: 30 steps of 3 m/s.
        EXPECT_NEAR(r.checks[1].measured, 3.0 * 0.5, 0.01);
        EXPECT_TRUE(r.passed);
    }
}

// gravityScale 0 floats, 2 falls twice as far as 1 (1/2 g t^2 at 1 s: 4.9 m and 9.8 m).
TEST(Runner, GravityScaleScalesEachBodysFall) {
    const Scenario s = parseScenario(R"({"family": "hard", "duration": 1, "gravity": [0, -9.8],
        "bodies": [
          {"position": [0, 0], "tag": "floating", "gravityScale": 0, "shape": {"type": "circle", "radius": 0.5}},
          {"position": [2, 0], "tag": "falling", "shape": {"type": "circle", "radius": 0.5}},
          {"position": [4, 0], "tag": "heavy", "gravityScale": 2, "shape": {"type": "circle", "radius": 0.5}}],
        "checks": [{"type": "bounds", "body": "floating", "lower": [-0.001, -0.001], "upper": [0.001, 0.001]},
                   {"type": "moves", "body": "falling", "distance": 4.5, "direction": [0, -1]},
                   {"type": "moves", "body": "heavy", "distance": 9.0, "direction": [0, -1]}]})",
                                     "gravity scale");
    for (const RunSpec& spec : {box2d(8, 3), e2d("soft", 4, 8, 3)}) {
        SCOPED_TRACE(spec.config.family());
        const RunResult r = runOne(s, spec);
        ASSERT_EQ(r.checks.size(), 3u);
        EXPECT_TRUE(r.checks[0].passed);
        EXPECT_NEAR(r.checks[1].measured, 4.9, 0.1);
        EXPECT_NEAR(r.checks[2].measured, 2.0 * r.checks[1].measured, 0.02);
        EXPECT_TRUE(r.passed);
    }
}

// Two bodies share the tag "top": one rests on the ground, the other is thrown off the edge. A
// standing check on the tag judges both, and the one that fell speaks for it.
TEST(Runner, ACheckOnASharedTagJudgesEveryBody) {
    const std::string text = R"({"family": "hard", "duration": 2, "bodies": [
          {"type": "static", "position": [0, -1], "shape": {"type": "box", "halfExtents": [3, 1]}},
          {"position": [-2, 0.5], "tag": "top", "shape": {"type": "box", "halfExtents": [0.5, 0.5]}},
          {"position": [2, 0.5], "tag": "top", "linearVelocity": [VX, 0], "shape": {"type": "box", "halfExtents": [0.5, 0.5]}}],
        "checks": [{"type": "standing", "body": "top", "tolerance": 0.05, "minY": 0.4}]})";
    auto withSpeed = [&](const char* vx) {
        std::string t = text;
        t.replace(t.find("VX"), 2, vx);
        return parseScenario(t, "shared tag");
    };
    const RunResult still = runOne(withSpeed("0"), box2d(8, 3));
    ASSERT_EQ(still.checks.size(), 1u);
    EXPECT_TRUE(still.checks[0].passed);
    const RunResult thrown = runOne(withSpeed("20"), box2d(8, 3));
    ASSERT_EQ(thrown.checks.size(), 1u);
    EXPECT_FALSE(thrown.checks[0].passed);
    EXPECT_THAT(thrown.checks[0].detail,
                ::testing::StartsWith("worst of 2 bodies tagged top: body 2"));
}

// The joints of a scene are built in both engines: the shipped pendulum swings at its analytic
// period (2 pi sqrt((r^2/2 + L^2) / (g L)) with the finite-amplitude terms, computed in the
// file's description) within 1 %, its joint holds, and the prismatic motor stops at its limit.
TEST(Runner, JointScenesInBothEngines) {
    const Scenario pendulum = shipped("pendulum_period");
    const double r = 0.05;
    const double L = 1.0;
    const double theta = 0.1;
    const double t0 = 2.0 * 3.14159265358979 * std::sqrt((r * r / 2.0 + L * L) / (10.0 * L));
    const double expected = t0 * (1.0 + theta * theta / 16.0 + 11.0 * std::pow(theta, 4) / 3072.0);
    ASSERT_NEAR(pendulum.checks[0].period, expected, 1e-5);
    const Scenario slider = shipped("prismatic_motor_limit");
    for (const RunSpec& spec : {box2d(8, 3), e2d("soft", 4, 8, 3), e2d("classic", 4, 8, 3)}) {
        SCOPED_TRACE(spec.config.family());
        const RunResult p = runOne(pendulum, spec);
        ASSERT_TRUE(p.failure.empty()) << p.failure;
        ASSERT_EQ(p.checks.size(), 2u);
        EXPECT_NEAR(p.checks[0].measured, expected, 0.01 * expected);
        EXPECT_LT(p.checks[1].measured, 0.005);
        const RunResult s = runOne(slider, spec);
        ASSERT_TRUE(s.failure.empty()) << s.failure;
        EXPECT_NEAR(s.checks[0].measured, 1.0, 0.02); // the upper limit
    }
}

// A joint error the check must catch: a two-link chain holds a disc of its own density, but a
// disc of 1000 times it (about 60 000 times a link's mass) pulls Box2D's joints apart.
TEST(Runner, JointErrorCanFail) {
    auto chain = [](const char* density) {
        std::string text = R"({"family": "hard", "duration": 2, "bodies": [
          {"type": "static", "position": [0, 10], "shape": {"type": "box", "halfExtents": [0.1, 0.1]}},
          {"position": [0.5, 10], "shape": {"type": "box", "halfExtents": [0.5, 0.05], "density": 1}},
          {"position": [1.5, 10], "shape": {"type": "box", "halfExtents": [0.5, 0.05], "density": 1}},
          {"position": [3.0, 10], "shape": {"type": "circle", "radius": 1, "density": DENSITY}}],
        "joints": [{"type": "revolute", "bodyA": 0, "bodyB": 1, "anchor": [0, 10]},
                   {"type": "revolute", "bodyA": 1, "bodyB": 2, "anchor": [1, 10]},
                   {"type": "revolute", "bodyA": 2, "bodyB": 3, "anchor": [2, 10]}],
        "checks": [{"type": "jointError", "limit": 0.05}]})";
        text.replace(text.find("DENSITY"), 7, density);
        return parseScenario(text, "chain");
    };
    const RunResult light = runOne(chain("1"), box2d(8, 3));
    ASSERT_EQ(light.checks.size(), 1u);
    EXPECT_TRUE(light.checks[0].passed) << light.checks[0].measured;
    const RunResult heavy = runOne(chain("1000"), box2d(8, 3));
    ASSERT_EQ(heavy.checks.size(), 1u);
    EXPECT_FALSE(heavy.checks[0].passed);
    EXPECT_GT(heavy.checks[0].measured, 0.05);
}

// The engines every joint and chain test runs on.
std::vector<RunSpec> allEngines() {
    return {box2d(8, 3), e2d("soft", 4, 8, 3), e2d("classic", 4, 8, 3)};
}

// A wheel under a static body on a vertical suspension of f = 2 Hz (damping ratio 1) sags by
// g / (2 pi f)^2 = 0.0633 m, its anchor staying on the axis; a wheel motor in zero gravity
// spins the wheel at its speed (3 rad/s for 2 s, less the spin-up: about 6 rad).
TEST(Runner, WheelJointSpringAndMotor) {
    const Scenario sag = parseScenario(R"({"family": "hard", "duration": 4, "bodies": [
        {"type": "static", "position": [0, 2], "shape": {"type": "box", "halfExtents": [0.5, 0.1]}},
        {"position": [0, 1], "tag": "wheel", "shape": {"type": "circle", "radius": 0.2}}],
        "joints": [{"type": "wheel", "bodyA": 0, "bodyB": 1, "anchor": [0, 1], "hertz": 2, "dampingRatio": 1}],
        "checks": [{"type": "moves", "body": "wheel", "distance": 0.01, "direction": [0, -1]},
                   {"type": "jointError", "limit": 0.001}]})",
                                       "wheel_sag");
    const double omega = 2.0 * 3.14159265358979 * 2.0;
    const Scenario spin =
        parseScenario(R"({"family": "hard", "duration": 2, "gravity": [0, 0], "bodies": [
        {"type": "static", "position": [0, 2], "shape": {"type": "box", "halfExtents": [0.5, 0.1]}},
        {"position": [0, 1], "tag": "wheel", "shape": {"type": "circle", "radius": 0.2}}],
        "joints": [{"type": "wheel", "bodyA": 0, "bodyB": 1, "anchor": [0, 1], "motorSpeed": 3, "maxMotorTorque": 10}],
        "checks": [{"type": "turn", "body": "wheel", "minTurn": 5}]})",
                      "wheel_spin");
    for (const RunSpec& spec : allEngines()) {
        SCOPED_TRACE(spec.config.family());
        const RunResult r = runOne(sag, spec);
        ASSERT_TRUE(r.failure.empty()) << r.failure;
        EXPECT_NEAR(r.checks[0].measured, 10.0 / (omega * omega), 0.003);
        EXPECT_TRUE(r.checks[1].passed) << r.checks[1].measured;
        const RunResult m = runOne(spin, spec);
        ASSERT_TRUE(m.failure.empty()) << m.failure;
        EXPECT_NEAR(m.checks[0].measured, 6.0, 0.1);
    }
}

// A mouse joint in zero gravity pulls a box 1 m to its target; one whose largest force (5 N) is
// below a 1 kg box's weight lets it fall at (10 - 5) m/s^2 or faster: at least 10 m in 2 s. A
// motor joint drives a box to the offset it is given from a static body (2 m to the right).
TEST(Runner, MouseAndMotorJoints) {
    const Scenario pull =
        parseScenario(R"({"family": "hard", "duration": 4, "gravity": [0, 0], "bodies": [
        {"type": "static", "position": [0, -5], "shape": {"type": "box"}},
        {"position": [0, 0], "tag": "box", "shape": {"type": "box"}}],
        "joints": [{"type": "mouse", "bodyA": 0, "bodyB": "box", "target": [1, 0], "hertz": 2, "dampingRatio": 1}],
        "checks": [{"type": "moves", "body": "box", "distance": 0.5, "direction": [1, 0]}]})",
                      "mouse_pull");
    const Scenario weak = parseScenario(R"({"family": "hard", "duration": 2, "bodies": [
        {"type": "static", "position": [0, -50], "shape": {"type": "box"}},
        {"position": [0, 0], "tag": "box", "shape": {"type": "box"}}],
        "joints": [{"type": "mouse", "bodyA": 0, "bodyB": "box", "target": [0, 0], "maxForce": 5}],
        "checks": [{"type": "moves", "body": "box", "distance": 9.9, "direction": [0, -1]}]})",
                                        "mouse_weak");
    const Scenario motor =
        parseScenario(R"({"family": "hard", "duration": 4, "gravity": [0, 0], "bodies": [
        {"type": "static", "position": [0, 0], "shape": {"type": "box", "halfExtents": [0.1, 0.1]}},
        {"position": [0, 1], "tag": "box", "shape": {"type": "box"}}],
        "joints": [{"type": "motor", "bodyA": 0, "bodyB": "box", "linearOffset": [2, 1], "maxForce": 100, "maxTorque": 100}],
        "checks": [{"type": "moves", "body": "box", "distance": 1, "direction": [1, 0]}]})",
                      "motor");
    for (const RunSpec& spec : allEngines()) {
        SCOPED_TRACE(spec.config.family());
        const RunResult p = runOne(pull, spec);
        ASSERT_TRUE(p.failure.empty()) << p.failure;
        EXPECT_NEAR(p.checks[0].measured, 1.0, 0.01);
        const RunResult w = runOne(weak, spec);
        ASSERT_TRUE(w.failure.empty()) << w.failure;
        EXPECT_TRUE(w.checks[0].passed) << w.checks[0].measured;
        EXPECT_LT(w.checks[0].measured, 20.5); // no faster than free fall (20 m)
        const RunResult m = runOne(motor, spec);
        ASSERT_TRUE(m.failure.empty()) << m.failure;
        EXPECT_NEAR(m.checks[0].measured, 2.0, 0.02);
    }
}

// Box2D 2.4.1's revolute joint has no spring: that run fails with the reason; e2d's spring
// (10 Hz) holds a horizontal bar that falls through 1 rad without it.
TEST(Runner, RevoluteSpringIsE2dOnly) {
    auto bar = [](const char* spring) {
        return parseScenario(std::string(R"({"family": "hard", "duration": 2, "bodies": [
            {"type": "static", "position": [0, 0], "shape": {"type": "box", "halfExtents": [0.1, 0.1]}},
            {"position": [0.5, 0], "tag": "bar", "shape": {"type": "box", "halfExtents": [0.5, 0.05]}}],
            "joints": [{"type": "revolute", "bodyA": 0, "bodyB": "bar", "anchor": [0, 0])") +
                                 spring + R"(}],
            "checks": [{"type": "turn", "body": "bar", "maxTurn": 1}]})",
                             "bar");
    };
    const Scenario sprung = bar(R"(, "hertz": 10, "dampingRatio": 1)");
    const RunResult box = runOne(sprung, box2d(8, 3));
    EXPECT_EQ(box.failure,
              "Box2D 2.4 cannot build this scene: joint 0: Box2D 2.4.1's revolute joint has no "
              "spring (b2RevoluteJointDef has no stiffness; Box2D v3's has one)");
    for (const RunSpec& spec : {e2d("soft", 4, 8, 3), e2d("classic", 4, 8, 3)}) {
        SCOPED_TRACE(spec.config.family());
        const RunResult held = runOne(sprung, spec);
        ASSERT_TRUE(held.failure.empty()) << held.failure;
        EXPECT_TRUE(held.checks[0].passed) << held.checks[0].measured;
        const RunResult fell = runOne(bar(""), spec);
        EXPECT_FALSE(fell.checks[0].passed) << fell.checks[0].measured;
    }
}

// A box launched at 4 m/s along a floor of 60 collinear chain segments never bumps (its origin
// stays within 5 cm of its resting height, Box2D's 0.02 m of skin allowed for) and never tilts;
// the segments right of x = 0 have friction 0.25 (with the box's 1: mu = 0.5), those left of it
// none, so it slides freely to x = 0 and stops v^2 / (2 mu g) = 1.6 m beyond: 9.6 m from x = -8.
TEST(Runner, ChainFloorWithAMaterialPerSegment) {
    std::string points;
    std::string materials;
    for (int i = 0; i <= 60; ++i) {
        points += (i == 0 ? "" : ", ") + std::string("[") + std::to_string(20.0 - 0.5 * i) + ", 0]";
        if (i < 60) {
            materials +=
                (i == 0 ? "" : ", ") +
                std::string(20.0 - 0.5 * i > 0.0 ? R"({"friction": 0.25})" : R"({"friction": 0})");
        }
    }
    const Scenario s = parseScenario(R"({"family": "hard", "duration": 4, "bodies": [
        {"type": "static", "shape": {"type": "chain", "points": [)" +
                                         points + R"(], "materials": [)" + materials + R"(]}},
        {"position": [-8, 0.5], "linearVelocity": [4, 0], "tag": "box", "shape": {"type": "box", "friction": 1}}],
        "checks": [{"type": "moves", "body": "box", "distance": 9, "direction": [1, 0]},
                   {"type": "bounds", "body": "box", "lower": [-9, 0.45], "upper": [12, 0.55]},
                   {"type": "turn", "body": "box", "maxTurnDeg": 1}]})",
                                     "chain_floor");
    for (const RunSpec& spec : allEngines()) {
        SCOPED_TRACE(spec.config.family());
        const RunResult r = runOne(s, spec);
        ASSERT_TRUE(r.failure.empty()) << r.failure;
        EXPECT_NEAR(r.checks[0].measured, 9.6, 0.25);
        EXPECT_TRUE(r.checks[1].passed) << r.checks[1].detail;
        EXPECT_TRUE(r.checks[2].passed) << r.checks[2].measured;
    }
}

// The shipped car (wheel joints with springs and a motor on one b2ChainShape / e2d chain)
// drives over its bumps in every engine; with its motor off it stays where it is put.
TEST(Runner, TheCarDrivesOverTheBumpyChain) {
    const Scenario car = shipped("car_bumpy_chain");
    Scenario parked = car;
    parked.scene.joints[0].enableMotor = false;
    for (const RunSpec& spec : allEngines()) {
        SCOPED_TRACE(spec.config.family());
        const RunResult r = runOne(car, spec);
        ASSERT_TRUE(r.failure.empty()) << r.failure;
        ASSERT_EQ(r.checks.size(), 4u);
        for (const CheckResult& c : r.checks) {
            EXPECT_TRUE(c.passed) << c.kind << " " << c.measured;
        }
        EXPECT_LT(r.checks[0].measured, 32.0); // no faster than rolling at the motor's speed
        const RunResult p = runOne(parked, spec);
        EXPECT_LT(std::abs(p.checks[0].measured), 0.1);
    }
}

} // namespace
} // namespace e2d::validation
