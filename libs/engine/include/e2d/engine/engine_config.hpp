// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/config.hpp>
#include <e2d/physics/world.hpp>
#include <e2d/render/camera.hpp>
#include <e2d/render/texture.hpp>
#include <e2d/render/window.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

/// The whole engine: the Game that wires every e2d library together, and what scenes reach
/// through GameSystem.
namespace e2d::engine {

/// Everything a game's configuration file sets, by section: SCENE, DISPLAY, TEXT, PHYSICS,
/// SOUND, LOOP, INPUT and DEBUG (the file format is core::ConfigReader's; every key below is
/// read by its own name). The settings use the libraries' own types (render::ScreenFit,
/// physics::SolverMode, ...); a new key is a field here and a line in engine_config.cpp.
///
/// PHYSICS values are SI (gravity m/s^2, lengths m, speeds m/s) whatever `unitsPerMetre`,
/// which only says how many world units make a metre (default 100: a pixel game feels right
/// as it is), `firstScene` is empty (a game-specific name is no library default) and `windowTitle` is "e2d".
struct EngineConfig {
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
    /// How the view fits a window of another aspect ratio: expand, widthFit, heightFit,
    /// bestFit. Default widthFit.
    render::ScreenFit screenFitMode = render::ScreenFit::WidthFit;
    /// windowed, fullscreen or borderless (headless runs are always windowed). Default
    /// windowed.
    render::WindowMode windowMode = render::WindowMode::Windowed;
    /// Any text, spaces allowed. Default "e2d".
    std::string windowTitle = "e2d";
    /// Filter of the textures loaded from files: nearest or linear. Default nearest.
    render::TextureFilter textureFilteringMode = render::TextureFilter::Nearest;
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
    /// Gravity in m/s^2 (the physics system gives it to the components in world units/s^2:
    /// times unitsPerMetre). Default (0, -9.81).
    float gravityX = 0.0f;
    float gravityY = -9.81f;
    /// Seconds per physics step, > 0 and <= 1. Default 1/60.
    double fixedTimestep = 1.0 / 60.0;
    /// Solver iterations per step (>= 1). Default 4.
    int collisionResolutionSteps = 4;
    /// The contact solver: softStep (soft contacts, sub-stepped; e2d's default) or classic
    /// (sequential impulses with position iterations). Default softStep.
    physics::SolverMode physicsSolver = physics::SolverMode::SoftStep;
    /// Overlap tolerated before position correction, metres (>= 0); used by the classic
    /// solver only. Default 0.005.
    float allowedPenetration = 0.005f;
    /// Fraction of the overlap corrected per position iteration, in [0, 1]; used by the
    /// classic solver only. Default 0.2.
    float penetrationBiasFactor = 0.2f;
    /// Speed below which a body may rest, m/s (>= 0). Default 0.05.
    float minRigidbodySpeed = 0.05f;
    /// Threads the physics step runs on, 1 to 64 (physics::WorldDef::workerCount: the world
    /// starts physicsWorkers - 1 threads of its own). The simulation is the same, bit for bit,
    /// for every count; 2 or more only makes large scenes step faster. Default 1.
    int physicsWorkers = 1;
    /// World units per physics metre (> 0). The engine's world unit is a reference pixel
    /// (the camera shows referenceWindowWidth of them), so the default, 100, makes the obvious
    /// pixel game fall as it looks (981 px/s^2, a 32-px crate is 0.32 m; Godot's 980 px/s^2 and
    /// Unity's 100 pixels per unit agree); a game laid out in metres says 1. Default 100.
    double unitsPerMetre = 100.0;

    // SOUND (world units, >= 0; each min at most its max)
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

    // INPUT
    /// Action bindings file (`action = binding, ...`), relative to the config file's folder;
    /// empty: none. Default "".
    std::string bindingsFile;
    /// Deliver the system's key auto-repeat to scenes as onKeyRepeat (`true` / `false`).
    /// Default true.
    bool keyRepeat = true;

    // LOOP
    /// Fixed steps run at most per frame before time is dropped (>= 1). Default 5.
    int maxStepsPerFrame = 5;
    /// Seed for the game's Random. Default 0.
    std::uint64_t randomSeed = 0;
    /// Longest frame time the loop accepts, seconds, > 0 and <= 10: a longer frame (a stall,
    /// a debugger stop) counts as this long and is counted as a spike. Default 0.25.
    double maxFrameTime = 0.25;

    // DEBUG
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

    // Not keys: where the configuration came from.
    /// The file the configuration was read from; empty when the defaults are used.
    std::filesystem::path file;
    /// Folder that relative asset paths (and `bindingsFile`) are resolved against: the
    /// config file's folder, or the working directory without a file.
    std::filesystem::path assetRoot;
};

/// The physics world a configuration asks for. The PHYSICS lengths are world units and are
/// divided by `unitsPerMetre` (the world runs in metres):
/// - physicsSolver (softStep|classic) -> solver.mode;
/// - gravityX / gravityY (m/s^2)      -> WorldDef::gravity (m/s^2);
/// - collisionResolutionSteps         -> solver.subSteps (soft step, capped at 64) and
///                                       solver.velocityIterations (classic solver);
/// - minRigidbodySpeed (m/s)          -> solver.linearSleepTolerance (m/s);
/// - physicsWorkers                   -> WorldDef::workerCount;
/// - allowedPenetration (m)           -> solver.classicAllowedPenetration (m, capped at
///                                       SolverDef's 0.1 m);
/// - penetrationBiasFactor            -> solver.classicPositionBias (same [0, 1] range; 0
///                                       turns the contacts' position correction off).
/// The last two are position-correction settings and only the classic solver
/// (`physicsSolver = classic`) uses them: the default soft-step solver's contacts are springs
/// with their own settings (see SolverDef). The defaults (0.005 m, 0.2) are SolverDef's own.
[[nodiscard]] physics::WorldDef makeWorldDef(const EngineConfig& config);

/// The result of reading a configuration file for a Game.
struct EngineConfigResult {
    EngineConfig config;
    /// Every problem with its line and key (`toString()`: "file:line: key: message"); the
    /// configuration may be used when `diagnostics.ok()` (warnings only).
    core::Diagnostics diagnostics;
};

/// Parses configuration text (core::ConfigReader's format, the keys of EngineConfig);
/// `sourceName` names it in diagnostics. Besides each key's own range, a min distance above
/// its max is an error blamed on whichever was written last, and both keep their defaults.
[[nodiscard]] EngineConfigResult parseEngineConfig(std::string_view text,
                                                   std::string_view sourceName = "config");

/// Reads the configuration file at `path` (see parseEngineConfig). A file that cannot be read
/// is an error when `required`, else a warning and the defaults.
[[nodiscard]] EngineConfigResult loadEngineConfig(const std::filesystem::path& path, bool required);

} // namespace e2d::engine
