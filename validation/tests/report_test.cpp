// SPDX-License-Identifier: MIT
#include "plan.hpp"
#include "report.hpp"
#include "runner.hpp"
#include "scenario_parser.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace e2d::validation {
namespace {

Scenario shipped(const std::string& name) {
    return loadScenario(std::filesystem::path(E2D_VALIDATION_SCENARIOS_DIR) / (name + ".json"));
}

Report smallReport() {
    Report report;
    report.scenarios = {shipped("stack_5"), shipped("drop_e050"), shipped("slope_slide")};
    report.runs = runPlan(report.scenarios,
                          makePlan(report.scenarios, {"box2d"}, SweepLevel::Quick, true), 2, {});
    report.env = collectEnvironment();
    report.env.command = "test <&>";
    return report;
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
        ++n;
    }
    return n;
}

TEST(ReportJson, RoundTripsAndHoldsEverything) {
    const Report report = smallReport();
    const std::string text = reportToJson(report).dump(1);
    const nlohmann::json j = nlohmann::json::parse(text); // throws if malformed
    EXPECT_EQ(j.at("tool"), "e2d-validate");
    EXPECT_EQ(j.at("environment").at("box2dVersion").get<std::string>().rfind("2.4.1", 0), 0u);
    EXPECT_FALSE(j.at("environment").at("compiler").get<std::string>().empty());
    EXPECT_FALSE(j.at("environment").at("cpu").get<std::string>().empty());
    EXPECT_EQ(j.at("scenarios").size(), 3u);
    EXPECT_EQ(j.at("runs").size(), report.runs.size());
    EXPECT_EQ(j.at("summary").size(), 3u);
    EXPECT_TRUE(j.at("summary")[0].at("engines").contains("box2d"));
    EXPECT_TRUE(j.at("sweeps").contains("stacking"));
    EXPECT_TRUE(j.at("features").contains("friction"));
    EXPECT_NE(j.at("engines")[0].at("translation").get<std::string>().find("0.01 m skin"),
              std::string::npos);
    const nlohmann::json& run = j.at("runs")[0];
    for (const char* key : {"msMedian", "msP95", "maxPenetration", "maxSpeed", "finalKineticEnergy",
                            "topDrift", "standing", "timeToSleep"}) {
        EXPECT_TRUE(run.at("metrics").contains(key)) << key;
    }
    EXPECT_EQ(j.at("passed").get<bool>(), exitStatus(report) == 0);
}

TEST(ReportHtml, IsSelfContainedAndBalanced) {
    const Report report = smallReport();
    const std::string html = reportToHtml(report);
    EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
    EXPECT_NE(html.find("</html>"), std::string::npos);
    for (const char* tag : {"table", "svg", "tr", "td", "th", "h2", "details", "p"}) {
        SCOPED_TRACE(tag);
        const std::string close = std::string("</") + tag + ">";
        // "<p" also starts "<path": count only the element itself ("<p>" or "<p ").
        const std::size_t opens =
            count(html, std::string("<") + tag + ">") + count(html, std::string("<") + tag + " ");
        EXPECT_EQ(opens, count(html, close));
    }
    EXPECT_EQ(html.find("<script"), std::string::npos);
    EXPECT_EQ(html.find("<link"), std::string::npos);
    EXPECT_EQ(html.find("src=\""), std::string::npos);
    // The only URL is the SVG namespace.
    EXPECT_EQ(count(html, "http"), count(html, "xmlns=\"http://www.w3.org/2000/svg\""));
    // Text from outside is escaped.
    EXPECT_EQ(html.find("test <&>"), std::string::npos);
    EXPECT_NE(html.find("test &lt;&amp;&gt;"), std::string::npos);
    // Summary, per-family speed plots, time series.
    EXPECT_NE(html.find("id=\"summary\""), std::string::npos);
    EXPECT_NE(html.find("stacking: speed against error"), std::string::npos);
    EXPECT_NE(html.find("first rebound"), std::string::npos);
    EXPECT_GE(count(html, "<svg"), 5u);
}

// The summary marks an e2d run red when it does worse than Box2D on the same scenario.
// The joints plot names the soft step's curves by joint model: the default's engine family
// ("e2d soft sat") names none, and read as if it were the only soft step.
TEST(ReportModel, JointCurvesAreNamedByJointModel) {
    EXPECT_EQ(curveLabel("joints", "e2d soft sat"), "e2d soft sat, Direct joints");
    EXPECT_EQ(curveLabel("joints", "e2d soft sat joints gauss-seidel"),
              "e2d soft sat, GaussSeidel joints");
    EXPECT_EQ(curveLabel("joints", "e2d soft sat joints soft"), "e2d soft sat, Soft joints");
    EXPECT_EQ(curveLabel("joints", "e2d classic sat"), "e2d classic sat");
    EXPECT_EQ(curveLabel("joints", "box2d"), "box2d");
    EXPECT_EQ(curveLabel("stacking", "e2d soft sat"), "e2d soft sat");
}

TEST(ReportModel, E2dWorseThanBox2DIsFlagged) {
    Report report;
    report.scenarios = {shipped("stack_5"), shipped("drop_e050")};
    auto run = [](int scenario, const std::string& engine, bool passed, double error) {
        RunResult r;
        r.spec.scenario = scenario;
        r.spec.config.engine = engine;
        r.passed = passed;
        r.normalizedError = error;
        return r;
    };
    report.runs = {run(0, "box2d", true, 0.2), run(0, "e2d", false, 1.5),
                   run(1, "box2d", true, 0.5), run(1, "e2d", true, 0.3)};
    const auto table = summaryTable(report);
    EXPECT_TRUE(table[0].at("e2d soft sat").worseThanReference);
    EXPECT_FALSE(table[1].at("e2d soft sat").worseThanReference);
    EXPECT_FALSE(table[0].at("box2d").worseThanReference);
    EXPECT_EQ(exitStatus(report), 1);
    const std::string html = reportToHtml(report);
    EXPECT_EQ(count(html, "class=\"worse\""), 1u);
    EXPECT_NE(reportSummary(report).find("WORSE stack_5 [e2d soft sat] than Box2D"),
              std::string::npos);
}

// Scenarios marked hardCase head the summary: one row each, Box2D first, each e2d mode once
// (SAT), with every check's numbers; the others are not listed.
TEST(ReportModel, HardCasesHeadTheSummary) {
    Report report;
    report.scenarios = {shipped("stack_5"), shipped("packed_discs")};
    ASSERT_FALSE(report.scenarios[0].hardCase);
    ASSERT_TRUE(report.scenarios[1].hardCase);
    auto run = [](int scenario, const std::string& engine, const std::string& solver,
                  const std::string& collision, bool passed, double speed) {
        RunResult r;
        r.spec.scenario = scenario;
        r.spec.config.engine = engine;
        r.spec.config.solver = solver;
        r.spec.config.collision = collision;
        r.passed = passed;
        CheckResult c;
        c.kind = "maxSpeed";
        c.expected = 3.0;
        c.tolerance = 3.0;
        c.measured = speed;
        c.passed = speed <= 3.0;
        r.checks = {c};
        return r;
    };
    report.runs = {
        run(0, "box2d", "soft", "sat", true, 1.0), run(1, "e2d", "soft", "sat", false, 3.4),
        run(1, "e2d", "soft", "gjk", false, 3.5), run(1, "box2d", "soft", "sat", true, 0.5),
        run(1, "e2d", "classic", "gjk", true, 0.25)};
    const std::vector<HardCaseRow> rows = hardCaseTable(report);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].scenario, 1u);
    ASSERT_EQ(rows[0].runs.size(), 3u);
    EXPECT_EQ(rows[0].runs[0].first, "box2d");
    EXPECT_EQ(rows[0].runs[1].first, "e2d soft sat");
    EXPECT_EQ(rows[0].runs[2].first, "e2d classic gjk"); // no classic SAT run to prefer
    ASSERT_EQ(rows[0].numbers.size(), 1u);
    EXPECT_EQ(rows[0].numbers[0],
              "maxSpeed [expected 3, tolerance 3]: box2d 0.5, e2d soft sat 3.4 FAIL, "
              "e2d classic gjk 0.25");
    const std::string summary = reportSummary(report);
    EXPECT_EQ(summary.rfind(
                  "HARD  packed_discs: box2d PASS; e2d soft sat FAIL; e2d classic gjk PASS;", 0),
              0u)
        << summary;
    const std::string html = reportToHtml(report);
    EXPECT_LT(html.find("id=\"hard-cases\""), html.find("<table class=\"summary\">"));
    const nlohmann::json j = reportToJson(report);
    ASSERT_EQ(j.at("hardCases").size(), 1u);
    EXPECT_EQ(j.at("hardCases")[0].at("passed").at("e2d soft sat"), false);
    EXPECT_TRUE(j.at("scenarios")[1].at("joints").empty());
    report.scenarios = {shipped("ragdoll_drop")};
    report.runs.clear();
    EXPECT_EQ(reportToJson(report).at("scenarios")[0].at("joints").at("revolute"), 9);
}

} // namespace
} // namespace e2d::validation
