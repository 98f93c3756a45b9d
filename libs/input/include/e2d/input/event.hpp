// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec2.hpp>

#include <cstdint>
#include <string_view>

namespace e2d::input {

/// Modifier bits of key and mouse button events (GLFW's GLFW_MOD_* values).
enum Mod : int {
    kModShift = 0x01,
    kModControl = 0x02,
    kModAlt = 0x04,
    kModSuper = 0x08,
    kModCapsLock = 0x10,
    kModNumLock = 0x20,
};

/// What happened. Window events come from GLFW's callbacks in the order GLFW reported them;
/// gamepad events come from polling at the start of the frame, after the window events.
enum class EventType : std::uint8_t {
    KeyDown,          ///< `code` key, `scancode`, `mods`
    KeyUp,            ///< `code` key, `scancode`, `mods`
    KeyRepeat,        ///< `code` key held long enough for the system's auto-repeat
    Text,             ///< `code` a Unicode code point (UTF-32)
    MouseButtonDown,  ///< `code` button, `mods`, `screen`/`world` cursor position
    MouseButtonUp,    ///< same
    MouseMove,        ///< `screen`/`world` new position, `delta` motion in pixels
    Scroll,           ///< `delta` scroll offset (y > 0 away from the user), `screen`/`world`
    FocusGained,      ///< the window got keyboard focus
    FocusLost,        ///< the window lost it; every held key and button was released before it
    GamepadConnected, ///< `gamepad` slot now has a joystick with a gamepad mapping
    GamepadDisconnected, ///< `gamepad` slot lost it (held buttons released before it)
    GamepadButtonDown,   ///< `gamepad`, `code` button (names.hpp; 15/16 are the triggers)
    GamepadButtonUp,     ///< same
    GamepadAxis,         ///< `gamepad`, `code` axis, `value` after dead zone
    JoystickConnected,   ///< `gamepad` slot has a joystick, mapped or not (see Input::joysticks())
    JoystickDisconnected, ///< the joystick of `gamepad` slot went away
};

/// Name of an event type ("KeyDown", ...), for logs and tests.
[[nodiscard]] std::string_view toString(EventType type) noexcept;

/// One input event. Fields that do not apply to the type are zero (gamepad: -1).
struct Event {
    EventType type = EventType::KeyDown;
    /// Key, mouse button, gamepad button or axis; code point for Text.
    int code = 0;
    /// Platform scancode of a key event.
    int scancode = 0;
    /// Modifier bits (Mod) of key and mouse button events.
    int mods = 0;
    /// Gamepad / joystick slot, 0..15; -1 for window events.
    int gamepad = -1;
    /// GamepadAxis: sticks in [-1, 1] after the radial dead zone, triggers in [0, 1].
    float value = 0.0f;
    /// Cursor position in window pixels (origin top left) for mouse events.
    glm::vec2 screen{0.0f};
    /// Same in world units (InputDef::screenToWorld; equal to `screen` without a converter).
    glm::vec2 world{0.0f};
    /// MouseMove: motion since the previous position, pixels. Scroll: the offset.
    glm::vec2 delta{0.0f};
};

} // namespace e2d::input
