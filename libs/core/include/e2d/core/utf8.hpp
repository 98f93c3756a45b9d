// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace e2d::core {

/// Replacement for every ill-formed UTF-8 sequence (U+FFFD).
inline constexpr char32_t kReplacementCharacter = 0xFFFD;

/// Decodes the code point starting at `text[pos]` and moves `pos` past it. An ill-formed
/// sequence (stray continuation byte, truncated sequence, overlong form, surrogate, value above
/// U+10FFFF, bytes F5..FF) gives U+FFFD and consumes its maximal valid prefix, at least one byte
/// (Unicode's "maximal subpart" practice), so decoding always moves on. `pos` < text.size().
char32_t decodeUtf8(std::string_view text, std::size_t& pos) noexcept;

/// True when `text` holds no control byte (below 0x20, or 0x7F; NUL included) and is
/// well-formed UTF-8: what core::printable() (printable.hpp) returns always is. For checks
/// that a message quotes nothing raw.
[[nodiscard]] bool isPrintable(std::string_view text) noexcept;

} // namespace e2d::core
