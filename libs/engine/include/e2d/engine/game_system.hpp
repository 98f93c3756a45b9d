// SPDX-License-Identifier: MIT
#pragma once

// Everything a scene reaches through GameSystem, so that one include does.
#include <e2d/audio/mixer.hpp>
#include <e2d/core/error.hpp>
#include <e2d/core/log.hpp>
#include <e2d/core/random.hpp>
#include <e2d/core/system.hpp>
#include <e2d/engine/engine_config.hpp>
#include <e2d/engine/frame_profile.hpp>
#include <e2d/input/actions.hpp>
#include <e2d/input/input.hpp>
#include <e2d/physics/physics_system.hpp>
#include <e2d/physics/world.hpp>
#include <e2d/render/render_system.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/text_renderer.hpp>
#include <e2d/render/window.hpp>

#include <filesystem>
#include <string_view>

namespace e2d::engine {

namespace detail {
struct GameState;
}

/// What a running Game offers its scenes and components: `scene()->system<GameSystem>()`.
/// Owned by the Game; valid while the game runs.
///
/// On a scene change (clear(), after the other systems' clear(): sprites destroyed, voices
/// stopped, bodies gone) it destroys every texture no sprite uses any more (the fonts and their
/// atlases are dropped too and reopened when next asked for).
class GameSystem final : public core::System {
public:
    explicit GameSystem(detail::GameState& state) noexcept : state_(state) {}

    /// The configuration the game runs with.
    [[nodiscard]] const EngineConfig& config() const noexcept;
    /// `relative` resolved against the config file's folder (apps keep their assets beside
    /// it); an absolute path is returned as is.
    [[nodiscard]] std::filesystem::path asset(std::string_view relative) const;

    [[nodiscard]] render::Window& window() noexcept;
    [[nodiscard]] render::Renderer& renderer() noexcept;
    [[nodiscard]] render::RenderSystem& renderSystem() noexcept;
    [[nodiscard]] render::TextRenderer& text();
    [[nodiscard]] input::Input& input() noexcept;
    /// The game's actions, loaded from the config's bindingsFile (if any).
    [[nodiscard]] input::ActionMap& actions() noexcept;
    [[nodiscard]] audio::Mixer& mixer() noexcept;
    /// The physics world, in metres (see unitsPerMetre()).
    [[nodiscard]] physics::World& world() noexcept;
    /// The physics system the components use, in world units.
    [[nodiscard]] physics::PhysicsSystem& physics() noexcept;
    [[nodiscard]] core::Logger& logger() noexcept;
    /// World units per physics metre (config unitsPerMetre, default 1). The config's PHYSICS
    /// lengths are divided by it for the world, the debug draw multiplies the world's metres
    /// by it, and the game's physics::PhysicsSystem has it as its unitsPerMetre(): Rigidbody,
    /// Collider and JointComponent take and give world units (positions, sizes, velocities,
    /// forces, contact points, PhysicsSystem ray casts), so a game that draws in pixels writes
    /// pixels everywhere. world() itself stays in metres.
    [[nodiscard]] double unitsPerMetre() const noexcept;
    /// The game's random numbers, seeded by `--seed` or the config's randomSeed.
    [[nodiscard]] core::Random& random() noexcept;

    /// Switches to the scene registered as `name` at the start of the next frame.
    void changeScene(std::string_view name);
    /// Ends the game after this frame.
    void terminateGame();

    /// Whether the physics debug draw (shapes, AABBs, contacts and normals, joints; colours in
    /// DebugDrawColors) is on.
    [[nodiscard]] bool debugDraw() const noexcept;
    void setDebugDraw(bool on) noexcept;

    /// Whether the frame profile overlay (config showProfile, `--profile`, the profileKey) is
    /// on: mean milliseconds per frame and per phase over the last 15 frames, drawn by the
    /// engine in camera space at the view's top-left corner, above everything.
    [[nodiscard]] bool profileOverlay() const noexcept;
    void setProfileOverlay(bool on) noexcept;

    /// Frames run so far (0 during the first frame).
    [[nodiscard]] std::int64_t frame() const noexcept;
    /// True for a `--frames N` run (fixed 1/60 s frames, hidden window).
    [[nodiscard]] bool headless() const noexcept;
    [[nodiscard]] const FrameProfile& profile() const noexcept;

    void clear() override;

private:
    detail::GameState& state_;
};

} // namespace e2d::engine
