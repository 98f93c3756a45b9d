// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

/// Checks made on JSON text before a JSON library parses it. Core reads no JSON itself; the
/// libraries that do (render's sprite sheets, the validation scenarios) share these, so every
/// JSON the project reads is bounded the same way.
namespace e2d::core {

/// A place in a text, both from 1; the column counts bytes.
struct TextPosition {
    int line = 1;
    int column = 1;
};

/// The line and column of byte `offset` of `text` (clamped to its end).
[[nodiscard]] TextPosition positionOf(std::string_view text, std::size_t offset) noexcept;

/// How deep arrays and objects may nest in the JSON files e2d reads unless a reader says
/// otherwise: far more than any sheet or scenario uses (4 to 6), far less than the depth at
/// which recursive JSON code (printing, copying, comparing a value) runs out of stack (about
/// 10 000 levels under AddressSanitizer).
inline constexpr int kMaxJsonDepth = 256;

/// The byte offset of the first `[` or `{` of `json` that opens nesting level `maxDepth + 1`
/// (the outermost array or object is level 1), or nullopt when nothing nests deeper than
/// `maxDepth`. Brackets inside strings do not count. Reads the text as JSON tokens without
/// checking them, in one pass and constant stack, so it is safe on any bytes; on text a JSON
/// parser accepts (or accepts up to the point it stops) it agrees with the parser's depth.
[[nodiscard]] std::optional<std::size_t>
findJsonNestingBeyond(std::string_view json, int maxDepth = kMaxJsonDepth) noexcept;

} // namespace e2d::core
