// SPDX-License-Identifier: MIT
#include <e2d/core/printable.hpp>

#include <e2d/core/utf8.hpp>

#include <cstdint>

namespace e2d::core {

namespace {

void escapeByte(std::string& out, char byte) {
    constexpr char kHex[] = "0123456789abcdef";
    const auto c = static_cast<std::uint8_t>(byte);
    out += "\\x";
    out += kHex[c >> 4];
    out += kHex[c & 0xF];
}

} // namespace

std::string printable(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    std::size_t pos = 0;
    while (pos < text.size()) {
        const std::size_t start = pos;
        const char32_t c = decodeUtf8(text, pos);
        const std::string_view bytes = text.substr(start, pos - start);
        if (c == '\\') {
            out += "\\\\";
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\t') {
            out += "\\t";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c < 0x20 || c == 0x7F ||
                   (c == kReplacementCharacter && bytes != "\xEF\xBF\xBD")) {
            // Control bytes, and the bytes the decoder could not read as UTF-8, one by one.
            for (const char byte : bytes) {
                escapeByte(out, byte);
            }
        } else {
            out.append(bytes);
        }
    }
    return out;
}

} // namespace e2d::core
