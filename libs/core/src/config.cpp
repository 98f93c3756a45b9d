// SPDX-License-Identifier: MIT
#include <e2d/core/config.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/core/printable.hpp>
#include <e2d/core/text_file.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <system_error>

namespace e2d::core {

namespace {

// What is wrong with a value, or nothing.
using Problem = std::optional<std::string>;

std::string describe(const ConfigBounds& bounds) {
    if (bounds.max == std::numeric_limits<double>::infinity()) {
        return std::string(bounds.minExclusive ? "> " : ">= ") + formatNumber(bounds.min);
    }
    return std::string(bounds.minExclusive ? "in (" : "in [") + formatNumber(bounds.min) + ", " +
           formatNumber(bounds.max) + "]";
}

bool contains(const ConfigBounds& bounds, double v) {
    return (bounds.minExclusive ? v > bounds.min : v >= bounds.min) && v <= bounds.max;
}

std::string_view trim(std::string_view s) {
    const auto isSpace = [](char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
    };
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
Problem parseInteger(std::string_view text, Int& out, const ConfigBounds& bounds) {
    const std::string_view digits = withoutPlus(text);
    Int value{};
    const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec == std::errc::result_out_of_range) {
        return "integer out of range, got " + quote(text);
    }
    if (ec != std::errc() || ptr != digits.data() + digits.size()) {
        return "expected an integer, got " + quote(text);
    }
    if (!contains(bounds, static_cast<double>(value))) {
        return "must be " + describe(bounds) + ", got " + printable(text);
    }
    out = value;
    return std::nullopt;
}

template <class Float>
Problem parseFloat(std::string_view text, Float& out, const ConfigBounds& bounds) {
    const std::string_view digits = withoutPlus(text);
    Float value{};
    const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec == std::errc::result_out_of_range) {
        return "number out of range, got " + quote(text);
    }
    if (ec != std::errc() || ptr != digits.data() + digits.size()) {
        return "expected a number, got " + quote(text);
    }
    if (!std::isfinite(value)) {
        return "expected a finite number, got " + quote(text);
    }
    if (!contains(bounds, static_cast<double>(value))) {
        return "must be " + describe(bounds) + ", got " + printable(text);
    }
    out = value;
    return std::nullopt;
}

// Edit distance counting a swap of neighbours as one edit (optimal string alignment), for
// "did you mean": `widht` is one edit from `width`. Keys are short; three rows are enough.
std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> before(b.size() + 1);
    std::vector<std::size_t> previous(b.size() + 1);
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) {
        previous[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i) {
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            row[j] = std::min({previous[j] + 1, row[j - 1] + 1, previous[j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
                row[j] = std::min(row[j], before[j - 2] + 1);
            }
        }
        std::swap(before, previous);
        std::swap(previous, row);
    }
    return previous[b.size()];
}

bool isKeyCharacter(char c) {
    return c != '=' && c != '#' && c != ' ' && c != '\t' && c != '\r' && c != '\n' && c != '\0';
}

} // namespace

int ConfigReport::lineOf(std::string_view key) const noexcept {
    const auto it = lines.find(key);
    return it != lines.end() ? it->second : 0;
}

void ConfigReport::error(std::string_view file, std::string_view key, std::string message) {
    diagnostics.error(file, lineOf(key), std::move(message), key);
}

void ConfigReader::add(std::string_view key, Setter setter) {
    if (key.empty() || !std::all_of(key.begin(), key.end(), isKeyCharacter)) {
        throw Error(
            "core::ConfigReader::add(): a key must be non-empty, without blanks, '=' or '#', got " +
            quote(key));
    }
    if (!setter) {
        throw Error("core::ConfigReader::add(): the setter of " + quote(key) + " is empty");
    }
    if (!keys_.emplace(std::string(key), std::move(setter)).second) {
        throw Error("core::ConfigReader::add(): key " + quote(key) + " is already added");
    }
}

void ConfigReader::add(std::string_view key, int& field, ConfigBounds bounds) {
    add(key, [&field, bounds](std::string_view v) { return parseInteger(v, field, bounds); });
}

void ConfigReader::add(std::string_view key, std::int64_t& field, ConfigBounds bounds) {
    add(key, [&field, bounds](std::string_view v) { return parseInteger(v, field, bounds); });
}

void ConfigReader::add(std::string_view key, std::uint64_t& field, ConfigBounds bounds) {
    add(key, [&field, bounds](std::string_view v) { return parseInteger(v, field, bounds); });
}

void ConfigReader::add(std::string_view key, float& field, ConfigBounds bounds) {
    add(key, [&field, bounds](std::string_view v) { return parseFloat(v, field, bounds); });
}

void ConfigReader::add(std::string_view key, double& field, ConfigBounds bounds) {
    add(key, [&field, bounds](std::string_view v) { return parseFloat(v, field, bounds); });
}

void ConfigReader::add(std::string_view key, bool& field) {
    add(key, [&field](std::string_view v) -> Problem {
        if (v == "true" || v == "false") {
            field = v == "true";
            return std::nullopt;
        }
        return "expected true or false, got " + quote(v);
    });
}

void ConfigReader::add(std::string_view key, std::string& field) {
    add(key, [&field](std::string_view v) -> Problem {
        field = std::string(v);
        return std::nullopt;
    });
}

std::string ConfigReader::unknownValue(std::string_view value,
                                       const std::vector<std::string_view>& names) {
    std::string message = "unknown value " + quote(value) + ", expected one of: ";
    for (std::size_t i = 0; i < names.size(); ++i) {
        message += (i == 0 ? "" : ", ");
        message += names[i];
    }
    return message;
}

std::vector<std::string_view> ConfigReader::keys() const {
    std::vector<std::string_view> out;
    out.reserve(keys_.size());
    for (const auto& entry : keys_) {
        out.push_back(entry.first);
    }
    return out;
}

ConfigReport ConfigReader::read(std::string_view text, std::string_view sourceName) const {
    ConfigReport result;
    const auto report = [&](Severity severity, int line, std::string_view key,
                            std::string message) {
        result.diagnostics.add(Diagnostic{severity, printable(sourceName), line, 0, printable(key),
                                          std::move(message)});
    };
    // The known key nearest to `key`, if it is near enough to be a typo (at most a third of
    // its letters wrong, and at most 3).
    const auto suggestion = [this](std::string_view key) -> std::string {
        std::string_view best;
        std::size_t bestDistance =
            std::min<std::size_t>(3, std::max<std::size_t>(1, key.size() / 3)) + 1;
        for (const auto& entry : keys_) {
            const std::string_view known = entry.first;
            const std::size_t gap =
                known.size() > key.size() ? known.size() - key.size() : key.size() - known.size();
            if (gap >= bestDistance) {
                continue;
            }
            const std::size_t distance = editDistance(key, known);
            if (distance < bestDistance) {
                bestDistance = distance;
                best = known;
            }
        }
        return best.empty() ? std::string() : " (did you mean " + quote(best) + "?)";
    };

    text = withoutByteOrderMark(text);

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
            report(Severity::Error, lineNumber, {}, "expected 'key = value', got " + quote(line));
            continue;
        }
        const std::string_view key = trim(line.substr(0, equals));
        const std::string_view value = trim(line.substr(equals + 1));
        if (key.empty()) {
            report(Severity::Error, lineNumber, {}, "empty key before '=' in " + quote(line));
            continue;
        }
        const auto field = keys_.find(key);
        if (field == keys_.end()) {
            report(Severity::Warning, lineNumber, key, "unknown key, ignored" + suggestion(key));
            continue;
        }
        if (const auto previous = result.lines.find(key); previous != result.lines.end()) {
            report(Severity::Warning, lineNumber, key,
                   "duplicate key, replaces the value set on line " +
                       std::to_string(previous->second));
        }
        if (Problem error = field->second(value)) {
            report(Severity::Error, lineNumber, key, std::move(*error));
            continue;
        }
        result.lines.insert_or_assign(std::string(key), lineNumber);
    }
    return result;
}

ConfigReport ConfigReader::load(const std::filesystem::path& path) const {
    const TextFile file = readTextFile(path);
    if (!file.ok()) {
        ConfigReport result;
        result.diagnostics.warning(printable(path.string()), 0,
                                   "cannot read the file (" + file.error + "), using the defaults");
        return result;
    }
    return read(file.text, path.string());
}

} // namespace e2d::core
