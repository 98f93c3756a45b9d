// SPDX-License-Identifier: MIT
#pragma once

#include "scenario.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace e2d::validation {

/// A scenario file that cannot be used. The message starts with the JSON path of the problem,
/// e.g. "bodies[3].shapes[0].radius: must be > 0, got -1".
class ScenarioError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The most steps a scenario may ask for (duration / timeStep): 600 s at 600 Hz.
inline constexpr double kMaxSteps = 360000.0;

/// Parses a scenario from JSON text. `fallbackName` names it when the file has no "name".
/// Throws ScenarioError naming the JSON path of the first problem: syntax errors, wrong types,
/// out-of-range values and unknown fields (typos) alike.
[[nodiscard]] Scenario parseScenario(std::string_view text, const std::string& fallbackName);

/// Reads and parses a file; the ScenarioError message is prefixed with the file name.
[[nodiscard]] Scenario loadScenario(const std::filesystem::path& file);

} // namespace e2d::validation
