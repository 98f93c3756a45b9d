// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/scene.hpp>
#include <e2d/core/scene_host.hpp>

#include <glm/vec2.hpp>

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace e2d::core {

class Logger;
class SceneRegistry;
class System;

/// Owns the current scene and changes scenes on request.
///
/// `changeToScene()` only records the request; `applyPendingChange()` (called by GameLoop at
/// the start of a frame) performs it: the old scene is terminated (its objects receive
/// onTerminate) and destroyed, every registered system's `clear()` runs, then the new scene
/// is created from the registry and initialised. An unknown name is logged as an error and
/// the current scene is kept. The last request of a frame wins; requesting the current
/// scene's name restarts it with a fresh instance.
class SceneDirector final : public SceneHost {
public:
    /// `registry` and `logger` must outlive the director.
    SceneDirector(const SceneRegistry& registry, Logger& logger);
    /// Destroys the current scene without sending events; call `stop()` first for an orderly
    /// end.
    ~SceneDirector() override;
    SceneDirector(const SceneDirector&) = delete;
    SceneDirector& operator=(const SceneDirector&) = delete;

    /// Registers a system (not owned) whose `clear()` runs on every scene change; GameLoop
    /// drives the registered systems in registration order. Throws core::Error if it is
    /// already registered.
    void addSystem(System& system);
    [[nodiscard]] std::span<System* const> systems() const override { return systems_; }

    /// Switches to `name` immediately (terminating the current scene, if any). Returns false
    /// and logs an error for an unknown name, keeping the current scene.
    bool start(std::string_view name);
    /// Terminates and destroys the current scene; afterwards there is none.
    void stop();

    /// The running scene, or nullptr before `start()` / after `stop()`.
    [[nodiscard]] Scene* scene() const noexcept { return scene_.get(); }
    /// The running scene's registry name (empty if none).
    [[nodiscard]] const std::string& sceneName() const noexcept;

    /// Performs the requested scene change, if any. Returns true if the scene changed.
    bool applyPendingChange();
    /// The requested scene name, if a change is pending.
    [[nodiscard]] const std::optional<std::string>& pendingChange() const noexcept {
        return pending_;
    }
    /// True once `terminateGame()` was called.
    [[nodiscard]] bool terminateRequested() const noexcept { return terminate_; }

    void setWindowSize(glm::ivec2 size) noexcept { windowSize_ = size; }
    void setReferenceWindowSize(glm::ivec2 size) noexcept { referenceWindowSize_ = size; }

    // SceneHost
    void changeToScene(std::string_view name) override;
    void terminateGame() override;
    [[nodiscard]] glm::ivec2 windowSize() const override { return windowSize_; }
    [[nodiscard]] glm::ivec2 referenceWindowSize() const override { return referenceWindowSize_; }
    [[nodiscard]] Logger& logger() override { return logger_; }

private:
    bool switchTo(std::string_view name);

    const SceneRegistry& registry_;
    Logger& logger_;
    std::vector<System*> systems_;
    std::unique_ptr<Scene> scene_;
    std::optional<std::string> pending_;
    bool terminate_ = false;
    glm::ivec2 windowSize_{1024, 624};
    glm::ivec2 referenceWindowSize_{1024, 624};
};

} // namespace e2d::core
