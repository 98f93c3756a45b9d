// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/error.hpp>
#include <e2d/physics/constants.hpp>
#include <e2d/physics/math.hpp>

#include <charconv>
#include <string>
#include <string_view>

namespace e2d::physics::detail {

// Shortest round-trip form ("-1", "0.25", "nan", "inf"), so messages show exactly what the
// caller passed.
inline std::string formatFloat(float value) {
    char buffer[32];
    auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
    return std::string(buffer, result.ptr);
}

inline std::string formatVec(Vec2 v) { return "(" + formatFloat(v.x) + ", " + formatFloat(v.y) + ")"; }

[[noreturn]] inline void fail(std::string_view function, std::string_view what) {
    std::string message;
    message.reserve(function.size() + what.size() + 2);
    message.append(function).append(": ").append(what);
    throw core::Error(message);
}

// Finite and within kHuge: both conditions every length and coordinate must meet.
inline bool isSane(float x) { return std::isfinite(x) && std::fabs(x) <= kHuge; }
inline bool isSane(Vec2 v) { return isSane(v.x) && isSane(v.y); }

} // namespace e2d::physics::detail
