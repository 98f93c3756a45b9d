// SPDX-License-Identifier: MIT
#include <e2d/engine/game.hpp>

#include <e2d/audio/audio_system.hpp>
#include <e2d/core/clock.hpp>
#include <e2d/core/error.hpp>
#include <e2d/core/fixed_stepper.hpp>
#include <e2d/core/game_loop.hpp>
#include <e2d/core/random.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/core/scene_director.hpp>
#include <e2d/engine/command_line.hpp>
#include <e2d/engine/engine_config.hpp>
#include <e2d/engine/game_system.hpp>
#include <e2d/input/actions.hpp>
#include <e2d/input/input.hpp>
#include <e2d/input/input_script.hpp>
#include <e2d/input/input_system.hpp>
#include <e2d/input/names.hpp>
#include <e2d/physics/physics_system.hpp>
#include <e2d/render/render_system.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/window.hpp>

#include "frame_systems.hpp"
#include "game_state.hpp"
#include "profile_overlay.hpp"
#include "profile_recorder.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

namespace e2d::engine {

namespace {

/// Exit codes of Game::run().
constexpr int kExitOk = 0;
constexpr int kExitRuntimeError = 1;
constexpr int kExitUsage = 2;
constexpr int kExitNoDisplay = 3;

/// Frame time of `--frames` runs.
constexpr double kHeadlessFrameTime = 1.0 / 60.0;

/// The executable's folder (Linux: /proc/self/exe), else argv[0]'s.
std::filesystem::path programFolder(const char* argv0) {
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        return self.parent_path();
    }
    return argv0 != nullptr ? std::filesystem::path(argv0).parent_path() : std::filesystem::path();
}

/// The systems of a running game and the objects they run, in construction order (so they are
/// destroyed in reverse: the scene before the systems, the systems before the window).
struct Running {
    render::Window window;
    render::Renderer renderer;
    render::RenderSystem renderSystem;
    input::Input input;
    input::ActionMap actions;
    audio::AudioSystem audio;
    physics::PhysicsSystem physics;
    core::Random random;
    GameSystem game;
    core::SceneDirector director;
    input::InputSystem inputSystem;
    detail::ProfileOverlay overlay;
    detail::FrameStart frameStart;
    detail::FrameEnd frameEnd;

    Running(detail::GameState& state, const render::WindowDef& windowDef,
            const render::RendererDef& rendererDef, const audio::MixerDef& mixerDef,
            const core::SceneRegistry& scenes, std::uint64_t seed)
        : window(windowDef), renderer(window, rendererDef),
          renderSystem(renderer, nullptr, state.logger), input(inputDef(state)), audio(mixerDef),
          physics(makeWorldDef(state.config), static_cast<float>(state.config.unitsPerMetre)),
          random(seed), game(state), director(scenes, *state.logger),
          inputSystem(input, director, &actions,
                      input::InputSystemDef{false, state.config.keyRepeat}),
          overlay(renderSystem, *state.profile, static_cast<float>(state.config.maxCameraDepth)),
          frameStart(state), frameEnd(state) {
        state.window = &window;
        state.renderer = &renderer;
        state.renderSystem = &renderSystem;
        state.input = &input;
        state.actions = &actions;
        state.audio = &audio;
        state.physics = &physics;
        state.random = &random;
        state.director = &director;
        state.overlay = &overlay;
    }

    input::InputDef inputDef(const detail::GameState& state) {
        input::InputDef def;
        def.window = window.handle();
        def.logger = state.logger;
        // Window pixels (top-left origin) -> framebuffer pixels (bottom-left) -> world, through
        // the camera the last frame was drawn with.
        def.screenToWorld = [this](glm::vec2 screen) {
            const glm::vec2 scale = window.contentScale();
            const glm::vec2 framebuffer{screen.x * scale.x,
                                        static_cast<float>(window.framebufferSize().y) -
                                            screen.y * scale.y};
            return renderSystem.activeCamera().screenToWorld(framebuffer);
        };
        return def;
    }
};

/// Everything run() reads before it opens anything: the command line, the configuration and
/// the input script. `exitCode` is set (and the reason logged) when the game must not start.
struct Startup {
    std::string program;
    CommandLine options;
    input::InputScript script;
    std::optional<int> exitCode;
};

std::optional<input::Key> keyOf(const std::string& name, const char* field,
                                const std::string& configName, core::Logger& logger,
                                Startup& startup) {
    if (name.empty()) {
        return std::nullopt;
    }
    const std::optional<input::Key> key = input::keyFromName(name);
    if (!key) {
        logger.error(configName + ": " + field + ": unknown key name '" + name + "'");
        startup.exitCode = kExitUsage;
    }
    return key;
}

Startup readStartup(int argc, char** argv, std::string_view defaultConfig,
                    const core::SceneRegistry& scenes, core::Logger& logger,
                    detail::GameState& state) {
    Startup startup;
    startup.program = argc > 0 && argv[0] != nullptr
                          ? std::filesystem::path(argv[0]).filename().string()
                          : std::string("game");
    std::vector<std::string_view> args;
    for (int i = 1; i < argc; ++i) {
        args.emplace_back(argv[i]);
    }
    try {
        startup.options = parseCommandLine(args);
    } catch (const core::Error& e) {
        logger.error(startup.program + ": " + e.what() + "\n" + usage(startup.program));
        startup.exitCode = kExitUsage;
        return startup;
    }
    const CommandLine& options = startup.options;
    if (options.help) {
        const std::string text = usage(startup.program);
        std::fwrite(text.data(), 1, text.size(), stdout);
        startup.exitCode = kExitOk;
        return startup;
    }

    std::filesystem::path configPath = options.config;
    const bool required = !configPath.empty();
    if (!required) {
        configPath = std::filesystem::path(defaultConfig);
        if (configPath.is_relative()) {
            const std::filesystem::path beside =
                programFolder(argc > 0 ? argv[0] : nullptr) / configPath;
            std::error_code ec;
            if (std::filesystem::is_regular_file(beside, ec)) {
                configPath = beside;
            }
        }
    }
    EngineConfigResult loaded = loadEngineConfig(configPath, required);
    for (const core::Diagnostic& d : loaded.diagnostics) {
        logger.log(d.severity == core::Severity::Error ? core::LogLevel::Error
                                                       : core::LogLevel::Warning,
                   d.toString());
    }
    if (!loaded.diagnostics.ok()) {
        logger.error(startup.program + ": the configuration has errors, not starting");
        startup.exitCode = kExitUsage;
        return startup;
    }
    state.config = std::move(loaded.config);
    state.headless = options.frames.has_value();
    state.frameLimit = options.frames.value_or(0);
    state.screenshot = options.screenshot;
    state.debugDraw = state.config.debugDraw || options.debugDraw;
    const EngineConfig& config = state.config;
    const std::string configName =
        config.file.empty() ? std::string("configuration") : config.file.string();

    if (config.firstScene.empty() || !scenes.contains(config.firstScene)) {
        std::string names;
        for (const std::string& n : scenes.names()) {
            names += (names.empty() ? "" : ", ") + n;
        }
        logger.error(configName + ": firstScene: " +
                     (config.firstScene.empty()
                          ? std::string("not set")
                          : "no scene is registered as '" + config.firstScene + "'") +
                     " (registered: " + (names.empty() ? std::string("none") : names) + ")");
        startup.exitCode = kExitUsage;
        return startup;
    }
    state.profileKey = keyOf(config.profileKey, "profileKey", configName, logger, startup);
    state.debugKey = keyOf(config.debugDrawKey, "debugDrawKey", configName, logger, startup);
    if (startup.exitCode) {
        return startup;
    }
    if (!options.inputScript.empty()) {
        try {
            startup.script = input::loadInputScript(options.inputScript);
        } catch (const core::Error& e) {
            logger.error(e.what());
            startup.exitCode = kExitUsage;
        }
    }
    return startup;
}

/// Opens the window and creates every system; nullptr (the reason logged, `exitCode` set)
/// when that fails.
std::unique_ptr<Running> openSystems(detail::GameState& state, const core::SceneRegistry& scenes,
                                     Startup& startup) {
    const EngineConfig& config = state.config;
    const CommandLine& options = startup.options;
    core::Logger& logger = *state.logger;
    render::WindowDef windowDef;
    windowDef.title = config.windowTitle;
    windowDef.size = {config.windowWidth, config.windowHeight};
    windowDef.mode = state.headless ? render::WindowMode::Windowed : config.windowMode;
    windowDef.samples = config.msaaSamples;
    windowDef.vsync = config.vsync && !state.headless;
    windowDef.visible = !state.headless || options.show;
    windowDef.logger = &logger;
    render::RendererDef rendererDef;
    rendererDef.depthRange = config.maxCameraDepth;
    rendererDef.logger = &logger;
    rendererDef.fileTextureFilter = config.textureFilteringMode;
    audio::MixerDef mixerDef;
    mixerDef.logger = &logger;
    mixerDef.voiceCount = config.voiceCount;
    mixerDef.masterGain = config.masterGain;
    mixerDef.spatial = {config.minAttenuationDistance, config.maxAttenuationDistance,
                        config.minPanningDistance, config.maxPanningDistance};
    const std::uint64_t seed = options.seed.value_or(config.randomSeed);

    std::unique_ptr<Running> running;
    try {
        running = std::make_unique<Running>(state, windowDef, rendererDef, mixerDef, scenes, seed);
    } catch (const core::Error& e) {
        const std::string what = e.what();
        const bool display = what.rfind("render::", 0) == 0;
        logger.error(
            startup.program + ": " +
            (display ? "cannot open the game window: " : "cannot start: ") + what +
            (display && std::getenv("DISPLAY") == nullptr
                 ? " (no display: set DISPLAY, or run under xvfb-run / scripts/with-display.sh)"
                 : ""));
        startup.exitCode = display ? kExitNoDisplay : kExitUsage;
        return nullptr;
    }
    Running& r = *running;
    r.overlay.setVisible(config.showProfile || options.profile);
    const std::string configName =
        config.file.empty() ? std::string("configuration") : config.file.string();
    if (!config.bindingsFile.empty()) {
        try {
            r.actions.load(r.game.asset(config.bindingsFile));
        } catch (const core::Error& e) {
            logger.error(configName + ": bindingsFile: " + e.what());
            startup.exitCode = kExitUsage;
            return nullptr;
        }
    }
    // The script is one more input device, resolved against the game's actions.
    try {
        r.input.play(input::ScriptedInput(startup.script, r.actions));
    } catch (const core::Error& e) {
        logger.error(e.what());
        startup.exitCode = kExitUsage;
        return nullptr;
    }

    render::Camera& camera = r.renderSystem.camera();
    camera.setReferenceSize({static_cast<float>(config.referenceWindowWidth),
                             static_cast<float>(config.referenceWindowHeight)});
    camera.setFit(config.screenFitMode);
    // The engine's own hooks (GameSystem::clear() adds them again after a scene change).
    r.renderSystem.addHook(r.overlay);

    // The order the loop runs them in each phase.
    r.director.addSystem(r.frameStart);
    r.director.addSystem(r.inputSystem);
    r.director.addSystem(r.physics);
    r.director.addSystem(r.audio);
    r.director.addSystem(r.renderSystem);
    r.director.addSystem(r.game);
    r.director.addSystem(r.frameEnd);
    r.director.setReferenceWindowSize({config.referenceWindowWidth, config.referenceWindowHeight});
    r.director.setWindowSize(r.window.size());
    return running;
}

} // namespace

Game::Game() = default;
Game::~Game() = default;

int Game::run(int argc, char** argv, std::string_view defaultConfig) {
    // Startup: command line, configuration, input script, window and systems.
    profile_ = {};
    detail::GameState state;
    state.logger = &logger_;
    state.profile = &profile_;
    Startup startup = readStartup(argc, argv, defaultConfig, scenes_, logger_, state);
    if (startup.exitCode) {
        return *startup.exitCode;
    }
    const std::unique_ptr<Running> running = openSystems(state, scenes_, startup);
    if (!running) {
        return *startup.exitCode;
    }
    const EngineConfig& config = state.config;
    core::Clock clock;
    core::FixedStepper stepper(config.fixedTimestep, config.maxStepsPerFrame);
    detail::ProfileRecorder recorder(profile_, state.frame, running->physics, running->audio);
    core::GameLoop loop(
        running->director, stepper, clock,
        core::GameLoopDef{.maxFrameTime = config.maxFrameTime,
                          .fixedFrameTime = state.headless ? kHeadlessFrameTime : 0.0,
                          .frameLimit = state.frameLimit,
                          .observer = &recorder});

    // The loop.
    int exitCode = kExitOk;
    try {
        if (!loop.start(config.firstScene)) {
            exitCode = kExitUsage;
        } else {
            loop.run();
            if (!state.screenshot.empty() && !state.screenshotTaken) {
                // The game ended before its last frame was known: draw the final state again.
                state.ended = true;
                loop.render();
            }
        }
    } catch (const std::exception& e) {
        logger_.error(startup.program + ": " + e.what());
        exitCode = kExitRuntimeError;
    }

    // Shutdown.
    try {
        loop.shutdown();
    } catch (const std::exception& e) {
        logger_.error(startup.program + ": while shutting down: " + e.what());
        exitCode = kExitRuntimeError;
    }
    if (config.printProfile && exitCode != kExitUsage) {
        logger_.info(profile_.toString());
    }
    return exitCode;
}

} // namespace e2d::engine
