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

/// A keyboard key: GLFW's key codes under readable names (`Key::Space` is GLFW_KEY_SPACE, 32),
/// so `static_cast<Key>(GLFW_KEY_A)` and `static_cast<int>(Key::A)` convert both ways. Keys
/// GLFW does not know arrive as `Unknown`.
enum class Key : int {
    Unknown = -1,
    Space = 32,
    Apostrophe = 39,
    Comma = 44,
    Minus = 45,
    Period = 46,
    Slash = 47,
    Num0 = 48,
    Num1 = 49,
    Num2 = 50,
    Num3 = 51,
    Num4 = 52,
    Num5 = 53,
    Num6 = 54,
    Num7 = 55,
    Num8 = 56,
    Num9 = 57,
    Semicolon = 59,
    Equal = 61,
    A = 65,
    B = 66,
    C = 67,
    D = 68,
    E = 69,
    F = 70,
    G = 71,
    H = 72,
    I = 73,
    J = 74,
    K = 75,
    L = 76,
    M = 77,
    N = 78,
    O = 79,
    P = 80,
    Q = 81,
    R = 82,
    S = 83,
    T = 84,
    U = 85,
    V = 86,
    W = 87,
    X = 88,
    Y = 89,
    Z = 90,
    LeftBracket = 91,
    Backslash = 92,
    RightBracket = 93,
    GraveAccent = 96,
    World1 = 161,
    World2 = 162,
    Escape = 256,
    Enter = 257,
    Tab = 258,
    Backspace = 259,
    Insert = 260,
    Delete = 261,
    Right = 262,
    Left = 263,
    Down = 264,
    Up = 265,
    PageUp = 266,
    PageDown = 267,
    Home = 268,
    End = 269,
    CapsLock = 280,
    ScrollLock = 281,
    NumLock = 282,
    PrintScreen = 283,
    Pause = 284,
    F1 = 290,
    F2 = 291,
    F3 = 292,
    F4 = 293,
    F5 = 294,
    F6 = 295,
    F7 = 296,
    F8 = 297,
    F9 = 298,
    F10 = 299,
    F11 = 300,
    F12 = 301,
    F13 = 302,
    F14 = 303,
    F15 = 304,
    F16 = 305,
    F17 = 306,
    F18 = 307,
    F19 = 308,
    F20 = 309,
    F21 = 310,
    F22 = 311,
    F23 = 312,
    F24 = 313,
    F25 = 314,
    Keypad0 = 320,
    Keypad1 = 321,
    Keypad2 = 322,
    Keypad3 = 323,
    Keypad4 = 324,
    Keypad5 = 325,
    Keypad6 = 326,
    Keypad7 = 327,
    Keypad8 = 328,
    Keypad9 = 329,
    KeypadDecimal = 330,
    KeypadDivide = 331,
    KeypadMultiply = 332,
    KeypadSubtract = 333,
    KeypadAdd = 334,
    KeypadEnter = 335,
    KeypadEqual = 336,
    LeftShift = 340,
    LeftControl = 341,
    LeftAlt = 342,
    LeftSuper = 343,
    RightShift = 344,
    RightControl = 345,
    RightAlt = 346,
    RightSuper = 347,
    Menu = 348,
};

/// A mouse button (GLFW's 0..7).
enum class MouseButton : int {
    Left = 0,
    Right = 1,
    Middle = 2,
    Button4 = 3,
    Button5 = 4,
    Button6 = 5,
    Button7 = 6,
    Button8 = 7,
};

/// A gamepad button in SDL's layout (GLFW's gamepad buttons 0..14), plus the two triggers
/// as buttons, pressed when their axis passes `InputDef::triggerPressThreshold`.
enum class GamepadButton : int {
    A = 0, ///< bottom face button (Xbox A, PlayStation cross)
    B = 1, ///< right face button
    X = 2, ///< left face button
    Y = 3, ///< top face button
    LeftBumper = 4,
    RightBumper = 5,
    Back = 6,
    Start = 7,
    Guide = 8,
    LeftThumb = 9,
    RightThumb = 10,
    DpadUp = 11,
    DpadRight = 12,
    DpadDown = 13,
    DpadLeft = 14,
    LeftTrigger = 15,
    RightTrigger = 16,
};

/// A gamepad axis (GLFW's): sticks in [-1, 1] (y down is positive), triggers in [0, 1].
enum class GamepadAxis : int {
    LeftX = 0,
    LeftY = 1,
    RightX = 2,
    RightY = 3,
    LeftTrigger = 4,
    RightTrigger = 5,
};

// The events InputSystem delivers to the current scene once per frame, in the order they
// happened (Scene::dispatch). A scene or component takes those it wants with core::Handles:
//
//     class Player : public core::Component, public core::Handles<input::KeyDown> {
//         void on(const input::KeyDown& e) override { if (e.key == input::Key::Space) jump(); }
//     };

/// What the key events carry. `mods` are Mod bits; `scancode` is the platform's.
struct KeyEvent {
    Key key = Key::Unknown;
    int scancode = 0;
    int mods = 0;
};
/// A key was pressed.
struct KeyDown : KeyEvent {};
/// A key was released.
struct KeyUp : KeyEvent {};
/// A held key auto-repeated (only with InputSystemDef::keyRepeat).
struct KeyRepeat : KeyEvent {};
/// Text was typed: one Unicode code point (UTF-32), after keyboard layout and modifiers.
struct TextEntered {
    char32_t codepoint = 0;
};
/// What the mouse button events carry: the button, Mod bits, and the cursor at `screen`
/// (pixels, origin top left) / `world` (world units).
struct MouseButtonEvent {
    MouseButton button = MouseButton::Left;
    int mods = 0;
    glm::vec2 screen{0.0f};
    glm::vec2 world{0.0f};
};
/// A mouse button was pressed.
struct MouseButtonDown : MouseButtonEvent {};
/// A mouse button was released.
struct MouseButtonUp : MouseButtonEvent {};
/// The cursor moved to `screen` / `world`, by `delta` pixels.
struct MouseMoved {
    glm::vec2 screen{0.0f};
    glm::vec2 world{0.0f};
    glm::vec2 delta{0.0f};
};
/// The wheel or touchpad scrolled by `offset` (y > 0 away from the user), cursor at
/// `screen` / `world`.
struct MouseScrolled {
    glm::vec2 offset{0.0f};
    glm::vec2 screen{0.0f};
    glm::vec2 world{0.0f};
};
/// The window gained keyboard focus.
struct FocusGained {};
/// The window lost it; every held key and button was released (with the usual up events)
/// before it.
struct FocusLost {};
/// A gamepad was connected in slot `gamepad` (0..15).
struct GamepadConnected {
    int gamepad = 0;
};
/// The gamepad in slot `gamepad` went away (its held buttons released before it).
struct GamepadDisconnected {
    int gamepad = 0;
};
/// What the gamepad button events carry: the slot (0..15) and the button.
struct GamepadButtonEvent {
    int gamepad = 0;
    GamepadButton button = GamepadButton::A;
};
/// A gamepad button was pressed.
struct GamepadButtonDown : GamepadButtonEvent {};
/// A gamepad button was released.
struct GamepadButtonUp : GamepadButtonEvent {};
/// A gamepad axis changed to `value` (after the dead zone).
struct GamepadAxisMoved {
    int gamepad = 0;
    GamepadAxis axis = GamepadAxis::LeftX;
    float value = 0.0f;
};

/// What the queue of Input::events() records (InputSystem turns each into one of the event
/// structs above). Window events come from GLFW's callbacks in the order GLFW reported them;
/// gamepad events come from polling at the start of the frame, after the window events.
enum class EventType : std::uint8_t {
    KeyDown,              ///< `code` key, `scancode`, `mods`
    KeyUp,                ///< `code` key, `scancode`, `mods`
    KeyRepeat,            ///< `code` key held long enough for the system's auto-repeat
    Text,                 ///< `code` a Unicode code point (UTF-32)
    MouseButtonDown,      ///< `code` button, `mods`, `screen`/`world` cursor position
    MouseButtonUp,        ///< same
    MouseMove,            ///< `screen`/`world` new position, `delta` motion in pixels
    Scroll,               ///< `delta` scroll offset (y > 0 away from the user), `screen`/`world`
    FocusGained,          ///< the window got keyboard focus
    FocusLost,            ///< the window lost it; every held key and button was released before it
    GamepadConnected,     ///< `gamepad` slot now has a joystick with a gamepad mapping
    GamepadDisconnected,  ///< `gamepad` slot lost it (held buttons released before it)
    GamepadButtonDown,    ///< `gamepad`, `code` button (names.hpp; 15/16 are the triggers)
    GamepadButtonUp,      ///< same
    GamepadAxis,          ///< `gamepad`, `code` axis, `value` after dead zone
    JoystickConnected,    ///< `gamepad` slot has a joystick, mapped or not (see Input::joysticks())
    JoystickDisconnected, ///< the joystick of `gamepad` slot went away
};

/// Name of an event type ("KeyDown", ...), for logs and tests.
[[nodiscard]] std::string_view toString(EventType type) noexcept;

/// One recorded input event, as Input queues it. Fields that do not apply to the type are zero
/// (gamepad: -1).
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
