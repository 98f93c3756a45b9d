// SPDX-License-Identifier: MIT
#include <e2d/core/utf8.hpp>

namespace e2d::core {

char32_t decodeUtf8(std::string_view text, std::size_t& pos) noexcept {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(pos);
    if (lead < 0x80) {
        ++pos;
        return lead;
    }
    int length = 0;
    char32_t value = 0;
    // The second byte's allowed range excludes overlong forms, surrogates and values past U+10FFFF.
    unsigned char low = 0x80;
    unsigned char high = 0xBF;
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2;
        value = lead & 0x1Fu;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3;
        value = lead & 0x0Fu;
        low = lead == 0xE0 ? 0xA0 : 0x80;
        high = lead == 0xED ? 0x9F : 0xBF;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4;
        value = lead & 0x07u;
        low = lead == 0xF0 ? 0x90 : 0x80;
        high = lead == 0xF4 ? 0x8F : 0xBF;
    } else {
        ++pos;
        return kReplacementCharacter;
    }
    std::size_t i = pos + 1;
    for (int k = 1; k < length; ++k, ++i) {
        if (i >= text.size()) {
            pos = i;
            return kReplacementCharacter;
        }
        const unsigned char b = byte(i);
        if (b < (k == 1 ? low : 0x80) || b > (k == 1 ? high : 0xBF)) {
            pos = i;
            return kReplacementCharacter;
        }
        value = (value << 6) | (b & 0x3Fu);
    }
    pos = i;
    return value;
}

bool isPrintable(std::string_view text) noexcept {
    std::size_t pos = 0;
    while (pos < text.size()) {
        const std::size_t start = pos;
        const char32_t c = decodeUtf8(text, pos);
        // U+FFFD written in the text is text; one made by the decoder stands for bad bytes.
        if (c < 0x20 || c == 0x7F ||
            (c == kReplacementCharacter && text.substr(start, pos - start) != "\xEF\xBF\xBD")) {
            return false;
        }
    }
    return true;
}

} // namespace e2d::core
