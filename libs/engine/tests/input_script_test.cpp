// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
#include <e2d/engine/input_script.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace {

using namespace e2d;
using engine::InputScript;
using engine::parseInputScript;
using engine::ScriptEvent;
using Kind = ScriptEvent::Kind;

std::string errorOf(std::string_view text) {
    try {
        static_cast<void>(parseInputScript(text, "run.txt"));
    } catch (const core::Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(InputScript, EventsAreSortedByFrameKeepingLineOrder) {
    const InputScript s = parseInputScript("# run right, then jump\n"
                                           "\n"
                                           "30 release right\n"
                                           "  0 press right  \n"
                                           "10\ttap key:space\n"
                                           "10 press mouse:left\n",
                                           "run.txt");
    EXPECT_EQ(s.source, "run.txt");
    ASSERT_EQ(s.events.size(), 5u);
    const auto expect = [&](std::size_t i, std::int64_t frame, Kind kind, const std::string& target, int line) {
        EXPECT_EQ(s.events[i].frame, frame) << i;
        EXPECT_EQ(s.events[i].kind, kind) << i;
        EXPECT_EQ(s.events[i].target, target) << i;
        EXPECT_EQ(s.events[i].line, line) << i;
    };
    expect(0, 0, Kind::Press, "right", 4);
    expect(1, 10, Kind::Press, "key:space", 5);
    expect(2, 10, Kind::Press, "mouse:left", 6);
    expect(3, 11, Kind::Release, "key:space", 5); // the tap's release, one frame later
    expect(4, 30, Kind::Release, "right", 3);
}

TEST(InputScript, MalformedLinesNameFileAndLine) {
    EXPECT_EQ(errorOf("0 press jump\njump\n"), "run.txt:2: expected '<frame> <press|release|tap> <target>', got 'jump'");
    EXPECT_EQ(errorOf("x press jump"), "run.txt:1: frame must be a whole number >= 0, got 'x'");
    EXPECT_EQ(errorOf("-1 press jump"), "run.txt:1: frame must be a whole number >= 0, got '-1'");
    EXPECT_EQ(errorOf("\n\n1.5 press jump"), "run.txt:3: frame must be a whole number >= 0, got '1.5'");
    EXPECT_EQ(errorOf("3 hold jump"), "run.txt:1: expected press, release or tap, got 'hold'");
    EXPECT_EQ(errorOf("3 press jump now"),
              "run.txt:1: expected '<frame> <press|release|tap> <target>', got '3 press jump now'");
    EXPECT_TRUE(parseInputScript("").events.empty());
}

TEST(InputScript, MissingFileIsNamed) {
    try {
        static_cast<void>(engine::loadInputScript("/no/such/script.txt"));
        FAIL();
    } catch (const core::Error& e) {
        EXPECT_STREQ(e.what(), "/no/such/script.txt: cannot read the input script");
    }
}

} // namespace
