// SPDX-License-Identifier: MIT
// Named actions: bindings, per-frame evaluation, rebinding by listening.
#include "action_name.hpp"

#include <e2d/input/actions.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/input/input.hpp>

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

namespace e2d::input {

namespace {

// Problem with a binding's codes, or empty.
std::string checkBinding(const Binding& b) {
    const auto key = [](int k) { return k >= 0 && k <= kKeyLast; };
    switch (b.kind) {
    case BindingKind::Key:
        return key(b.code) ? "" : "key " + std::to_string(b.code) + " out of range";
    case BindingKind::KeyAxis:
        return key(b.code) && key(b.negativeKey) ? "" : "key pair out of range";
    case BindingKind::MouseButton:
        return b.code >= 0 && b.code < kMouseButtonCount
                   ? ""
                   : "mouse button " + std::to_string(b.code) + " out of range";
    case BindingKind::GamepadButton:
    case BindingKind::GamepadAxis: {
        const int count =
            b.kind == BindingKind::GamepadButton ? kGamepadButtonCount : kGamepadAxisCount;
        if (b.code < 0 || b.code >= count) {
            return "gamepad code " + std::to_string(b.code) + " out of range";
        }
        return b.gamepad >= -1 && b.gamepad < kMaxGamepads
                   ? ""
                   : "gamepad slot " + std::to_string(b.gamepad) + " out of range";
    }
    }
    return "unknown binding kind";
}

} // namespace

ActionMap::ActionMap(ActionMapDef def) : def_(def) {
    if (!(def_.pressThreshold > 0.0f && def_.pressThreshold <= 1.0f)) {
        throw core::Error("input::ActionMap::ActionMap(): pressThreshold must be in (0, 1], got " +
                          core::formatNumber(def_.pressThreshold));
    }
    if (!(def_.listenAxisThreshold > 0.0f && def_.listenAxisThreshold <= 1.0f)) {
        throw core::Error(
            "input::ActionMap::ActionMap(): listenAxisThreshold must be in (0, 1], got " +
            core::formatNumber(def_.listenAxisThreshold));
    }
}

ActionId ActionMap::add(std::string_view name) {
    if (!detail::isActionName(name)) {
        throw core::Error("input::ActionMap::add(): " + std::string(detail::kActionNameRule) +
                          ", got " + core::quote(name));
    }
    if (!find(name).isNull()) {
        throw core::Error("input::ActionMap::add(): action '" + std::string(name) +
                          "' already exists");
    }
    actions_.push_back(Action{std::string(name), {}, 0.0f, false, false, false});
    return ActionId::forSlot(static_cast<std::uint32_t>(actions_.size() - 1));
}

ActionId ActionMap::find(std::string_view name) const noexcept {
    for (std::size_t i = 0; i < actions_.size(); ++i) {
        if (actions_[i].name == name) {
            return ActionId::forSlot(static_cast<std::uint32_t>(i));
        }
    }
    return {};
}

ActionId ActionMap::findOrAdd(std::string_view name) {
    const ActionId id = find(name);
    return id.isNull() ? add(name) : id;
}

const ActionMap::Action& ActionMap::at(ActionId id, const char* function) const {
    const std::optional<std::uint32_t> index = core::slotOf(id, actions_.size());
    if (!index) {
        throw core::Error(std::string("input::ActionMap::") + function + "(): no action with id " +
                          std::to_string(id.index1));
    }
    return actions_[*index];
}

ActionMap::Action& ActionMap::at(ActionId id, const char* function) {
    return const_cast<Action&>(std::as_const(*this).at(id, function));
}

ActionId ActionMap::require(std::string_view name, const char* function) const {
    const ActionId id = find(name);
    if (id.isNull()) {
        throw core::Error(std::string("input::ActionMap::") + function + "(): no action named " +
                          core::quote(name));
    }
    return id;
}

const std::string& ActionMap::name(ActionId id) const { return at(id, "name").name; }

void ActionMap::bind(ActionId id, const Binding& binding) {
    Action& action = at(id, "bind");
    if (std::string problem = checkBinding(binding); !problem.empty()) {
        throw core::Error("input::ActionMap::bind(): " + problem);
    }
    if (std::find(action.bindings.begin(), action.bindings.end(), binding) ==
        action.bindings.end()) {
        action.bindings.push_back(binding);
    }
}

void ActionMap::clearBindings(ActionId id) { at(id, "clearBindings").bindings.clear(); }

std::span<const Binding> ActionMap::bindings(ActionId id) const {
    return at(id, "bindings").bindings;
}

bool ActionMap::pressed(ActionId id) const { return at(id, "pressed").pressed; }

bool ActionMap::held(ActionId id) const { return at(id, "held").held; }

bool ActionMap::released(ActionId id) const { return at(id, "released").released; }

float ActionMap::value(ActionId id) const { return at(id, "value").value; }

// Evaluation ---------------------------------------------------------------------------------

void ActionMap::evaluate(Action& action, const Input& input) const {
    float value = 0.0f;
    bool digitalDown = false;
    bool tapped = false; // a digital binding went down during this frame
    const auto offer = [&](float v) {
        if (std::abs(v) > std::abs(value)) {
            value = v;
        }
    };
    const auto padRange = [](int gamepad, int& first, int& last) {
        first = gamepad < 0 ? 0 : gamepad;
        last = gamepad < 0 ? kMaxGamepads - 1 : gamepad;
    };
    for (const Binding& b : action.bindings) {
        switch (b.kind) {
        case BindingKind::Key:
            if (input.isKeyDown(Key(b.code))) {
                digitalDown = true;
                offer(1.0f);
            }
            tapped = tapped || input.wasKeyPressed(Key(b.code));
            break;
        case BindingKind::MouseButton:
            if (input.isMouseButtonDown(MouseButton(b.code))) {
                digitalDown = true;
                offer(1.0f);
            }
            tapped = tapped || input.wasMouseButtonPressed(MouseButton(b.code));
            break;
        case BindingKind::KeyAxis: {
            const Key positive{b.code};
            const Key negative{b.negativeKey};
            offer((input.isKeyDown(positive) ? 1.0f : 0.0f) -
                  (input.isKeyDown(negative) ? 1.0f : 0.0f));
            if (input.isKeyDown(positive) || input.isKeyDown(negative)) {
                digitalDown = true;
            }
            tapped = tapped || input.wasKeyPressed(positive) || input.wasKeyPressed(negative);
        } break;
        case BindingKind::GamepadButton: {
            int first = 0;
            int last = 0;
            padRange(b.gamepad, first, last);
            for (int pad = first; pad <= last; ++pad) {
                if (input.isGamepadButtonDown(pad, GamepadButton(b.code))) {
                    digitalDown = true;
                    offer(1.0f);
                }
                tapped = tapped || input.wasGamepadButtonPressed(pad, GamepadButton(b.code));
            }
            break;
        }
        case BindingKind::GamepadAxis: {
            int first = 0;
            int last = 0;
            padRange(b.gamepad, first, last);
            for (int pad = first; pad <= last; ++pad) {
                const float v = input.gamepadAxis(pad, GamepadAxis(b.code));
                offer(b.inverted ? -v : v);
            }
            break;
        }
        }
    }
    const bool wasHeld = action.held;
    const bool held = digitalDown || std::abs(value) >= def_.pressThreshold;
    action.value = std::clamp(value, -1.0f, 1.0f);
    action.held = held;
    action.pressed = !wasHeld && (held || tapped);
    action.released = (wasHeld && !held) || (!wasHeld && !held && tapped);
}

void ActionMap::update(const Input& input) {
    if (listening()) {
        listenStep(input);
    }
    for (Action& action : actions_) {
        evaluate(action, input);
    }
}

void ActionMap::listen(ActionId id, ListenMode mode) {
    static_cast<void>(at(id, "listen"));
    listening_ = id;
    listenMode_ = mode;
    captured_.reset();
}

void ActionMap::listenStep(const Input& input) {
    std::optional<Binding> found;
    for (const Event& e : input.events()) {
        switch (e.type) {
        case EventType::KeyDown:
            if (def_.listenCancelKey != Key::Unknown && Key(e.code) == def_.listenCancelKey) {
                cancelListen();
                return;
            }
            if (e.code >= 0 && e.code <= kKeyLast) {
                found = Binding::key(Key(e.code));
            }
            break;
        case EventType::MouseButtonDown:
            if (e.code >= 0 && e.code < kMouseButtonCount) {
                found = Binding::mouseButton(MouseButton(e.code));
            }
            break;
        case EventType::GamepadButtonDown:
            found = Binding::gamepadButton(GamepadButton(e.code));
            break;
        case EventType::GamepadAxis:
            if (std::abs(e.value) >= def_.listenAxisThreshold) {
                found = Binding::gamepadAxis(GamepadAxis(e.code), e.value < 0.0f);
            }
            break;
        default:
            break;
        }
        if (found) {
            break;
        }
    }
    if (!found) {
        return;
    }
    Action& action = actions_[listening_.index()];
    if (listenMode_ == ListenMode::Replace) {
        action.bindings.clear();
    }
    if (std::find(action.bindings.begin(), action.bindings.end(), *found) ==
        action.bindings.end()) {
        action.bindings.push_back(*found);
    }
    captured_ = found;
    listening_ = {};
}

} // namespace e2d::input
