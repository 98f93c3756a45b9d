// SPDX-License-Identifier: MIT
#pragma once

#include "scenario.hpp"

#include <e2d/core/diagnostics.hpp>

#include <filesystem>
#include <string>
#include <string_view>

namespace e2d::validation {

/// A scenario file that cannot be used: a core::ParseError whose diagnostic names the JSON path
/// of the problem (Diagnostic::field), and the line and column of malformed JSON, e.g.
/// "bodies[3].shapes[0].radius: must be > 0, got -1", "line 3, column 13: bodies[0].shape.radius:
/// not valid JSON: number overflow parsing '1e999'"; loadScenario() adds the file.
class ScenarioError : public core::ParseError {
public:
    using core::ParseError::ParseError;
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
