// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace e2d::engine {

/// Timed presses, releases and moves that a Game feeds to its Input as if they were typed,
/// clicked or pushed on a gamepad, for tests, recorded demos and reproducible runs
/// (`--input-script FILE`).
///
/// Format, one event per line; blank lines and lines starting with `#` are ignored:
///
///     <frame> <press|release|tap> <target>
///     <frame> move mouse <x> <y>
///     <frame> move <axis binding> <value>
///
/// - `frame`: the frame (0 is the game's first frame) at whose start the event is delivered;
///   whole number >= 0. Lines may come in any order; events of one frame keep their order.
/// - `press` holds the input down, `release` lets it go, `tap` presses it at `frame` and
///   releases it at `frame + 1`.
/// - `target`: an action name of the game's ActionMap (its first keyboard or mouse-button
///   binding is pressed: the scene sees the events, the action map its value), or a binding
///   in the bindings-file text form: `key:space`, `mouse:left`, `button:a`, `button@1:start`
///   (a gamepad button, triggers included; without `@` gamepad slot 0).
/// - `move mouse <x> <y>`: the cursor goes to window pixel (x, y), from the window's top-left
///   corner, y down (as GLFW reports it; scenes get the world position through the camera).
///   A click at a place is a move and a tap on the same frame: `30 move mouse 900 200` then
///   `30 tap mouse:left`.
/// - `move axis:<name> <value>` (`axis@<slot>:<name>`, `axis:-<name>` inverted): a gamepad
///   axis is held at `value` from that frame on, as the pad reports it before its dead zone:
///   sticks in [-1, 1] (y down, as GLFW's), triggers in [0, 1] (0 released). The axis names
///   are the bindings files' (leftx, lefty, rightx, righty, lefttrigger, righttrigger).
///
/// A script that uses a gamepad (a button or axis target) plugs in a scripted gamepad in each
/// slot it names, connected from frame 0 (name "e2d input script"), and the real joysticks
/// are not read during that run.
///
/// With `--frames N` every frame lasts exactly 1/60 s, so frame numbers are game time:
/// frame 120 is t = 2 s.
struct ScriptEvent {
    enum class Kind { Press, Release, Move };
    std::int64_t frame = 0;
    Kind kind = Kind::Press;
    /// As written (action name, binding text, or `mouse` for a cursor move).
    std::string target;
    /// Line in the script, for messages.
    int line = 0;
    /// Move: the cursor position (x, y) or the axis value (x).
    float x = 0.0f;
    float y = 0.0f;
};

/// A parsed script: events sorted by frame (stable: a frame's events keep their line order).
struct InputScript {
    std::string source;
    std::vector<ScriptEvent> events;
};

/// Parses script text; throws core::Error "<source>:<line>: <what is wrong>" for a malformed
/// line (`"s.txt:3: expected '<frame> <press|release|tap> <target>', got 'jump'"`,
/// `"s.txt:4: move mouse: expected '<x> <y>' in window pixels, got '12'"`).
[[nodiscard]] InputScript parseInputScript(std::string_view text, std::string_view source = "<script>");
/// Reads and parses the file; throws core::Error naming the file if it cannot be read.
[[nodiscard]] InputScript loadInputScript(const std::filesystem::path& path);

} // namespace e2d::engine
