// SPDX-License-Identifier: MIT
#pragma once

#include "runner.hpp"
#include "scenario.hpp"

#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

namespace e2d::validation {

/// Where and how the report was produced.
struct Environment {
    std::string e2dVersion;
    std::string box2dVersion;
    std::string compiler;
    std::string buildType;
    std::string flags;
    std::string cpu;
    int cores = 0;
    int threads = 0;
    std::string date; ///< UTC, ISO 8601
    std::string command;
    std::string sweep; ///< none, quick or full
    double wallSeconds = 0.0;
};

/// Fills what the build and the machine know (versions, compiler, flags, CPU, date).
[[nodiscard]] Environment collectEnvironment();

struct Report {
    Environment env;
    std::vector<Scenario> scenarios;
    std::vector<RunResult> runs;
};

/// One cell of the summary table: a scenario's baseline run on one engine family.
struct SummaryCell {
    const RunResult* run = nullptr;
    bool worseThanReference = false; ///< an e2d run that does worse than Box2D on this scenario
};

/// Engine families in plan order, e.g. {"box2d", "e2d soft sat", ...}.
[[nodiscard]] std::vector<std::string> engineFamilies(const Report& report);
/// summary[scenario index][family] for the baseline runs.
[[nodiscard]] std::vector<std::map<std::string, SummaryCell>> summaryTable(const Report& report);

/// The hard-case table at the top of the summary: one row per scenario with `hardCase` set,
/// its baseline run on Box2D and on each e2d mode (SAT; GJK/EPA only where there is no SAT
/// run), and the measurement of every check on each.
struct HardCaseRow {
    std::size_t scenario = 0;
    std::vector<std::pair<std::string, const RunResult*>>
        runs; ///< engine family, run (may be null)
    /// Per check: "kind(body) [expected e, tolerance t]: box2d m1, e2d soft sat m2 FAIL (detail), ...".
    std::vector<std::string> numbers;
};
[[nodiscard]] std::vector<HardCaseRow> hardCaseTable(const Report& report);

/// One point of a family's speed-against-error curve: summed over the family's swept
/// scenarios.
struct SweepPoint {
    std::string label;
    int effort = 0;     ///< iterations or sub-steps: the order along the curve
    double ms = 0.0;    ///< sum of the median ms/step
    double error = 0.0; ///< mean normalised error (1 = at tolerance)
    int failed = 0;     ///< scenarios with a failed check
    int scenarios = 0;
};
/// curves[scenario family][engine family], in order of solver effort.
[[nodiscard]] std::map<std::string, std::map<std::string, std::vector<SweepPoint>>>
sweepCurves(const Report& report);

/// How the curve of `engine` (an engine family, EngineConfig::family()) is named on the plot of
/// scenario family `family`: on the joints plot the soft step's curves by their joint model
/// ("e2d soft sat, Direct joints" for the default, whose engine family names no joint model),
/// elsewhere the engine family itself.
[[nodiscard]] std::string curveLabel(const std::string& family, const std::string& engine);

/// The effect of one feature switch on a scenario family, against the reference runs of the
/// same scenarios: the sweep point at the baseline's effort (sleeping off). The "sleep on" row
/// is the baseline run itself against that reference.
struct FeatureCost {
    std::string feature;
    double baselineMs = 0.0;
    double ms = 0.0;
    double baselineError = 0.0;
    double error = 0.0;
    int baselineFailed = 0;
    int failed = 0;
    int scenarios = 0;
};
/// costs[scenario family][engine family]
[[nodiscard]] std::map<std::string, std::map<std::string, std::vector<FeatureCost>>>
featureCosts(const Report& report);

/// Exit status: 0 when every baseline check passed, 1 otherwise.
[[nodiscard]] int exitStatus(const Report& report);

[[nodiscard]] nlohmann::json reportToJson(const Report& report);
[[nodiscard]] std::string reportToHtml(const Report& report);
/// A few lines for stdout: what passed, what failed, where e2d is worse than Box2D.
[[nodiscard]] std::string reportSummary(const Report& report);

} // namespace e2d::validation
