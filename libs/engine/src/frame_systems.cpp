// SPDX-License-Identifier: MIT
#include "frame_systems.hpp"

#include <e2d/core/scene_director.hpp>
#include <e2d/input/input.hpp>
#include <e2d/physics/physics_system.hpp>
#include <e2d/render/render_system.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/window.hpp>

#include "debug_draw.hpp"
#include "game_state.hpp"
#include "profile_overlay.hpp"

namespace e2d::engine::detail {

void FrameStart::beginFrame() {
    state_.window->pollEvents();
    state_.director->setWindowSize(state_.window->size());
    if (state_.window->shouldClose()) {
        state_.director->terminateGame();
    }
}

void FrameStart::render(double /*alpha*/) {
    if (state_.debugDraw) {
        drawPhysics(state_.physics->world(), state_.renderSystem->activeCamera(),
                    state_.config.unitsPerMetre, state_.renderer->drawer());
    }
}

void FrameEnd::beginFrame() {
    if (state_.debugKey && state_.input->wasKeyPressed(*state_.debugKey)) {
        state_.debugDraw = !state_.debugDraw;
    }
    if (state_.profileKey && state_.input->wasKeyPressed(*state_.profileKey)) {
        state_.overlay->setVisible(!state_.overlay->visible());
    }
}

void FrameEnd::render(double /*alpha*/) {
    // The last frame of a `--frames N` run, or the picture drawn again after the game ended
    // before it.
    if (!state_.screenshot.empty() && !state_.screenshotTaken &&
        (state_.frame + 1 == state_.frameLimit || state_.ended)) {
        state_.renderer->screenshot(state_.screenshot);
        state_.screenshotTaken = true;
    }
    state_.window->swapBuffers();
}

} // namespace e2d::engine::detail
