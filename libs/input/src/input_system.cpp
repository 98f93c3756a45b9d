// SPDX-License-Identifier: MIT
#include <e2d/input/input_system.hpp>

#include <e2d/core/scene.hpp>
#include <e2d/core/scene_director.hpp>
#include <e2d/input/actions.hpp>
#include <e2d/input/event.hpp>
#include <e2d/input/input.hpp>

#include <GLFW/glfw3.h>

namespace e2d::input {

InputSystem::InputSystem(Input& input, core::SceneDirector& director, ActionMap* actions,
                         InputSystemDef def)
    : InputSystem(
          input, [&director] { return director.scene(); }, actions, def) {}

InputSystem::InputSystem(Input& input, std::function<core::Scene*()> currentScene,
                         ActionMap* actions, InputSystemDef def)
    : input_(input), currentScene_(std::move(currentScene)), actions_(actions), def_(def) {}

void InputSystem::beginFrame() {
    if (def_.pollWindowEvents && input_.window() != nullptr) {
        glfwPollEvents();
    }
    input_.beginFrame();
    if (actions_ != nullptr) {
        actions_->update(input_);
    }
    core::Scene* scene = currentScene_ ? currentScene_() : nullptr;
    if (scene == nullptr) {
        return;
    }
    for (const Event& event : input_.events()) {
        if (event.type == EventType::KeyRepeat && !def_.keyRepeat) {
            continue;
        }
        dispatch(event, *scene);
    }
}

void InputSystem::dispatch(const Event& e, core::Scene& scene) {
    const auto key = static_cast<Key>(e.code);
    const auto button = static_cast<MouseButton>(e.code);
    const auto padButton = static_cast<GamepadButton>(e.code);
    switch (e.type) {
    case EventType::KeyDown:
        scene.dispatch(KeyDown{{key, e.scancode, e.mods}});
        break;
    case EventType::KeyUp:
        scene.dispatch(KeyUp{{key, e.scancode, e.mods}});
        break;
    case EventType::KeyRepeat:
        scene.dispatch(KeyRepeat{{key, e.scancode, e.mods}});
        break;
    case EventType::Text:
        scene.dispatch(TextEntered{static_cast<char32_t>(e.code)});
        break;
    case EventType::MouseButtonDown:
        scene.dispatch(MouseButtonDown{{button, e.mods, e.screen, e.world}});
        break;
    case EventType::MouseButtonUp:
        scene.dispatch(MouseButtonUp{{button, e.mods, e.screen, e.world}});
        break;
    case EventType::MouseMove:
        scene.dispatch(MouseMoved{e.screen, e.world, e.delta});
        break;
    case EventType::Scroll:
        scene.dispatch(MouseScrolled{e.delta, e.screen, e.world});
        break;
    case EventType::FocusGained:
        scene.dispatch(FocusGained{});
        break;
    case EventType::FocusLost:
        scene.dispatch(FocusLost{});
        break;
    case EventType::GamepadConnected:
        scene.dispatch(GamepadConnected{e.gamepad});
        break;
    case EventType::GamepadDisconnected:
        scene.dispatch(GamepadDisconnected{e.gamepad});
        break;
    case EventType::GamepadButtonDown:
        scene.dispatch(GamepadButtonDown{{e.gamepad, padButton}});
        break;
    case EventType::GamepadButtonUp:
        scene.dispatch(GamepadButtonUp{{e.gamepad, padButton}});
        break;
    case EventType::GamepadAxis:
        scene.dispatch(GamepadAxisMoved{e.gamepad, static_cast<GamepadAxis>(e.code), e.value});
        break;
    case EventType::JoystickConnected:
    case EventType::JoystickDisconnected:
        break;
    }
}

} // namespace e2d::input
