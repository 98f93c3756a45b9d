// SPDX-License-Identifier: MIT
#pragma once

#include "scenario.hpp"

#include <string>
#include <vector>

namespace e2d::validation {

/// Why a run is in the plan.
enum class RunRole {
    Baseline, ///< the engine's default settings (plus the scenario's overrides): checks count
    Sweep,    ///< one point of the solver-effort sweep: speed against error
    Feature,  ///< the baseline with one optional feature switched: what it costs
};

[[nodiscard]] const char* runRoleName(RunRole role);

/// The solver-effort label of a configuration ("vel 8, pos 3", "sub-steps 4").
[[nodiscard]] std::string effortLabel(const EngineConfig& config);

struct RunSpec {
    int scenario = 0; ///< index into the scenario list
    RunRole role = RunRole::Baseline;
    EngineConfig config;
    std::string variant; ///< sweep point or feature switch, e.g. "vel 4" or "ccd off"
};

/// How much of the sweep to run.
enum class SweepLevel { None, Quick, Full };

/// The engine configurations every scenario is checked with: one per engine and solver mode,
/// at that engine's defaults (Box2D: 8 velocity and 3 position iterations).
[[nodiscard]] std::vector<EngineConfig> baselineConfigs(const std::vector<std::string>& engines);

/// Sweep points of one baseline: the solver effort (iterations or sub-steps) from low to high,
/// with sleeping off. The same points for every scenario: nothing is tuned per scenario.
[[nodiscard]] std::vector<std::pair<std::string, EngineConfig>>
sweepPoints(const EngineConfig& baseline, SweepLevel level);

/// The baseline with sleeping off and one optional feature switched, labelled ("ccd off",
/// "speculative 0", ...). Compared with the sweep point at the baseline's effort.
[[nodiscard]] std::vector<std::pair<std::string, EngineConfig>>
featureVariants(const EngineConfig& baseline);

/// Every run for `scenarios` on `engines`. Sweep and feature runs only for scenarios whose
/// `sweep` flag is set.
[[nodiscard]] std::vector<RunSpec> makePlan(const std::vector<Scenario>& scenarios,
                                            const std::vector<std::string>& engines,
                                            SweepLevel level, bool features);

} // namespace e2d::validation
