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

/// `text` made safe to quote in a message: well-formed UTF-8 that prints is kept as it is;
/// every other byte (controls, DEL, C1 controls, ill-formed UTF-8, NUL) becomes `\xNN`, and a
/// backslash becomes `\\`, so the result is printable, holds no NUL and reads back unambiguously.
/// `printable("k\xFF\ty")` is `k\xFF\x09y`.
[[nodiscard]] std::string printable(std::string_view text);

/// True when every byte of `text` is part of well-formed UTF-8 that prints (no control
/// character, no NUL): what printable() returns always is.
[[nodiscard]] bool isPrintable(std::string_view text) noexcept;

} // namespace e2d::core
