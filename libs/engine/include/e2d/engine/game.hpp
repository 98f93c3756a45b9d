// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/log.hpp>
#include <e2d/core/scene_registry.hpp>
#include <e2d/engine/frame_profile.hpp>

#include <memory>
#include <string_view>

namespace e2d::engine {

/// A whole game: a user's `main()` is
///
///     e2d::engine::Game game;
///     E2D_REGISTER_SCENE(game.scenes(), TitleScene);
///     return game.run(argc, argv, "config.txt");
///
/// `run()` parses the command line (see CommandLine: `--frames N`, `--screenshot FILE.png`,
/// `--config FILE`, `--seed N`, `--input-script FILE`, `--debug-draw`, `--show`, `--help`),
/// reads the configuration (EngineConfig), opens the window and its renderer, the mixer
/// (silent, with one message, when there is no audio device), the input and the physics world,
/// registers their systems with the scene director — input::InputSystem,
/// physics::PhysicsSystem, audio::AudioSystem, render::RenderSystem and engine::GameSystem, in
/// that order, between the engine's own first and last steps of a frame — and runs the
/// config's firstScene on core::GameLoop until the window closes, a scene calls
/// terminateGame(), or N frames ran. Then it saves the screenshot, prints the frame profile
/// (config printProfile) and returns.
///
/// Each frame (core::GameLoop's sequence): a requested scene change is applied (the old scene
/// ends; sprites, voices, bodies and textures no longer used are released), the scene's
/// deferred objects join, the window's events are read, input (the input script's events
/// included: it is one more input device) is delivered to the scene (mouse positions
/// converted to world units through the active camera), the frame time (1/60 s with
/// `--frames`, else the clock's, clamped to maxFrameTime) runs whole fixed steps (scene, then
/// physics), then the scene's and systems' update, then drawing: objects moved during the
/// fixed steps (bodies, and anything moved in fixedUpdate) are drawn between their last two
/// states, children and cameras with them (core::GameObject::renderTransform()), the physics
/// debug draw on top. The frame profile times each phase through the loop's FrameObserver.
///
/// One Game runs at a time in a process: GLFW's state is process-wide, and a Game run while
/// another runs fails with exit code 3 and a message saying so (the outer game goes on).
///
/// Exit codes: 0 success; 1 an error while running (an exception out of a scene: its message
/// is logged); 2 bad command line or configuration (the message names the argument or the
/// file, line and key); 3 no display or no OpenGL context.
class Game {
public:
    Game();
    ~Game();
    Game(const Game&) = delete;
    Game& operator=(const Game&) = delete;

    /// Register the game's scenes here before run().
    [[nodiscard]] core::SceneRegistry& scenes() noexcept { return scenes_; }
    /// Where the game's messages go (stderr by default; set a sink to capture them).
    [[nodiscard]] core::Logger& logger() noexcept { return logger_; }

    /// Runs the game (see the class description); returns the exit code. `defaultConfig` is
    /// used when there is no `--config`: relative, it is looked up beside the executable, then
    /// in the working directory; missing, the defaults are used (with a warning).
    int run(int argc, char** argv, std::string_view defaultConfig = "config.txt");

    /// The profile of the last run().
    [[nodiscard]] const FrameProfile& profile() const noexcept { return profile_; }

private:
    core::SceneRegistry scenes_;
    core::Logger logger_;
    FrameProfile profile_;
};

} // namespace e2d::engine
