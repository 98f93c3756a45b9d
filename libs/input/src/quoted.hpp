// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/printable.hpp>

#include <cstddef>
#include <string>
#include <string_view>

namespace e2d::input::detail {

/// `text` in single quotes for a message, escaped by core::printable() (a control byte, a NUL
/// or ill-formed UTF-8 read from a file becomes `\xNN`, so it can neither hide nor cut the
/// message short), and cut after `maxShown` bytes with "...".
inline std::string quoted(std::string_view text, std::size_t maxShown = 80) {
    std::string out = "'" + core::printable(text.substr(0, maxShown));
    if (text.size() > maxShown) {
        out += "...";
    }
    return out + "'";
}

} // namespace e2d::input::detail
