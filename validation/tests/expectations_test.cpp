// SPDX-License-Identifier: MIT
#include "engine.hpp"
#include "expectations.hpp"
#include "metrics.hpp"
#include "svg_plot.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace e2d::validation {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Expectations, BounceApexIsESquaredH) {
    EXPECT_DOUBLE_EQ(bounceApex(0.5, 5.0), 1.25);
    EXPECT_DOUBLE_EQ(bounceApex(0.75, 5.0), 2.8125);
    EXPECT_DOUBLE_EQ(bounceApex(0.0, 5.0), 0.0);
    EXPECT_DOUBLE_EQ(bounceApex(1.0, 5.0), 5.0);
}

TEST(Expectations, SlideDistanceOnASlope) {
    // 30 deg, mu 0.2, g 10: a = 10 (0.5 - 0.2 * 0.8660254) = 3.2679492; 2 s: 0.5 a 4 = 6.5358984.
    EXPECT_NEAR(slideDistance(10.0, kPi / 6.0, 0.2, 2.0), 6.5358984, 1e-6);
    // 45 deg, mu 0.5: a = 10 * 0.7071068 * 0.5 = 3.5355339; 1.5 s: 0.5 a 2.25 = 3.9774756.
    EXPECT_NEAR(slideDistance(10.0, kPi / 4.0, 0.5, 1.5), 3.9774756, 1e-6);
    // Below the friction angle (tan 20 deg = 0.364 < 0.5) the box holds.
    EXPECT_DOUBLE_EQ(slideDistance(10.0, 20.0 * kPi / 180.0, 0.5, 2.0), 0.0);
    // Frictionless: 0.5 g sin t^2.
    EXPECT_NEAR(slideDistance(10.0, kPi / 6.0, 0.0, 1.0), 2.5, 1e-12);
}

TEST(Expectations, StoppingDistanceAndPosition) {
    // 5 m/s, mu 0.5, g 10: 25 / 10 = 2.5 m, reached at t = v / (mu g) = 1 s.
    EXPECT_DOUBLE_EQ(stoppingDistance(5.0, 0.5, 10.0), 2.5);
    EXPECT_DOUBLE_EQ(slidingPosition(5.0, 0.5, 10.0, 0.5), 5.0 * 0.5 - 0.5 * 5.0 * 0.25);
    EXPECT_DOUBLE_EQ(slidingPosition(5.0, 0.5, 10.0, 1.0), 2.5);
    EXPECT_DOUBLE_EQ(slidingPosition(5.0, 0.5, 10.0, 3.0), 2.5);
}

TEST(Expectations, RollingDiscAcceleratesAtTwoThirdsGSin) {
    // 30 deg, g 10: a = (2/3) 10 0.5 = 10/3; 2 s: 0.5 a 4 = 20/3.
    EXPECT_NEAR(rollingDistance(10.0, kPi / 6.0, 2.0), 20.0 / 3.0, 1e-12);
}

TEST(Expectations, OneDimensionalImpacts) {
    // m2 = 3 m1, 4 m/s against -2 m/s. P = 4 - 6 = -2 (per m1), M = 4.
    const Impact1D elastic = impact1D(1.0, 4.0, 3.0, -2.0, 1.0);
    EXPECT_NEAR(elastic.v1, -5.0, 1e-12);
    EXPECT_NEAR(elastic.v2, 1.0, 1e-12);
    const Impact1D half = impact1D(1.0, 4.0, 3.0, -2.0, 0.5);
    EXPECT_NEAR(half.v1, -2.75, 1e-12);
    EXPECT_NEAR(half.v2, 0.25, 1e-12);
    // KE ratio of the shipped inelastic scenario: (0.5 * 7.5625 + 1.5 * 0.0625) / 14 = 3.875/14.
    const double ke0 = 0.5 * 16.0 + 1.5 * 4.0;
    const double ke1 = 0.5 * half.v1 * half.v1 + 1.5 * half.v2 * half.v2;
    EXPECT_NEAR(ke1 / ke0, 0.276786, 1e-6);
    const Impact1D plastic = impact1D(1.0, 4.0, 3.0, -2.0, 0.0);
    EXPECT_NEAR(plastic.v1, -0.5, 1e-12);
    EXPECT_NEAR(plastic.v2, -0.5, 1e-12);
}

TEST(Metrics, MedianAndP95) {
    std::vector<double> v;
    for (int i = 20; i >= 1; --i) {
        v.push_back(i);
    }
    const auto [median, p95] = medianAndP95(v);
    EXPECT_DOUBLE_EQ(median, 10.5);
    EXPECT_DOUBLE_EQ(p95, 19.0); // nearest rank: ceil(0.95 * 20) = 19th value
    EXPECT_EQ(medianAndP95({}), (std::pair<double, double>{0.0, 0.0}));
}

// A recording of a ball that falls from 5 m above rest and rebounds with e = 0.5 perfectly
// (exact ballistic samples), for the evaluation code.
Recording bouncingBall(double e) {
    Recording rec;
    rec.timeStep = 1.0f / 600.0f;
    const double g = 10.0;
    const double h = 5.0;
    const double restY = 0.5;
    const double tImpact = std::sqrt(2.0 * h / g);
    const double vUp = e * g * tImpact;
    std::vector<Sample> ball;
    // Up to 1.8 s: after the first rebound, before the second landing (at 2 s for e = 0.5).
    for (int k = 0; k <= 1080; ++k) {
        const double t = k * double(rec.timeStep);
        double y;
        double vy;
        if (t < tImpact) {
            y = restY + h - 0.5 * g * t * t;
            vy = -g * t;
        } else {
            const double s = t - tImpact;
            y = restY + vUp * s - 0.5 * g * s * s;
            vy = vUp - g * s;
        }
        ball.push_back({{0.0f, static_cast<float>(y)}, 0.0f, {0.0f, static_cast<float>(vy)}});
        rec.kineticEnergy.push_back(0.5f * static_cast<float>(vy * vy));
        rec.momentum.push_back({0.0f, static_cast<float>(vy)});
        rec.maxSpeed.push_back(static_cast<float>(std::abs(vy)));
        rec.penetration.push_back(0.0f);
        rec.allAsleep.push_back(false);
        if (k > 0) {
            rec.stepMs.push_back(1.0);
        }
    }
    rec.tagged["ball"] = ball;
    return rec;
}

TEST(Evaluate, BounceHeightOfAnExactTrajectory) {
    const Recording rec = bouncingBall(0.5);
    Check c;
    c.kind = CheckKind::BounceHeight;
    c.body = "ball";
    c.height = 5.0f;
    c.restY = 0.5f;
    c.restitution = 0.5f;
    c.tolerance = 0.01f;
    const CheckResult r = evaluate(c, rec, 10.0f);
    EXPECT_DOUBLE_EQ(r.expected, 1.25);
    EXPECT_NEAR(r.measured, 1.25, 1e-3);
    EXPECT_TRUE(r.passed);
    // The same trajectory judged as e = 0.75 (expected 2.8125 m) fails.
    c.restitution = 0.75f;
    EXPECT_FALSE(evaluate(c, rec, 10.0f).passed);
}

TEST(Evaluate, MomentumKineticEnergyAndSpeed) {
    const Recording rec = bouncingBall(0.5);
    Check c;
    c.kind = CheckKind::MaxSpeed;
    c.limit = 11.0f;
    // Fastest at impact: g t = sqrt(2 g h) = 10 m/s.
    CheckResult r = evaluate(c, rec, 10.0f);
    EXPECT_NEAR(r.measured, 10.0, 0.02);
    EXPECT_TRUE(r.passed);
    c.limit = 9.0f;
    EXPECT_FALSE(evaluate(c, rec, 10.0f).passed);
    // Naming a body judges that body alone: a faster body elsewhere does not count.
    Recording withFastLink = rec;
    for (float& v : withFastLink.maxSpeed) {
        v = 20.0f;
    }
    c.limit = 11.0f;
    EXPECT_FALSE(evaluate(c, withFastLink, 10.0f).passed);
    c.body = "ball";
    r = evaluate(c, withFastLink, 10.0f);
    EXPECT_NEAR(r.measured, 10.0, 0.02);
    EXPECT_TRUE(r.passed);
    EXPECT_EQ(r.quantity, "fastest speed of \"ball\" over the run, m/s");
    c.body.clear();
    // Gravity changes momentum: the check must see it.
    c.kind = CheckKind::Momentum;
    c.tolerance = 0.01f;
    EXPECT_FALSE(evaluate(c, rec, 10.0f).passed);
}

TEST(Evaluate, SlideDistanceIsMeasuredAlongTheSlope) {
    Recording rec;
    rec.timeStep = 0.5f;
    const float theta = static_cast<float>(kPi / 6.0);
    const glm::vec2 down{-std::cos(theta), -std::sin(theta)};
    const glm::vec2 normal{-std::sin(theta), std::cos(theta)};
    std::vector<Sample> block;
    for (int k = 0; k <= 4; ++k) {
        const float t = 0.5f * static_cast<float>(k);
        const float s = static_cast<float>(slideDistance(10.0, theta, 0.2, t));
        // A push out along the normal (a skin) must not count as sliding.
        block.push_back({s * down + (k > 0 ? 0.015f : 0.0f) * normal, 0.0f, {}});
        rec.kineticEnergy.push_back(0.0f);
    }
    rec.tagged["block"] = block;
    Check c;
    c.kind = CheckKind::SlideDistance;
    c.body = "block";
    c.slopeAngle = theta;
    c.friction = 0.2f;
    c.time = 2.0f;
    c.tolerance = 1e-3f;
    const CheckResult r = evaluate(c, rec, 10.0f);
    EXPECT_NEAR(r.expected, 6.5358984, 1e-6);
    EXPECT_NEAR(r.measured, 6.5358984, 1e-4);
    EXPECT_TRUE(r.passed);
}

TEST(Evaluate, StandingFailsWhenTheTopFalls) {
    Recording rec;
    rec.tagged["top"] = {{{0.0f, 9.5f}, 0.0f, {}}, {{0.02f, 9.45f}, 0.0f, {}}};
    rec.kineticEnergy = {0.0f, 0.0f};
    Check c;
    c.kind = CheckKind::Standing;
    c.body = "top";
    c.tolerance = 0.05f;
    c.minY = 9.0f;
    EXPECT_TRUE(evaluate(c, rec, 10.0f).passed);
    rec.tagged["top"].back().position = {0.02f, 0.5f}; // fell straight down
    EXPECT_FALSE(evaluate(c, rec, 10.0f).passed);
    rec.tagged["top"].back().position = {0.3f, 9.5f}; // slid off sideways
    EXPECT_FALSE(evaluate(c, rec, 10.0f).passed);
}

// A body that turns a quarter turn and a half, through the wrap at pi: e2d reports angles in
// (-pi, pi], so a step from 3.1 to -3.1 is a turn of 0.083 rad, not 6.2.
Recording turning(const std::vector<float>& angles) {
    Recording rec;
    rec.timeStep = 0.5f;
    for (float a : angles) {
        rec.tagged["domino"].push_back({{0.0f, 0.0f}, a, {}});
        rec.kineticEnergy.push_back(0.0f);
        rec.momentum.emplace_back(0.0f);
        rec.maxSpeed.push_back(0.0f);
        rec.penetration.push_back(0.0f);
        rec.allAsleep.push_back(false);
    }
    return rec;
}

TEST(Evaluate, TurnIsUnwrappedAndJudgedAtTheEndOrEveryInstant) {
    const float pi = static_cast<float>(kPi);
    // 0 -> 1.5 -> 3.0 -> -3.0 (= 3.283) -> -2.0 (= 4.283): four and a bit radians.
    const Recording rec = turning({0.0f, 1.5f, 3.0f, -3.0f, -2.0f});
    Check c;
    c.kind = CheckKind::Turn;
    c.body = "domino";
    c.minTurn = 4.0f;
    CheckResult r = evaluate(c, rec, 10.0f);
    EXPECT_NEAR(r.measured, 2.0 * pi - 2.0, 1e-5);
    EXPECT_TRUE(r.passed);
    c.minTurn = 4.5f;
    EXPECT_FALSE(evaluate(c, rec, 10.0f).passed);

    // A box that must stay level: judged by its largest tilt, even when it ends level.
    const Recording tipped = turning({0.0f, 0.05f, 0.3f, 0.0f});
    Check level;
    level.kind = CheckKind::Turn;
    level.body = "domino";
    level.maxTurn = 0.1f;
    r = evaluate(level, tipped, 10.0f);
    EXPECT_FALSE(r.passed);
    EXPECT_NEAR(r.measured, 0.3, 1e-6);
    level.maxTurn = 0.35f;
    EXPECT_TRUE(evaluate(level, tipped, 10.0f).passed);
    const Series series = seriesFor(level, tipped, 10.0f, 1);
    ASSERT_EQ(series.measured.size(), 4u);
    EXPECT_NEAR(series.measured[2], 0.3f, 1e-6f);
    EXPECT_FLOAT_EQ(series.expected[2], 0.35f);
}

TEST(Evaluate, MovesMeasuresDistanceOrDistanceAlongADirection) {
    Recording rec = turning({0.0f, 0.0f, 0.0f});
    auto& s = rec.tagged["domino"];
    s[1].position = {1.0f, -1.0f};
    s[2].position = {3.0f, -4.0f}; // 5 m away, 4 m down, 3 m right
    Check c;
    c.kind = CheckKind::Moves;
    c.body = "domino";
    c.distance = 4.9f;
    CheckResult r = evaluate(c, rec, 10.0f);
    EXPECT_NEAR(r.measured, 5.0, 1e-6);
    EXPECT_TRUE(r.passed);
    c.direction = {0.0f, -1.0f};
    r = evaluate(c, rec, 10.0f);
    EXPECT_NEAR(r.measured, 4.0, 1e-6);
    EXPECT_FALSE(r.passed);
    c.direction = {0.0f, 1.0f}; // it went down, not up
    EXPECT_NEAR(evaluate(c, rec, 10.0f).measured, -4.0, 1e-6);
    // A non-finite position fails however far it got.
    s[1].position.x = std::numeric_limits<float>::infinity();
    c.direction = {0.0f, -1.0f};
    c.distance = 1.0f;
    EXPECT_FALSE(evaluate(c, rec, 10.0f).passed);
}

TEST(Evaluate, TheWorstBodyWithATagSpeaksForTheCheck) {
    Recording rec = turning({0.0f, 0.0f});
    rec.moreTagged["domino"] = {{{{0.0f, 0.0f}, 0.0f, {}}, {{0.0f, 0.0f}, 1.2f, {}}},
                                {{{0.0f, 0.0f}, 0.0f, {}}, {{0.0f, 0.0f}, 0.4f, {}}}};
    Check c;
    c.kind = CheckKind::Turn;
    c.body = "domino";
    c.maxTurn = 0.5f;
    const CheckResult r = evaluate(c, rec, 10.0f);
    EXPECT_FALSE(r.passed);
    EXPECT_NEAR(r.measured, 1.2, 1e-6);
    EXPECT_EQ(r.detail.rfind("worst of 3 bodies tagged domino: body 2", 0), 0u) << r.detail;
}

// x = A cos(2 pi t / T), sampled at 60 Hz with its velocity: the period check finds T from the
// leftmost turns, and fails a wrong expectation.
TEST(Evaluate, PeriodOfASampledSwing) {
    Recording rec;
    rec.timeStep = 1.0f / 60.0f;
    const double period = 1.7;
    const double w = 2.0 * kPi / period;
    for (int k = 0; k <= 600; ++k) {
        const double t = k * double(rec.timeStep);
        rec.tagged["bob"].push_back({{static_cast<float>(0.3 * std::cos(w * t)), 0.0f},
                                     0.0f,
                                     {static_cast<float>(-0.3 * w * std::sin(w * t)), 0.0f}});
        rec.kineticEnergy.push_back(0.0f);
    }
    Check c;
    c.kind = CheckKind::Period;
    c.body = "bob";
    c.period = 1.7f;
    c.tolerance = 0.005f;
    CheckResult r = evaluate(c, rec, 10.0f);
    EXPECT_NEAR(r.measured, period, 1e-3);
    EXPECT_TRUE(r.passed);
    c.period = 1.75f;
    EXPECT_FALSE(evaluate(c, rec, 10.0f).passed);
    // A body at rest has no swing to time.
    rec.tagged["bob"].assign(601, Sample{});
    r = evaluate(c, rec, 10.0f);
    EXPECT_FALSE(r.passed);
    EXPECT_EQ(r.detail, "fewer than two swings");
}

TEST(Evaluate, JointErrorIsTheLargestGapAndFailsOnNaN) {
    Recording rec = turning({0.0f, 0.0f, 0.0f});
    rec.jointError = {0.0f, 0.004f, 0.002f};
    Check c;
    c.kind = CheckKind::JointError;
    c.limit = 0.005f;
    CheckResult r = evaluate(c, rec, 10.0f);
    EXPECT_FLOAT_EQ(static_cast<float>(r.measured), 0.004f);
    EXPECT_TRUE(r.passed);
    c.limit = 0.003f;
    EXPECT_FALSE(evaluate(c, rec, 10.0f).passed);
    rec.jointError[2] = std::numeric_limits<float>::quiet_NaN();
    c.limit = 1.0f;
    r = evaluate(c, rec, 10.0f);
    EXPECT_FALSE(r.passed);
    EXPECT_EQ(r.detail, "non-finite state at t = 1 s");
}

// An engine that reports the body states and joint anchors it is given, to drive a Recorder.
class ScriptedEngine final : public Engine {
public:
    std::vector<BodyState> bodies;
    std::vector<std::pair<glm::vec2, glm::vec2>> anchors;
    void step() override {}
    [[nodiscard]] int bodyCount() const override { return static_cast<int>(bodies.size()); }
    void readBodies(std::vector<BodyState>& out) const override { out = bodies; }
    [[nodiscard]] float maxPenetration() const override { return 0.0f; }
    void readJointAnchors(std::vector<std::pair<glm::vec2, glm::vec2>>& out) const override {
        out = anchors;
    }
};

// A wheel joint's error is its wheel's anchor off the suspension axis, which turns with body A:
// travel along the axis is no error; the same offset after A has turned a quarter is one.
TEST(Recorder, WheelJointErrorIsTheDistanceOffTheTurningAxis) {
    scenes::SceneDesc scene;
    scene.bodies.resize(2);
    scene.bodies[0].angle = 0.5f; // the axis below is given in world axes at this angle
    scenes::JointDesc wheel;
    wheel.kind = scenes::JointKind::Wheel;
    wheel.bodyA = 0;
    wheel.bodyB = 1;
    wheel.axis = {0.0f, 1.0f};
    scene.joints.push_back(wheel);
    Recorder recorder(scene, 0.0f);
    ScriptedEngine engine;
    engine.bodies.resize(2);
    engine.bodies[0].angle = 0.5f;
    engine.anchors = {{{1.0f, 1.0f}, {1.0f, 0.7f}}}; // 0.3 m down the axis: the spring at work
    recorder.record(engine, 0.0);
    engine.anchors = {{{1.0f, 1.0f}, {1.2f, 0.7f}}}; // and 0.2 m to the side of it
    recorder.record(engine, 0.0);
    engine.bodies[0].angle = 0.5f + static_cast<float>(kPi / 2.0); // A turned: the axis is now x
    recorder.record(engine, 0.0);
    const std::vector<float>& error = recorder.recording().jointError;
    ASSERT_EQ(error.size(), 3u);
    EXPECT_NEAR(error[0], 0.0f, 1e-6f);
    EXPECT_NEAR(error[1], 0.2f, 1e-6f);
    EXPECT_NEAR(error[2], 0.3f, 1e-6f); // now the 0.3 m down is off the axis, the 0.2 m along it
}

TEST(SvgPlot, ParetoFrontKeepsTheUnbeatenPoints) {
    const auto front = paretoFront({{3.0, 1.0}, {1.0, 5.0}, {2.0, 2.0}, {2.5, 3.0}, {4.0, 1.0}});
    const std::vector<std::pair<double, double>> expected{{1.0, 5.0}, {2.0, 2.0}, {3.0, 1.0}};
    EXPECT_EQ(front, expected);
}

TEST(SvgPlot, EscapesText) {
    EXPECT_EQ(escapeHtml("a<b & \"c\">"), "a&lt;b &amp; &quot;c&quot;&gt;");
    Plot p;
    p.title = "<x>";
    p.series.push_back({"s", "#000", {{1.0, 2.0}, {2.0, 3.0}}, false, true, {}});
    const std::string svg = renderSvg(p);
    EXPECT_EQ(svg.find("<x>"), std::string::npos);
    EXPECT_NE(svg.find("&lt;x&gt;"), std::string::npos);
    EXPECT_EQ(svg.rfind("<svg", 0), 0u);
}

} // namespace
} // namespace e2d::validation
