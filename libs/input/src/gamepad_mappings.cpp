// SPDX-License-Identifier: MIT
// SDL gamepad mapping lines: checked here, then handed to GLFW's database.
#include <e2d/input/gamepad_mappings.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/core/printable.hpp>
#include <e2d/core/text_file.hpp>

#include <GLFW/glfw3.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <vector>

namespace e2d::input {

namespace {

// GLFW keeps a line only if it is shorter than its 1024-byte buffer and a name shorter than 128.
constexpr std::size_t kMaxLine = 1023;
constexpr std::size_t kMaxName = 127;

constexpr std::array<std::string_view, 21> kElementFields = {"a",
                                                             "b",
                                                             "x",
                                                             "y",
                                                             "back",
                                                             "start",
                                                             "guide",
                                                             "leftshoulder",
                                                             "rightshoulder",
                                                             "leftstick",
                                                             "rightstick",
                                                             "dpup",
                                                             "dpright",
                                                             "dpdown",
                                                             "dpleft",
                                                             "lefttrigger",
                                                             "righttrigger",
                                                             "leftx",
                                                             "lefty",
                                                             "rightx",
                                                             "righty"};
// SDL fields GLFW has no use for (and skips); their elements are still checked.
constexpr std::array<std::string_view, 11> kIgnoredElementFields = {
    "misc1",   "misc2",   "misc3",   "misc4",   "misc5",   "misc6",
    "paddle1", "paddle2", "paddle3", "paddle4", "touchpad"};
// SDL fields with free-form values.
constexpr std::array<std::string_view, 4> kTextFields = {"crc", "hint", "sdk>=", "sdk<="};
// The axes an SDL output modifier can name (+leftx: the element drives the positive half only).
constexpr std::array<std::string_view, 6> kSplitAxes = {"leftx",  "lefty",       "rightx",
                                                        "righty", "lefttrigger", "righttrigger"};
// SDL's platform names (the database's "platform:" values).
constexpr std::array<std::string_view, 5> kPlatforms = {"Windows", "Mac OS X", "Linux", "Android",
                                                        "iOS"};

constexpr std::string_view kPlatform = "Linux";

bool contains(auto const& list, std::string_view s) {
    return std::find(list.begin(), list.end(), s) != list.end();
}

bool isHex(char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; }

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// Fields are short; a long value is cut in messages.

// Reads a decimal number of at most three digits <= limit; advances `s`.
bool readNumber(std::string_view& s, int limit, int& value) {
    std::size_t n = 0;
    value = 0;
    while (n < s.size() && isDigit(s[n]) && n < 4) {
        value = value * 10 + (s[n] - '0');
        ++n;
    }
    s.remove_prefix(n);
    return n > 0 && n < 4 && value <= limit;
}

// An element such as b3, a2, +a1, -a0~, h0.4; empty string if fine, otherwise the problem.
std::string checkElement(std::string_view value) {
    std::string_view s = value;
    bool halfAxis = false;
    if (!s.empty() && (s.front() == '+' || s.front() == '-')) {
        halfAxis = true;
        s.remove_prefix(1);
    }
    if (s.empty()) {
        return "expected bN, aN or hH.B";
    }
    const char kind = s.front();
    s.remove_prefix(1);
    int index = 0;
    switch (kind) {
    case 'b':
        if (halfAxis) {
            return "a half-axis prefix (+/-) applies to axes only";
        }
        if (!readNumber(s, 255, index)) {
            return "button index must be 0..255";
        }
        break;
    case 'a':
        if (!readNumber(s, 255, index)) {
            return "axis index must be 0..255";
        }
        if (!s.empty() && s.front() == '~') {
            s.remove_prefix(1);
        }
        break;
    case 'h': {
        if (halfAxis) {
            return "a half-axis prefix (+/-) applies to axes only";
        }
        if (!readNumber(s, 15, index)) {
            return "hat index must be 0..15";
        }
        if (s.empty() || s.front() != '.') {
            return "expected hH.B (hat and bit)";
        }
        s.remove_prefix(1);
        int bit = 0;
        if (!readNumber(s, 8, bit) || (bit != 1 && bit != 2 && bit != 4 && bit != 8)) {
            return "hat bit must be 1, 2, 4 or 8";
        }
        break;
    }
    default:
        return "expected bN, aN or hH.B";
    }
    if (!s.empty()) {
        return "unexpected " + core::quote(s, 40) + " after the element";
    }
    return {};
}

// What one non-comment line holds.
struct LineCheck {
    std::string problem;               // why the line cannot be used; empty if it can
    std::vector<std::string> warnings; // what was left out of it
    std::string kept;                  // the line as handed to GLFW
    bool otherPlatform = false;
};

// The value of the line's platform field, or empty.
std::string_view platformOf(std::string_view line) {
    constexpr std::string_view kKey = ",platform:";
    const std::size_t at = line.find(kKey);
    if (at == std::string_view::npos) {
        return {};
    }
    const std::string_view value = line.substr(at + kKey.size());
    return value.substr(0, value.find(','));
}

LineCheck checkLine(std::string_view line) {
    LineCheck check;
    const auto fail = [&](std::string problem) {
        check.problem = std::move(problem);
        return check;
    };
    if (line.size() > kMaxLine) {
        return fail("line is " + std::to_string(line.size()) + " bytes, GLFW takes at most " +
                    std::to_string(kMaxLine));
    }
    // GLFW reads C strings and splits lines at '\r' as well as '\n'.
    for (char c : line) {
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t') {
            return fail("control character " + std::to_string(static_cast<int>(c)) +
                        " in the line");
        }
    }
    // Another platform's line is not for GLFW here, whatever it holds (Windows lines may name
    // the "xinput" GUID, which GLFW cannot parse).
    if (const std::string_view platform = platformOf(line);
        !platform.empty() && platform != kPlatform) {
        if (!contains(kPlatforms, platform)) {
            return fail("unknown platform " + core::quote(platform, 40) +
                        " (SDL's are Windows, Mac OS X, Linux, Android, iOS)");
        }
        check.otherPlatform = true;
        return check;
    }
    const std::size_t guidEnd = line.find(',');
    const std::string_view guid = line.substr(0, guidEnd);
    if (guid.size() != 32 || !std::all_of(guid.begin(), guid.end(), isHex)) {
        return fail("GUID must be 32 hex digits, got " + core::quote(guid, 40));
    }
    if (guidEnd == std::string_view::npos) {
        return fail("expected a name after the GUID");
    }
    std::string_view rest = line.substr(guidEnd + 1);
    const std::size_t nameEnd = rest.find(',');
    const std::string_view name = rest.substr(0, nameEnd);
    if (name.empty()) {
        return fail("the name is empty");
    }
    if (name.size() > kMaxName) {
        return fail("name is " + std::to_string(name.size()) + " bytes, GLFW takes at most " +
                    std::to_string(kMaxName));
    }
    if (nameEnd == std::string_view::npos) {
        return fail("expected fields after the name");
    }
    check.kept = std::string(line.substr(0, guidEnd + 1 + nameEnd + 1));
    rest.remove_prefix(nameEnd + 1);
    int elements = 0;
    std::vector<std::string> dropped;
    while (!rest.empty()) {
        const std::size_t end = rest.find(',');
        const std::string_view field = rest.substr(0, end);
        rest = end == std::string_view::npos ? std::string_view{} : rest.substr(end + 1);
        if (field.empty()) {
            continue; // SDL lines end with a comma
        }
        const std::size_t colon = field.find(':');
        if (colon == std::string_view::npos) {
            return fail("field " + core::quote(field, 40) + " has no ':'");
        }
        std::string_view key = field.substr(0, colon);
        const std::string_view value = field.substr(colon + 1);
        const bool modifier = !key.empty() && (key.front() == '+' || key.front() == '-');
        if (modifier) {
            key.remove_prefix(1);
            if (!contains(kSplitAxes, key)) {
                return fail(
                    "an output modifier (+/-) applies to an axis (leftx ... righttrigger), got " +
                    core::quote(field, 40));
            }
        } else if (key == "platform" || contains(kTextFields, key)) {
            check.kept.append(field).append(",");
            continue;
        } else if (!contains(kElementFields, key) && !contains(kIgnoredElementFields, key)) {
            // GLFW skips fields it does not know, and so does the mapping here.
            check.warnings.push_back(
                "unknown field " + core::quote(key, 40) +
                " ignored (SDL's gamepad fields are a, b, x, y, "
                "back, start, guide, dp*, left*, right*, misc1-6, paddle1-4, touchpad)");
            continue;
        }
        if (std::string problem = checkElement(value); !problem.empty()) {
            return fail("field " + core::quote(field.substr(0, colon), 40) + ": " + problem +
                        ", got " + core::quote(value, 40));
        }
        if (modifier) {
            // GLFW 3.3 refuses a whole mapping that holds one (it has no half-axis outputs).
            dropped.push_back(core::quote(field, 40));
            continue;
        }
        check.kept.append(field).append(",");
        ++elements;
    }
    if (!dropped.empty()) {
        std::string list;
        for (const std::string& d : dropped) {
            list += (list.empty() ? "" : ", ") + d;
        }
        check.warnings.push_back("output modifier" + std::string(dropped.size() > 1 ? "s " : " ") +
                                 list + " left out (GLFW 3.3 has no half-axis outputs)");
    }
    if (elements == 0) {
        return fail("no button or axis fields");
    }
    if (line.back() != ',') {
        check.kept.pop_back(); // no longer than the line, so within GLFW's limit
        // Fields left out may have followed a free-form one that ends in blanks ("hint:x ,q:r");
        // the kept line ends where a line read back would end, so it reads back as itself.
        while (check.kept.back() == ' ' || check.kept.back() == '\t') {
            check.kept.pop_back();
        }
    }
    return check;
}

} // namespace

MappingParseResult parseGamepadMappings(std::string_view text, std::string_view source) {
    MappingParseResult result;
    text = core::withoutByteOrderMark(text);
    const std::string file = core::printable(source);
    // Every mapping line so far ended with ',' / had a platform field (SDL's database: all do).
    bool allClosed = true;
    bool allWithPlatform = true;
    int mappingLines = 0;
    int lineNumber = 0;
    while (!text.empty()) {
        ++lineNumber;
        const std::size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
        while (!line.empty() &&
               (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) {
            line.remove_suffix(1);
        }
        while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) {
            line.remove_prefix(1);
        }
        if (line.empty() || line.front() == '#') {
            continue;
        }
        const bool closed = line.back() == ',';
        const bool withPlatform = !platformOf(line).empty();
        // A file cut short ends inside its last line: no newline after it, and without the
        // closing ',' or the platform field that every line before it has.
        if (end == std::string_view::npos && mappingLines > 0 &&
            ((allClosed && !closed) || (allWithPlatform && !withPlatform))) {
            result.diagnostics.error(
                file, lineNumber,
                "the text ends inside this line (no newline after it, and no " +
                    std::string(allClosed && !closed ? "',' closing its last field"
                                                     : "platform field") +
                    " as every line before it has): cut short?");
            break;
        }
        ++mappingLines;
        allClosed = allClosed && closed;
        allWithPlatform = allWithPlatform && withPlatform;
        LineCheck check = checkLine(line);
        if (!check.problem.empty()) {
            result.diagnostics.error(file, lineNumber, std::move(check.problem));
            continue;
        }
        if (check.otherPlatform) {
            ++result.otherPlatform;
            continue;
        }
        for (std::string& warning : check.warnings) {
            result.diagnostics.warning(file, lineNumber, std::move(warning));
        }
        result.lines.push_back(std::move(check.kept));
    }
    return result;
}

MappingLoadResult loadGamepadMappings(std::string_view text, std::string_view source) {
    MappingParseResult parsed = parseGamepadMappings(text, source);
    MappingLoadResult result;
    result.otherPlatform = parsed.otherPlatform;
    result.diagnostics = std::move(parsed.diagnostics);
    std::string joined;
    for (const std::string& line : parsed.lines) {
        joined += line;
        joined += '\n';
    }
    // Also with nothing to load, so a missing glfwInit() is found at once.
    if (glfwUpdateGamepadMappings(joined.c_str()) != GLFW_TRUE) {
        throw core::Error("input::loadGamepadMappings(): GLFW is not initialised");
    }
    result.loaded = static_cast<int>(parsed.lines.size());
    return result;
}

MappingLoadResult loadGamepadMappingsFile(const std::filesystem::path& path) {
    return loadGamepadMappings(core::readRequiredTextFile(path, "input::loadGamepadMappingsFile()"),
                               path.string());
}

std::string makeGamepadMapping(std::string_view guid, std::string_view name,
                               std::string_view fields) {
    std::string line = std::string(guid) + "," + std::string(name) + "," + std::string(fields);
    if (line.find('\n') != std::string::npos) {
        throw core::Error("input::makeGamepadMapping(): the mapping must be one line");
    }
    const LineCheck check = checkLine(line);
    if (!check.problem.empty()) {
        throw core::Error("input::makeGamepadMapping(): " + check.problem);
    }
    if (!check.warnings.empty()) {
        throw core::Error("input::makeGamepadMapping(): " + check.warnings.front());
    }
    return line;
}

} // namespace e2d::input
