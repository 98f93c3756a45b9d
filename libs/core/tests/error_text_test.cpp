// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>

using namespace e2d::core;

namespace {

std::string messageOf(void (*call)()) {
    try {
        call();
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

} // namespace

TEST(ErrorText, NumbersReadBackAsTheSameValueInPlainDigitsWhenReadable) {
    EXPECT_EQ(formatNumber(-1.0f), "-1");
    EXPECT_EQ(formatNumber(0.25f), "0.25");
    EXPECT_EQ(formatNumber(0.1f), "0.1"); // the float nearest 0.1, not 0.100000001
    EXPECT_EQ(formatNumber(0.1), "0.1");
    EXPECT_EQ(formatNumber(0.0f), "0");
    EXPECT_EQ(formatNumber(-0.0f), "-0");
    EXPECT_EQ(formatNumber(500000.0f), "500000");
    EXPECT_EQ(formatNumber(600000.0), "600000");
    EXPECT_EQ(formatNumber(0.0001f), "0.0001");
    EXPECT_EQ(formatNumber(123456789.0), "123456789");
    // Outside [1e-4, 1e9) the exponent form is shorter than the zeros it replaces.
    EXPECT_EQ(formatNumber(1.0e30f), "1e+30");
    EXPECT_EQ(formatNumber(3.0e-7), "3e-07");
    EXPECT_EQ(formatNumber(1.0e9), "1e+09");
    EXPECT_EQ(formatNumber(std::numeric_limits<float>::max()), "3.4028235e+38");
}

TEST(ErrorText, NonFiniteNumbersAreNamed) {
    EXPECT_EQ(formatNumber(std::numeric_limits<float>::quiet_NaN()), "nan");
    EXPECT_EQ(formatNumber(std::numeric_limits<double>::infinity()), "inf");
    EXPECT_EQ(formatNumber(-std::numeric_limits<float>::infinity()), "-inf");
}

TEST(ErrorText, WholeNumbersAndVectors) {
    EXPECT_EQ(formatNumber(-3), "-3");
    EXPECT_EQ(formatNumber(std::uint64_t{18446744073709551615u}), "18446744073709551615");
    EXPECT_EQ(formatVector(glm::vec2(1.0f, 6.0e5f)), "(1, 600000)");
    EXPECT_EQ(formatVector(glm::vec3(0.5f, -2.0f, std::numeric_limits<float>::quiet_NaN())),
              "(0.5, -2, nan)");
    EXPECT_EQ(formatVector(glm::ivec2(640, -1)), "(640, -1)");
}

TEST(ErrorText, QuotedTextIsPrintable) {
    EXPECT_EQ(quote("width"), "'width'");
    EXPECT_EQ(quote(""), "''");
    EXPECT_EQ(quote(std::string("wi\0dth", 6)), "'wi\\x00dth'");
    EXPECT_EQ(quote("a\nb\x7F"), "'a\\nb\\x7f'");
    EXPECT_EQ(quote("caf\xC3\xA9"), "'caf\xC3\xA9'");
    EXPECT_EQ(quote("\xFF"), "'\\xff'");
}

TEST(ErrorText, LongValuesAreCutOnACharacterBoundary) {
    EXPECT_EQ(shortened("abcdef", 6), "abcdef");
    EXPECT_EQ(shortened("abcdefg", 6), "abc...");
    // "\xC3\xA9" (é) would be split after its first byte: the cut moves before it.
    EXPECT_EQ(shortened("ab\xC3\xA9xyz", 6), "ab...");
    EXPECT_EQ(quote(std::string(100, 'x')), "'" + std::string(77, 'x') + "...'");
    EXPECT_EQ(quote(std::string(100, 'x'), 10), "'xxxxxxx...'");
    // Cut first, escaped after: the escape of a control byte is never cut in half.
    EXPECT_EQ(quote(std::string(6, '\x01') + "tail", 6), "'\\x01\\x01\\x01...'");
}

TEST(ErrorText, ThrownMessagesNameFunctionFieldAndValue) {
    EXPECT_EQ(messageOf([] { throwError("core::Thing::set()", "no thing"); }),
              "core::Thing::set(): no thing");
    EXPECT_EQ(messageOf([] { throwInvalid("core::Thing::set()", "def.size", ">= 0", -1.5f); }),
              "core::Thing::set(): def.size must be >= 0, got -1.5");
    EXPECT_EQ(messageOf([] { throwInvalid("core::Thing::set()", "count", "in [1, 8]", 9); }),
              "core::Thing::set(): count must be in [1, 8], got 9");
    EXPECT_EQ(messageOf([] { throwInvalid("f()", "at", "inside", glm::vec2(1.0f, 2.0f)); }),
              "f(): at must be inside, got (1, 2)");
    EXPECT_EQ(
        messageOf([] { requireFinite("f()", "zoom", std::numeric_limits<float>::infinity()); }),
        "f(): zoom must be finite, got inf");
    EXPECT_EQ(messageOf([] {
                  requireFinite("f()", "p",
                                glm::vec2(0.0f, std::numeric_limits<float>::quiet_NaN()));
              }),
              "f(): p must be finite, got (0, nan)");
    EXPECT_EQ(messageOf([] { requireFinite("f()", "p", glm::vec2(0.0f, 1.0f)); }), "no error");
}
