// SPDX-License-Identifier: MIT
#include <e2d/engine/game.hpp>

#include <e2d/audio/audio_system.hpp>
#include <e2d/core/clock.hpp>
#include <e2d/core/error.hpp>
#include <e2d/core/fixed_stepper.hpp>
#include <e2d/core/random.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/core/scene_director.hpp>
#include <e2d/engine/command_line.hpp>
#include <e2d/engine/engine_config.hpp>
#include <e2d/engine/game_system.hpp>
#include <e2d/engine/input_script.hpp>
#include <e2d/input/actions.hpp>
#include <e2d/input/input.hpp>
#include <e2d/input/input_system.hpp>
#include <e2d/input/names.hpp>
#include <e2d/physics/physics_system.hpp>
#include <e2d/render/render_system.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/window.hpp>

#include "debug_draw.hpp"
#include "game_state.hpp"
#include "profile_overlay.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <exception>
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

using Stopwatch = std::chrono::steady_clock;

double msSince(Stopwatch::time_point start) {
    return std::chrono::duration<double, std::milli>(Stopwatch::now() - start).count();
}

render::ScreenFit toScreenFit(core::ScreenFitMode mode) {
    switch (mode) {
    case core::ScreenFitMode::Expand:
        return render::ScreenFit::Expand;
    case core::ScreenFitMode::WidthFit:
        return render::ScreenFit::WidthFit;
    case core::ScreenFitMode::HeightFit:
        return render::ScreenFit::HeightFit;
    case core::ScreenFitMode::BestFit:
        return render::ScreenFit::BestFit;
    }
    return render::ScreenFit::BestFit;
}

/// The executable's folder (Linux: /proc/self/exe), else argv[0]'s.
std::filesystem::path programFolder(const char* argv0) {
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        return self.parent_path();
    }
    return argv0 != nullptr ? std::filesystem::path(argv0).parent_path() : std::filesystem::path();
}

/// A scripted input resolved to what is pressed or moved.
struct ScriptTarget {
    enum class Kind { Key, Mouse, PadButton, PadAxis, Cursor };
    Kind kind = Kind::Key;
    int code = 0;
    /// PadButton, PadAxis: the gamepad slot.
    int slot = 0;
    /// Move: the cursor position, or the axis value in GLFW's range.
    float x = 0.0f;
    float y = 0.0f;
};

/// Whether a script names a gamepad button or axis (it then drives scripted gamepads, and the
/// real joysticks are not read).
bool scriptUsesGamepad(const InputScript& script) {
    return std::any_of(script.events.begin(), script.events.end(), [](const ScriptEvent& e) {
        return e.target.rfind("button", 0) == 0 || e.target.rfind("axis", 0) == 0;
    });
}

/// The gamepads an input script drives: a snapshot per slot, fed to Input on change.
struct ScriptedPads {
    std::array<input::JoystickSnapshot, input::kMaxGamepads> pads{};
    std::array<bool, input::kMaxGamepads> used{};
    std::array<bool, input::kMaxGamepads> changed{};

    void use(int slot) {
        const auto s = static_cast<std::size_t>(slot);
        if (!used[s]) {
            used[s] = true;
            changed[s] = true;
            input::JoystickSnapshot& pad = pads[s];
            pad.present = true;
            pad.gamepad = true;
            pad.guid = "00000000000000000000000000000000";
            pad.name = "e2d input script";
            pad.axes.fill(0.0f);
            pad.axes[GLFW_GAMEPAD_AXIS_LEFT_TRIGGER] = -1.0f; // released, as GLFW reports it
            pad.axes[GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER] = -1.0f;
        }
    }
    void button(int slot, int code, bool down) {
        const auto s = static_cast<std::size_t>(slot);
        if (code == input::kGamepadButtonLeftTrigger || code == input::kGamepadButtonRightTrigger) {
            const int axis = code == input::kGamepadButtonLeftTrigger ? GLFW_GAMEPAD_AXIS_LEFT_TRIGGER
                                                                      : GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER;
            pads[s].axes[static_cast<std::size_t>(axis)] = down ? 1.0f : -1.0f;
        } else {
            pads[s].buttons[static_cast<std::size_t>(code)] = down ? 1 : 0;
        }
        changed[s] = true;
    }
    void axis(int slot, int code, float raw) {
        pads[static_cast<std::size_t>(slot)].axes[static_cast<std::size_t>(code)] = raw;
        changed[static_cast<std::size_t>(slot)] = true;
    }
    void feed(input::Input& input) {
        for (int slot = 0; slot < input::kMaxGamepads; ++slot) {
            if (changed[static_cast<std::size_t>(slot)]) {
                input.handleJoystick(slot, pads[static_cast<std::size_t>(slot)]);
                changed[static_cast<std::size_t>(slot)] = false;
            }
        }
    }
};

/// Resolves an input-script target: an action's first key or mouse binding, or a binding text.
ScriptTarget resolveTarget(const ScriptEvent& event, const InputScript& script, const input::ActionMap& actions) {
    const auto fail = [&](const std::string& why) -> ScriptTarget {
        throw core::Error(script.source + ":" + std::to_string(event.line) + ": " + why);
    };
    const auto fromBinding = [&](const input::Binding& b) -> std::optional<ScriptTarget> {
        if (b.kind == input::BindingKind::Key) {
            return ScriptTarget{ScriptTarget::Kind::Key, b.code};
        }
        if (b.kind == input::BindingKind::MouseButton) {
            return ScriptTarget{ScriptTarget::Kind::Mouse, b.code};
        }
        return std::nullopt;
    };
    if (event.kind == ScriptEvent::Kind::Move) {
        if (event.target == "mouse") {
            return ScriptTarget{ScriptTarget::Kind::Cursor, 0, 0, event.x, event.y};
        }
        input::Binding axis;
        try {
            axis = input::parseBinding(event.target);
        } catch (const core::Error& e) {
            return fail(e.what());
        }
        if (axis.kind != input::BindingKind::GamepadAxis) {
            return fail("move: '" + event.target + "' is not a gamepad axis (axis:leftx, axis@1:righttrigger)");
        }
        const float value = axis.inverted ? -event.x : event.x;
        const bool trigger =
            axis.code == GLFW_GAMEPAD_AXIS_LEFT_TRIGGER || axis.code == GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER;
        if (trigger && value < 0.0f) {
            char number[32];
            std::snprintf(number, sizeof number, "%g", static_cast<double>(event.x));
            return fail("move " + event.target + ": a trigger's value is in [0, 1], got " + number);
        }
        // GLFW reports a trigger from -1 (released) to 1.
        return ScriptTarget{ScriptTarget::Kind::PadAxis, axis.code, std::max(axis.gamepad, 0),
                            trigger ? 2.0f * value - 1.0f : value, 0.0f};
    }
    if (const input::ActionId id = actions.find(event.target); !id.isNull()) {
        for (const input::Binding& b : actions.bindings(id)) {
            if (auto t = fromBinding(b)) {
                return *t;
            }
        }
        return fail("action '" + event.target + "' has no keyboard or mouse-button binding to press");
    }
    if (event.target.find(':') == std::string::npos) {
        return fail("'" + event.target + "' is not an action of the game (nor a binding such as key:space)");
    }
    input::Binding binding;
    try {
        binding = input::parseBinding(event.target);
    } catch (const core::Error& e) {
        return fail(e.what());
    }
    if (auto t = fromBinding(binding)) {
        return *t;
    }
    if (binding.kind == input::BindingKind::GamepadButton) {
        return ScriptTarget{ScriptTarget::Kind::PadButton, binding.code, std::max(binding.gamepad, 0), 0.0f, 0.0f};
    }
    return fail("'" + event.target + "': only key:, mouse: and button: bindings can be pressed (axes are moved: "
                "'<frame> move " + event.target + " <value>')");
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

    Running(detail::GameState& state, const render::WindowDef& windowDef, const render::RendererDef& rendererDef,
            const audio::MixerDef& mixerDef, const core::SceneRegistry& scenes, std::uint64_t seed)
        : window(windowDef), renderer(window, rendererDef), renderSystem(renderer, nullptr, state.logger),
          input(inputDef(state)), audio(mixerDef),
          physics(makeWorldDef(state.config), static_cast<float>(state.config.unitsPerMetre)), random(seed),
          game(state), director(scenes, *state.logger),
          inputSystem(input, director, &actions, input::InputSystemDef{false, state.config.keyRepeat}),
          overlay(renderSystem, *state.profile, static_cast<float>(state.config.maxCameraDepth)) {}

    input::InputDef inputDef(const detail::GameState& state) {
        input::InputDef def;
        def.window = window.handle();
        def.logger = state.logger;
        def.pollGamepads = !state.scriptedGamepads;
        // Window pixels (top-left origin) -> framebuffer pixels (bottom-left) -> world, through
        // the camera the last frame was drawn with.
        def.screenToWorld = [this](glm::vec2 screen) {
            const glm::vec2 scale = window.contentScale();
            const glm::vec2 framebuffer{screen.x * scale.x,
                                        static_cast<float>(window.framebufferSize().y) - screen.y * scale.y};
            return renderSystem.activeCamera().screenToWorld(framebuffer);
        };
        return def;
    }
};

} // namespace

Game::Game() = default;
Game::~Game() = default;

int Game::run(int argc, char** argv, std::string_view defaultConfig) {
    profile_ = {};
    const std::string program = argc > 0 && argv[0] != nullptr ? std::filesystem::path(argv[0]).filename().string()
                                                                 : std::string("game");
    std::vector<std::string_view> args;
    for (int i = 1; i < argc; ++i) {
        args.emplace_back(argv[i]);
    }
    CommandLine options;
    try {
        options = parseCommandLine(args);
    } catch (const core::Error& e) {
        logger_.error(program + ": " + e.what() + "\n" + usage(program));
        return kExitUsage;
    }
    if (options.help) {
        const std::string text = usage(program);
        std::fwrite(text.data(), 1, text.size(), stdout);
        return kExitOk;
    }

    // Configuration.
    std::filesystem::path configPath = options.config;
    const bool required = !configPath.empty();
    if (!required) {
        configPath = std::filesystem::path(defaultConfig);
        if (configPath.is_relative()) {
            const std::filesystem::path beside = programFolder(argc > 0 ? argv[0] : nullptr) / configPath;
            std::error_code ec;
            if (std::filesystem::is_regular_file(beside, ec)) {
                configPath = beside;
            }
        }
    }
    EngineConfigResult loaded = loadEngineConfig(configPath, required);
    for (const std::string& w : loaded.warnings) {
        logger_.warning(w);
    }
    if (!loaded.errors.empty()) {
        for (const std::string& e : loaded.errors) {
            logger_.error(e);
        }
        logger_.error(program + ": the configuration has errors, not starting");
        return kExitUsage;
    }
    detail::GameState state;
    state.config = std::move(loaded.config);
    state.logger = &logger_;
    state.profile = &profile_;
    state.headless = options.frames.has_value();
    state.debugDraw = state.config.debugDraw || options.debugDraw;
    const EngineConfig& config = state.config;
    const std::string configName = config.file.empty() ? std::string("configuration") : config.file.string();

    if (config.firstScene.empty() || !scenes_.contains(config.firstScene)) {
        std::string names;
        for (const std::string& n : scenes_.names()) {
            names += (names.empty() ? "" : ", ") + n;
        }
        logger_.error(configName + ": firstScene: " +
                      (config.firstScene.empty() ? std::string("not set")
                                                 : "no scene is registered as '" + config.firstScene + "'") +
                      " (registered: " + (names.empty() ? std::string("none") : names) + ")");
        return kExitUsage;
    }
    std::optional<int> profileKey;
    if (!config.profileKey.empty()) {
        profileKey = input::keyFromName(config.profileKey);
        if (!profileKey) {
            logger_.error(configName + ": profileKey: unknown key name '" + config.profileKey + "'");
            return kExitUsage;
        }
    }
    std::optional<int> debugKey;
    if (!config.debugDrawKey.empty()) {
        debugKey = input::keyFromName(config.debugDrawKey);
        if (!debugKey) {
            logger_.error(configName + ": debugDrawKey: unknown key name '" + config.debugDrawKey + "'");
            return kExitUsage;
        }
    }
    InputScript script;
    if (!options.inputScript.empty()) {
        try {
            script = loadInputScript(options.inputScript);
        } catch (const core::Error& e) {
            logger_.error(e.what());
            return kExitUsage;
        }
    }

    state.scriptedGamepads = scriptUsesGamepad(script);

    // Window, renderer, input, mixer, physics.
    render::WindowDef windowDef;
    windowDef.title = config.windowTitle;
    windowDef.size = {config.windowWidth, config.windowHeight};
    windowDef.mode = config.windowMode == core::WindowMode::Fullscreen && !state.headless
                         ? render::WindowMode::Fullscreen
                         : render::WindowMode::Windowed;
    windowDef.samples = config.msaaSamples;
    windowDef.vsync = config.vsync && !state.headless;
    windowDef.visible = !state.headless || options.show;
    windowDef.logger = &logger_;
    render::RendererDef rendererDef;
    rendererDef.depthRange = config.maxCameraDepth;
    rendererDef.logger = &logger_;
    rendererDef.fileTextureFilter = config.textureFilteringMode == core::TextureFilteringMode::Nearest
                                        ? render::TextureFilter::Nearest
                                        : render::TextureFilter::Linear;
    audio::MixerDef mixerDef;
    mixerDef.logger = &logger_;
    mixerDef.voiceCount = config.voiceCount;
    mixerDef.masterGain = config.masterGain;
    mixerDef.spatial = {config.minAttenuationDistance, config.maxAttenuationDistance, config.minPanningDistance,
                        config.maxPanningDistance};
    const std::uint64_t seed = options.seed.value_or(config.randomSeed);

    std::unique_ptr<Running> running;
    try {
        running = std::make_unique<Running>(state, windowDef, rendererDef, mixerDef, scenes_, seed);
    } catch (const core::Error& e) {
        const std::string what = e.what();
        const bool display = what.rfind("render::", 0) == 0;
        logger_.error(program + ": " + (display ? "cannot open the game window: " : "cannot start: ") + what +
                      (display && std::getenv("DISPLAY") == nullptr
                           ? " (no display: set DISPLAY, or run under xvfb-run / scripts/with-display.sh)"
                           : ""));
        return display ? kExitNoDisplay : kExitUsage;
    }
    Running& r = *running;
    state.window = &r.window;
    state.renderer = &r.renderer;
    state.renderSystem = &r.renderSystem;
    state.input = &r.input;
    state.actions = &r.actions;
    state.audio = &r.audio;
    state.physics = &r.physics;
    state.random = &r.random;
    state.director = &r.director;
    state.overlay = &r.overlay;
    r.overlay.setVisible(config.showProfile || options.profile);

    if (!config.bindingsFile.empty()) {
        try {
            r.actions.load(r.game.asset(config.bindingsFile));
        } catch (const core::Error& e) {
            logger_.error(configName + ": bindingsFile: " + e.what());
            return kExitUsage;
        }
    }
    std::vector<std::pair<std::int64_t, std::pair<ScriptTarget, bool>>> scripted;
    ScriptedPads pads;
    try {
        for (const ScriptEvent& event : script.events) {
            const ScriptTarget target = resolveTarget(event, script, r.actions);
            if (target.kind == ScriptTarget::Kind::PadButton || target.kind == ScriptTarget::Kind::PadAxis) {
                pads.use(target.slot); // connected from the first frame
            }
            scripted.push_back({event.frame, {target, event.kind == ScriptEvent::Kind::Press}});
        }
    } catch (const core::Error& e) {
        logger_.error(e.what());
        return kExitUsage;
    }

    render::Camera& camera = r.renderSystem.camera();
    camera.setReferenceSize({static_cast<float>(config.referenceWindowWidth),
                             static_cast<float>(config.referenceWindowHeight)});
    camera.setFit(toScreenFit(config.screenFitMode));
    // The engine's own hooks (GameSystem::clear() adds them again after a scene change).
    r.renderSystem.addHook(r.overlay);

    r.director.addSystem(r.inputSystem);
    r.director.addSystem(r.physics);
    r.director.addSystem(r.audio);
    r.director.addSystem(r.renderSystem);
    r.director.addSystem(r.game);
    r.director.setReferenceWindowSize({config.referenceWindowWidth, config.referenceWindowHeight});
    r.director.setWindowSize(r.window.size());

    core::Clock clock;
    core::FixedStepper stepper(config.fixedTimestep, config.maxStepsPerFrame);
    const std::span<core::System* const> systems = r.director.systems();
    std::size_t nextScripted = 0;
    double lastAlpha = 0.0;
    bool screenshotTaken = false;
    int exitCode = kExitOk;

    const auto drawFrame = [&](double alpha) {
        if (state.debugDraw) {
            detail::drawPhysics(r.physics.world(), r.renderSystem.activeCamera(), config.unitsPerMetre,
                                r.renderer.drawer());
        }
        for (core::System* system : systems) {
            system->render(alpha);
        }
    };

    try {
        for (core::System* system : systems) {
            system->init();
        }
        if (!r.director.start(config.firstScene)) {
            return kExitUsage;
        }
        clock.tick();
        while (!r.director.terminateRequested() && !r.window.shouldClose() &&
               !(options.frames && profile_.frames >= *options.frames)) {
            const Stopwatch::time_point frameStart = Stopwatch::now();
            FrameTimes times;
            state.frame = profile_.frames;

            if (r.director.applyPendingChange()) {
                ++profile_.sceneChanges;
                stepper.reset();
            }
            core::Scene* scene = r.director.scene();

            // Input: deferred objects join, scripted events, window events, delivery.
            Stopwatch::time_point t = Stopwatch::now();
            if (scene != nullptr) {
                scene->beginFrame();
            }
            for (; nextScripted < scripted.size() && scripted[nextScripted].first <= state.frame; ++nextScripted) {
                const auto& [target, press] = scripted[nextScripted].second;
                switch (target.kind) {
                case ScriptTarget::Kind::Key:
                    r.input.handleKey(target.code, 0, press ? GLFW_PRESS : GLFW_RELEASE, 0);
                    break;
                case ScriptTarget::Kind::Mouse:
                    r.input.handleMouseButton(target.code, press ? GLFW_PRESS : GLFW_RELEASE, 0);
                    break;
                case ScriptTarget::Kind::Cursor:
                    r.input.handleCursorPos(target.x, target.y);
                    break;
                case ScriptTarget::Kind::PadButton:
                    pads.button(target.slot, target.code, press);
                    break;
                case ScriptTarget::Kind::PadAxis:
                    pads.axis(target.slot, target.code, target.x);
                    break;
                }
            }
            pads.feed(r.input);
            r.window.pollEvents();
            r.director.setWindowSize(r.window.size());
            for (core::System* system : systems) {
                system->beginFrame();
            }
            if (debugKey && r.input.wasKeyPressed(*debugKey)) {
                state.debugDraw = !state.debugDraw;
            }
            if (profileKey && r.input.wasKeyPressed(*profileKey)) {
                r.overlay.setVisible(!r.overlay.visible());
            }
            times.input = msSince(t);

            // Fixed steps.
            double dt = state.headless ? kHeadlessFrameTime : clock.tick();
            if (dt > config.maxFrameTime) {
                dt = config.maxFrameTime;
                ++profile_.spikes;
            }
            const int steps = stepper.advance(dt);
            profile_.droppedSeconds += stepper.droppedTime();
            t = Stopwatch::now();
            for (int i = 0; i < steps; ++i) {
                if (scene != nullptr) {
                    scene->dispatchFixedUpdate(stepper.step());
                }
                for (core::System* system : systems) {
                    if (system == &r.physics) {
                        const Stopwatch::time_point p = Stopwatch::now();
                        system->fixedUpdate(stepper.step());
                        times.physics += msSince(p);
                    } else {
                        system->fixedUpdate(stepper.step());
                    }
                }
            }
            times.fixedSteps = msSince(t);
            if (scene != nullptr) {
                scene->setFrameAlpha(stepper.alpha()); // where objects are drawn (renderTransform())
            }
            profile_.fixedSteps += steps;

            // Update.
            t = Stopwatch::now();
            if (scene != nullptr) {
                scene->dispatchUpdate(dt);
            }
            for (core::System* system : systems) {
                if (system == &r.audio) {
                    const Stopwatch::time_point a = Stopwatch::now();
                    system->update(dt);
                    times.audio += msSince(a);
                } else {
                    system->update(dt);
                }
            }
            times.update = msSince(t);

            // Render.
            t = Stopwatch::now();
            lastAlpha = stepper.alpha();
            drawFrame(lastAlpha);
            if (options.frames && profile_.frames + 1 == *options.frames && !options.screenshot.empty()) {
                r.renderer.screenshot(options.screenshot);
                screenshotTaken = true;
            }
            r.window.swapBuffers();
            times.render = msSince(t);

            times.total = msSince(frameStart);
            ++profile_.frames;
            profile_.last = times;
            profile_.sum.input += times.input;
            profile_.sum.fixedSteps += times.fixedSteps;
            profile_.sum.physics += times.physics;
            profile_.sum.update += times.update;
            profile_.sum.audio += times.audio;
            profile_.sum.render += times.render;
            profile_.sum.total += times.total;
            profile_.maxFrameMs = std::max(profile_.maxFrameMs, times.total);
        }
        if (!options.screenshot.empty() && !screenshotTaken) {
            // The game ended before its last frame was known: draw the final state again.
            drawFrame(lastAlpha);
            r.renderer.screenshot(options.screenshot);
        }
    } catch (const std::exception& e) {
        logger_.error(program + ": " + e.what());
        exitCode = kExitRuntimeError;
    }

    try {
        r.director.stop();
        for (auto it = systems.rbegin(); it != systems.rend(); ++it) {
            (*it)->shutdown();
        }
    } catch (const std::exception& e) {
        logger_.error(program + ": while shutting down: " + e.what());
        exitCode = kExitRuntimeError;
    }
    if (config.printProfile) {
        logger_.info(profile_.toString());
    }
    return exitCode;
}

} // namespace e2d::engine
