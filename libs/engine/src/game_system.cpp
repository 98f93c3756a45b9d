// SPDX-License-Identifier: MIT
#include <e2d/engine/game_system.hpp>

#include <e2d/audio/audio_system.hpp>
#include <e2d/core/scene_director.hpp>
#include <e2d/physics/physics_system.hpp>
#include <e2d/render/render_system.hpp>
#include <e2d/render/renderer.hpp>

#include "game_state.hpp"
#include "profile_overlay.hpp"

namespace e2d::engine {

const EngineConfig& GameSystem::config() const noexcept { return state_.config; }

std::filesystem::path GameSystem::asset(std::string_view relative) const {
    const std::filesystem::path path(relative);
    if (path.is_absolute()) {
        return path;
    }
    return state_.config.assetRoot / path;
}

render::Window& GameSystem::window() noexcept { return *state_.window; }
render::Renderer& GameSystem::renderer() noexcept { return *state_.renderer; }
render::RenderSystem& GameSystem::renderSystem() noexcept { return *state_.renderSystem; }
render::TextRenderer& GameSystem::text() { return state_.renderSystem->text(); }
input::Input& GameSystem::input() noexcept { return *state_.input; }
input::ActionMap& GameSystem::actions() noexcept { return *state_.actions; }
audio::Mixer& GameSystem::mixer() noexcept { return state_.audio->mixer(); }
physics::World& GameSystem::world() noexcept { return state_.physics->world(); }
physics::PhysicsSystem& GameSystem::physics() noexcept { return *state_.physics; }
core::Logger& GameSystem::logger() noexcept { return *state_.logger; }
double GameSystem::unitsPerMetre() const noexcept { return state_.config.unitsPerMetre; }
core::Random& GameSystem::random() noexcept { return *state_.random; }

void GameSystem::changeScene(std::string_view name) { state_.director->changeToScene(name); }
void GameSystem::terminateGame() { state_.director->terminateGame(); }

bool GameSystem::debugDraw() const noexcept { return state_.debugDraw; }
void GameSystem::setDebugDraw(bool on) noexcept { state_.debugDraw = on; }
bool GameSystem::profileOverlay() const noexcept { return state_.overlay->visible(); }
void GameSystem::setProfileOverlay(bool on) noexcept { state_.overlay->setVisible(on); }
std::int64_t GameSystem::frame() const noexcept { return state_.frame; }
bool GameSystem::headless() const noexcept { return state_.headless; }
const FrameProfile& GameSystem::profile() const noexcept { return *state_.profile; }

void GameSystem::clear() {
    // The other systems cleared first (registered before this one): no sprite, voice or body
    // of the old scene is left, and the render system dropped its hooks.
    state_.texturesReleased = state_.renderSystem->releaseUnusedTextures();
    // The engine's own hooks go back, before the new scene's components add theirs.
    if (state_.overlay != nullptr) {
        state_.renderSystem->addHook(*state_.overlay);
    }
}

} // namespace e2d::engine
