// SPDX-License-Identifier: MIT
#pragma once

#include <functional>
#include <string_view>

namespace e2d::core {

/// Severity of a log message, lowest first. `Off` as a minimum level silences everything.
enum class LogLevel { Trace, Debug, Info, Warning, Error, Off };

/// Lower-case name of a level ("trace", "debug", "info", "warning", "error", "off").
[[nodiscard]] std::string_view toString(LogLevel level) noexcept;

/// A logger owned by whoever runs the game and passed by reference to whatever logs.
///
/// Messages below the minimum level are dropped before reaching the sink. The sink is any
/// callable; the default one writes `"[level] message\n"` to stderr, which is the only place
/// in e2d::core that writes to a stream. Not thread-safe: give each thread its own logger or
/// make the sink synchronise.
class Logger {
public:
    /// Receives every message at or above the minimum level.
    using Sink = std::function<void(LogLevel, std::string_view)>;

    /// Minimum level Info, default stderr sink.
    Logger();
    /// Minimum level `minLevel`; an empty `sink` means the default stderr sink.
    explicit Logger(LogLevel minLevel, Sink sink = {});

    /// Messages below this level are dropped. Default Info.
    [[nodiscard]] LogLevel level() const noexcept { return level_; }
    void setLevel(LogLevel level) noexcept { level_ = level; }

    /// Replaces the sink; an empty function restores the default stderr sink.
    void setSink(Sink sink);

    /// True when a message of `level` would reach the sink (use it to skip building
    /// expensive messages).
    [[nodiscard]] bool enabled(LogLevel level) const noexcept;

    /// Sends `message` to the sink if `level` is enabled. `LogLevel::Off` is never sent.
    void log(LogLevel level, std::string_view message);

    void trace(std::string_view message) { log(LogLevel::Trace, message); }
    void debug(std::string_view message) { log(LogLevel::Debug, message); }
    void info(std::string_view message) { log(LogLevel::Info, message); }
    void warning(std::string_view message) { log(LogLevel::Warning, message); }
    void error(std::string_view message) { log(LogLevel::Error, message); }

private:
    LogLevel level_ = LogLevel::Info;
    Sink sink_;
};

} // namespace e2d::core
