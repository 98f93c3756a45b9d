// SPDX-License-Identifier: MIT
#include <e2d/core/game_loop.hpp>

#include <e2d/core/clock.hpp>
#include <e2d/core/error.hpp>
#include <e2d/core/fixed_stepper.hpp>
#include <e2d/core/scene_director.hpp>
#include <e2d/core/system.hpp>

namespace e2d::core {

bool GameLoop::start(std::string_view firstScene) {
    if (started_) {
        throw Error("core::GameLoop::start(): the loop is already started");
    }
    for (System* system : director_.systems()) {
        system->init();
    }
    started_ = true;
    const bool ok = director_.start(firstScene);
    // The first frame should not count the time spent loading as game time.
    clock_.tick();
    return ok;
}

FrameInfo GameLoop::frame() {
    FrameInfo info;
    info.sceneChanged = director_.applyPendingChange();
    Scene* scene = director_.scene();
    const auto& systems = director_.systems();

    if (scene != nullptr) {
        scene->beginFrame();
    }
    for (System* system : systems) {
        system->beginFrame();
    }

    info.dt = clock_.tick();
    info.fixedSteps = stepper_.advance(info.dt);
    const double step = stepper_.step();
    for (int i = 0; i < info.fixedSteps; ++i) {
        if (scene != nullptr) {
            scene->dispatchFixedUpdate(step);
        }
        for (System* system : systems) {
            system->fixedUpdate(step);
        }
    }

    if (scene != nullptr) {
        scene->setFrameAlpha(stepper_.alpha()); // where objects are drawn (renderTransform())
        scene->dispatchUpdate(info.dt);
    }
    for (System* system : systems) {
        system->update(info.dt);
    }

    info.alpha = stepper_.alpha();
    for (System* system : systems) {
        system->render(info.alpha);
    }
    return info;
}

bool GameLoop::running() const noexcept {
    return started_ && !director_.terminateRequested();
}

void GameLoop::shutdown() {
    if (!started_) {
        return;
    }
    started_ = false;
    director_.stop();
    const auto& systems = director_.systems();
    for (auto it = systems.rbegin(); it != systems.rend(); ++it) {
        (*it)->shutdown();
    }
}

} // namespace e2d::core
