// SPDX-License-Identifier: MIT
#include <e2d/core/printable.hpp>

#include <gtest/gtest.h>

#include <string>

using e2d::core::printable;

TEST(Printable, KeepsTextAndUtf8AndEscapesTheRest) {
    EXPECT_EQ(printable("width = 12"), "width = 12");
    EXPECT_EQ(printable("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x8E\xAE"),
              "caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x8E\xAE");
    EXPECT_EQ(printable(std::string("a\0b", 3)), "a\\x00b");
    EXPECT_EQ(printable("tab\there\r\n"), "tab\\there\\r\\n");
    EXPECT_EQ(printable("back\\slash"), "back\\\\slash");
    EXPECT_EQ(printable("\x7F\x1B"), "\\x7f\\x1b");
    // Not UTF-8: a lone continuation byte, a cut sequence, an overlong '/', a surrogate.
    EXPECT_EQ(printable("\x80"), "\\x80");
    EXPECT_EQ(printable("\xE2\x82"), "\\xe2\\x82");
    EXPECT_EQ(printable("\xC0\xAF"), "\\xc0\\xaf");
    EXPECT_EQ(printable("\xED\xA0\x80"), "\\xed\\xa0\\x80");
    EXPECT_EQ(printable(""), "");
}
