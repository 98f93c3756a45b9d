// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/physics/constants.hpp>
#include <e2d/physics/math.hpp>

#include <cmath>
#include <string>

// Building the messages of World's input checks: "physics::World::fn(): what, got value".
namespace e2d::physics::detail::world_check {

inline std::string text(float x) { return core::formatNumber(x); }
inline std::string text(Vec2 v) { return core::formatVector(v); }

[[noreturn]] inline void fail(const char* function, const std::string& what) {
    throw core::Error(std::string("physics::World::") + function + "(): " + what);
}

inline void requireFinite(const char* function, const char* name, float x) {
    if (!isFinite(x)) {
        fail(function, std::string(name) + " must be finite, got " + text(x));
    }
}

inline void requireFinite(const char* function, const char* name, Vec2 v) {
    if (!isFinite(v)) {
        fail(function, std::string(name) + " must be finite, got " + text(v));
    }
}

inline void requireNonNegative(const char* function, const char* name, float x) {
    if (!(isFinite(x) && x >= 0.0f)) {
        fail(function, std::string(name) + " must be finite and >= 0, got " + text(x));
    }
}

inline void requirePosition(const char* function, const char* name, Vec2 v) {
    if (!isWithinHuge(v)) {
        fail(function, std::string(name) + " must be finite with |x|, |y| <= kHuge (" +
                           text(kHuge) + " m), got " + text(v));
    }
}

} // namespace e2d::physics::detail::world_check
