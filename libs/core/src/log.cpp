// SPDX-License-Identifier: MIT
#include <e2d/core/log.hpp>

#include <cstdio>
#include <string>

namespace e2d::core {

namespace {

void writeToStderr(LogLevel level, std::string_view message) {
    // One fwrite per message so lines from several loggers do not interleave mid-line.
    std::string line;
    line.reserve(message.size() + 12);
    line += '[';
    line += toString(level);
    line += "] ";
    line += message;
    line += '\n';
    std::fwrite(line.data(), 1, line.size(), stderr);
}

} // namespace

std::string_view toString(LogLevel level) noexcept {
    switch (level) {
    case LogLevel::Trace:
        return "trace";
    case LogLevel::Debug:
        return "debug";
    case LogLevel::Info:
        return "info";
    case LogLevel::Warning:
        return "warning";
    case LogLevel::Error:
        return "error";
    case LogLevel::Off:
        return "off";
    }
    return "unknown";
}

Logger::Logger() : sink_(writeToStderr) {}

Logger::Logger(LogLevel minLevel, Sink sink) : level_(minLevel), sink_(std::move(sink)) {
    if (!sink_) {
        sink_ = writeToStderr;
    }
}

void Logger::setSink(Sink sink) { sink_ = sink ? std::move(sink) : Sink(writeToStderr); }

bool Logger::enabled(LogLevel level) const noexcept {
    return level != LogLevel::Off && level >= level_;
}

void Logger::log(LogLevel level, std::string_view message) {
    if (enabled(level)) {
        sink_(level, message);
    }
}

} // namespace e2d::core
