// SPDX-License-Identifier: MIT
#include <e2d/core/config.hpp>

#include "format.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <system_error>

namespace e2d::core {

namespace {

constexpr std::array<std::string_view, 4> kScreenFitNames{"expand", "widthFit", "heightFit", "bestFit"};
constexpr std::array<std::string_view, 2> kWindowModeNames{"windowed", "fullscreen"};
constexpr std::array<std::string_view, 2> kFilteringNames{"nearest", "linear"};
constexpr std::array<std::string_view, 2> kPhysicsSolverNames{"softStep", "classic"};

constexpr double kInf = std::numeric_limits<double>::infinity();

// Inclusive unless minExclusive; infinite ends mean unbounded.
struct Bounds {
    double min = -kInf;
    double max = kInf;
    bool minExclusive = false;

    [[nodiscard]] bool contains(double v) const {
        return (minExclusive ? v > min : v >= min) && v <= max;
    }
    [[nodiscard]] std::string describe() const {
        if (max == kInf) {
            return std::string(minExclusive ? "> " : ">= ") + detail::formatNumber(min);
        }
        return std::string(minExclusive ? "in (" : "in [") + detail::formatNumber(min) + ", " +
               detail::formatNumber(max) + "]";
    }
};

using ParseError = std::optional<std::string>;

std::string_view trim(std::string_view s) {
    const auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; };
    while (!s.empty() && isSpace(s.front())) {
        s.remove_prefix(1);
    }
    while (!s.empty() && isSpace(s.back())) {
        s.remove_suffix(1);
    }
    return s;
}

// from_chars rejects a leading '+', which people do write.
std::string_view withoutPlus(std::string_view s) {
    if (s.size() > 1 && s.front() == '+' && s[1] != '-' && s[1] != '+') {
        s.remove_prefix(1);
    }
    return s;
}

template <class Int>
ParseError parseInteger(std::string_view text, Int& out, Bounds bounds) {
    const std::string_view digits = withoutPlus(text);
    Int value{};
    const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec == std::errc::result_out_of_range) {
        return "integer out of range, got " + detail::quoted(text);
    }
    if (ec != std::errc() || ptr != digits.data() + digits.size()) {
        return "expected an integer, got " + detail::quoted(text);
    }
    if (!bounds.contains(static_cast<double>(value))) {
        return "must be " + bounds.describe() + ", got " + std::string(text);
    }
    out = value;
    return std::nullopt;
}

template <class Float>
ParseError parseFloat(std::string_view text, Float& out, Bounds bounds) {
    const std::string_view digits = withoutPlus(text);
    Float value{};
    const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec == std::errc::result_out_of_range) {
        return "number out of range, got " + detail::quoted(text);
    }
    if (ec != std::errc() || ptr != digits.data() + digits.size()) {
        return "expected a number, got " + detail::quoted(text);
    }
    if (!std::isfinite(value)) {
        return "expected a finite number, got " + detail::quoted(text);
    }
    if (!bounds.contains(static_cast<double>(value))) {
        return "must be " + bounds.describe() + ", got " + std::string(text);
    }
    out = value;
    return std::nullopt;
}

template <class Enum, std::size_t N>
ParseError parseEnum(std::string_view text, Enum& out, const std::array<std::string_view, N>& names) {
    for (std::size_t i = 0; i < N; ++i) {
        if (names[i] == text) {
            out = static_cast<Enum>(i);
            return std::nullopt;
        }
    }
    std::string message = "unknown value " + detail::quoted(text) + ", expected one of: ";
    for (std::size_t i = 0; i < N; ++i) {
        message += (i == 0 ? "" : ", ");
        message += names[i];
    }
    return message;
}

using Setter = std::function<ParseError(Config&, std::string_view)>;

template <class Int>
Setter integer(Int Config::*field, Bounds bounds = {}) {
    return [field, bounds](Config& c, std::string_view v) { return parseInteger(v, c.*field, bounds); };
}

template <class Float>
Setter real(Float Config::*field, Bounds bounds = {}) {
    return [field, bounds](Config& c, std::string_view v) { return parseFloat(v, c.*field, bounds); };
}

Setter boolean(bool Config::*field) {
    return [field](Config& c, std::string_view v) -> ParseError {
        if (v == "true" || v == "false") {
            c.*field = v == "true";
            return std::nullopt;
        }
        return "expected true or false, got " + detail::quoted(v);
    };
}

Setter text(std::string Config::*field) {
    return [field](Config& c, std::string_view v) -> ParseError {
        c.*field = std::string(v);
        return std::nullopt;
    };
}

template <class Enum, std::size_t N>
Setter enumeration(Enum Config::*field, const std::array<std::string_view, N>& names) {
    return [field, &names](Config& c, std::string_view v) { return parseEnum(v, c.*field, names); };
}

const std::map<std::string_view, Setter>& fields() {
    constexpr Bounds kPositive{0.0, kInf, true};
    constexpr Bounds kNonNegative{0.0, kInf, false};
    constexpr Bounds kAtLeastOne{1.0, kInf, false};
    static const std::map<std::string_view, Setter> kFields{
        {"firstScene", text(&Config::firstScene)},
        {"referenceWindowWidth", integer(&Config::referenceWindowWidth, kAtLeastOne)},
        {"referenceWindowHeight", integer(&Config::referenceWindowHeight, kAtLeastOne)},
        {"windowWidth", integer(&Config::windowWidth, kAtLeastOne)},
        {"windowHeight", integer(&Config::windowHeight, kAtLeastOne)},
        {"screenFitMode", enumeration(&Config::screenFitMode, kScreenFitNames)},
        {"windowMode", enumeration(&Config::windowMode, kWindowModeNames)},
        {"windowTitle", text(&Config::windowTitle)},
        {"textureFilteringMode", enumeration(&Config::textureFilteringMode, kFilteringNames)},
        {"maxCameraDepth", real(&Config::maxCameraDepth, kPositive)},
        {"vsync", boolean(&Config::vsync)},
        {"msaaSamples", integer(&Config::msaaSamples, Bounds{0.0, 16.0, false})},
        {"fontSize", integer(&Config::fontSize, kAtLeastOne)},
        {"gravityX", real(&Config::gravityX)},
        {"gravityY", real(&Config::gravityY)},
        {"fixedTimestep", real(&Config::fixedTimestep, Bounds{0.0, 1.0, true})},
        {"collisionResolutionSteps", integer(&Config::collisionResolutionSteps, kAtLeastOne)},
        {"allowedPenetration", real(&Config::allowedPenetration, kNonNegative)},
        {"penetrationBiasFactor", real(&Config::penetrationBiasFactor, Bounds{0.0, 1.0, false})},
        {"minRigidbodySpeed", real(&Config::minRigidbodySpeed, kNonNegative)},
        {"physicsSolver", enumeration(&Config::physicsSolver, kPhysicsSolverNames)},
        {"unitsPerMetre", real(&Config::unitsPerMetre, kPositive)},
        {"minAttenuationDistance", real(&Config::minAttenuationDistance, kNonNegative)},
        {"maxAttenuationDistance", real(&Config::maxAttenuationDistance, kNonNegative)},
        {"minPanningDistance", real(&Config::minPanningDistance, kNonNegative)},
        {"maxPanningDistance", real(&Config::maxPanningDistance, kNonNegative)},
        {"masterGain", real(&Config::masterGain, kNonNegative)},
        {"voiceCount", integer(&Config::voiceCount, Bounds{1.0, 1024.0, false})},
        {"bindingsFile", text(&Config::bindingsFile)},
        {"keyRepeat", boolean(&Config::keyRepeat)},
        {"maxStepsPerFrame", integer(&Config::maxStepsPerFrame, kAtLeastOne)},
        {"randomSeed", integer(&Config::randomSeed)},
        {"maxFrameTime", real(&Config::maxFrameTime, Bounds{0.0, 10.0, true})},
        {"debugDraw", boolean(&Config::debugDraw)},
        {"debugDrawKey", text(&Config::debugDrawKey)},
        {"printProfile", boolean(&Config::printProfile)},
        {"showProfile", boolean(&Config::showProfile)},
        {"profileKey", text(&Config::profileKey)},
    };
    return kFields;
}

} // namespace

std::string_view toString(ScreenFitMode mode) noexcept {
    return kScreenFitNames[static_cast<std::size_t>(mode)];
}

std::string_view toString(WindowMode mode) noexcept {
    return kWindowModeNames[static_cast<std::size_t>(mode)];
}

std::string_view toString(TextureFilteringMode mode) noexcept {
    return kFilteringNames[static_cast<std::size_t>(mode)];
}

std::string_view toString(PhysicsSolver solver) noexcept {
    return kPhysicsSolverNames[static_cast<std::size_t>(solver)];
}

std::string ConfigDiagnostic::toString() const {
    std::string out = file;
    if (line > 0) {
        out += ':';
        out += std::to_string(line);
    }
    out += ": ";
    if (!key.empty()) {
        out += key;
        out += ": ";
    }
    out += message;
    return out;
}

bool ConfigResult::hasErrors() const noexcept {
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [](const ConfigDiagnostic& d) { return d.severity == ConfigDiagnostic::Severity::Error; });
}

bool ConfigResult::hasWarnings() const noexcept {
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [](const ConfigDiagnostic& d) { return d.severity == ConfigDiagnostic::Severity::Warning; });
}

ConfigResult parseConfig(std::string_view text, std::string_view sourceName) {
    using Severity = ConfigDiagnostic::Severity;
    ConfigResult result;
    const auto report = [&](Severity severity, int line, std::string_view key, std::string message) {
        result.diagnostics.push_back(
            ConfigDiagnostic{severity, std::string(sourceName), line, std::string(key), std::move(message)});
    };

    constexpr std::string_view kBom = "\xEF\xBB\xBF";
    if (text.starts_with(kBom)) {
        text.remove_prefix(kBom.size());
    }

    std::map<std::string, int, std::less<>> seen; // key -> line it was last set on
    int lineNumber = 0;
    while (!text.empty()) {
        ++lineNumber;
        const std::size_t end = text.find('\n');
        const std::string_view rawLine = text.substr(0, end);
        text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);

        const std::string_view line = trim(rawLine);
        if (line.empty() || line.front() == '#') {
            continue;
        }
        const std::size_t equals = line.find('=');
        if (equals == std::string_view::npos) {
            report(Severity::Error, lineNumber, {}, "expected 'key = value', got " + detail::quoted(line));
            continue;
        }
        const std::string_view key = trim(line.substr(0, equals));
        const std::string_view value = trim(line.substr(equals + 1));
        if (key.empty()) {
            report(Severity::Error, lineNumber, {}, "empty key before '=' in " + detail::quoted(line));
            continue;
        }
        const auto field = fields().find(key);
        if (field == fields().end()) {
            report(Severity::Warning, lineNumber, key, "unknown key, ignored");
            continue;
        }
        if (const auto previous = seen.find(key); previous != seen.end()) {
            report(Severity::Warning, lineNumber, key,
                   "duplicate key, replaces the value set on line " + std::to_string(previous->second));
        }
        if (ParseError error = field->second(result.config, value)) {
            report(Severity::Error, lineNumber, key, std::move(*error));
            continue;
        }
        seen.insert_or_assign(std::string(key), lineNumber);
    }

    // A min above its max is blamed on whichever of the two was written last; both go back
    // to their defaults, which are consistent.
    const auto checkOrder = [&](std::string_view minKey, float Config::*minField, std::string_view maxKey,
                                float Config::*maxField) {
        Config& c = result.config;
        if (c.*minField <= c.*maxField) {
            return;
        }
        const auto lineOf = [&seen](std::string_view k) {
            const auto it = seen.find(k);
            return it != seen.end() ? it->second : 0;
        };
        const int minLine = lineOf(minKey);
        const int maxLine = lineOf(maxKey);
        if (maxLine > minLine) {
            report(Severity::Error, maxLine, maxKey,
                   "must be >= " + std::string(minKey) + " (" + detail::formatNumber(c.*minField) + "), got " +
                       detail::formatNumber(c.*maxField));
        } else {
            report(Severity::Error, minLine, minKey,
                   "must be <= " + std::string(maxKey) + " (" + detail::formatNumber(c.*maxField) + "), got " +
                       detail::formatNumber(c.*minField));
        }
        const Config defaults;
        c.*minField = defaults.*minField;
        c.*maxField = defaults.*maxField;
    };
    checkOrder("minAttenuationDistance", &Config::minAttenuationDistance, "maxAttenuationDistance",
               &Config::maxAttenuationDistance);
    checkOrder("minPanningDistance", &Config::minPanningDistance, "maxPanningDistance", &Config::maxPanningDistance);
    return result;
}

ConfigResult loadConfig(const std::filesystem::path& path) {
    // An ifstream opens a directory without complaint on POSIX systems; reading it fails
    // silently, so it is checked for explicitly.
    std::error_code ec;
    const bool isDirectory = std::filesystem::is_directory(path, ec);
    std::ifstream file;
    if (!isDirectory) {
        file.open(path, std::ios::binary);
    }
    std::ostringstream contents;
    if (file.is_open()) {
        contents << file.rdbuf();
    }
    if (!file.is_open() || file.bad()) {
        ConfigResult result;
        result.diagnostics.push_back(ConfigDiagnostic{ConfigDiagnostic::Severity::Warning, path.string(), 0, {},
                                                      "cannot read the file, using the defaults"});
        return result;
    }
    return parseConfig(contents.str(), path.string());
}

} // namespace e2d::core
