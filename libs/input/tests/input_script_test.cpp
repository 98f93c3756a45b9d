// SPDX-License-Identifier: MIT
#include <e2d/core/diagnostics.hpp>
#include <e2d/core/error.hpp>
#include <e2d/input/actions.hpp>
#include <e2d/input/input.hpp>
#include <e2d/input/input_script.hpp>
#include <e2d/input/names.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace {

using namespace e2d;
using input::InputScript;
using input::parseInputScript;
using input::ScriptEvent;
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
    const auto expect = [&](std::size_t i, std::int64_t frame, Kind kind, const std::string& target,
                            int line) {
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
    EXPECT_EQ(errorOf("0 press jump\njump\n"),
              "run.txt:2: expected '<frame> <press|release|tap> <target>', got 'jump'");
    EXPECT_EQ(errorOf("x press jump"), "run.txt:1: frame must be a whole number >= 0, got 'x'");
    EXPECT_EQ(errorOf("-1 press jump"), "run.txt:1: frame must be a whole number >= 0, got '-1'");
    EXPECT_EQ(errorOf("\n\n1.5 press jump"),
              "run.txt:3: frame must be a whole number >= 0, got '1.5'");
    EXPECT_EQ(errorOf("3 hold jump"),
              "run.txt:1: expected press, release, tap or move, got 'hold'");
    EXPECT_EQ(errorOf("3 press jump now"),
              "run.txt:1: expected '<frame> <press|release|tap> <target>', got '3 press jump now'");
    EXPECT_TRUE(parseInputScript("").events.empty());
}

TEST(InputScript, MissingFileIsNamed) {
    try {
        static_cast<void>(input::loadInputScript("/no/such/script.txt"));
        FAIL();
    } catch (const core::Error& e) {
        EXPECT_STREQ(e.what(), "/no/such/script.txt: cannot read the input script (no such file)");
    }
}

TEST(InputScript, MovesCarryTheCursorPositionOrTheAxisValue) {
    const InputScript s = parseInputScript("5 move mouse 120 90.5\n"
                                           "5 tap mouse:left\n"
                                           "2 move axis:leftx -0.75\n"
                                           "3 move axis@1:righttrigger 1\n"
                                           "4 press button:a\n",
                                           "run.txt");
    ASSERT_EQ(s.events.size(), 6u);
    EXPECT_EQ(s.events[0].kind, Kind::Move);
    EXPECT_EQ(s.events[0].target, "axis:leftx");
    EXPECT_EQ(s.events[0].x, -0.75f);
    EXPECT_EQ(s.events[1].target, "axis@1:righttrigger");
    EXPECT_EQ(s.events[1].x, 1.0f);
    EXPECT_EQ(s.events[2].kind, Kind::Press);
    EXPECT_EQ(s.events[2].target, "button:a");
    EXPECT_EQ(s.events[3].kind, Kind::Move);
    EXPECT_EQ(s.events[3].target, "mouse");
    EXPECT_EQ(s.events[3].x, 120.0f);
    EXPECT_EQ(s.events[3].y, 90.5f);
    EXPECT_EQ(s.events[3].frame, 5);
    EXPECT_EQ(s.events[4].kind, Kind::Press) << "the click after the move, on the same frame";
    EXPECT_EQ(s.events[4].target, "mouse:left");
}

TEST(InputScript, MalformedMovesNameFileLineAndValue) {
    EXPECT_EQ(errorOf("1 move mouse 12"),
              "run.txt:1: move mouse: expected '<x> <y>' in window pixels, got '12'");
    EXPECT_EQ(errorOf("1 move mouse 12 y"),
              "run.txt:1: move mouse: expected '<x> <y>' in window pixels, got '12 y'");
    EXPECT_EQ(errorOf("1 move mouse 1 2 3"),
              "run.txt:1: move mouse: expected '<x> <y>' in window pixels, got '1 2 3'");
    EXPECT_EQ(errorOf("\n1 move axis:leftx 1.5"),
              "run.txt:2: move axis:leftx: expected one value in [-1, 1], got '1.5'");
    EXPECT_EQ(errorOf("1 move axis:leftx"),
              "run.txt:1: move axis:leftx: expected one value in [-1, 1], got ''");
    EXPECT_EQ(errorOf("1 move axis:leftx nan"),
              "run.txt:1: move axis:leftx: expected one value in [-1, 1], got 'nan'");
    EXPECT_EQ(errorOf("1 move jump 1"),
              "run.txt:1: move: expected 'mouse' or a gamepad axis (axis:leftx), got 'jump'");
}

TEST(InputScript, FramesAreBoundedSoATapCannotOverflow) {
    // A tap's release is one frame later: at INT64_MAX it was signed overflow (UBSan) and the
    // release landed at frame -2^63.
    EXPECT_EQ(
        errorOf("\n9223372036854775807 tap key:space"),
        "run.txt:2: frame must be a whole number in [0, 1000000000], got '9223372036854775807'");
    EXPECT_EQ(errorOf("99999999999999999999999 press key:space"),
              "run.txt:1: frame must be a whole number in [0, 1000000000], got "
              "'99999999999999999999999'");
    EXPECT_EQ(errorOf("1000000001 press key:space"),
              "run.txt:1: frame must be a whole number in [0, 1000000000], got '1000000001'");
    const InputScript s = parseInputScript("1000000000 tap key:space");
    ASSERT_EQ(s.events.size(), 2u);
    EXPECT_EQ(s.events[1].frame, input::kMaxScriptFrame + 1);
}

TEST(InputScript, BytesThatAreNotPrintableAreQuotedEscaped) {
    EXPECT_EQ(errorOf(std::string("3 pr\0ess jump", 14)),
              "run.txt:1: expected press, release, tap or move, got 'pr\\x00ess'");
    EXPECT_EQ(errorOf("3 move mouse \x1b[2J 4"),
              "run.txt:1: move mouse: expected '<x> <y>' in window pixels, got '\\x1b[2J 4'");
}

// --- The script as a device ------------------------------------------------------------------

std::string playError(std::string_view text, const input::ActionMap& actions = input::ActionMap()) {
    try {
        static_cast<void>(input::ScriptedInput(parseInputScript(text, "run.txt"), actions));
    } catch (const core::Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(ScriptedInput, FeedsTheInputQueueAndPollingStateOnItsFrames) {
    input::ActionMap actions;
    actions.bind(actions.add("jump"), input::Binding::key(*input::keyFromName("space")));
    input::Input in; // detached: a script is enough
    in.play(input::ScriptedInput(parseInputScript("1 tap jump\n"
                                                  "2 move mouse 10 20\n"
                                                  "0 press button@1:a\n"
                                                  "3 move axis@1:righttrigger 1\n"),
                                 actions));
    const input::Key space = *input::keyFromName("space");
    in.beginFrame(); // frame 0: the scripted pad is plugged in, its A held
    EXPECT_TRUE(in.isGamepadConnected(1));
    EXPECT_FALSE(in.isGamepadConnected(0));
    EXPECT_TRUE(in.isGamepadButtonDown(1, input::GamepadButton::A));
    EXPECT_FALSE(in.isKeyDown(space));
    in.beginFrame(); // frame 1: the tap's press
    EXPECT_TRUE(in.wasKeyPressed(space));
    ASSERT_FALSE(in.events().empty());
    EXPECT_EQ(in.events().front().type, input::EventType::KeyDown);
    in.beginFrame(); // frame 2: its release, the cursor move
    EXPECT_TRUE(in.wasKeyReleased(space));
    EXPECT_FALSE(in.isKeyDown(space));
    EXPECT_EQ(in.mousePosition(), glm::vec2(10.0f, 20.0f));
    in.beginFrame(); // frame 3: the trigger pulled all the way
    EXPECT_EQ(in.gamepadAxis(1, input::GamepadAxis::RightTrigger), 1.0f);
}

TEST(ScriptedInput, TargetsThatCannotBePlayedNameTheLine) {
    EXPECT_EQ(playError("\n0 press jump"),
              "run.txt:2: 'jump' is not an action of the game (nor a binding such as key:space)");
    EXPECT_THAT(playError("0 press key:spcae"),
                testing::StartsWith("run.txt:1: input::parseBinding(): unknown key name"));
    EXPECT_EQ(playError("0 press axis:leftx"), "run.txt:1: 'axis:leftx': only key:, mouse: and "
                                               "button: bindings can be pressed (axes are moved: "
                                               "'<frame> move axis:leftx <value>')");
    EXPECT_EQ(playError("0 move axis:lefttrigger -0.5"),
              "run.txt:1: move axis:lefttrigger: a trigger's value is in [0, 1], got -0.5");
    input::ActionMap actions;
    actions.bind(actions.add("steer"), input::Binding::gamepadAxis(input::GamepadAxis::LeftX));
    EXPECT_EQ(playError("0 press steer", actions),
              "run.txt:1: action 'steer' has no keyboard or mouse-button binding to press");
}

TEST(InputScript, AnErrorKeepsItsDiagnostic) {
    try {
        static_cast<void>(parseInputScript("0 press key:a\nx press key:b\n", "s.txt"));
        FAIL() << "no error";
    } catch (const core::ParseError& e) {
        EXPECT_EQ(e.diagnostic().file, "s.txt");
        EXPECT_EQ(e.diagnostic().line, 2);
        EXPECT_EQ(e.diagnostic().message, "frame must be a whole number >= 0, got 'x'");
        EXPECT_EQ(std::string(e.what()), "s.txt:2: " + e.diagnostic().message);
    }
}

} // namespace
