// SPDX-License-Identifier: MIT
#pragma once

#include "metrics.hpp"
#include "scenario.hpp"

#include <glm/vec2.hpp>

#include <string>
#include <vector>

/// Closed-form expectations of classical mechanics, and the evaluation of a scenario's checks
/// against a run's recording.
namespace e2d::validation {

/// Apex of the first bounce of a ball dropped from height h with restitution e: e^2 h.
[[nodiscard]] double bounceApex(double restitution, double height);
/// Distance slid down a slope of angle theta (radians) from rest after t seconds:
/// 1/2 g (sin theta - mu cos theta) t^2, or 0 when friction holds (tan theta <= mu).
[[nodiscard]] double slideDistance(double g, double theta, double mu, double t);
/// Distance a box launched at speed v slides on flat ground before friction stops it:
/// v^2 / (2 mu g).
[[nodiscard]] double stoppingDistance(double v, double mu, double g);
/// Position along the path at time t of that box: v t - 1/2 mu g t^2 until it stops.
[[nodiscard]] double slidingPosition(double v, double mu, double g, double t);
/// Distance a solid disc rolls (without slipping) down a slope from rest in t seconds:
/// 1/2 a t^2 with a = (2/3) g sin theta.
[[nodiscard]] double rollingDistance(double g, double theta, double t);

/// Velocities after a 1D impact of m1 at v1 and m2 at v2 with restitution e.
struct Impact1D {
    double v1 = 0.0;
    double v2 = 0.0;
};
[[nodiscard]] Impact1D impact1D(double m1, double v1, double m2, double v2, double e);

/// One check's outcome.
struct CheckResult {
    std::string kind;     ///< as in the scenario file
    std::string body;     ///< tag, if any
    std::string quantity; ///< what was measured, with unit
    double expected = 0.0;
    double measured = 0.0;
    double error = 0.0;     ///< |measured - expected| or the amount over the limit
    double tolerance = 0.0; ///< error allowed
    bool passed = false;
    std::string detail;
};

/// A named curve for the report's time-series plots; `expected` is empty or as long as `t`.
struct Series {
    std::string name;
    std::string unit;
    std::vector<float> t;
    std::vector<float> measured;
    std::vector<float> expected;
};

/// Evaluates `check` on a finished run. `gravity` is |g| of the scene, m/s^2. A check whose
/// body or quantity was not finite at some instant of the run, or whose measurement is not
/// finite, fails (error infinite, the instant in `detail`), whatever the comparison would say.
[[nodiscard]] CheckResult evaluate(const Check& check, const Recording& rec, float gravity);
/// The comparison alone, assuming finite values (evaluate() guards it).
[[nodiscard]] CheckResult evaluateFinite(const Check& check, const Recording& rec, float gravity);

/// The time series that shows `check` (bounce heights, drift, distance against the analytic
/// curve), sampled at most every `stride` instants. Empty name when the check has none.
[[nodiscard]] Series seriesFor(const Check& check, const Recording& rec, float gravity, int stride);

} // namespace e2d::validation
