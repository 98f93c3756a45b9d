// SPDX-License-Identifier: MIT
#include <e2d/core/error_text.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/printable.hpp>

#include <charconv>

namespace e2d::core {

namespace {

template <class T>
std::string numberText(T value) {
    char buffer[64];
    const T magnitude = std::fabs(value);
    // Fixed notation is still the shortest round-trip text, only without an exponent: "100000"
    // reads better than "1e+05", and nobody counts the zeros of numbers up to 1e9.
    const bool plain = magnitude == T(0) || (magnitude >= T(1.0e-4) && magnitude < T(1.0e9));
    const auto result =
        plain ? std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::fixed)
              : std::to_chars(buffer, buffer + sizeof(buffer), value);
    return std::string(buffer, result.ptr);
}

// Appended piece by piece: GCC 12 at -O3 misreads `"(" + std::string` as an overlapping memcpy
// (-Werror=restrict, a known false positive).
template <class Vector>
std::string vectorText(const Vector& value) {
    std::string out = "(";
    for (int i = 0; i < Vector::length(); ++i) {
        out.append(i == 0 ? "" : ", ").append(formatNumber(value[i]));
    }
    return out.append(")");
}

} // namespace

std::string formatNumber(double value) { return numberText(value); }

std::string formatNumber(float value) { return numberText(value); }

std::string formatVector(glm::vec2 value) { return vectorText(value); }

std::string formatVector(glm::vec3 value) { return vectorText(value); }

std::string formatVector(glm::ivec2 value) { return vectorText(value); }

std::string shortened(std::string_view text, std::size_t maxBytes) {
    if (text.size() <= maxBytes) {
        return std::string(text);
    }
    std::size_t cut = maxBytes < 3 ? 0 : maxBytes - 3;
    // Back to the start of a UTF-8 sequence: continuation bytes are 10xxxxxx.
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) {
        --cut;
    }
    std::string out(text.substr(0, cut));
    return out.append("...");
}

std::string quote(std::string_view text, std::size_t maxBytes) {
    std::string out = "'";
    return out.append(printable(shortened(text, maxBytes))).append("'");
}

void throwError(std::string_view function, std::string_view what) {
    std::string message;
    message.reserve(function.size() + what.size() + 2);
    message.append(function).append(": ").append(what);
    throw Error(message);
}

void throwInvalid(std::string_view function, std::string_view field, std::string_view rule,
                  std::string_view shown) {
    std::string what(field);
    what.append(" must be ").append(rule).append(", got ").append(shown);
    throwError(function, what);
}

namespace detail {

void failNotFinite(std::string_view function, std::string_view field, float value) {
    throwInvalid(function, field, "finite", value);
}

void failNotFinite(std::string_view function, std::string_view field, glm::vec2 value) {
    throwInvalid(function, field, "finite", value);
}

} // namespace detail

} // namespace e2d::core
