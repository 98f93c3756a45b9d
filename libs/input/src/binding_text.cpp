// SPDX-License-Identifier: MIT
// The text form of a binding (bindings files, rebinding UIs).

#include <e2d/input/actions.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/input/input.hpp>
#include <e2d/input/names.hpp>

#include <string>

namespace e2d::input {

namespace {

[[noreturn]] void fail(const std::string& what, std::string_view text) {
    throw core::Error("input::parseBinding(): " + what + " in " + core::quote(text));
}

std::string nameOf(std::string_view name, int code, const char* kind) {
    if (name.empty()) {
        throw core::Error(std::string("input::formatBinding(): ") + kind + " " +
                          std::to_string(code) + " has no name");
    }
    return std::string(name);
}

} // namespace

Binding parseBinding(std::string_view text) {
    const std::size_t colon = text.find(':');
    if (colon == std::string_view::npos) {
        fail("expected <kind>:<name> (key, keys, mouse, button, axis)", text);
    }
    std::string_view kind = text.substr(0, colon);
    std::string_view name = text.substr(colon + 1);
    int gamepad = -1;
    if (const std::size_t at = kind.find('@'); at != std::string_view::npos) {
        const std::string_view slot = kind.substr(at + 1);
        kind = kind.substr(0, at);
        if (kind != "button" && kind != "axis") {
            fail("a gamepad slot (@N) applies to button and axis only", text);
        }
        if (slot.empty() || slot.size() > 2 ||
            slot.find_first_not_of("0123456789") != std::string_view::npos ||
            std::stoi(std::string(slot)) >= kMaxGamepads) {
            fail("gamepad slot must be 0..15, got " + core::quote(slot), text);
        }
        gamepad = std::stoi(std::string(slot));
    }
    if (name.empty()) {
        fail("missing name after ':'", text);
    }
    if (kind == "key") {
        if (auto key = keyFromName(name)) {
            return Binding::key(*key);
        }
        fail("unknown key name " + core::quote(name), text);
    }
    if (kind == "keys") {
        const std::size_t slash = name.find('/');
        if (slash == std::string_view::npos) {
            fail("expected keys:<negative>/<positive>", text);
        }
        const auto negative = keyFromName(name.substr(0, slash));
        const auto positive = keyFromName(name.substr(slash + 1));
        if (!negative) {
            fail("unknown key name " + core::quote(name.substr(0, slash)), text);
        }
        if (!positive) {
            fail("unknown key name " + core::quote(name.substr(slash + 1)), text);
        }
        return Binding::keyAxis(*negative, *positive);
    }
    if (kind == "mouse") {
        if (auto button = mouseButtonFromName(name)) {
            return Binding::mouseButton(*button);
        }
        fail("unknown mouse button name " + core::quote(name), text);
    }
    if (kind == "button") {
        if (auto button = gamepadButtonFromName(name)) {
            return Binding::gamepadButton(*button, gamepad);
        }
        fail("unknown gamepad button name " + core::quote(name), text);
    }
    if (kind == "axis") {
        const bool inverted = name.front() == '-';
        if (inverted) {
            name.remove_prefix(1);
        }
        if (auto axis = gamepadAxisFromName(name)) {
            return Binding::gamepadAxis(*axis, inverted, gamepad);
        }
        fail("unknown gamepad axis name " + core::quote(name), text);
    }
    fail("unknown binding kind " + core::quote(kind) + " (expected key, keys, mouse, button, axis)",
         text);
}

std::string formatBinding(const Binding& b) {
    // Appended, not "@" + to_string(...): GCC 12 at -O3 warns (-Wrestrict) about the
    // operator+ form, a false positive.
    std::string slot;
    if (b.gamepad >= 0) {
        slot.append("@").append(std::to_string(b.gamepad));
    }
    switch (b.kind) {
    case BindingKind::Key:
        return "key:" + nameOf(keyName(Key(b.code)), b.code, "key");
    case BindingKind::KeyAxis:
        return "keys:" + nameOf(keyName(Key(b.negativeKey)), b.negativeKey, "key") + "/" +
               nameOf(keyName(Key(b.code)), b.code, "key");
    case BindingKind::MouseButton:
        return "mouse:" + nameOf(mouseButtonName(MouseButton(b.code)), b.code, "mouse button");
    case BindingKind::GamepadButton:
        return "button" + slot + ":" +
               nameOf(gamepadButtonName(GamepadButton(b.code)), b.code, "gamepad button");
    case BindingKind::GamepadAxis:
        return "axis" + slot + ":" + (b.inverted ? "-" : "") +
               nameOf(gamepadAxisName(GamepadAxis(b.code)), b.code, "gamepad axis");
    }
    throw core::Error("input::formatBinding(): unknown binding kind");
}

} // namespace e2d::input
