// SPDX-License-Identifier: MIT
// The generic `key = value` reader, with the keys of a small settings struct of every type.
#include <e2d/core/config.hpp>
#include <e2d/core/error.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using e2d::core::ConfigBounds;
using e2d::core::ConfigReader;
using e2d::core::ConfigReport;
using e2d::core::Diagnostic;
using e2d::core::Severity;
using testing::ElementsAre;
using testing::IsEmpty;

namespace {

enum class Shape { Round, Square };

struct Settings {
    std::string title = "none";
    int width = 640;
    std::int64_t frames = 0;
    std::uint64_t seed = 0;
    float gain = 0.5f;
    double step = 0.25;
    bool smooth = true;
    Shape shape = Shape::Round;
};

struct Reader {
    Settings settings;
    ConfigReader reader;

    Reader() {
        reader.add("title", settings.title);
        reader.add("width", settings.width, ConfigBounds::atLeast(1.0));
        reader.add("frames", settings.frames);
        reader.add("seed", settings.seed);
        reader.add("gain", settings.gain, ConfigBounds{0.0, 1.0});
        reader.add("step", settings.step, ConfigBounds{0.0, 1.0, true});
        reader.add("smooth", settings.smooth);
        reader.add("shape", settings.shape, {{"round", Shape::Round}, {"square", Shape::Square}});
    }
};

std::vector<std::string> texts(const ConfigReport& report) {
    std::vector<std::string> out;
    for (const Diagnostic& d : report.diagnostics) {
        out.push_back(d.toString());
    }
    return out;
}

} // namespace

TEST(ConfigReader, ReadsEveryTypeWithWhitespaceCommentsCrlfAndABom) {
    Reader r;
    const ConfigReport report = r.reader.read("\xEF\xBB\xBF# comment\r\n"
                                              "   \t\r\n"
                                              "  title   =   My  Game # not a comment  \r\n"
                                              "\twidth=800\r\n"
                                              "   # indented comment\n"
                                              "seed = 18446744073709551615\n"
                                              "frames = -9000000000\n"
                                              "gain = +0.75\n"
                                              "step = 1e-2\n"
                                              "smooth = false\n"
                                              "shape = square",
                                              "game.cfg");
    EXPECT_THAT(texts(report), IsEmpty());
    EXPECT_EQ(r.settings.title, "My  Game # not a comment");
    EXPECT_EQ(r.settings.width, 800);
    EXPECT_EQ(r.settings.seed, 18446744073709551615ull);
    EXPECT_EQ(r.settings.frames, -9000000000);
    EXPECT_EQ(r.settings.gain, 0.75f);
    EXPECT_EQ(r.settings.step, 0.01);
    EXPECT_FALSE(r.settings.smooth);
    EXPECT_EQ(r.settings.shape, Shape::Square);
    EXPECT_EQ(report.lineOf("width"), 4);
    EXPECT_EQ(report.lineOf("nothing"), 0);
}

TEST(ConfigReader, EveryErrorKindWithItsLineAndWrongValuesKeepTheField) {
    Reader r;
    const ConfigReport report = r.reader.read("width = abc\n"         // 1: not a number
                                              "width = 12px\n"        // 2: trailing junk
                                              "width = 1.5\n"         // 3: not an integer
                                              "width = -5\n"          // 4: below the minimum
                                              "width = 99999999999\n" // 5: overflows int
                                              "shape = oval\n"        // 6: unknown enum value
                                              "just some words\n"     // 7: missing '='
                                              " = 5\n"                // 8: empty key
                                              "gain = 2\n"            // 9: above the maximum
                                              "step = 0\n"            // 10: must be > 0
                                              "gain = inf\n"          // 11: not finite
                                              "gain = 1e60\n"         // 12: overflows float
                                              "smooth = yes\n"        // 13: not a boolean
                                              "frames =\n",           // 14: empty value
                                              "game.cfg");
    EXPECT_THAT(
        texts(report),
        ElementsAre("game.cfg:1: width: expected an integer, got 'abc'",
                    "game.cfg:2: width: expected an integer, got '12px'",
                    "game.cfg:3: width: expected an integer, got '1.5'",
                    "game.cfg:4: width: must be >= 1, got -5",
                    "game.cfg:5: width: integer out of range, got '99999999999'",
                    "game.cfg:6: shape: unknown value 'oval', expected one of: round, square",
                    "game.cfg:7: expected 'key = value', got 'just some words'",
                    "game.cfg:8: empty key before '=' in '= 5'",
                    "game.cfg:9: gain: must be in [0, 1], got 2",
                    "game.cfg:10: step: must be in (0, 1], got 0",
                    "game.cfg:11: gain: expected a finite number, got 'inf'",
                    "game.cfg:12: gain: number out of range, got '1e60'",
                    "game.cfg:13: smooth: expected true or false, got 'yes'",
                    "game.cfg:14: frames: expected an integer, got ''"));
    for (const Diagnostic& d : report.diagnostics) {
        EXPECT_EQ(d.severity, Severity::Error);
    }
    EXPECT_EQ(report.diagnostics[0].line, 1);
    EXPECT_EQ(report.diagnostics[0].field, "width");
    EXPECT_EQ(report.diagnostics[6].field, "");
    EXPECT_FALSE(report.diagnostics.ok());
    EXPECT_EQ(report.diagnostics.errorCount(), 14);
    EXPECT_EQ(report.diagnostics.warningCount(), 0);
    const Settings defaults;
    EXPECT_EQ(r.settings.width, defaults.width);
    EXPECT_EQ(r.settings.shape, defaults.shape);
    EXPECT_EQ(r.settings.gain, defaults.gain);
    EXPECT_EQ(r.settings.step, defaults.step);
    EXPECT_EQ(report.lineOf("width"), 0) << "no line set it without error";
}

TEST(ConfigReader, UnknownKeysSuggestTheNearestKnownKey) {
    Reader r;
    const ConfigReport report = r.reader.read("widht = 800\n"
                                              "\n"
                                              "width = 640\n"
                                              "smoth = true\n"
                                              "colour = red\n"
                                              "Width = 2\n"
                                              "width = 641\n",
                                              "game.cfg");
    EXPECT_THAT(texts(report),
                ElementsAre("game.cfg:1: widht: unknown key, ignored (did you mean 'width'?)",
                            "game.cfg:4: smoth: unknown key, ignored (did you mean 'smooth'?)",
                            "game.cfg:5: colour: unknown key, ignored",
                            "game.cfg:6: Width: unknown key, ignored (did you mean 'width'?)",
                            "game.cfg:7: width: duplicate key, replaces the value set on line 3"));
    EXPECT_EQ(report.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(r.settings.width, 641); // the last one wins
    EXPECT_TRUE(report.diagnostics.ok()) << "warnings only";
    EXPECT_EQ(report.diagnostics.warningCount(), 5);
}

TEST(ConfigReader, RawBytesInMessagesAreEscaped) {
    Reader r;
    const std::string text = std::string("wi\0dth = 3\n", 11) + "width = 1\x1b[2J\n" +
                             "shape = \xff\xfe\n" + "\x01\x02 no equals\n";
    const ConfigReport report = r.reader.read(text, "bin.cfg");
    EXPECT_THAT(
        texts(report),
        ElementsAre("bin.cfg:1: wi\\x00dth: unknown key, ignored (did you mean 'width'?)",
                    "bin.cfg:2: width: expected an integer, got '1\\x1b[2J'",
                    "bin.cfg:3: shape: unknown value '\\xff\\xfe', expected one of: round, square",
                    "bin.cfg:4: expected 'key = value', got '\\x01\\x02 no equals'"));
    for (const std::string& line : texts(report)) {
        EXPECT_EQ(line.find('\0'), std::string::npos);
        EXPECT_EQ(line.find('\x1b'), std::string::npos);
    }
}

TEST(ConfigReader, KeysAreCheckedWhenAdded) {
    ConfigReader reader;
    int value = 0;
    reader.add("value", value);
    EXPECT_THROW(reader.add("value", value), e2d::core::Error);
    EXPECT_THROW(reader.add("", value), e2d::core::Error);
    EXPECT_THROW(reader.add("two words", value), e2d::core::Error);
    EXPECT_THROW(reader.add("a=b", value), e2d::core::Error);
    EXPECT_THROW(reader.add("other", ConfigReader::Setter{}), e2d::core::Error);
    EXPECT_THAT(reader.keys(), ElementsAre("value"));
}

TEST(ConfigReader, EmptyTextChangesNothing) {
    Reader r;
    EXPECT_TRUE(r.reader.read("", "empty.cfg").diagnostics.empty());
    EXPECT_EQ(r.settings.width, 640);
}

TEST(ConfigReader, MissingFileOrFolderWarnsAndChangesNothing) {
    Reader r;
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "e2d-core-test-does-not-exist.cfg";
    const ConfigReport report = r.reader.load(path);
    ASSERT_EQ(report.diagnostics.size(), 1u);
    EXPECT_EQ(report.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(report.diagnostics[0].line, 0);
    EXPECT_EQ(report.diagnostics[0].toString(),
              path.string() + ": cannot read the file (no such file), using the defaults");
    EXPECT_EQ(r.settings.width, 640);
    const ConfigReport folder = r.reader.load(std::filesystem::temp_directory_path());
    ASSERT_EQ(folder.diagnostics.size(), 1u);
    EXPECT_EQ(folder.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(folder.diagnostics[0].message,
              "cannot read the file (it is a directory), using the defaults");
}

TEST(ConfigReader, LoadsAFile) {
    Reader r;
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "e2d-core-test-load.cfg";
    std::ofstream(path, std::ios::binary) << "# test\ntitle = Loaded Game\nwidth = x\n";
    const ConfigReport report = r.reader.load(path);
    std::filesystem::remove(path);
    EXPECT_EQ(r.settings.title, "Loaded Game");
    EXPECT_THAT(texts(report),
                ElementsAre(path.string() + ":3: width: expected an integer, got 'x'"));
}

TEST(ConfigReader, ChecksAcrossKeysAreReportedOnTheLineOfTheKey) {
    Reader r;
    ConfigReport report = r.reader.read("width = 10\nframes = 20\n", "x.cfg");
    report.error("x.cfg", "frames", "must be <= width (10), got 20");
    EXPECT_THAT(texts(report), ElementsAre("x.cfg:2: frames: must be <= width (10), got 20"));
}
