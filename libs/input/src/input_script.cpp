// SPDX-License-Identifier: MIT
#include <e2d/input/input_script.hpp>

#include <e2d/core/diagnostics.hpp>
#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/core/printable.hpp>
#include <e2d/core/text_file.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

namespace e2d::input {

namespace {

std::string_view trim(std::string_view s) {
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    while (!s.empty() && space(s.front())) {
        s.remove_prefix(1);
    }
    while (!s.empty() && space(s.back())) {
        s.remove_suffix(1);
    }
    return s;
}

// Splits on runs of blanks.
std::vector<std::string_view> words(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) {
            ++i;
        }
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') {
            ++i;
        }
        if (i > start) {
            out.push_back(line.substr(start, i - start));
        }
    }
    return out;
}

[[noreturn]] void fail(std::string_view source, int line, const std::string& message) {
    throw core::ParseError(
        core::Diagnostic{core::Severity::Error, core::printable(source), line, 0, {}, message});
}

// Bounded, so a tap's release (frame + 1) cannot overflow.
std::int64_t parseFrame(std::string_view word, std::string_view source, int line) {
    std::int64_t frame = 0;
    const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), frame);
    if (ec == std::errc::invalid_argument || ptr != word.data() + word.size() ||
        (ec == std::errc() && frame < 0)) {
        fail(source, line, "frame must be a whole number >= 0, got " + core::quote(word));
    }
    if (ec != std::errc() || frame > kMaxScriptFrame) {
        fail(source, line,
             "frame must be a whole number in [0, " + std::to_string(kMaxScriptFrame) + "], got " +
                 core::quote(word));
    }
    return frame;
}

// A finite decimal number, or nothing.
std::optional<float> number(std::string_view word) {
    float value = 0.0f;
    const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (ec != std::errc() || ptr != word.data() + word.size() || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value;
}

// `<frame> move mouse <x> <y>` or `<frame> move axis:<name> <value>`.
ScriptEvent parseMove(const std::vector<std::string_view>& w, std::string_view line,
                      std::string_view source, int lineNumber) {
    ScriptEvent event;
    event.frame = parseFrame(w[0], source, lineNumber);
    event.kind = ScriptEvent::Kind::Move;
    event.target = std::string(w[2]);
    event.line = lineNumber;
    const auto rest = [&](std::size_t from) {
        const std::size_t at =
            w.size() > from ? static_cast<std::size_t>(w[from].data() - line.data()) : line.size();
        return std::string(line.substr(at));
    };
    if (w[2] == "mouse") {
        const std::optional<float> x = w.size() == 5 ? number(w[3]) : std::nullopt;
        const std::optional<float> y = w.size() == 5 ? number(w[4]) : std::nullopt;
        if (!x || !y) {
            fail(source, lineNumber,
                 "move mouse: expected '<x> <y>' in window pixels, got " + core::quote(rest(3)));
        }
        event.x = *x;
        event.y = *y;
        return event;
    }
    if (w[2].substr(0, 4) != "axis") {
        fail(source, lineNumber,
             "move: expected 'mouse' or a gamepad axis (axis:leftx), got " + core::quote(w[2]));
    }
    const std::optional<float> value = w.size() == 4 ? number(w[3]) : std::nullopt;
    if (!value || *value < -1.0f || *value > 1.0f) {
        fail(source, lineNumber,
             "move " + core::printable(w[2]) + ": expected one value in [-1, 1], got " +
                 core::quote(rest(3)));
    }
    event.x = *value;
    return event;
}

} // namespace

InputScript parseInputScript(std::string_view text, std::string_view source) {
    InputScript script;
    script.source = std::string(source);
    int lineNumber = 0;
    while (!text.empty()) {
        ++lineNumber;
        const std::size_t end = text.find('\n');
        const std::string_view line = trim(text.substr(0, end));
        text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
        if (line.empty() || line.front() == '#') {
            continue;
        }
        const std::vector<std::string_view> w = words(line);
        if (w.size() >= 3 && w[1] == "move") {
            script.events.push_back(parseMove(w, line, source, lineNumber));
            continue;
        }
        if (w.size() != 3) {
            fail(source, lineNumber,
                 "expected '<frame> <press|release|tap> <target>', got " + core::quote(line));
        }
        const std::int64_t frame = parseFrame(w[0], source, lineNumber);
        const std::string target(w[2]);
        if (w[1] == "press" || w[1] == "release") {
            script.events.push_back(
                {frame, w[1] == "press" ? ScriptEvent::Kind::Press : ScriptEvent::Kind::Release,
                 target, lineNumber});
        } else if (w[1] == "tap") {
            script.events.push_back({frame, ScriptEvent::Kind::Press, target, lineNumber});
            script.events.push_back({frame + 1, ScriptEvent::Kind::Release, target, lineNumber});
        } else {
            fail(source, lineNumber,
                 "expected press, release, tap or move, got " + core::quote(w[1]));
        }
    }
    std::stable_sort(script.events.begin(), script.events.end(),
                     [](const ScriptEvent& a, const ScriptEvent& b) { return a.frame < b.frame; });
    return script;
}

InputScript loadInputScript(const std::filesystem::path& path) {
    const core::TextFile file = core::readTextFile(path);
    if (!file.ok()) {
        throw core::ParseError(
            core::Diagnostic{core::Severity::Error,
                             core::printable(path.string()),
                             0,
                             0,
                             {},
                             "cannot read the input script (" + file.error + ")"});
    }
    return parseInputScript(file.text, path.string());
}

} // namespace e2d::input
