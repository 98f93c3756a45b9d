// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <concepts>
#include <cstddef>
#include <string>
#include <string_view>

/// The pieces every e2d library builds its error messages from, so that all of them show a
/// value the same way: `"physics::World::createBody(): def.density must be >= 0, got -1"`,
/// `"render::Camera::setZoom(): zoom must be finite, got nan"`, `"unknown key 'widht'"`.
namespace e2d::core {

/// A number as a message shows it: the shortest text that reads back as the same value, in
/// plain digits when its magnitude is 0 or in [1e-4, 1e9) (`"-1"`, `"0.25"`, `"500000"`) and
/// in exponent form otherwise (`"1e+30"`, `"3e-07"`); `"nan"`, `"inf"`, `"-inf"`.
[[nodiscard]] std::string formatNumber(double value);
[[nodiscard]] std::string formatNumber(float value);
/// A whole number in decimal digits.
template <std::integral T>
[[nodiscard]] std::string formatNumber(T value) {
    return std::to_string(value);
}

/// A vector as `"(x, y)"` or `"(x, y, z)"`, each component by formatNumber().
[[nodiscard]] std::string formatVector(glm::vec2 value);
[[nodiscard]] std::string formatVector(glm::vec3 value);
[[nodiscard]] std::string formatVector(glm::ivec2 value);

/// `text` cut to at most `maxBytes` bytes, the last three of them `"..."`, when it is longer;
/// the cut never splits a UTF-8 sequence. `maxBytes` >= 3.
[[nodiscard]] std::string shortened(std::string_view text, std::size_t maxBytes);

/// `text` in single quotes for a message: shortened() to `maxBytes`, then escaped by
/// printable() (printable.hpp), so a control byte, a NUL or ill-formed UTF-8 read from a file
/// can neither hide nor cut the message short: `"'wi\x00dth'"`.
[[nodiscard]] std::string quote(std::string_view text, std::size_t maxBytes = 80);

/// Throws core::Error(`"<function>: <what>"`); `function` names the function with its
/// namespace and parentheses (`"render::Camera::setZoom()"`).
[[noreturn]] void throwError(std::string_view function, std::string_view what);

/// Throws core::Error(`"<function>: <field> must be <rule>, got <shown>"`).
[[noreturn]] void throwInvalid(std::string_view function, std::string_view field,
                               std::string_view rule, std::string_view shown);

/// throwInvalid() showing a number or a vector by formatNumber() or formatVector().
template <class T>
requires requires(T v) { formatNumber(v); } || requires(T v) {
    formatVector(v);
}
[[noreturn]] void throwInvalid(std::string_view function, std::string_view field,
                               std::string_view rule, T value) {
    if constexpr (requires { formatNumber(value); }) {
        throwInvalid(function, field, rule, std::string_view(formatNumber(value)));
    } else {
        throwInvalid(function, field, rule, std::string_view(formatVector(value)));
    }
}

/// True when both components are finite (neither NaN nor infinite).
[[nodiscard]] inline bool isFinite(glm::vec2 value) noexcept {
    return std::isfinite(value.x) && std::isfinite(value.y);
}

/// Throws `"<function>: <field> must be finite, got <value>"` unless every component of
/// `value` is finite. The check inlines; the throw is out of line.
void requireFinite(std::string_view function, std::string_view field, float value);
void requireFinite(std::string_view function, std::string_view field, glm::vec2 value);

namespace detail {
[[noreturn, gnu::cold]] void failNotFinite(std::string_view function, std::string_view field,
                                           float value);
[[noreturn, gnu::cold]] void failNotFinite(std::string_view function, std::string_view field,
                                           glm::vec2 value);
} // namespace detail

inline void requireFinite(std::string_view function, std::string_view field, float value) {
    if (!std::isfinite(value)) [[unlikely]] {
        detail::failNotFinite(function, field, value);
    }
}

inline void requireFinite(std::string_view function, std::string_view field, glm::vec2 value) {
    if (!isFinite(value)) [[unlikely]] {
        detail::failNotFinite(function, field, value);
    }
}

} // namespace e2d::core
