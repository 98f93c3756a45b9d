// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace e2d::engine {

/// Timed presses and releases that a Game feeds to its Input as if they were typed, for
/// tests, recorded demos and reproducible runs (`--input-script FILE`).
///
/// Format, one event per line; blank lines and lines starting with `#` are ignored:
///
///     <frame> <press|release|tap> <target>
///
/// - `frame`: the frame (0 is the game's first frame) at whose start the event is delivered;
///   whole number >= 0. Lines may come in any order; events of one frame keep their order.
/// - `press` holds the input down, `release` lets it go, `tap` presses it at `frame` and
///   releases it at `frame + 1`.
/// - `target`: an action name of the game's ActionMap (its first keyboard or mouse-button
///   binding is pressed: the scene sees the key events, the action map its value), or a
///   binding in the bindings-file text form, `key:space` or `mouse:left`.
///
/// With `--frames N` every frame lasts exactly 1/60 s, so frame numbers are game time:
/// frame 120 is t = 2 s.
struct ScriptEvent {
    enum class Kind { Press, Release };
    std::int64_t frame = 0;
    Kind kind = Kind::Press;
    /// As written (action name or binding text).
    std::string target;
    /// Line in the script, for messages.
    int line = 0;
};

/// A parsed script: events sorted by frame (stable: a frame's events keep their line order).
struct InputScript {
    std::string source;
    std::vector<ScriptEvent> events;
};

/// Parses script text; throws core::Error "<source>:<line>: <what is wrong>" for a malformed
/// line (`"s.txt:3: expected '<frame> <press|release|tap> <target>', got 'jump'"`).
[[nodiscard]] InputScript parseInputScript(std::string_view text, std::string_view source = "<script>");
/// Reads and parses the file; throws core::Error naming the file if it cannot be read.
[[nodiscard]] InputScript loadInputScript(const std::filesystem::path& path);

} // namespace e2d::engine
