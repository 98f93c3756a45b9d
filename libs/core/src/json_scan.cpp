// SPDX-License-Identifier: MIT
#include <e2d/core/json_scan.hpp>

#include <algorithm>

namespace e2d::core {

TextPosition positionOf(std::string_view text, std::size_t offset) noexcept {
    offset = std::min(offset, text.size());
    TextPosition at;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++at.line;
            at.column = 1;
        } else {
            ++at.column;
        }
    }
    return at;
}

std::optional<std::size_t> findJsonNestingBeyond(std::string_view json, int maxDepth) noexcept {
    int depth = 0;
    bool inString = false;
    for (std::size_t i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (inString) {
            if (c == '\\') {
                ++i; // the escaped character, a quote included, does not end the string
            } else if (c == '"') {
                inString = false;
            }
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > maxDepth) {
                return i;
            }
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return std::nullopt;
}

} // namespace e2d::core
