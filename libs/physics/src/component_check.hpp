// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/error.hpp>

#include "error_format.hpp"

#include <cmath>
#include <string>

// Checks of the components' definition structs: "physics::<function>(): def.<field> ...".
namespace e2d::physics::detail::component_check {

inline void requireFinite(const char* function, const char* field, float value) {
    if (!std::isfinite(value)) {
        throw core::Error(std::string("physics::") + function + "(): def." + field +
                          " must be finite, got " + formatFloat(value));
    }
}

inline void requireNonNegative(const char* function, const char* field, float value) {
    if (!std::isfinite(value) || value < 0.0f) {
        throw core::Error(std::string("physics::") + function + "(): def." + field +
                          " must be finite and >= 0, got " + formatFloat(value));
    }
}

inline void requireUnitInterval(const char* function, const char* field, float value) {
    if (!std::isfinite(value) || value < 0.0f || value > 1.0f) {
        throw core::Error(std::string("physics::") + function + "(): def." + field +
                          " must be finite and in [0, 1], got " + formatFloat(value));
    }
}

} // namespace e2d::physics::detail::component_check
