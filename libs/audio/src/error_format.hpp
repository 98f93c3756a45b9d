// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/error.hpp>

#include <sstream>
#include <string>
#include <string_view>

namespace e2d::audio::detail {

/// A number as a message shows it: "-1", "0.5", "1e+30", "nan".
template <class T>
std::string formatValue(T value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

/// Throws core::Error("<function>: <field> must be <rule>, got <value>").
template <class T>
[[noreturn]] void throwInvalid(std::string_view function, std::string_view field, std::string_view rule,
                               T value) {
    throw core::Error(std::string(function) + ": " + std::string(field) + " must be " + std::string(rule) +
                      ", got " + formatValue(value));
}

} // namespace e2d::audio::detail
