// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/error.hpp>
#include <e2d/physics/constants.hpp>
#include <e2d/physics/math.hpp>

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

namespace e2d::physics::detail {

// Shortest round-trip form ("-1", "0.25", "100000", "nan", "inf"), so messages show exactly
// what the caller passed; plain digits unless the magnitude makes them unreadable.
inline std::string formatFloat(float value) {
    char buffer[64];
    float magnitude = std::fabs(value);
    bool plain = magnitude == 0.0f || (magnitude >= 1.0e-4f && magnitude < 1.0e9f);
    auto result = plain ? std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::fixed)
                        : std::to_chars(buffer, buffer + sizeof(buffer), value);
    return std::string(buffer, result.ptr);
}

// Appends rather than `"(" + std::string`, which trips GCC 12's -Wrestrict false positive at -O3.
inline std::string formatVec(Vec2 v) {
    std::string text(1, '(');
    text.append(formatFloat(v.x)).append(", ").append(formatFloat(v.y)).push_back(')');
    return text;
}

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
