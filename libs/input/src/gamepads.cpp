// SPDX-License-Identifier: MIT
// Gamepads: GLFW's 16 joystick slots polled once per frame, dead zones, button and axis events.
#include <e2d/input/input.hpp>

#include <e2d/core/error.hpp>

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace e2d::input {

namespace {

bool validSlot(int slot) noexcept { return slot >= 0 && slot < kMaxGamepads; }

bool validPadButton(int button) noexcept { return button >= 0 && button < kGamepadButtonCount; }

} // namespace

glm::vec2 Input::applyStickDeadZone(glm::vec2 raw, float deadZone) noexcept {
    const float length = std::sqrt(raw.x * raw.x + raw.y * raw.y);
    if (!(length > deadZone) || !std::isfinite(length)) {
        return glm::vec2(0.0f);
    }
    const float scaled = (std::min(length, 1.0f) - deadZone) / (1.0f - deadZone);
    return raw * (scaled / length);
}

float Input::applyTriggerDeadZone(float raw, float deadZone) noexcept {
    const float travel = std::clamp((raw + 1.0f) * 0.5f, 0.0f, 1.0f); // NaN stays NaN here
    if (!(travel > deadZone)) {
        return 0.0f;
    }
    return (travel - deadZone) / (1.0f - deadZone);
}

void Input::handleJoystick(int slot, const JoystickSnapshot& snapshot) {
    if (!validSlot(slot)) {
        throw core::Error("input::Input::handleJoystick(): slot must be in [0, 15], got " +
                          std::to_string(slot));
    }
    PendingPad& pending = pendingPads_[static_cast<std::size_t>(slot)];
    pending.fed = true;
    pending.snapshot = snapshot;
    // Copies (assign reuses the capacity: no allocation once a pad is known).
    pending.guid.assign(snapshot.guid);
    pending.name.assign(snapshot.name);
    pending.snapshot.guid = {};
    pending.snapshot.name = {};
}

void Input::pollJoysticks() {
    for (int slot = 0; slot < kMaxGamepads; ++slot) {
        const int jid = GLFW_JOYSTICK_1 + slot;
        JoystickSnapshot snap;
        snap.present = glfwJoystickPresent(jid) == GLFW_TRUE;
        const Pad& pad = pads_[static_cast<std::size_t>(slot)];
        if (!snap.present && !pad.present) {
            continue;
        }
        if (snap.present) {
            snap.gamepad = glfwJoystickIsGamepad(jid) == GLFW_TRUE;
            if (!pad.present || !pad.gamepad) {
                const char* guid = glfwGetJoystickGUID(jid);
                const char* name = glfwGetJoystickName(jid);
                snap.guid = guid != nullptr ? guid : "";
                snap.name = name != nullptr ? name : "";
            } else {
                snap.guid = pad.guid;
                snap.name = pad.name;
            }
            GLFWgamepadstate state;
            if (snap.gamepad && glfwGetGamepadState(jid, &state) == GLFW_TRUE) {
                std::copy(std::begin(state.axes), std::end(state.axes), snap.axes.begin());
                std::copy(std::begin(state.buttons), std::end(state.buttons), snap.buttons.begin());
            } else if (snap.gamepad) {
                snap.gamepad = false;
            }
            // Triggers rest at -1 in GLFW's state: an unmapped pad reads as released.
            snap.axes[GLFW_GAMEPAD_AXIS_LEFT_TRIGGER] =
                snap.gamepad ? snap.axes[GLFW_GAMEPAD_AXIS_LEFT_TRIGGER] : -1.0f;
            snap.axes[GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER] =
                snap.gamepad ? snap.axes[GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER] : -1.0f;
        }
        handleJoystick(slot, snap);
    }
}

void Input::setPadButton(int slot, Pad& pad, int button, bool down) {
    const auto b = static_cast<std::size_t>(button);
    if (pad.down[b] == down) {
        return;
    }
    pad.down[b] = down;
    (down ? pad.pressed[b] : pad.released[b]) = true;
    Event e;
    e.type = down ? EventType::GamepadButtonDown : EventType::GamepadButtonUp;
    e.gamepad = slot;
    e.code = button;
    events_.push_back(e);
}

void Input::applyPad(int slot, PendingPad& pending) {
    Pad& pad = pads_[static_cast<std::size_t>(slot)];
    const JoystickSnapshot& snap = pending.snapshot;
    const bool wasGamepad = pad.present && pad.gamepad;
    const bool isGamepad = snap.present && snap.gamepad;
    const auto emit = [&](EventType type) {
        Event e;
        e.type = type;
        e.gamepad = slot;
        events_.push_back(e);
    };

    if (wasGamepad && !isGamepad) {
        for (int button = 0; button < kGamepadButtonCount; ++button) {
            setPadButton(slot, pad, button, false);
        }
        pad.axes.fill(0.0f);
        emit(EventType::GamepadDisconnected);
    }
    if (pad.present && !snap.present) {
        pad.present = false;
        pad.gamepad = false;
        emit(EventType::JoystickDisconnected);
        return;
    }
    if (!snap.present) {
        return;
    }
    if (!pad.present) {
        pad.present = true;
        pad.guid = pending.guid;
        pad.name = pending.name;
        emit(EventType::JoystickConnected);
    } else if (!isGamepad || !wasGamepad) {
        pad.guid = pending.guid;
        pad.name = pending.name;
    }
    pad.gamepad = snap.gamepad;
    if (!isGamepad) {
        return;
    }
    if (!wasGamepad) {
        emit(EventType::GamepadConnected);
    }

    // Axes: sticks through the radial dead zone, triggers to [0, 1].
    std::array<float, kGamepadAxisCount> axes{};
    for (int stick = 0; stick < 2; ++stick) {
        const auto x = static_cast<std::size_t>(stick * 2);
        const glm::vec2 v =
            applyStickDeadZone(glm::vec2(snap.axes[x], snap.axes[x + 1]), def_.stickDeadZone);
        axes[x] = v.x;
        axes[x + 1] = v.y;
    }
    for (std::size_t t = GLFW_GAMEPAD_AXIS_LEFT_TRIGGER; t <= GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER;
         ++t) {
        axes[t] = applyTriggerDeadZone(snap.axes[t], def_.triggerDeadZone);
    }

    for (int button = 0; button <= GLFW_GAMEPAD_BUTTON_LAST; ++button) {
        setPadButton(slot, pad, button,
                     snap.buttons[static_cast<std::size_t>(button)] == GLFW_PRESS);
    }
    setPadButton(slot, pad, static_cast<int>(GamepadButton::LeftTrigger),
                 axes[GLFW_GAMEPAD_AXIS_LEFT_TRIGGER] >= def_.triggerPressThreshold);
    setPadButton(slot, pad, static_cast<int>(GamepadButton::RightTrigger),
                 axes[GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER] >= def_.triggerPressThreshold);

    for (int axis = 0; axis < kGamepadAxisCount; ++axis) {
        const auto a = static_cast<std::size_t>(axis);
        if (axes[a] != pad.axes[a]) {
            pad.axes[a] = axes[a];
            Event e;
            e.type = EventType::GamepadAxis;
            e.gamepad = slot;
            e.code = axis;
            e.value = axes[a];
            events_.push_back(e);
        }
    }
}

bool Input::isGamepadConnected(int slot) const noexcept {
    return validSlot(slot) && pads_[static_cast<std::size_t>(slot)].present &&
           pads_[static_cast<std::size_t>(slot)].gamepad;
}

bool Input::isGamepadButtonDown(int slot, GamepadButton button) const noexcept {
    const int code = static_cast<int>(button);
    return validSlot(slot) && validPadButton(code) &&
           pads_[static_cast<std::size_t>(slot)].down[static_cast<std::size_t>(code)];
}

bool Input::wasGamepadButtonPressed(int slot, GamepadButton button) const noexcept {
    const int code = static_cast<int>(button);
    return validSlot(slot) && validPadButton(code) &&
           pads_[static_cast<std::size_t>(slot)].pressed[static_cast<std::size_t>(code)];
}

bool Input::wasGamepadButtonReleased(int slot, GamepadButton button) const noexcept {
    const int code = static_cast<int>(button);
    return validSlot(slot) && validPadButton(code) &&
           pads_[static_cast<std::size_t>(slot)].released[static_cast<std::size_t>(code)];
}

float Input::gamepadAxis(int slot, GamepadAxis axis) const noexcept {
    const int code = static_cast<int>(axis);
    if (!validSlot(slot) || code < 0 || code >= kGamepadAxisCount) {
        return 0.0f;
    }
    return pads_[static_cast<std::size_t>(slot)].axes[static_cast<std::size_t>(code)];
}

std::vector<JoystickInfo> Input::joysticks() const {
    std::vector<JoystickInfo> list;
    for (int slot = 0; slot < kMaxGamepads; ++slot) {
        const Pad& pad = pads_[static_cast<std::size_t>(slot)];
        if (pad.present) {
            list.push_back(JoystickInfo{slot, pad.guid, pad.name, pad.gamepad});
        }
    }
    return list;
}

} // namespace e2d::input
