// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/input/event.hpp>

#include <optional>
#include <string_view>

namespace e2d::input {

/// The names of keys, mouse buttons, gamepad buttons and axes (event.hpp's enums, whose values
/// are GLFW's codes) in config files, bindings and input scripts.

/// Number of gamepad buttons Input tracks: GLFW's 15 plus the two triggers.
inline constexpr int kGamepadButtonCount = 17;
/// Number of gamepad axes (GLFW's: left x, left y, right x, right y, left trigger, right trigger).
inline constexpr int kGamepadAxisCount = 6;
/// Number of mouse buttons (GLFW's 8).
inline constexpr int kMouseButtonCount = 8;
/// Highest key code (GLFW_KEY_LAST, "menu").
inline constexpr int kKeyLast = 348;

/// The config-file name of a key: lower case GLFW names without the prefix ("space", "a",
/// "left_shift", "kp_enter", "f12"). Empty for a code that is not a key.
[[nodiscard]] std::string_view keyName(Key key) noexcept;
/// The key of a name (case-insensitive), or nullopt for an unknown name.
[[nodiscard]] std::optional<Key> keyFromName(std::string_view name) noexcept;

/// "left", "right", "middle", "button4" ... "button8"; empty if out of range.
[[nodiscard]] std::string_view mouseButtonName(MouseButton button) noexcept;
/// Case-insensitive; also accepts "button1" ... "button8".
[[nodiscard]] std::optional<MouseButton> mouseButtonFromName(std::string_view name) noexcept;

/// SDL names, as in mapping strings: "a", "b", "x", "y", "leftshoulder", "rightshoulder",
/// "back", "start", "guide", "leftstick", "rightstick", "dpup", "dpright", "dpdown", "dpleft",
/// plus "lefttrigger" and "righttrigger" for the two trigger buttons. Empty if out of range.
[[nodiscard]] std::string_view gamepadButtonName(GamepadButton button) noexcept;
[[nodiscard]] std::optional<GamepadButton> gamepadButtonFromName(std::string_view name) noexcept;

/// "leftx", "lefty", "rightx", "righty", "lefttrigger", "righttrigger". Empty if out of range.
[[nodiscard]] std::string_view gamepadAxisName(GamepadAxis axis) noexcept;
[[nodiscard]] std::optional<GamepadAxis> gamepadAxisFromName(std::string_view name) noexcept;

} // namespace e2d::input
