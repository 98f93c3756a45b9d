// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/error.hpp>

#include <glm/vec2.hpp>

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

namespace e2d::render::detail {

// Shortest round-trip form, so messages show exactly what the caller passed.
inline std::string formatFloat(float value) {
    char buffer[64];
    auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
    return std::string(buffer, result.ptr);
}

inline std::string formatVec(glm::vec2 v) {
    std::string text(1, '(');
    text.append(formatFloat(v.x)).append(", ").append(formatFloat(v.y)).push_back(')');
    return text;
}

inline std::string formatVec(glm::ivec2 v) {
    std::string text(1, '(');
    text.append(std::to_string(v.x)).append(", ").append(std::to_string(v.y)).push_back(')');
    return text;
}

[[noreturn]] inline void fail(std::string_view function, std::string_view what) {
    std::string message;
    message.reserve(function.size() + what.size() + 2);
    message.append(function).append(": ").append(what);
    throw core::Error(message);
}

inline bool isFinite(glm::vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

inline void requireFinite(std::string_view function, std::string_view field, float value) {
    if (!std::isfinite(value)) {
        fail(function, std::string(field) + " must be finite, got " + formatFloat(value));
    }
}

inline void requireFinite(std::string_view function, std::string_view field, glm::vec2 value) {
    if (!isFinite(value)) {
        fail(function, std::string(field) + " must be finite, got " + formatVec(value));
    }
}

} // namespace e2d::render::detail
