// SPDX-License-Identifier: MIT
#include <e2d/core/scene_director.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/core/log.hpp>
#include <e2d/core/scene_registry.hpp>
#include <e2d/core/system.hpp>

#include <algorithm>

namespace e2d::core {

SceneDirector::SceneDirector(const SceneRegistry& registry, Logger& logger)
    : registry_(registry), logger_(logger) {}

SceneDirector::~SceneDirector() = default;

void SceneDirector::addSystem(System& system) {
    if (std::find(systems_.begin(), systems_.end(), &system) != systems_.end()) {
        throw Error("core::SceneDirector::addSystem(): this system is already registered");
    }
    systems_.push_back(&system);
}

const std::string& SceneDirector::sceneName() const noexcept {
    static const std::string kNone;
    return scene_ ? scene_->name() : kNone;
}

bool SceneDirector::start(std::string_view name) {
    pending_.reset();
    return switchTo(name);
}

void SceneDirector::stop() {
    pending_.reset();
    if (scene_) {
        scene_->dispatchTerminate();
        scene_.reset();
    }
}

bool SceneDirector::applyPendingChange() {
    if (!pending_) {
        return false;
    }
    const std::string name = std::move(*pending_);
    pending_.reset();
    return switchTo(name);
}

bool SceneDirector::switchTo(std::string_view name) {
    if (!registry_.contains(name)) {
        logger_.error("core::SceneDirector: unknown scene " + quote(name) +
                      (scene_ ? ", keeping scene " + quote(scene_->name())
                              : std::string(", no scene is running")));
        return false;
    }
    if (scene_) {
        logger_.info("core::SceneDirector: leaving scene " + quote(scene_->name()));
        scene_->dispatchTerminate();
        scene_.reset();
        for (System* system : systems_) {
            system->clear();
        }
    }
    logger_.info("core::SceneDirector: entering scene " + quote(name));
    scene_ = registry_.create(name);
    scene_->attachHost(this, std::string(name));
    scene_->dispatchInitialize();
    return true;
}

void SceneDirector::changeToScene(std::string_view name) { pending_ = std::string(name); }

void SceneDirector::terminateGame() { terminate_ = true; }

} // namespace e2d::core
