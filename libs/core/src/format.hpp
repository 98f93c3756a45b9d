// SPDX-License-Identifier: MIT
#pragma once

#include <cxxabi.h>

#include <charconv>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>
#include <typeinfo>

namespace e2d::core::detail {

// Shortest round-trip text, so messages say "got -1" rather than "got -1.000000".
template <class T>
std::string formatNumber(T value) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
    return std::string(buffer, result.ptr);
}

inline std::string quoted(std::string_view text) {
    std::string out;
    out.reserve(text.size() + 2);
    out += '\'';
    out += text;
    out += '\'';
    return out;
}

// A type's readable name ("e2d::physics::PhysicsSystem"), for messages.
inline std::string demangledName(const std::type_info& type) {
    int status = 0;
    const std::unique_ptr<char, void (*)(void*)> name(abi::__cxa_demangle(type.name(), nullptr, nullptr, &status),
                                                       std::free);
    return status == 0 && name ? std::string(name.get()) : std::string(type.name());
}

} // namespace e2d::core::detail
