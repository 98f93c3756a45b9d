// SPDX-License-Identifier: MIT
#include <e2d/core/diagnostics.hpp>
#include <e2d/core/error.hpp>
#include <e2d/input/actions.hpp>
#include <e2d/input/names.hpp>

#include <GLFW/glfw3.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace e2d::input {
namespace {

using ::testing::ElementsAre;

std::string errorOf(auto&& f) {
    try {
        f();
    } catch (const core::Error& e) {
        return e.what();
    }
    return "no error";
}

const char* kFile = "# controls\n"
                    "jump = key:space, button:a\n"
                    "\n"
                    "  move_x =keys:a/d,axis:leftx ,  axis@1:-rightx\r\n"
                    "fire = mouse:left, button@0:righttrigger\n"
                    "pause =\n";

TEST(BindingsFile, LoadsEveryActionWithItsBindings) {
    ActionMap actions;
    actions.loadFromString(kFile);
    ASSERT_EQ(actions.size(), 4u);
    EXPECT_THAT(actions.bindings(actions.find("jump")),
                ElementsAre(Binding::key(Key::Space), Binding::gamepadButton(GamepadButton::A)));
    EXPECT_THAT(actions.bindings(actions.find("move_x")),
                ElementsAre(Binding::keyAxis(Key::A, Key::D),
                            Binding::gamepadAxis(GamepadAxis::LeftX),
                            Binding::gamepadAxis(GamepadAxis::RightX, true, 1)));
    EXPECT_THAT(actions.bindings(actions.find("fire")),
                ElementsAre(Binding::mouseButton(MouseButton::Left),
                            Binding::gamepadButton(GamepadButton::RightTrigger, 0)));
    EXPECT_TRUE(actions.bindings(actions.find("pause")).empty());
}

TEST(BindingsFile, SaveThenLoadGivesTheSameMap) {
    const std::filesystem::path path =
        std::filesystem::path(::testing::TempDir()) / "e2d_input_bindings.txt";
    ActionMap original;
    original.loadFromString(kFile);
    original.bind(original.add("menu"), Binding::key(Key::F10));
    original.save(path);

    ActionMap loaded;
    loaded.load(path);
    ASSERT_EQ(loaded.size(), original.size());
    for (std::uint32_t i = 1; i <= original.size(); ++i) {
        EXPECT_EQ(loaded.name(ActionId{i}), original.name(ActionId{i}));
        EXPECT_TRUE(
            std::ranges::equal(loaded.bindings(ActionId{i}), original.bindings(ActionId{i})))
            << i;
    }
    EXPECT_EQ(loaded.toString(), original.toString());
    std::filesystem::remove(path);
}

TEST(BindingsFile, LoadingReplacesListedActionsAndKeepsTheOthers) {
    ActionMap actions;
    const ActionId keep = actions.add("keep");
    actions.bind(keep, Binding::key(Key::K));
    const ActionId jump = actions.add("jump");
    actions.bind(jump, Binding::key(Key::W));
    actions.loadFromString("jump = key:up\n");
    EXPECT_THAT(actions.bindings(jump), ElementsAre(Binding::key(Key::Up)));
    EXPECT_THAT(actions.bindings(keep), ElementsAre(Binding::key(Key::K)));
}

TEST(BindingsFile, MalformedLinesNameFileAndLineAndChangeNothing) {
    ActionMap actions;
    const ActionId jump = actions.add("jump");
    actions.bind(jump, Binding::key(Key::W));
    const auto message = [&](std::string_view text) {
        return errorOf([&] { actions.loadFromString(text, "controls.txt"); });
    };
    EXPECT_EQ(message("jump = key:up\nfire = key:spcae\n"),
              "controls.txt:2: unknown key name 'spcae' in 'key:spcae'");
    EXPECT_EQ(message("# c\n\njump key:up\n"),
              "controls.txt:3: expected '<action> = <binding>, ...'");
    EXPECT_EQ(message("jump = key:up,,key:w\n"), "controls.txt:1: empty binding");
    EXPECT_EQ(message("ju mp = key:up\n"),
              "controls.txt:1: action name must be letters, digits, '_', '-' or '.', got 'ju mp'");
    EXPECT_EQ(message(" = key:up\n"),
              "controls.txt:1: action name must be letters, digits, '_', '-' or '.', got ''");
    EXPECT_EQ(message("a = key:up\na = key:w\n"), "controls.txt:2: action 'a' is listed twice");
    EXPECT_EQ(message("a = button:fire\n"),
              "controls.txt:1: unknown gamepad button name 'fire' in 'button:fire'");
    // Nothing of the failed loads stuck.
    EXPECT_EQ(actions.size(), 1u);
    EXPECT_THAT(actions.bindings(jump), ElementsAre(Binding::key(Key::W)));
}

// Editors on Windows start a UTF-8 file with a byte order mark; it used to become part of the
// first action's name ("action name must be letters... got 'jump'", the mark invisible).
TEST(BindingsFile, AByteOrderMarkIsSkipped) {
    ActionMap actions;
    actions.loadFromString("\xEF\xBB\xBFjump = key:space\nfire = key:f\n", "controls.txt");
    EXPECT_FALSE(actions.find("jump").isNull());
    EXPECT_EQ(actions.size(), 2u);
}

// Bytes from the file are quoted escaped: a control byte or invalid UTF-8 no longer hides in the
// message, and a NUL no longer cuts what() short.
TEST(BindingsFile, RawBytesInMessagesAreEscaped) {
    ActionMap actions;
    const auto message = [&](std::string_view text) {
        return errorOf([&] { actions.loadFromString(text, "controls.txt"); });
    };
    EXPECT_EQ(
        message("\x01jump = key:space\n"),
        "controls.txt:1: action name must be letters, digits, '_', '-' or '.', got '\\x01jump'");
    EXPECT_EQ(message(std::string_view("jump = key:sp\0ace\n", 19)),
              "controls.txt:1: unknown key name 'sp\\x00ace' in 'key:sp\\x00ace'");
    EXPECT_EQ(message("jump = button:\xff\xfe\n"),
              "controls.txt:1: unknown gamepad button name '\\xff\\xfe' in 'button:\\xff\\xfe'");
    // Printable UTF-8 stays as it is.
    EXPECT_EQ(
        message("saut\xc3\xa9 = key:space\n"),
        "controls.txt:1: action name must be letters, digits, '_', '-' or '.', got 'saut\xc3\xa9'");
    EXPECT_EQ(errorOf([&] { static_cast<void>(actions.held("\x1b[2J")); }),
              "input::ActionMap::held(): no action named '\\x1b[2J'");
}

TEST(BindingsFile, AnErrorKeepsItsDiagnostic) {
    ActionMap actions;
    try {
        actions.loadFromString("jump = key:space\n\nfire key:f\n", "controls.txt");
        FAIL() << "no error";
    } catch (const core::ParseError& e) {
        EXPECT_EQ(e.diagnostic().file, "controls.txt");
        EXPECT_EQ(e.diagnostic().line, 3);
        EXPECT_EQ(std::string(e.what()), "controls.txt:3: expected '<action> = <binding>, ...'");
    }
}

TEST(BindingsFile, UnreadableAndUnwritableFilesAreNamed) {
    ActionMap actions;
    EXPECT_EQ(
        errorOf([&] { actions.load("/nonexistent/e2d/controls.txt"); }),
        "input::ActionMap::load(): cannot read '/nonexistent/e2d/controls.txt': no such file");
    // A directory opens as a stream that reads nothing: it loaded zero actions with no error.
    const std::string dir = ::testing::TempDir();
    EXPECT_EQ(errorOf([&] { actions.load(dir); }),
              "input::ActionMap::load(): cannot read '" + dir + "': it is a directory");
    EXPECT_EQ(errorOf([&] { actions.save("/nonexistent/e2d/controls.txt"); }),
              "input::ActionMap::save(): cannot write '/nonexistent/e2d/controls.txt'");
    // A file error names the file path as the source.
    const std::filesystem::path path =
        std::filesystem::path(::testing::TempDir()) / "e2d_input_bad_bindings.txt";
    std::ofstream(path) << "jump = key:space\n\nfire = mouse:nine\n";
    EXPECT_EQ(errorOf([&] { actions.load(path); }),
              path.string() + ":3: unknown mouse button name 'nine' in 'mouse:nine'");
    std::filesystem::remove(path);
}

} // namespace
} // namespace e2d::input
