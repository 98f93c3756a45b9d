// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/engine/engine_config.hpp>
#include <e2d/engine/frame_profile.hpp>
#include <e2d/input/event.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>

namespace e2d::audio {
class AudioSystem;
}
namespace e2d::core {
class Logger;
class Random;
class SceneDirector;
} // namespace e2d::core
namespace e2d::input {
class ActionMap;
class Input;
} // namespace e2d::input
namespace e2d::physics {
class PhysicsSystem;
}
namespace e2d::render {
class Renderer;
class RenderSystem;
class Window;
} // namespace e2d::render

namespace e2d::engine::detail {

class ProfileOverlay;

/// Everything a running Game owns, as GameSystem reaches it. Filled in by Game::run() (which
/// owns the objects) before the first scene starts.
struct GameState {
    EngineConfig config;
    core::Logger* logger = nullptr;
    render::Window* window = nullptr;
    render::Renderer* renderer = nullptr;
    render::RenderSystem* renderSystem = nullptr;
    input::Input* input = nullptr;
    input::ActionMap* actions = nullptr;
    audio::AudioSystem* audio = nullptr;
    physics::PhysicsSystem* physics = nullptr;
    core::Random* random = nullptr;
    core::SceneDirector* director = nullptr;
    FrameProfile* profile = nullptr;
    ProfileOverlay* overlay = nullptr;
    /// Textures released by the last scene change.
    int texturesReleased = 0;
    bool debugDraw = false;
    bool headless = false;
    /// The frame running (set by the game loop's profile recorder).
    std::int64_t frame = 0;
    /// `--frames N`, else 0.
    std::int64_t frameLimit = 0;
    /// The keys that toggle the debug draw and the profile overlay (config), if any.
    std::optional<input::Key> debugKey;
    std::optional<input::Key> profileKey;
    /// `--screenshot FILE` (empty: none), and whether it was written.
    std::filesystem::path screenshot;
    bool screenshotTaken = false;
    /// The loop has ended: a last picture is being drawn.
    bool ended = false;
};

} // namespace e2d::engine::detail
