// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace e2d::input {

/// A line of a mapping text that could not be used.
struct MappingError {
    /// 1-based line number in the text or file.
    int line = 0;
    /// `"<source>:<line>: <what is wrong>"`, e.g.
    /// `"pads.txt:3: unknown field 'zz' (expected an SDL gamepad field such as a, leftx, platform)"`.
    std::string message;
};

/// What a mapping text held.
struct MappingParseResult {
    /// The well-formed lines for this platform (Linux, or no platform field), ready for GLFW.
    std::vector<std::string> lines;
    /// Well-formed lines for another platform (not loaded; not an error).
    int otherPlatform = 0;
    /// Malformed lines, in order.
    std::vector<MappingError> errors;
};

/// Checks an SDL-format gamepad mapping text (the gamecontrollerdb.txt format) line by line,
/// without GLFW. Each line is `GUID,name,field:element,...`: a GUID of 32 hex digits, a name
/// (at most 127 bytes), then fields named as in SDL (a, b, x, y, back, guide, start,
/// leftstick, rightstick, leftshoulder, rightshoulder, dpup, dpdown, dpleft, dpright, leftx,
/// lefty, rightx, righty, lefttrigger, righttrigger; misc1, paddle1-4, touchpad, which GLFW
/// ignores; platform; crc, hint, sdk>= and sdk<=, which are passed on) whose elements are `bN`
/// (button), `hH.B` (hat H, bit 1/2/4/8) or `aN` (axis) with an optional `+`/`-` half-axis
/// prefix and `~` inversion suffix. Empty lines and lines starting with `#` are skipped. A line
/// must be shorter than 1024 bytes (GLFW's limit). `source` names the text in messages.
///
/// Why not simply hand the text to GLFW: `glfwUpdateGamepadMappings` returns true whatever the
/// text holds, drops some bad lines with only an error callback, and silently accepts others
/// (an unknown field, an element like `q0`, an index above 255 wraps).
[[nodiscard]] MappingParseResult parseGamepadMappings(std::string_view text, std::string_view source = "<string>");

/// What loading a mapping text did.
struct MappingLoadResult {
    /// Lines handed to GLFW and accepted (a mapping for a GUID GLFW already had replaces it).
    int loaded = 0;
    /// Well-formed lines for another platform, skipped.
    int otherPlatform = 0;
    /// Malformed lines; the good lines loaded anyway.
    std::vector<MappingError> errors;
    [[nodiscard]] bool ok() const noexcept { return errors.empty(); }
};

/// Checks `text` with parseGamepadMappings() and gives the good lines to
/// `glfwUpdateGamepadMappings` (GLFW's database, shared by every window and Input: a joystick
/// that becomes mapped is reported as GamepadConnected at the next frame). Needs an
/// initialised GLFW: throws core::Error otherwise
/// (`"input::loadGamepadMappings(): GLFW is not initialised"`).
MappingLoadResult loadGamepadMappings(std::string_view text, std::string_view source = "<string>");
/// Same with the text of a file; throws core::Error naming the file if it cannot be read.
MappingLoadResult loadGamepadMappingsFile(const std::filesystem::path& path);

/// A mapping line for a joystick known only by GUID and name (JoystickInfo), so an unmapped
/// joystick can be mapped at run time: `fields` is the part after the name, e.g.
/// `"a:b0,b:b1,leftx:a0,lefty:a1"`. Throws core::Error when the result is not a valid line
/// (the message names the problem as parseGamepadMappings() would).
[[nodiscard]] std::string makeGamepadMapping(std::string_view guid, std::string_view name, std::string_view fields);

} // namespace e2d::input
