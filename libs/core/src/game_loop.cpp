// SPDX-License-Identifier: MIT
#include <e2d/core/game_loop.hpp>

#include <e2d/core/clock.hpp>
#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/core/fixed_stepper.hpp>
#include <e2d/core/scene_director.hpp>
#include <e2d/core/system.hpp>

#include <cmath>
#include <string>

namespace e2d::core {

namespace {

// Keeps the loop free of null checks: without an observer, this one (it has no state) is told.
class QuietObserver final : public FrameObserver {};

FrameObserver& quietObserver() {
    static QuietObserver quiet;
    return quiet;
}

} // namespace

GameLoop::GameLoop(SceneDirector& director, FixedStepper& stepper, Clock& clock, GameLoopDef def)
    : director_(director), stepper_(stepper), clock_(clock), def_(def) {
    constexpr const char* kCtor = "core::GameLoop::GameLoop(): ";
    if (!(def.maxFrameTime > 0.0) || std::isnan(def.maxFrameTime)) {
        throw Error(std::string(kCtor) + "maxFrameTime must be > 0, got " +
                    formatNumber(def.maxFrameTime));
    }
    if (!std::isfinite(def.fixedFrameTime) || def.fixedFrameTime < 0.0) {
        throw Error(std::string(kCtor) + "fixedFrameTime must be finite and >= 0, got " +
                    formatNumber(def.fixedFrameTime));
    }
    if (def.frameLimit < 0) {
        throw Error(std::string(kCtor) + "frameLimit must be >= 0, got " +
                    std::to_string(def.frameLimit));
    }
    if (def_.observer == nullptr) {
        def_.observer = &quietObserver();
    }
}

bool GameLoop::start(std::string_view firstScene) {
    if (started_) {
        throw Error("core::GameLoop::start(): the loop is already started");
    }
    for (System* system : director_.systems()) {
        system->init();
    }
    started_ = true;
    frames_ = 0;
    const bool ok = director_.start(firstScene);
    // The first frame should not count the time spent loading as game time.
    clock_.tick();
    return ok;
}

FrameInfo GameLoop::frame() {
    FrameObserver& observer = *def_.observer;
    FrameInfo info;
    info.index = frames_;
    observer.frameStarted(info.index);
    info.sceneChanged = director_.applyPendingChange();
    if (info.sceneChanged) {
        // The old scene's leftover time is not the new scene's.
        stepper_.reset();
    }
    Scene* scene = director_.scene();
    const auto& systems = director_.systems();
    const auto eachSystem = [&](FramePhase phase, auto&& call) {
        for (System* system : systems) {
            observer.systemStarted(phase, *system);
            call(*system);
            observer.systemEnded(phase, *system);
        }
    };

    observer.phaseStarted(FramePhase::Begin);
    if (scene != nullptr) {
        scene->beginFrame();
    }
    eachSystem(FramePhase::Begin, [](System& s) { s.beginFrame(); });
    observer.phaseEnded(FramePhase::Begin);

    const double clockDt = clock_.tick();
    info.dt = def_.fixedFrameTime > 0.0 ? def_.fixedFrameTime : clockDt;
    if (info.dt > def_.maxFrameTime) {
        info.dt = def_.maxFrameTime;
        info.spike = true;
    }
    info.fixedSteps = stepper_.advance(info.dt);
    info.droppedTime = stepper_.droppedTime();
    const double step = stepper_.step();
    observer.phaseStarted(FramePhase::FixedSteps);
    for (int i = 0; i < info.fixedSteps; ++i) {
        if (scene != nullptr) {
            scene->dispatchFixedUpdate(step);
        }
        eachSystem(FramePhase::FixedSteps, [step](System& s) { s.fixedUpdate(step); });
    }
    observer.phaseEnded(FramePhase::FixedSteps);

    observer.phaseStarted(FramePhase::Update);
    if (scene != nullptr) {
        scene->setFrameAlpha(stepper_.alpha()); // where objects are drawn (renderTransform())
        scene->dispatchUpdate(info.dt);
    }
    eachSystem(FramePhase::Update, [&info](System& s) { s.update(info.dt); });
    observer.phaseEnded(FramePhase::Update);

    info.alpha = stepper_.alpha();
    lastAlpha_ = info.alpha;
    observer.phaseStarted(FramePhase::Render);
    eachSystem(FramePhase::Render, [&info](System& s) { s.render(info.alpha); });
    observer.phaseEnded(FramePhase::Render);

    ++frames_;
    observer.frameEnded(info);
    return info;
}

void GameLoop::run() {
    while (running()) {
        frame();
    }
}

void GameLoop::render() {
    for (System* system : director_.systems()) {
        system->render(lastAlpha_);
    }
}

bool GameLoop::running() const noexcept {
    return started_ && !director_.terminateRequested() &&
           (def_.frameLimit == 0 || frames_ < def_.frameLimit);
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
