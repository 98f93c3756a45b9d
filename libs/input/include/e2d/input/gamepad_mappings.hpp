// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/diagnostics.hpp>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace e2d::input {

/// What a mapping text held.
struct MappingParseResult {
    /// The usable lines for this platform (Linux, or no platform field), as handed to GLFW:
    /// GUID, name, then each field GLFW can use followed by ','.
    std::vector<std::string> lines;
    /// Lines for another platform (not loaded, not checked further; not an error).
    int otherPlatform = 0;
    /// Lines that cannot be used (errors) and lines used without a part GLFW cannot take
    /// (warnings: output modifiers such as `+leftx:h0.2`, left out; unknown fields, ignored as
    /// GLFW ignores them), in line order, each with its line:
    /// `"pads.txt:3: field 'a': expected bN, aN or hH.B, got 'q0'"`.
    core::Diagnostics diagnostics;
};

/// Checks an SDL-format gamepad mapping text (the gamecontrollerdb.txt format) line by line,
/// without GLFW. Each line is `GUID,name,field:element,...`: a GUID of 32 hex digits, a name
/// (at most 127 bytes), then fields named as in SDL (a, b, x, y, back, guide, start,
/// leftstick, rightstick, leftshoulder, rightshoulder, dpup, dpdown, dpleft, dpright, leftx,
/// lefty, rightx, righty, lefttrigger, righttrigger; misc1-6, paddle1-4, touchpad, which GLFW
/// ignores; platform; crc, hint, sdk>= and sdk<=, which are passed on) whose elements are `bN`
/// (button), `hH.B` (hat H, bit 1/2/4/8) or `aN` (axis) with an optional `+`/`-` half-axis
/// prefix and `~` inversion suffix. Empty lines and lines starting with `#` are skipped, and
/// so is a UTF-8 byte order mark. A line must be shorter than 1024 bytes (GLFW's limit).
/// `source` names the text in messages.
///
/// Every mapping GLFW 3.3 can use is kept: an output modifier (`+leftx:h0.2`, a Joy-Con's stick
/// on a hat), which makes GLFW refuse the whole line, is left out of it with a warning, and an
/// unknown field (SDL adds some now and then) is ignored with a warning. Lines for another
/// platform are counted, not checked (Windows lines may name the GUID `xinput`). A text cut
/// short is seen at its last line: with no newline after it, a line without the closing ','
/// or the platform field that every line before it has is an error, not a mapping.
///
/// Why not simply hand the text to GLFW: `glfwUpdateGamepadMappings` returns true whatever the
/// text holds, drops some bad lines with only an error callback, and silently accepts others
/// (an unknown field, an element like `q0`, an index above 255 wraps).
[[nodiscard]] MappingParseResult parseGamepadMappings(std::string_view text,
                                                      std::string_view source = "<string>");

/// What loading a mapping text did.
struct MappingLoadResult {
    /// Lines handed to GLFW and accepted (a mapping for a GUID GLFW already had replaces it).
    int loaded = 0;
    /// Well-formed lines for another platform, skipped.
    int otherPlatform = 0;
    /// MappingParseResult::diagnostics: the lines in error were left out, the good lines
    /// loaded anyway.
    core::Diagnostics diagnostics;
    /// No errors (warnings allowed).
    [[nodiscard]] bool ok() const noexcept { return diagnostics.ok(); }
};

/// Checks `text` with parseGamepadMappings() and gives the good lines to
/// `glfwUpdateGamepadMappings` (GLFW's database, shared by every window and Input: a joystick
/// that becomes mapped is reported as GamepadConnected at the next frame). Needs an
/// initialised GLFW: throws core::Error otherwise
/// (`"input::loadGamepadMappings(): GLFW is not initialised"`).
MappingLoadResult loadGamepadMappings(std::string_view text, std::string_view source = "<string>");
/// Same with the text of a file; throws core::Error naming the file if it cannot be read (a
/// directory included).
MappingLoadResult loadGamepadMappingsFile(const std::filesystem::path& path);

/// A mapping line for a joystick known only by GUID and name (JoystickInfo), so an unmapped
/// joystick can be mapped at run time: `fields` is the part after the name, e.g.
/// `"a:b0,b:b1,leftx:a0,lefty:a1"`. Throws core::Error when the result is not a valid line or
/// holds a part GLFW cannot take (the message names the problem as parseGamepadMappings() would).
[[nodiscard]] std::string makeGamepadMapping(std::string_view guid, std::string_view name,
                                             std::string_view fields);

} // namespace e2d::input
