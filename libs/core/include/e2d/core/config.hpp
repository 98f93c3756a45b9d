// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/diagnostics.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace e2d::core {

/// What reading a configuration found: the diagnostics, and the line each key was set on.
struct ConfigReport {
    /// Each problem with its line and key (Diagnostic::field):
    /// `"game.cfg:12: windowWidth: expected an integer, got 'abc'"`.
    Diagnostics diagnostics;
    /// Key -> the line it was last set on without error.
    std::map<std::string, int, std::less<>> lines;

    /// The line `key` was set on, 0 if it was not.
    [[nodiscard]] int lineOf(std::string_view key) const noexcept;
    /// Adds an error about `key` on the line it was set on (a check across keys, after reading).
    void error(std::string_view file, std::string_view key, std::string message);
};

/// The range a number must be in: [min, max], or (min, max] when `minExclusive`. Infinite ends
/// are unbounded. Default: any finite number.
struct ConfigBounds {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool minExclusive = false;

    /// >= value.
    [[nodiscard]] static constexpr ConfigBounds atLeast(double value) noexcept { return {value}; }
    /// > value.
    [[nodiscard]] static constexpr ConfigBounds above(double value) noexcept {
        return {value, std::numeric_limits<double>::infinity(), true};
    }
};

/// The generic reader of `key = value` configuration files. Whoever owns the settings (a game
/// engine, a tool) adds its keys, each bound to a field it owns, then reads text or a file
/// into them; core knows no key itself.
///
/// Format: one `key = value` per line; blank lines and lines starting with `#` are ignored;
/// whitespace around key and value is trimmed and a value may contain spaces
/// (`windowTitle = My Game`); there are no inline comments; a UTF-8 byte order mark is
/// skipped. Keys and enum values are case-sensitive. Booleans are `true` or `false`. Numbers
/// are read locale-independently; an integer must be a whole integer ("12px" and "1.5" are
/// errors).
///
/// Errors: bad or out-of-range number, unknown enum value (the accepted ones are listed), line
/// without `=`, empty key. Warnings: unknown key (ignored; the nearest known key is suggested:
/// "unknown key, ignored (did you mean 'windowWidth'?)"), duplicate key (the last value wins).
/// A value in error leaves its field as it was (its default). Raw bytes quoted in messages are
/// escaped where not printable (core::printable).
class ConfigReader {
public:
    /// Parses a value into its field; returns what is wrong with it, or nothing.
    using Setter = std::function<std::optional<std::string>(std::string_view value)>;

    /// Adds a key read by `setter`. Throws core::Error for an empty key, one with '=',
    /// '#' or blanks in it, or one already added.
    void add(std::string_view key, Setter setter);
    /// Keys bound to fields: the value is parsed as the field's type and checked against
    /// `bounds` (numbers).
    void add(std::string_view key, int& field, ConfigBounds bounds = {});
    void add(std::string_view key, std::int64_t& field, ConfigBounds bounds = {});
    void add(std::string_view key, std::uint64_t& field, ConfigBounds bounds = {});
    void add(std::string_view key, float& field, ConfigBounds bounds = {});
    void add(std::string_view key, double& field, ConfigBounds bounds = {});
    void add(std::string_view key, bool& field);
    /// Any text, spaces included.
    void add(std::string_view key, std::string& field);
    /// One of `names` (the config file's spelling of each value).
    template <class Enum>
    void add(std::string_view key, Enum& field,
             std::vector<std::pair<std::string_view, Enum>> names);

    /// The keys added, sorted.
    [[nodiscard]] std::vector<std::string_view> keys() const;

    /// Reads configuration text into the fields; `sourceName` names it in diagnostics.
    ConfigReport read(std::string_view text, std::string_view sourceName = "config") const;
    /// Reads the file at `path`. A file that cannot be read (missing, a folder) gives one
    /// warning, line 0, and changes nothing; it never throws for that.
    ConfigReport load(const std::filesystem::path& path) const;

private:
    static std::string unknownValue(std::string_view value,
                                    const std::vector<std::string_view>& names);

    std::map<std::string, Setter, std::less<>> keys_;
};

template <class Enum>
void ConfigReader::add(std::string_view key, Enum& field,
                       std::vector<std::pair<std::string_view, Enum>> names) {
    add(key,
        [&field, names = std::move(names)](std::string_view value) -> std::optional<std::string> {
            std::vector<std::string_view> spelled;
            for (const auto& [name, enumerator] : names) {
                if (name == value) {
                    field = enumerator;
                    return std::nullopt;
                }
                spelled.push_back(name);
            }
            return unknownValue(value, spelled);
        });
}

} // namespace e2d::core
