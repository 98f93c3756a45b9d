// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/input/input.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace e2d::input {

class ActionMap;

/// Timed presses, releases and moves played into an Input as if they were typed, clicked or
/// pushed on a gamepad, for tests, recorded demos and reproducible runs (a Game's
/// `--input-script FILE`).
///
/// Format, one event per line; blank lines and lines starting with `#` are ignored:
///
///     <frame> <press|release|tap> <target>
///     <frame> move mouse <x> <y>
///     <frame> move <axis binding> <value>
///
/// - `frame`: the frame (0 is the first frame played) at whose start the event is delivered;
///   a whole number in [0, kMaxScriptFrame]. Lines may come in any order; events of one frame
///   keep their order.
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
/// are not read while it plays.
///
/// With a Game's `--frames N` every frame lasts exactly 1/60 s, so frame numbers are game
/// time: frame 120 is t = 2 s.
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

/// The last frame a script may name: 10^9 frames, over 190 days at 60 frames per second (so a
/// tap's release, one frame later, cannot overflow).
inline constexpr std::int64_t kMaxScriptFrame = 1'000'000'000;

/// A parsed script: events sorted by frame (stable: a frame's events keep their line order).
struct InputScript {
    std::string source;
    std::vector<ScriptEvent> events;
};

/// Parses script text; throws core::Error "<source>:<line>: <what is wrong>" for a malformed
/// line (`"s.txt:3: expected '<frame> <press|release|tap> <target>', got 'jump'"`,
/// `"s.txt:4: move mouse: expected '<x> <y>' in window pixels, got '12'"`, `"s.txt:5: frame
/// must be a whole number in [0, 1000000000], got '9223372036854775807'"`). Bytes that are not
/// printable are quoted escaped (`\x01`).
[[nodiscard]] InputScript parseInputScript(std::string_view text,
                                           std::string_view source = "<script>");
/// Reads and parses the file; throws core::Error naming the file if it cannot be read.
[[nodiscard]] InputScript loadInputScript(const std::filesystem::path& path);

/// An input script as a device: its events go into an Input's queue through the same entry
/// points as a window's callbacks and a joystick poll, so scenes, polling and actions see
/// them exactly as they see real input. Give it to `Input::play()`.
class ScriptedInput {
public:
    /// Resolves every event's target (action names through `actions`, which is read now and
    /// not kept). Throws core::Error "<source>:<line>: <why>" for a target that cannot be
    /// played: an unknown action or binding, an action with no key or mouse-button binding, an
    /// axis that is pressed, a trigger moved below 0.
    ScriptedInput(const InputScript& script, const ActionMap& actions);

    /// True when the script names a gamepad button or axis (the real joysticks are then not
    /// read while it plays).
    [[nodiscard]] bool drivesGamepads() const noexcept;
    /// Queues into `input` every event of frames up to `frame` not fed yet, then the state of
    /// the scripted gamepads that changed. Input::beginFrame() calls it with its frame count.
    void feed(Input& input, std::int64_t frame);
    /// True once every event was fed.
    [[nodiscard]] bool finished() const noexcept { return next_ == events_.size(); }

private:
    /// A scripted event resolved to what is pressed or moved.
    struct Resolved {
        enum class Kind { Key, Mouse, PadButton, PadAxis, Cursor };
        std::int64_t frame = 0;
        Kind kind = Kind::Key;
        bool press = false;
        int code = 0;
        /// PadButton, PadAxis: the gamepad slot.
        int slot = 0;
        /// Cursor: the position; PadAxis: the value in GLFW's range (x).
        float x = 0.0f;
        float y = 0.0f;
    };

    static Resolved resolve(const ScriptEvent& event, const InputScript& script,
                            const ActionMap& actions);
    void plugIn(int slot);

    std::vector<Resolved> events_;
    std::size_t next_ = 0;
    std::array<JoystickSnapshot, kMaxGamepads> pads_{};
    std::array<bool, kMaxGamepads> used_{};
    std::array<bool, kMaxGamepads> changed_{};
};

} // namespace e2d::input
