// SPDX-License-Identifier: MIT
#include <e2d/input/input_system.hpp>

#include <e2d/core/scene.hpp>
#include <e2d/core/scene_director.hpp>
#include <e2d/input/actions.hpp>
#include <e2d/input/input.hpp>

#include <GLFW/glfw3.h>

namespace e2d::input {

InputSystem::InputSystem(Input& input, core::SceneDirector& director, ActionMap* actions, InputSystemDef def)
    : InputSystem(input, [&director] { return director.scene(); }, actions, def) {}

InputSystem::InputSystem(Input& input, std::function<core::Scene*()> currentScene, ActionMap* actions,
                         InputSystemDef def)
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
        dispatch(event, *scene);
    }
}

void InputSystem::dispatch(const Event& e, core::Scene& scene) {
    switch (e.type) {
    case EventType::KeyDown:
        scene.dispatchButtonDown(e.code);
        scene.dispatchKeyDown(e.code, e.mods);
        break;
    case EventType::KeyUp:
        scene.dispatchButtonUp(e.code);
        scene.dispatchKeyUp(e.code, e.mods);
        break;
    case EventType::KeyRepeat: scene.dispatchKeyRepeat(e.code, e.mods); break;
    case EventType::Text: scene.dispatchTextInput(static_cast<char32_t>(e.code)); break;
    case EventType::MouseButtonDown: scene.dispatchMouseButtonDown(e.code, e.screen, e.world); break;
    case EventType::MouseButtonUp: scene.dispatchMouseButtonUp(e.code, e.screen, e.world); break;
    case EventType::MouseMove: scene.dispatchMouseMove(e.screen, e.world); break;
    case EventType::Scroll: scene.dispatchScroll(e.delta, e.screen, e.world); break;
    case EventType::FocusGained: scene.dispatchFocusChanged(true); break;
    case EventType::FocusLost: scene.dispatchFocusChanged(false); break;
    case EventType::GamepadConnected: scene.dispatchControllerConnected(e.gamepad); break;
    case EventType::GamepadDisconnected: scene.dispatchControllerDisconnected(e.gamepad); break;
    case EventType::GamepadButtonDown: scene.dispatchControllerButtonDown(e.gamepad, e.code); break;
    case EventType::GamepadButtonUp: scene.dispatchControllerButtonUp(e.gamepad, e.code); break;
    case EventType::GamepadAxis: scene.dispatchControllerAxis(e.gamepad, e.code, e.value); break;
    case EventType::JoystickConnected:
    case EventType::JoystickDisconnected: break;
    }
}

} // namespace e2d::input
