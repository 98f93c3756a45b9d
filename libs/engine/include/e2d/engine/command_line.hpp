// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace e2d::engine {

/// What `Game::run()` reads from the command line.
struct CommandLine {
    /// `--frames N`: run N frames (N >= 1) of exactly 1/60 s each, then stop (headless runs:
    /// the window is hidden and vsync off unless `--show`).
    std::optional<std::int64_t> frames;
    /// `--screenshot FILE.png`: save the last frame there.
    std::filesystem::path screenshot;
    /// `--config FILE`: the configuration to read instead of the default one.
    std::filesystem::path config;
    /// `--seed N`: seeds the game's Random (overrides the config's randomSeed).
    std::optional<std::uint64_t> seed;
    /// `--input-script FILE`: timed presses (see input::InputScript).
    std::filesystem::path inputScript;
    /// `--debug-draw`: start with the physics debug draw on.
    bool debugDraw = false;
    /// `--profile`: start with the frame profile overlay on.
    bool profile = false;
    /// `--show`: keep the window visible with `--frames`.
    bool show = false;
    /// `--help` / `-h`.
    bool help = false;
};

/// Parses the arguments after the program name. Both `--frames 10` and `--frames=10` are
/// accepted. Throws core::Error naming the argument ("--frames: expected a whole number >= 1,
/// got 'ten'", "unknown argument '--fast'", "--screenshot: missing value").
[[nodiscard]] CommandLine parseCommandLine(std::span<const std::string_view> args);

/// The usage text printed by `--help` (and after a usage error).
[[nodiscard]] std::string usage(std::string_view program);

} // namespace e2d::engine
