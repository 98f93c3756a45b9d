// SPDX-License-Identifier: MIT
// SDL gamepad mapping lines: checked here, then handed to GLFW's database.
#include <e2d/input/gamepad_mappings.hpp>

#include <e2d/core/error.hpp>

#include <GLFW/glfw3.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <fstream>
#include <sstream>

namespace e2d::input {

namespace {

// GLFW keeps a line only if it is shorter than its 1024-byte buffer and a name shorter than 128.
constexpr std::size_t kMaxLine = 1023;
constexpr std::size_t kMaxName = 127;

constexpr std::array<std::string_view, 21> kElementFields = {
    "a", "b", "x", "y", "back", "start", "guide", "leftshoulder", "rightshoulder", "leftstick", "rightstick",
    "dpup", "dpright", "dpdown", "dpleft", "lefttrigger", "righttrigger", "leftx", "lefty", "rightx", "righty"};
// SDL fields GLFW has no use for; their elements are still checked.
constexpr std::array<std::string_view, 6> kIgnoredElementFields = {"misc1", "paddle1", "paddle2",
                                                                   "paddle3", "paddle4", "touchpad"};
// SDL fields with free-form values.
constexpr std::array<std::string_view, 4> kTextFields = {"crc", "hint", "sdk>=", "sdk<="};

constexpr std::string_view kPlatform = "Linux";

bool contains(auto const& list, std::string_view s) {
    return std::find(list.begin(), list.end(), s) != list.end();
}

bool isHex(char c) {
    return std::isxdigit(static_cast<unsigned char>(c)) != 0;
}

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

std::string quoted(std::string_view s) {
    constexpr std::size_t kShown = 40;
    std::string out = "'";
    for (char c : s.substr(0, kShown)) {
        out += std::isprint(static_cast<unsigned char>(c)) != 0 ? c : '?';
    }
    if (s.size() > kShown) {
        out += "...";
    }
    return out + "'";
}

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
        return "unexpected " + quoted(s) + " after the element";
    }
    return {};
}

// Checks one non-comment line. Returns the problem, or empty; sets otherPlatform.
std::string checkLine(std::string_view line, bool& otherPlatform) {
    otherPlatform = false;
    if (line.size() > kMaxLine) {
        return "line is " + std::to_string(line.size()) + " bytes, GLFW takes at most " + std::to_string(kMaxLine);
    }
    // GLFW reads C strings and splits lines at '\r' as well as '\n'.
    for (char c : line) {
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t') {
            return "control character " + std::to_string(static_cast<int>(c)) + " in the line";
        }
    }
    const std::size_t guidEnd = line.find(',');
    const std::string_view guid = line.substr(0, guidEnd);
    if (guid.size() != 32 || !std::all_of(guid.begin(), guid.end(), isHex)) {
        return "GUID must be 32 hex digits, got " + quoted(guid);
    }
    if (guidEnd == std::string_view::npos) {
        return "expected a name after the GUID";
    }
    std::string_view rest = line.substr(guidEnd + 1);
    const std::size_t nameEnd = rest.find(',');
    const std::string_view name = rest.substr(0, nameEnd);
    if (name.empty()) {
        return "the name is empty";
    }
    if (name.size() > kMaxName) {
        return "name is " + std::to_string(name.size()) + " bytes, GLFW takes at most " + std::to_string(kMaxName);
    }
    if (nameEnd == std::string_view::npos) {
        return "expected fields after the name";
    }
    rest.remove_prefix(nameEnd + 1);
    int elements = 0;
    while (!rest.empty()) {
        const std::size_t end = rest.find(',');
        const std::string_view field = rest.substr(0, end);
        rest = end == std::string_view::npos ? std::string_view{} : rest.substr(end + 1);
        if (field.empty()) {
            continue; // SDL lines end with a comma
        }
        const std::size_t colon = field.find(':');
        if (colon == std::string_view::npos) {
            return "field " + quoted(field) + " has no ':'";
        }
        std::string_view key = field.substr(0, colon);
        const std::string_view value = field.substr(colon + 1);
        if (key == "platform") {
            if (value != kPlatform) {
                otherPlatform = true;
            }
            continue;
        }
        if (contains(kTextFields, key)) {
            continue;
        }
        if (!key.empty() && (key.front() == '+' || key.front() == '-')) {
            return "output modifier in " + quoted(field) + " is not supported by GLFW 3.3";
        }
        if (!contains(kElementFields, key) && !contains(kIgnoredElementFields, key)) {
            return "unknown field " + quoted(key) + " (expected an SDL gamepad field such as a, leftx, platform)";
        }
        if (std::string problem = checkElement(value); !problem.empty()) {
            return "field '" + std::string(key) + "': " + problem + ", got " + quoted(value);
        }
        ++elements;
    }
    if (elements == 0) {
        return "no button or axis fields";
    }
    return {};
}

} // namespace

MappingParseResult parseGamepadMappings(std::string_view text, std::string_view source) {
    MappingParseResult result;
    int lineNumber = 0;
    while (!text.empty()) {
        ++lineNumber;
        const std::size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) {
            line.remove_suffix(1);
        }
        while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) {
            line.remove_prefix(1);
        }
        if (line.empty() || line.front() == '#') {
            continue;
        }
        bool otherPlatform = false;
        std::string problem = checkLine(line, otherPlatform);
        if (!problem.empty()) {
            result.errors.push_back(
                MappingError{lineNumber, std::string(source) + ":" + std::to_string(lineNumber) + ": " + problem});
        } else if (otherPlatform) {
            ++result.otherPlatform;
        } else {
            result.lines.emplace_back(line);
        }
    }
    return result;
}

MappingLoadResult loadGamepadMappings(std::string_view text, std::string_view source) {
    MappingParseResult parsed = parseGamepadMappings(text, source);
    MappingLoadResult result;
    result.otherPlatform = parsed.otherPlatform;
    result.errors = std::move(parsed.errors);
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
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw core::Error("input::loadGamepadMappingsFile(): cannot read '" + path.string() + "'");
    }
    std::ostringstream text;
    text << file.rdbuf();
    return loadGamepadMappings(text.str(), path.string());
}

std::string makeGamepadMapping(std::string_view guid, std::string_view name, std::string_view fields) {
    std::string line = std::string(guid) + "," + std::string(name) + "," + std::string(fields);
    if (line.find('\n') != std::string::npos) {
        throw core::Error("input::makeGamepadMapping(): the mapping must be one line");
    }
    bool otherPlatform = false;
    if (std::string problem = checkLine(line, otherPlatform); !problem.empty()) {
        throw core::Error("input::makeGamepadMapping(): " + problem);
    }
    return line;
}

} // namespace e2d::input
