// SPDX-License-Identifier: MIT
#include <e2d/core/json_scan.hpp>

#include <gtest/gtest.h>

#include <string>

using e2d::core::findJsonNestingBeyond;
using e2d::core::positionOf;

TEST(JsonScan, FindsTheBracketThatOpensOneLevelTooMany) {
    EXPECT_EQ(findJsonNestingBeyond("[[1], {\"a\": [2]}]", 3), std::nullopt);
    EXPECT_EQ(findJsonNestingBeyond("[[1], {\"a\": [2]}]", 2), std::optional<std::size_t>(12));
    EXPECT_EQ(findJsonNestingBeyond("{}", 0), std::optional<std::size_t>(0));
    EXPECT_EQ(findJsonNestingBeyond("", 0), std::nullopt);
    // Closed levels are counted off: a long flat run of siblings is depth 2.
    std::string siblings = "[";
    for (int i = 0; i < 1000; ++i) {
        siblings += "[],";
    }
    siblings += "[]]";
    EXPECT_EQ(findJsonNestingBeyond(siblings, 2), std::nullopt);
}

TEST(JsonScan, BracketsInStringsDoNotCount) {
    EXPECT_EQ(findJsonNestingBeyond(R"({"[[[[": "{{{{"})", 1), std::nullopt);
    // An escaped quote does not end the string; an escaped backslash does not escape the quote.
    EXPECT_EQ(findJsonNestingBeyond(R"(["\"[[[", "\\", [[0]]])", 2),
              std::optional<std::size_t>(17));
}

TEST(JsonScan, AHundredThousandLevelsCutShortOrNotAreFoundInConstantStack) {
    const int n = 100000;
    const std::string deep = std::string(n, '[') + std::string(n, ']');
    EXPECT_EQ(findJsonNestingBeyond(deep), std::optional<std::size_t>(256));
    EXPECT_EQ(findJsonNestingBeyond(deep.substr(0, n / 2)), std::optional<std::size_t>(256));
    EXPECT_EQ(findJsonNestingBeyond(deep, n), std::nullopt);
}

TEST(JsonScan, PositionsCountLinesAndBytesFromOne) {
    const std::string text = "{\n  \"a\": [\n[";
    EXPECT_EQ(positionOf(text, 0).line, 1);
    EXPECT_EQ(positionOf(text, 0).column, 1);
    EXPECT_EQ(positionOf(text, 9).line, 2);
    EXPECT_EQ(positionOf(text, 9).column, 8);
    EXPECT_EQ(positionOf(text, 11).line, 3);
    EXPECT_EQ(positionOf(text, 11).column, 1);
    EXPECT_EQ(positionOf(text, 999).line, 3); // clamped to the end
    EXPECT_EQ(positionOf(text, 999).column, 2);
}
