// SPDX-License-Identifier: MIT
#include <e2d/core/printable.hpp>
#include <e2d/core/utf8.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

using e2d::core::decodeUtf8;
using e2d::core::printable;

namespace {

std::vector<char32_t> decodeAll(std::string_view text) {
    std::vector<char32_t> out;
    std::size_t pos = 0;
    while (pos < text.size()) {
        const std::size_t before = pos;
        out.push_back(decodeUtf8(text, pos));
        EXPECT_GT(pos, before);
    }
    return out;
}

} // namespace

TEST(Utf8, DecodesOneToFourByteSequences) {
    EXPECT_THAT(decodeAll("A\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80"),
                testing::ElementsAre(U'A', U'\u00E9', U'\u20AC', U'\U0001F600'));
    EXPECT_THAT(decodeAll(std::string_view("\0z", 2)), testing::ElementsAre(U'\0', U'z'));
}

TEST(Utf8, EveryIllFormedSequenceGivesReplacementAndMovesOn) {
    constexpr char32_t R = 0xFFFD;
    // A stray continuation byte, a byte that never starts a sequence, overlong forms.
    EXPECT_THAT(decodeAll("\x80z"), testing::ElementsAre(R, U'z'));
    EXPECT_THAT(decodeAll("\xFFz"), testing::ElementsAre(R, U'z'));
    EXPECT_THAT(decodeAll("\xC0\xAFz"), testing::ElementsAre(R, R, U'z'));
    EXPECT_THAT(decodeAll("\xE0\x80\xAFz"), testing::ElementsAre(R, R, R, U'z'));
    // A surrogate (U+D800) and a value past U+10FFFF.
    EXPECT_THAT(decodeAll("\xED\xA0\x80z"), testing::ElementsAre(R, R, R, U'z'));
    EXPECT_THAT(decodeAll("\xF4\x90\x80\x80z"), testing::ElementsAre(R, R, R, R, U'z'));
    // Truncated: the valid prefix is one replacement, then the next character survives.
    EXPECT_THAT(decodeAll("\xE2\x82z"), testing::ElementsAre(R, U'z'));
    EXPECT_THAT(decodeAll("\xF0\x9F\x98"), testing::ElementsAre(R));
    // Largest valid values of each length.
    EXPECT_THAT(decodeAll("\x7F\xDF\xBF\xEF\xBF\xBF\xF4\x8F\xBF\xBF"),
                testing::ElementsAre(U'\x7F', U'\u07FF', U'\uFFFF', U'\U0010FFFF'));
}

TEST(Utf8, IsPrintableTellsWhetherTextNeedsEscaping) {
    using e2d::core::isPrintable;
    EXPECT_TRUE(isPrintable("caf\xC3\xA9 \\ \xEF\xBF\xBD"));
    EXPECT_FALSE(isPrintable("a\tb"));
    EXPECT_FALSE(isPrintable(std::string_view("a\0b", 3)));
    EXPECT_FALSE(isPrintable("\xE2\x82"));
    for (const char* raw : {"\x01\xFF", "\xC0\xAF", "ok"}) {
        EXPECT_TRUE(isPrintable(printable(raw))) << raw;
    }
}
