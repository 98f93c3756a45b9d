// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/system.hpp>

#include <functional>

namespace e2d::core {
class Scene;
class SceneDirector;
} // namespace e2d::core

namespace e2d::input {

class ActionMap;
struct Event;
class Input;

/// Settings of an InputSystem.
struct InputSystemDef {
    /// Call glfwPollEvents() at the start of beginFrame() (when the Input is attached to a
    /// window). Turn off when something else (the window owner) already polls. Default true.
    bool pollWindowEvents = true;
    /// Send KeyRepeat events (the system's auto-repeat of a held key) to the scene. Off: they still reach polling and `Input::events()`, not the scene.
    /// Default true.
    bool keyRepeat = true;
};

/// Plugs an Input (and optionally an ActionMap) into the core loop: `beginFrame()` polls
/// GLFW, delivers the frame's events (Input::beginFrame), updates the actions, then sends each
/// event, in order, to the current scene with `Scene::dispatch()` as one of the structs of
/// event.hpp (KeyDown, KeyUp, KeyRepeat, TextEntered, MouseButtonDown/Up, MouseMoved,
/// MouseScrolled, FocusGained, FocusLost, GamepadConnected/Disconnected, GamepadButtonDown/Up,
/// GamepadAxisMoved): the scene and the components that derive from `core::Handles<...>` of
/// that type receive it.
///
/// Joystick events (mapped or not) are not sent; components poll through
/// `scene()->system<InputSystem>().input()`. Input and ActionMap are not owned.
class InputSystem final : public core::System {
public:
    /// Events go to `director.scene()` (none while there is no scene).
    InputSystem(Input& input, core::SceneDirector& director, ActionMap* actions = nullptr,
                InputSystemDef def = {});
    /// Events go to whatever `currentScene` returns (nullptr: nowhere).
    InputSystem(Input& input, std::function<core::Scene*()> currentScene,
                ActionMap* actions = nullptr, InputSystemDef def = {});

    void beginFrame() override;

    [[nodiscard]] Input& input() const noexcept { return input_; }
    /// nullptr when none was given.
    [[nodiscard]] ActionMap* actions() const noexcept { return actions_; }
    void setActions(ActionMap* actions) noexcept { actions_ = actions; }

    /// Sends one recorded event to `scene` as its event struct.
    static void dispatch(const Event& event, core::Scene& scene);

private:
    Input& input_;
    std::function<core::Scene*()> currentScene_;
    ActionMap* actions_ = nullptr;
    InputSystemDef def_;
};

} // namespace e2d::input
