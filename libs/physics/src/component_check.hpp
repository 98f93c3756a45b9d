// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/physics/constants.hpp>

#include <glm/mat2x2.hpp>

#include <cmath>
#include <string>
#include <string_view>

// Checks of the components' definition structs: "physics::<function>(): def.<field> ...".
namespace e2d::physics::detail::component_check {

inline void requireFinite(const char* function, const char* field, float value) {
    if (!std::isfinite(value)) {
        throw core::Error(std::string("physics::") + function + "(): def." + field +
                          " must be finite, got " + core::formatNumber(value));
    }
}

inline void requireNonNegative(const char* function, const char* field, float value) {
    if (!std::isfinite(value) || value < 0.0f) {
        throw core::Error(std::string("physics::") + function + "(): def." + field +
                          " must be finite and >= 0, got " + core::formatNumber(value));
    }
}

inline void requireUnitInterval(const char* function, const char* field, float value) {
    if (!std::isfinite(value) || value < 0.0f || value > 1.0f) {
        throw core::Error(std::string("physics::") + function + "(): def." + field +
                          " must be finite and in [0, 1], got " + core::formatNumber(value));
    }
}

// "physics::Rigidbody on object 'crate': ..."
[[noreturn]] inline void failOn(const core::GameObject& object, std::string_view component,
                                const std::string& what) {
    throw core::Error("physics::" + std::string(component) + " on " + object.describe() + ": " +
                      what);
}

// The object's world position must be within the World's range (kHuge metres), reported in
// the world units the user gave.
inline void requireInRange(const core::GameObject& object, std::string_view component,
                           float unitsPerMetre) {
    const glm::vec3 p = object.worldPosition();
    const Vec2 units{p.x, p.y};
    const Vec2 metres = units / unitsPerMetre;
    if (std::isfinite(metres.x) && std::isfinite(metres.y) && std::fabs(metres.x) <= kHuge &&
        std::fabs(metres.y) <= kHuge) {
        return;
    }
    failOn(object, component,
           "world position " + core::formatVector(units) +
               " world units is out of the physics range (finite, |x| and |y| <= " +
               core::formatNumber(kHuge * unitsPerMetre) +
               " world units: " + core::formatNumber(kHuge) + " m at " +
               core::formatNumber(unitsPerMetre) + " units per metre)");
}

// A collider's placement on its body (its object's scale and pose relative to the body) must
// be finite; a degenerate but finite one only leaves the collider without a shape.
inline void requireFinitePlacement(const core::GameObject& object, std::string_view component,
                                   const glm::mat2& linear, glm::vec2 offset) {
    const bool finite = std::isfinite(linear[0][0]) && std::isfinite(linear[0][1]) &&
                        std::isfinite(linear[1][0]) && std::isfinite(linear[1][1]) &&
                        std::isfinite(offset.x) && std::isfinite(offset.y);
    if (!finite) {
        failOn(object, component,
               "the object's scale, orientation or position relative to its body is not finite "
               "(scale " +
                   core::formatVector(object.scale()) + ", orientation " +
                   core::formatNumber(object.orientation()) + ")");
    }
}

} // namespace e2d::physics::detail::component_check
