// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/config.hpp>
#include <e2d/physics/world.hpp>

#include <filesystem>
#include <string>
#include <vector>

/// The whole engine: the Game that wires every e2d library together, and what scenes reach
/// through GameSystem.
namespace e2d::engine {

/// The game's configuration: every key of core::Config (see
/// core/config.hpp for each key, its unit and default) and where it was read from.
struct EngineConfig : core::Config {
    /// The file the configuration was read from; empty when the defaults are used.
    std::filesystem::path file;
    /// Folder that relative asset paths (and `bindingsFile`) are resolved against: the
    /// config file's folder, or the working directory without a file.
    std::filesystem::path assetRoot;
};

/// The physics world a configuration asks for. The PHYSICS lengths are world units and are
/// divided by `unitsPerMetre` (the world runs in metres):
/// - physicsSolver (softStep|classic) -> solver.mode;
/// - gravityX / gravityY (units/s^2)  -> WorldDef::gravity (m/s^2);
/// - collisionResolutionSteps         -> solver.subSteps (soft step, capped at 64) and
///                                       solver.velocityIterations (classic solver);
/// - minRigidbodySpeed (units/s)      -> solver.linearSleepTolerance (m/s);
/// - allowedPenetration (units)       -> solver.classicAllowedPenetration (m, capped at
///                                       SolverDef's 0.1 m);
/// - penetrationBiasFactor            -> solver.classicPositionBias (same [0, 1] range; 0
///                                       turns the contacts' position correction off).
/// The last two are position-correction settings and only the classic solver
/// (`physicsSolver = classic`) uses them: the default soft-step solver's contacts are springs
/// with their own settings (see SolverDef). The defaults (0.005 units at 1 unit per metre,
/// 0.2) are SolverDef's own.
[[nodiscard]] physics::WorldDef makeWorldDef(const core::Config& config);

/// The result of reading a configuration file for a Game.
struct EngineConfigResult {
    EngineConfig config;
    /// Every diagnostic, formatted "file:line: key: message".
    std::vector<std::string> warnings;
    std::vector<std::string> errors;
};

/// Reads the configuration file at `path` (core::loadConfig's format and checks). A file that
/// cannot be read is an error when `required`, else a warning and the defaults.
[[nodiscard]] EngineConfigResult loadEngineConfig(const std::filesystem::path& path, bool required);

} // namespace e2d::engine
