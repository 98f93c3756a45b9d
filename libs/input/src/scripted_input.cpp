// SPDX-License-Identifier: MIT
// An input script played as a device: resolved once, fed into an Input frame by frame.
#include <e2d/input/input_script.hpp>

#include <e2d/core/diagnostics.hpp>
#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/core/printable.hpp>
#include <e2d/input/actions.hpp>

#include <GLFW/glfw3.h>

#include <algorithm>
#include <optional>
#include <string>

namespace e2d::input {

namespace {

bool isTrigger(int axis) noexcept {
    return axis == GLFW_GAMEPAD_AXIS_LEFT_TRIGGER || axis == GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER;
}

} // namespace

ScriptedInput::ScriptedInput(const InputScript& script, const ActionMap& actions) {
    events_.reserve(script.events.size());
    for (const ScriptEvent& event : script.events) {
        const Resolved resolved = resolve(event, script, actions);
        if (resolved.kind == Resolved::Kind::PadButton ||
            resolved.kind == Resolved::Kind::PadAxis) {
            plugIn(resolved.slot); // connected from the first frame
        }
        events_.push_back(resolved);
    }
}

ScriptedInput::Resolved ScriptedInput::resolve(const ScriptEvent& event, const InputScript& script,
                                               const ActionMap& actions) {
    const auto fail = [&](const std::string& why) -> Resolved {
        throw core::ParseError(core::Diagnostic{
            core::Severity::Error, core::printable(script.source), event.line, 0, {}, why});
    };
    const std::string target = core::quote(event.target);
    Resolved r;
    r.frame = event.frame;
    r.press = event.kind == ScriptEvent::Kind::Press;
    const auto fromBinding = [&r](const Binding& b) -> std::optional<Resolved> {
        if (b.kind != BindingKind::Key && b.kind != BindingKind::MouseButton) {
            return std::nullopt;
        }
        Resolved out = r;
        out.kind = b.kind == BindingKind::Key ? Resolved::Kind::Key : Resolved::Kind::Mouse;
        out.code = b.code;
        return out;
    };
    const auto parse = [&](std::string_view text) -> Binding {
        try {
            return parseBinding(text);
        } catch (const core::Error& e) {
            fail(e.what());
        }
        return {};
    };

    if (event.kind == ScriptEvent::Kind::Move) {
        if (event.target == "mouse") {
            r.kind = Resolved::Kind::Cursor;
            r.x = event.x;
            r.y = event.y;
            return r;
        }
        const Binding axis = parse(event.target);
        if (axis.kind != BindingKind::GamepadAxis) {
            return fail("move: " + target +
                        " is not a gamepad axis (axis:leftx, axis@1:righttrigger)");
        }
        const float value = axis.inverted ? -event.x : event.x;
        const bool trigger = isTrigger(axis.code);
        if (trigger && value < 0.0f) {
            return fail("move " + core::printable(event.target) +
                        ": a trigger's value is in [0, 1], got " + core::formatNumber(event.x));
        }
        r.kind = Resolved::Kind::PadAxis;
        r.code = axis.code;
        r.slot = std::max(axis.gamepad, 0);
        // GLFW reports a trigger from -1 (released) to 1.
        r.x = trigger ? 2.0f * value - 1.0f : value;
        return r;
    }
    if (const ActionId id = actions.find(event.target); !id.isNull()) {
        for (const Binding& b : actions.bindings(id)) {
            if (auto resolved = fromBinding(b)) {
                return *resolved;
            }
        }
        return fail("action " + target + " has no keyboard or mouse-button binding to press");
    }
    if (event.target.find(':') == std::string::npos) {
        return fail(target + " is not an action of the game (nor a binding such as key:space)");
    }
    const Binding binding = parse(event.target);
    if (auto resolved = fromBinding(binding)) {
        return *resolved;
    }
    if (binding.kind == BindingKind::GamepadButton) {
        r.kind = Resolved::Kind::PadButton;
        r.code = binding.code;
        r.slot = std::max(binding.gamepad, 0);
        return r;
    }
    return fail(
        target +
        ": only key:, mouse: and button: bindings can be pressed (axes are moved: '<frame> move " +
        core::printable(event.target) + " <value>')");
}

void ScriptedInput::plugIn(int slot) {
    const auto s = static_cast<std::size_t>(slot);
    if (used_[s]) {
        return;
    }
    used_[s] = true;
    changed_[s] = true;
    JoystickSnapshot& pad = pads_[s];
    pad.present = true;
    pad.gamepad = true;
    pad.guid = "00000000000000000000000000000000";
    pad.name = "e2d input script";
    pad.axes.fill(0.0f);
    pad.axes[GLFW_GAMEPAD_AXIS_LEFT_TRIGGER] = -1.0f; // released, as GLFW reports it
    pad.axes[GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER] = -1.0f;
}

bool ScriptedInput::drivesGamepads() const noexcept {
    return std::find(used_.begin(), used_.end(), true) != used_.end();
}

void ScriptedInput::feed(Input& input, std::int64_t frame) {
    for (; next_ < events_.size() && events_[next_].frame <= frame; ++next_) {
        const Resolved& e = events_[next_];
        const auto slot = static_cast<std::size_t>(e.slot);
        switch (e.kind) {
        case Resolved::Kind::Key:
            input.handleKey(e.code, 0, e.press ? GLFW_PRESS : GLFW_RELEASE, 0);
            break;
        case Resolved::Kind::Mouse:
            input.handleMouseButton(e.code, e.press ? GLFW_PRESS : GLFW_RELEASE, 0);
            break;
        case Resolved::Kind::Cursor:
            input.handleCursorPos(e.x, e.y);
            break;
        case Resolved::Kind::PadButton:
            if (const auto button = static_cast<GamepadButton>(e.code);
                button == GamepadButton::LeftTrigger || button == GamepadButton::RightTrigger) {
                const int axis = button == GamepadButton::LeftTrigger
                                     ? GLFW_GAMEPAD_AXIS_LEFT_TRIGGER
                                     : GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER;
                pads_[slot].axes[static_cast<std::size_t>(axis)] = e.press ? 1.0f : -1.0f;
            } else {
                pads_[slot].buttons[static_cast<std::size_t>(e.code)] = e.press ? 1 : 0;
            }
            changed_[slot] = true;
            break;
        case Resolved::Kind::PadAxis:
            pads_[slot].axes[static_cast<std::size_t>(e.code)] = e.x;
            changed_[slot] = true;
            break;
        }
    }
    for (int slot = 0; slot < kMaxGamepads; ++slot) {
        if (changed_[static_cast<std::size_t>(slot)]) {
            input.handleJoystick(slot, pads_[static_cast<std::size_t>(slot)]);
            changed_[static_cast<std::size_t>(slot)] = false;
        }
    }
}

} // namespace e2d::input
