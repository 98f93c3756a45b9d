// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec2.hpp>

#include <cstdint>
#include <span>
#include <string_view>

namespace e2d::core {

class Logger;
class System;

/// What a Scene needs from whatever runs it.
/// Implemented by SceneDirector; tests can implement it directly.
class SceneHost {
public:
    virtual ~SceneHost() = default;

    /// Requests a change to the scene registered as `name`, done at the start of the next
    /// frame.
    virtual void changeToScene(std::string_view name) = 0;
    /// Requests the end of the game loop.
    virtual void terminateGame() = 0;
    /// Current window size in pixels.
    [[nodiscard]] virtual glm::ivec2 windowSize() const = 0;
    /// Size the game was designed for, in pixels (see Config::referenceWindowWidth).
    [[nodiscard]] virtual glm::ivec2 referenceWindowSize() const = 0;
    /// The game's logger.
    [[nodiscard]] virtual Logger& logger() = 0;
    /// The systems running the scene (physics, renderer, mixer, input, ...), which components
    /// find through `Scene::system<T>()`. None by default.
    [[nodiscard]] virtual std::span<System* const> systems() const { return {}; }

    /// A tag for the next scene attached to this host (1, 2, 3, ...), which Scene::attachHost()
    /// writes into the ids of its objects so that ids of one scene are refused by the next.
    [[nodiscard]] std::uint32_t nextSceneTag() noexcept { return ++scenesAttached_; }

protected:
    SceneHost() = default;
    SceneHost(const SceneHost&) = default;
    SceneHost& operator=(const SceneHost&) = default;

private:
    std::uint32_t scenesAttached_ = 0;
};

} // namespace e2d::core
