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
    // Appended piece by piece: GCC 12 at -O3 misreads `"'" + std::string` as an overlapping
    // memcpy (-Werror=restrict, a known false positive).
    std::string out = "'";
    out.append(core::printable(text.substr(0, maxShown)));
    if (text.size() > maxShown) {
        out += "...";
    }
    return out.append("'");
}

} // namespace e2d::input::detail
