// SPDX-License-Identifier: MIT
#include <e2d/core/diagnostics.hpp>
#include <e2d/core/text_file.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace e2d::core;

TEST(Diagnostics, OneFormatLeavesOutWhatIsAbsent) {
    EXPECT_EQ((Diagnostic{Severity::Error, "game.cfg", 12, 0, "windowWidth",
                          "expected an integer, got 'abc'"}
                   .toString()),
              "game.cfg:12: windowWidth: expected an integer, got 'abc'");
    EXPECT_EQ((Diagnostic{Severity::Error, "pads.txt", 3, 7, "", "GUID must be 32 hex digits"}
                   .toString()),
              "pads.txt:3:7: GUID must be 32 hex digits");
    EXPECT_EQ(
        (Diagnostic{Severity::Warning, "sheet.json", 0, 5, "frames[0].w", "expected an integer"}
             .toString()),
        "sheet.json: frames[0].w: expected an integer")
        << "a column without a line means nothing";
    EXPECT_EQ(
        (Diagnostic{Severity::Warning, "missing.cfg", 0, 0, "", "cannot read the file"}.toString()),
        "missing.cfg: cannot read the file");
    EXPECT_EQ((Diagnostic{Severity::Error, "", 3, 7, "bodies[2]", "not valid JSON"}.toString()),
              "line 3, column 7: bodies[2]: not valid JSON");
    EXPECT_EQ((Diagnostic{Severity::Error, "", 0, 0, "radius", "must be > 0"}.toString()),
              "radius: must be > 0");
}

TEST(Diagnostics, OkMeansNoErrorsWarningsAllowed) {
    Diagnostics d;
    EXPECT_TRUE(d.ok());
    EXPECT_TRUE(d.empty());
    EXPECT_EQ(d.firstError(), nullptr);
    d.warning("a.txt", 1, "unknown field 'q', ignored");
    EXPECT_TRUE(d.ok());
    EXPECT_EQ(d.warningCount(), 1);
    d.error("a.txt", 2, "expected '='", "key");
    d.warning("a.txt", 3, "duplicate");
    EXPECT_FALSE(d.ok());
    EXPECT_EQ(d.errorCount(), 1);
    EXPECT_EQ(d.warningCount(), 2);
    ASSERT_EQ(d.size(), 3u);
    ASSERT_NE(d.firstError(), nullptr);
    EXPECT_EQ(d.firstError()->line, 2);
    EXPECT_EQ(d[1].field, "key");
    ASSERT_EQ(d.errors().size(), 1u);
    EXPECT_EQ(d.errors()[0].message, "expected '='");
    ASSERT_EQ(d.warnings().size(), 2u);
    EXPECT_EQ(d.warnings()[1].line, 3);
    EXPECT_EQ(
        d.toString(),
        "a.txt:1: unknown field 'q', ignored\na.txt:2: key: expected '='\na.txt:3: duplicate");
}

TEST(Diagnostics, ParseErrorIsACoreErrorThatKeepsItsDiagnostic) {
    try {
        throw ParseError(Diagnostic{Severity::Error, "s.json", 0, 0, "frames", "expected an array"},
                         "render::SpriteSheet: ");
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "render::SpriteSheet: s.json: frames: expected an array");
        const auto* parse = dynamic_cast<const ParseError*>(&e);
        ASSERT_NE(parse, nullptr);
        EXPECT_EQ(parse->diagnostic().field, "frames");
    }
}

TEST(TextFile, ReadsEveryByteOrSaysWhyNot) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "e2d-core-text-file-test";
    std::filesystem::create_directories(dir);
    const std::filesystem::path path = dir / "bytes.txt";
    const std::string bytes("a\r\nb\0c\xFF", 7);
    std::ofstream(path, std::ios::binary) << bytes;
    const TextFile read = readTextFile(path);
    EXPECT_TRUE(read.ok()) << read.error;
    EXPECT_EQ(read.text, bytes);

    const TextFile missing = readTextFile(dir / "missing.txt");
    EXPECT_FALSE(missing.ok());
    EXPECT_EQ(missing.error, "no such file");
    EXPECT_EQ(readTextFile(dir).error, "it is a directory");

    EXPECT_EQ(readRequiredTextFile(path, "f()"), bytes);
    try {
        static_cast<void>(readRequiredTextFile(dir, "input::ActionMap::load()"));
        ADD_FAILURE() << "a directory was read";
    } catch (const Error& e) {
        EXPECT_EQ(e.what(), "input::ActionMap::load(): cannot read '" + dir.string() +
                                "': it is a directory");
    }

    std::filesystem::permissions(path, std::filesystem::perms::none);
    if (!std::ifstream(path)) { // root reads the file whatever its permissions
        EXPECT_EQ(readTextFile(path).error, "Permission denied");
    }
    std::filesystem::remove_all(dir);
}

TEST(TextFile, ByteOrderMarkIsSkipped) {
    EXPECT_EQ(withoutByteOrderMark("\xEF\xBB\xBFkey = 1"), "key = 1");
    EXPECT_EQ(withoutByteOrderMark("key = 1"), "key = 1");
    EXPECT_EQ(withoutByteOrderMark("\xEF\xBB"), "\xEF\xBB");
}
