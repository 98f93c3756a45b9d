// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace e2d::core {

/// How the view adapts when the window's aspect ratio differs from the reference size.
enum class ScreenFitMode { Expand, WidthFit, HeightFit, BestFit };
enum class WindowMode { Windowed, Fullscreen };
enum class TextureFilteringMode { Nearest, Linear };
/// Which contact solver the game's physics world uses (see physics::SolverMode).
enum class PhysicsSolver { SoftStep, Classic };

/// The spelling used in config files ("expand", "widthFit", "heightFit", "bestFit", ...).
[[nodiscard]] std::string_view toString(ScreenFitMode mode) noexcept;
[[nodiscard]] std::string_view toString(WindowMode mode) noexcept;
[[nodiscard]] std::string_view toString(TextureFilteringMode mode) noexcept;
[[nodiscard]] std::string_view toString(PhysicsSolver solver) noexcept;

/// Everything the game configuration file sets, by section: SCENE, DISPLAY, TEXT, PHYSICS,
/// SOUND, LOOP, INPUT and DEBUG.
///
/// Lengths in PHYSICS are world units (metres at the default `unitsPerMetre` of 1),
/// `firstScene` is empty (a game-specific name is no library default) and `windowTitle` is "e2d".
struct Config {
    // SCENE
    /// Registry name of the scene to start with. Default "" (none).
    std::string firstScene;

    // DISPLAY
    /// Size the game is designed for, in pixels (>= 1). Default 1024 x 624.
    int referenceWindowWidth = 1024;
    int referenceWindowHeight = 624;
    /// Initial window size in pixels (>= 1). Default 1024 x 624.
    int windowWidth = 1024;
    int windowHeight = 624;
    /// Default widthFit.
    ScreenFitMode screenFitMode = ScreenFitMode::WidthFit;
    /// Default windowed.
    WindowMode windowMode = WindowMode::Windowed;
    /// Any text, spaces allowed. Default "e2d".
    std::string windowTitle = "e2d";
    /// Default nearest.
    TextureFilteringMode textureFilteringMode = TextureFilteringMode::Nearest;
    /// Draw-order (z) range of the camera, > 0. Default 1000.
    float maxCameraDepth = 1000.0f;
    /// Swap buffers at the monitor's refresh rate (`true` / `false`). Default true.
    bool vsync = true;
    /// Multisample anti-aliasing samples, 0 (off) to 16. Default 0.
    int msaaSamples = 0;

    // TEXT
    /// Base font size in pixels (>= 1). Default 100.
    int fontSize = 100;

    // PHYSICS
    /// Gravity in m/s^2. Default (0, -9.81).
    float gravityX = 0.0f;
    float gravityY = -9.81f;
    /// Seconds per physics step, > 0 and <= 1. Default 1/60.
    double fixedTimestep = 1.0 / 60.0;
    /// Solver iterations per step (>= 1). Default 4.
    int collisionResolutionSteps = 4;
    /// The contact solver: "softStep" (soft contacts, sub-stepped; e2d's default) or "classic"
    /// (sequential impulses with position iterations). Default softStep.
    PhysicsSolver physicsSolver = PhysicsSolver::SoftStep;
    /// Overlap tolerated before position correction, world units (>= 0); used by the classic
    /// solver only. Default 0.005.
    float allowedPenetration = 0.005f;
    /// Fraction of the overlap corrected per position iteration, in [0, 1]; used by the
    /// classic solver only. Default 0.2.
    float penetrationBiasFactor = 0.2f;
    /// Speed below which a body may rest, m/s (>= 0). Default 0.05.
    float minRigidbodySpeed = 0.05f;
    /// World units per physics metre (> 0): the PHYSICS lengths above (gravity, penetration,
    /// speed) are in world units and are divided by it before reaching the physics world,
    /// which runs in metres. A config written in pixels (gravity -1000) says e.g. 100. Default 1.
    double unitsPerMetre = 1.0;

    // SOUND (world units, >= 0)
    /// Default 256.
    float minAttenuationDistance = 256.0f;
    /// Default 512.
    float maxAttenuationDistance = 512.0f;
    /// Default 256.
    float minPanningDistance = 256.0f;
    /// Default 512.
    float maxPanningDistance = 512.0f;
    /// Overall gain (>= 0). Default 0.2.
    float masterGain = 0.2f;
    /// Voices that can sound at once, 1..1024. Default 32.
    int voiceCount = 32;

    // INPUT (e2d additions)
    /// Action bindings file (`action = binding, ...`), relative to the config file's folder;
    /// empty: none. Default "".
    std::string bindingsFile;
    /// Deliver the system's key auto-repeat to scenes as onKeyRepeat (`true` / `false`).
    /// Default true.
    bool keyRepeat = true;

    // LOOP (e2d additions)
    /// Fixed steps run at most per frame before time is dropped (>= 1). Default 5.
    int maxStepsPerFrame = 5;
    /// Seed for the game's Random. Default 0.
    std::uint64_t randomSeed = 0;
    /// Longest frame time the loop accepts, seconds, > 0 and <= 10: a longer frame (a stall,
    /// a debugger stop) counts as this long and is counted as a spike. Default 0.25.
    double maxFrameTime = 0.25;

    // DEBUG (e2d additions)
    /// Start with the physics debug draw on (`true` / `false`). Default false.
    bool debugDraw = false;
    /// Key name (as in bindings files, e.g. `f1`, `tab`) that toggles the debug draw at run
    /// time; empty: no key. Default "f1".
    std::string debugDrawKey = "f1";
    /// Print the frame profile (mean milliseconds per phase) when the game ends. Default true.
    bool printProfile = true;
    /// Start with the frame profile overlay on: milliseconds per frame and per phase (update,
    /// fixed steps, physics, render, audio, input) in the top-left corner. Default false.
    bool showProfile = false;
    /// Key name that toggles the profile overlay at run time; empty: no key. Default "f2".
    std::string profileKey = "f2";
};

/// One problem found while reading a configuration.
struct ConfigDiagnostic {
    enum class Severity { Warning, Error };

    Severity severity = Severity::Error;
    /// Source name as given to parseConfig / the path given to loadConfig.
    std::string file;
    /// 1-based line, 0 when the problem is not tied to a line (missing file).
    int line = 0;
    /// The key concerned (empty when there is none, e.g. a line without '=').
    std::string key;
    /// What is wrong, e.g. "expected an integer, got 'abc'".
    std::string message;

    /// "file:line: key: message", e.g. "game.cfg:12: windowWidth: expected an integer,
    /// got 'abc'" (line and key left out when absent).
    [[nodiscard]] std::string toString() const;
};

/// A configuration plus what went wrong reading it. Anything missing or wrong keeps its
/// default, so `config` is always usable.
struct ConfigResult {
    Config config;
    std::vector<ConfigDiagnostic> diagnostics;

    [[nodiscard]] bool hasErrors() const noexcept;
    [[nodiscard]] bool hasWarnings() const noexcept;
};

/// Parses configuration text.
///
/// Format: one `key = value` per line; blank lines and lines starting with `#` are ignored;
/// whitespace around key and value is trimmed and a value may contain spaces
/// (`windowTitle = My Game`); there are no inline comments. Keys and enum values are
/// case-sensitive. Booleans are `true` or `false`. Numbers are read locale-independently; an integer must be a whole
/// integer ("12px" and "1.5" are errors).
///
/// Errors: bad or out-of-range number, unknown enum value (the accepted ones are listed),
/// line without `=`, empty key, a min distance above its max (both reset to defaults). Warnings: unknown key (ignored), duplicate key (the last value
/// wins). `sourceName` is used in diagnostics.
[[nodiscard]] ConfigResult parseConfig(std::string_view text, std::string_view sourceName = "config");

/// Reads and parses the file at `path`. A file that cannot be read gives the defaults and a
/// warning; it never throws for that.
[[nodiscard]] ConfigResult loadConfig(const std::filesystem::path& path);

} // namespace e2d::core
