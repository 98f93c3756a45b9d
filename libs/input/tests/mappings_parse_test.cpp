// SPDX-License-Identifier: MIT
// The mapping-line checker alone (no GLFW); mappings_glfw_test.cpp feeds GLFW itself.
#include <e2d/core/error.hpp>
#include <e2d/input/gamepad_mappings.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace e2d::input {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

const std::string kPad =
    "030000005e0400008e02000010010000,X360 Pad,a:b0,b:b1,back:b6,dpdown:h0.4,dpleft:h0.8,"
    "dpright:h0.2,dpup:h0.1,guide:b8,leftshoulder:b4,leftstick:b9,lefttrigger:a2,leftx:a0,"
    "lefty:a1~,rightshoulder:b5,rightstick:b10,righttrigger:+a5,rightx:a3,righty:-a4,start:b7,"
    "x:b2,y:b3,platform:Linux,";

std::vector<int> lines(const MappingParseResult& r) {
    std::vector<int> out;
    for (const e2d::core::Diagnostic& e : r.diagnostics.errors()) {
        out.push_back(e.line);
    }
    return out;
}

std::string problem(const std::string& line) {
    const MappingParseResult r = parseGamepadMappings(line, "t");
    return r.diagnostics.ok() ? std::string("ok") : r.diagnostics.errors()[0].toString();
}

TEST(MappingParse, AWellFormedLineIsKeptAsIs) {
    const MappingParseResult r = parseGamepadMappings(kPad);
    EXPECT_TRUE(r.diagnostics.ok());
    EXPECT_THAT(r.lines, ElementsAre(kPad));
    EXPECT_EQ(r.otherPlatform, 0);
}

TEST(MappingParse, CommentsBlankLinesAndOtherPlatformsAreNotErrors) {
    const std::string windows = "03000000de280000ff11000000000000,Other,a:b0,platform:Windows,";
    const std::string text =
        "# SDL database\r\n\n   \n" + kPad + "\r\n" + windows + "\n  # indented comment\n";
    const MappingParseResult r = parseGamepadMappings(text);
    EXPECT_TRUE(r.diagnostics.ok());
    EXPECT_THAT(r.lines, ElementsAre(kPad)); // the \r is not part of the line
    EXPECT_EQ(r.otherPlatform, 1);
}

TEST(MappingParse, EachBadLineIsReportedWithItsNumberAndTheGoodOnesKept) {
    const std::string text = kPad +
                             "\n"                      // 1 good
                             "0300000,bad guid,a:b0\n" // 2
                             "# fine\n"                // 3
                             + kPad +
                             "\n"                                            // 4 good
                             "03000000de280000ff11000001000000,Name,a:q1\n"; // 5
    const MappingParseResult r = parseGamepadMappings(text, "pads.txt");
    EXPECT_EQ(r.lines.size(), 2u);
    EXPECT_THAT(lines(r), ElementsAre(2, 5));
    EXPECT_EQ(r.diagnostics.errors()[0].toString(),
              "pads.txt:2: GUID must be 32 hex digits, got '0300000'");
    EXPECT_EQ(r.diagnostics.errors()[1].toString(),
              "pads.txt:5: field 'a': expected bN, aN or hH.B, got 'q1'");
}

TEST(MappingParse, TheMistakesGlfwWouldSwallowAreCaught) {
    const std::string g = "03000000de280000ff11000001000000,";
    // GLFW takes these without an error (measured with GLFW 3.3.8): the checker does not.
    EXPECT_EQ(problem(g + "Name,a:q0,"), "t:1: field 'a': expected bN, aN or hH.B, got 'q0'");
    EXPECT_EQ(problem(g + "Name,a:b999999,"),
              "t:1: field 'a': button index must be 0..255, got 'b999999'");
    EXPECT_EQ(
        problem(g + "Name,+a:b0,"),
        "t:1: an output modifier (+/-) applies to an axis (leftx ... righttrigger), got '+a:b0'");
    EXPECT_EQ(problem(g + "Name,+leftx:q0,"),
              "t:1: field '+leftx': expected bN, aN or hH.B, got 'q0'");
    EXPECT_EQ(problem(g + "Name,dpup:h0.3,"),
              "t:1: field 'dpup': hat bit must be 1, 2, 4 or 8, got 'h0.3'");
    EXPECT_EQ(problem(g + "Name,dpup:h16.1,"),
              "t:1: field 'dpup': hat index must be 0..15, got 'h16.1'");
    EXPECT_EQ(problem(g + "Name,a:+b0,"),
              "t:1: field 'a': a half-axis prefix (+/-) applies to axes only, got '+b0'");
    EXPECT_EQ(problem(g + "Name,leftx:a0x,"),
              "t:1: field 'leftx': unexpected 'x' after the element, got 'a0x'");
    EXPECT_EQ(problem(g + "Name,a,"), "t:1: field 'a' has no ':'");
    EXPECT_EQ(problem(g + "Name,platform:Linux,"), "t:1: no button or axis fields");
    // And the ones GLFW reports only through its error callback.
    EXPECT_EQ(problem(g + "Name"), "t:1: expected fields after the name");
    EXPECT_EQ(problem("03000000de280000ff11000001000000"), "t:1: expected a name after the GUID");
    EXPECT_EQ(problem(g + ",a:b0"), "t:1: the name is empty");
    EXPECT_EQ(problem(g + std::string(128, 'n') + ",a:b0"),
              "t:1: name is 128 bytes, GLFW takes at most 127");
    EXPECT_THAT(problem(g + "Name,a:b0," + std::string(1100, ',')),
                HasSubstr("GLFW takes at most 1023"));
    EXPECT_EQ(problem(g + std::string("Na\0me", 5) + ",a:b0"),
              "t:1: control character 0 in the line");
    // SDL extras are accepted.
    EXPECT_EQ(
        problem(g +
                "Name,a:b0,misc1:b15,paddle1:b16,touchpad:b17,crc:ab12,hint:!SDL_X:=1,sdk>=:33,"),
        "ok");
    EXPECT_EQ(problem(g + "Name,a:b0,misc2:b13,misc6:b14,"), "ok");
    // Bytes from the file are quoted escaped.
    EXPECT_EQ(problem("\xff\xfe" + g),
              "t:1: GUID must be 32 hex digits, got '\\xff\\xfe03000000de280000ff11000001000000'");
    EXPECT_EQ(problem(g + "Name,a:b0,platform:Linx,"),
              "t:1: unknown platform 'Linx' (SDL's are Windows, Mac OS X, Linux, Android, iOS)");
}

// Lines of SDL's community database that GLFW 3.3 can use, written here in its format: each
// was refused whole before. GLFW refuses a line with an output modifier, so that field is left
// out; it skips unknown fields itself.
TEST(MappingParse, EveryMappingGlfwCanUseIsKeptWithWarningsApartFromErrors) {
    const std::string g = "050000007e0500000620000001800000,";
    // A Joy-Con held sideways: its stick is a hat, each direction half an axis.
    const std::string joyCon =
        g + "Joy-Con (L),a:b0,b:b1,start:b9,+leftx:h0.2,-leftx:h0.8,+lefty:h0.4,-lefty:h0.1,"
            "leftshoulder:b4,platform:Linux,";
    // C buttons of an N64 pad as half axes, and a misc2 button (SDL 3).
    const std::string n64 =
        "03000000c82d00000290000011010000,N64 Adapter,a:b1,b:b0,+rightx:b9,-rightx:b8,"
        "misc2:b12,platform:Linux,";
    const std::string future =
        "03000000c82d00000290000011020000,Future Pad,a:b0,misc9:b20,face:abxy,platform:Linux,";
    const std::string xinput = "xinput,XInput Controller,a:b0,b:b1,platform:Windows,";
    const MappingParseResult r =
        parseGamepadMappings(joyCon + "\n" + n64 + "\n" + future + "\n" + xinput + "\n", "db.txt");
    EXPECT_TRUE(r.diagnostics.ok()) << r.diagnostics.errors()[0].toString();
    EXPECT_EQ(r.otherPlatform, 1);
    EXPECT_THAT(
        r.lines,
        ElementsAre(
            g + "Joy-Con (L),a:b0,b:b1,start:b9,leftshoulder:b4,platform:Linux,",
            "03000000c82d00000290000011010000,N64 Adapter,a:b1,b:b0,misc2:b12,platform:Linux,",
            "03000000c82d00000290000011020000,Future Pad,a:b0,platform:Linux,"));
    ASSERT_EQ(r.diagnostics.warnings().size(), 4u);
    EXPECT_EQ(r.diagnostics.warnings()[0].toString(),
              "db.txt:1: output modifiers '+leftx:h0.2', '-leftx:h0.8', '+lefty:h0.4', "
              "'-lefty:h0.1' left out (GLFW 3.3 has no half-axis outputs)");
    EXPECT_EQ(r.diagnostics.warnings()[1].toString(),
              "db.txt:2: output modifiers '+rightx:b9', '-rightx:b8' left out (GLFW 3.3 has no "
              "half-axis outputs)");
    EXPECT_THAT(r.diagnostics.warnings()[2].toString(),
                HasSubstr("db.txt:3: unknown field 'misc9' ignored"));
    EXPECT_THAT(r.diagnostics.warnings()[3].toString(),
                HasSubstr("db.txt:3: unknown field 'face' ignored"));
}

// The kept line is what GLFW gets and what a reader of it would read back: fields left out
// after a free-form value that ends in a blank leave no blank at the end (found by the fuzzer).
TEST(MappingParse, AKeptLineReadsBackAsItself) {
    const std::string g = "00000000000000000000000000000000,n,a:b0,";
    for (const std::string& line : {g + "hint:x ,q:r", g + "crc:\t,+leftx:a0", g + "hint:x ,"}) {
        const MappingParseResult r = parseGamepadMappings(line);
        ASSERT_EQ(r.lines.size(), 1u) << line;
        const MappingParseResult again = parseGamepadMappings(r.lines[0]);
        EXPECT_TRUE(again.diagnostics.empty()) << line;
        EXPECT_THAT(again.lines, ElementsAre(r.lines[0])) << line;
    }
    EXPECT_THAT(parseGamepadMappings(g + "hint:x ,q:r").lines, ElementsAre(g + "hint:x"));
}

// A database cut short (a download that stopped) ends inside its last line. Cut anywhere, that
// line lacks the ',' that closes each of SDL's lines or the platform field that ends them.
TEST(MappingParse, ACutLastLineIsAnErrorNotAMapping) {
    const std::string text = "# Game Controller DB\n" + kPad + "\n" + kPad + "\n";
    const std::size_t lastStart = text.size() - kPad.size() - 1;
    int refused = 0;
    for (std::size_t cut = lastStart + 1; cut < text.size() - 1; ++cut) {
        const MappingParseResult r = parseGamepadMappings(text.substr(0, cut), "db.txt");
        EXPECT_EQ(r.lines.size(), 1u) << "cut at " << cut;
        ASSERT_EQ(r.diagnostics.errors().size(), 1u) << "cut at " << cut;
        EXPECT_EQ(r.diagnostics.errors()[0].line, 3);
        EXPECT_THAT(r.diagnostics.errors()[0].toString(),
                    HasSubstr("db.txt:3: the text ends inside this line (no newline after it"));
        refused += 1;
    }
    EXPECT_EQ(refused, static_cast<int>(kPad.size()) - 1);
    EXPECT_THAT(
        parseGamepadMappings(text.substr(0, text.size() - 40)).diagnostics.errors()[0].toString(),
        HasSubstr("and no ',' closing its last field as every line before it has): cut short?"));
    EXPECT_THAT(parseGamepadMappings(text.substr(0, text.find(",platform:Linux,", lastStart) + 1))
                    .diagnostics.errors()[0]
                    .toString(),
                HasSubstr("and no platform field as every line before it has): cut short?"));
    // Whole, with or without the last newline, it is two mappings.
    EXPECT_EQ(parseGamepadMappings(text).lines.size(), 2u);
    EXPECT_EQ(parseGamepadMappings(text.substr(0, text.size() - 1)).lines.size(), 2u);
    // One line written in code needs neither, and is handed to GLFW as it is.
    EXPECT_THAT(parseGamepadMappings("03000000de280000ff11000001000000,Pad,a:b0,leftx:a0").lines,
                ElementsAre("03000000de280000ff11000001000000,Pad,a:b0,leftx:a0"));
}

TEST(MappingParse, AByteOrderMarkIsSkipped) {
    const MappingParseResult r = parseGamepadMappings("\xEF\xBB\xBF" + kPad + "\n");
    EXPECT_TRUE(r.diagnostics.ok());
    EXPECT_THAT(r.lines, ElementsAre(kPad));
}

TEST(MappingParse, ADirectoryIsAnErrorLikeAMissingFile) {
    const auto dir = std::filesystem::temp_directory_path();
    try {
        static_cast<void>(loadGamepadMappingsFile(dir));
        FAIL() << "no error";
    } catch (const core::Error& e) {
        EXPECT_EQ(std::string(e.what()), "input::loadGamepadMappingsFile(): cannot read '" +
                                             dir.string() + "': it is a directory");
    }
}

TEST(MappingParse, MakeMappingBuildsAValidLineOrSaysWhatIsWrong) {
    const std::string line =
        makeGamepadMapping("03000000de280000ff11000001000000", "My Stick", "a:b0,leftx:a0,");
    EXPECT_EQ(line, "03000000de280000ff11000001000000,My Stick,a:b0,leftx:a0,");
    EXPECT_THAT(parseGamepadMappings(line).lines, ElementsAre(line));
    try {
        static_cast<void>(makeGamepadMapping("xyz", "My Stick", "a:b0"));
        FAIL() << "no error";
    } catch (const core::Error& e) {
        EXPECT_STREQ(e.what(),
                     "input::makeGamepadMapping(): GUID must be 32 hex digits, got 'xyz'");
    }
    EXPECT_THROW(
        static_cast<void>(makeGamepadMapping("03000000de280000ff11000001000000", "A\nB", "a:b0")),
        core::Error);
}

} // namespace
} // namespace e2d::input
