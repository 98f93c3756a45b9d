// SPDX-License-Identifier: MIT
// The mapping-line checker alone (no GLFW); mappings_glfw_test.cpp feeds GLFW itself.
#include <e2d/core/error.hpp>
#include <e2d/input/gamepad_mappings.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace e2d::input {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

const std::string kPad = "030000005e0400008e02000010010000,X360 Pad,a:b0,b:b1,back:b6,dpdown:h0.4,dpleft:h0.8,"
                         "dpright:h0.2,dpup:h0.1,guide:b8,leftshoulder:b4,leftstick:b9,lefttrigger:a2,leftx:a0,"
                         "lefty:a1~,rightshoulder:b5,rightstick:b10,righttrigger:+a5,rightx:a3,righty:-a4,start:b7,"
                         "x:b2,y:b3,platform:Linux,";

std::vector<int> lines(const MappingParseResult& r) {
    std::vector<int> out;
    for (const MappingError& e : r.errors) {
        out.push_back(e.line);
    }
    return out;
}

std::string problem(const std::string& line) {
    const MappingParseResult r = parseGamepadMappings(line, "t");
    return r.errors.empty() ? std::string("ok") : r.errors[0].message;
}

TEST(MappingParse, AWellFormedLineIsKeptAsIs) {
    const MappingParseResult r = parseGamepadMappings(kPad);
    EXPECT_TRUE(r.errors.empty());
    EXPECT_THAT(r.lines, ElementsAre(kPad));
    EXPECT_EQ(r.otherPlatform, 0);
}

TEST(MappingParse, CommentsBlankLinesAndOtherPlatformsAreNotErrors) {
    const std::string windows = "03000000de280000ff11000000000000,Other,a:b0,platform:Windows,";
    const std::string text = "# SDL database\r\n\n   \n" + kPad + "\r\n" + windows + "\n  # indented comment\n";
    const MappingParseResult r = parseGamepadMappings(text);
    EXPECT_TRUE(r.errors.empty());
    EXPECT_THAT(r.lines, ElementsAre(kPad)); // the \r is not part of the line
    EXPECT_EQ(r.otherPlatform, 1);
}

TEST(MappingParse, EachBadLineIsReportedWithItsNumberAndTheGoodOnesKept) {
    const std::string text = kPad + "\n"                     // 1 good
                             "0300000,bad guid,a:b0\n"       // 2
                             "# fine\n"                      // 3
                             + kPad + "\n"                   // 4 good
                             "03000000de280000ff11000001000000,Name,zz:b1\n"; // 5
    const MappingParseResult r = parseGamepadMappings(text, "pads.txt");
    EXPECT_EQ(r.lines.size(), 2u);
    EXPECT_THAT(lines(r), ElementsAre(2, 5));
    EXPECT_EQ(r.errors[0].message, "pads.txt:2: GUID must be 32 hex digits, got '0300000'");
    EXPECT_EQ(r.errors[1].message,
              "pads.txt:5: unknown field 'zz' (expected an SDL gamepad field such as a, leftx, platform)");
}

TEST(MappingParse, TheMistakesGlfwWouldSwallowAreCaught) {
    const std::string g = "03000000de280000ff11000001000000,";
    // GLFW takes these without an error (measured with GLFW 3.3.8): the checker does not.
    EXPECT_EQ(problem(g + "Name,a:q0,"), "t:1: field 'a': expected bN, aN or hH.B, got 'q0'");
    EXPECT_EQ(problem(g + "Name,a:b999999,"), "t:1: field 'a': button index must be 0..255, got 'b999999'");
    EXPECT_EQ(problem(g + "Name,+a:b0,"), "t:1: output modifier in '+a:b0' is not supported by GLFW 3.3");
    EXPECT_EQ(problem(g + "Name,dpup:h0.3,"), "t:1: field 'dpup': hat bit must be 1, 2, 4 or 8, got 'h0.3'");
    EXPECT_EQ(problem(g + "Name,dpup:h16.1,"), "t:1: field 'dpup': hat index must be 0..15, got 'h16.1'");
    EXPECT_EQ(problem(g + "Name,a:+b0,"), "t:1: field 'a': a half-axis prefix (+/-) applies to axes only, got '+b0'");
    EXPECT_EQ(problem(g + "Name,leftx:a0x,"), "t:1: field 'leftx': unexpected 'x' after the element, got 'a0x'");
    EXPECT_EQ(problem(g + "Name,a,"), "t:1: field 'a' has no ':'");
    EXPECT_EQ(problem(g + "Name,platform:Linux,"), "t:1: no button or axis fields");
    // And the ones GLFW reports only through its error callback.
    EXPECT_EQ(problem(g + "Name"), "t:1: expected fields after the name");
    EXPECT_EQ(problem("03000000de280000ff11000001000000"), "t:1: expected a name after the GUID");
    EXPECT_EQ(problem(g + ",a:b0"), "t:1: the name is empty");
    EXPECT_EQ(problem(g + std::string(128, 'n') + ",a:b0"), "t:1: name is 128 bytes, GLFW takes at most 127");
    EXPECT_THAT(problem(g + "Name,a:b0," + std::string(1100, ',')), HasSubstr("GLFW takes at most 1023"));
    EXPECT_EQ(problem(g + std::string("Na\0me", 5) + ",a:b0"), "t:1: control character 0 in the line");
    // SDL extras are accepted.
    EXPECT_EQ(problem(g + "Name,a:b0,misc1:b15,paddle1:b16,touchpad:b17,crc:ab12,hint:!SDL_X:=1,sdk>=:33,"), "ok");
}

TEST(MappingParse, MakeMappingBuildsAValidLineOrSaysWhatIsWrong) {
    const std::string line = makeGamepadMapping("03000000de280000ff11000001000000", "My Stick", "a:b0,leftx:a0,");
    EXPECT_EQ(line, "03000000de280000ff11000001000000,My Stick,a:b0,leftx:a0,");
    EXPECT_THAT(parseGamepadMappings(line).lines, ElementsAre(line));
    try {
        static_cast<void>(makeGamepadMapping("xyz", "My Stick", "a:b0"));
        FAIL() << "no error";
    } catch (const core::Error& e) {
        EXPECT_STREQ(e.what(), "input::makeGamepadMapping(): GUID must be 32 hex digits, got 'xyz'");
    }
    EXPECT_THROW(static_cast<void>(makeGamepadMapping("03000000de280000ff11000001000000", "A\nB", "a:b0")),
                 core::Error);
}

} // namespace
} // namespace e2d::input
