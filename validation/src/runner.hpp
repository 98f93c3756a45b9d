// SPDX-License-Identifier: MIT
#pragma once

#include "expectations.hpp"
#include "metrics.hpp"
#include "plan.hpp"
#include "scenario.hpp"

#include <functional>
#include <string>
#include <vector>

namespace e2d::validation {

/// The outcome of one run of the plan.
struct RunResult {
    RunSpec spec;
    int bodies = 0;
    int steps = 0;
    double seconds = 0.0; ///< wall time of the whole run, recording included
    Metrics metrics;
    std::vector<CheckResult> checks;
    std::vector<Series> series; ///< baseline runs only
    bool passed = false;        ///< every check passed and the run did not fail
    /// Largest error / tolerance over the checks (1 = at the limit): the y axis of the
    /// speed-against-error plots. 0 when the scenario has no checks.
    double normalizedError = 0.0;
    std::string failure; ///< set when the engine threw
};

/// Called from inside a long run, at most every `kStepProgressSeconds` of wall time, with the
/// run's spec, the steps done, the steps in all and the seconds since the run started (building
/// the world included: step 0 says how long building took). Called on the run's own thread.
using StepProgress = std::function<void(const RunSpec&, int, int, double)>;
inline constexpr double kStepProgressSeconds = 5.0;

/// A check whose error is not finite counts this much (error / tolerance) in normalizedError,
/// so plots and sums stay finite; the check itself fails.
inline constexpr double kNonFiniteError = 1.0e6;

/// Runs one spec to the end on the calling thread.
[[nodiscard]] RunResult runOne(const Scenario& scenario, const RunSpec& spec,
                               const StepProgress& stepProgress = {},
                               double progressSeconds = kStepProgressSeconds);

/// Called after each finished run with (finished so far, total, that run's result); calls are
/// serialised.
using Progress = std::function<void(int, int, const RunResult&)>;

/// Runs the plan on `threads` worker threads (each world lives and dies on one thread), the
/// most expensive runs first. Results come back in plan order. `stepProgress` (may be empty)
/// is called from the worker threads, not serialised.
[[nodiscard]] std::vector<RunResult> runPlan(const std::vector<Scenario>& scenarios,
                                             const std::vector<RunSpec>& plan, int threads,
                                             const Progress& progress,
                                             const StepProgress& stepProgress = {});

} // namespace e2d::validation
