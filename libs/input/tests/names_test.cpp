// SPDX-License-Identifier: MIT
#include <e2d/input/names.hpp>

#include <GLFW/glfw3.h>

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace e2d::input {
namespace {

TEST(Names, KeysBothWays) {
    EXPECT_EQ(keyName(Key::Space), "space");
    EXPECT_EQ(keyName(Key::A), "a");
    EXPECT_EQ(keyName(Key::LeftShift), "left_shift");
    EXPECT_EQ(keyName(Key::KeypadEnter), "kp_enter");
    EXPECT_EQ(keyName(Key::F25), "f25");
    EXPECT_EQ(keyName(Key::Menu), "menu");
    EXPECT_EQ(keyFromName("space"), Key::Space);
    EXPECT_EQ(keyFromName("SPACE"), Key::Space);
    EXPECT_EQ(keyFromName("Page_Down"), Key::PageDown);
    EXPECT_EQ(keyFromName("9"), Key::Num9);
    EXPECT_EQ(keyFromName("spcae"), std::nullopt);
    EXPECT_EQ(keyFromName(""), std::nullopt);
    EXPECT_EQ(keyName(Key::Unknown), "");
    EXPECT_EQ(keyName(Key{33}), ""); // a gap in GLFW's codes
    EXPECT_EQ(keyName(Key{100000}), "");
}

TEST(Names, EveryKeyCodeHasAUniqueNameThatMapsBack) {
    std::set<std::string> seen;
    int named = 0;
    for (int key = -1; key <= GLFW_KEY_LAST + 1; ++key) {
        const std::string_view name = keyName(Key{key});
        if (name.empty()) {
            continue;
        }
        ++named;
        EXPECT_TRUE(seen.insert(std::string(name)).second) << name;
        EXPECT_EQ(keyFromName(name), Key{key}) << name;
    }
    // glfw3.h defines 120 named keys (GLFW_KEY_SPACE .. GLFW_KEY_MENU).
    EXPECT_EQ(named, 120);
}

TEST(Names, MouseAndGamepad) {
    EXPECT_EQ(mouseButtonName(MouseButton::Left), "left");
    EXPECT_EQ(mouseButtonName(MouseButton::Middle), "middle");
    EXPECT_EQ(mouseButtonFromName("right"), MouseButton::Right);
    EXPECT_EQ(mouseButtonFromName("button1"), MouseButton::Left);
    EXPECT_EQ(mouseButtonFromName("button8"), MouseButton::Button8);
    EXPECT_EQ(mouseButtonName(MouseButton{8}), "");
    EXPECT_EQ(mouseButtonName(MouseButton{-1}), "");
    EXPECT_EQ(gamepadButtonName(GamepadButton{17}), "");
    EXPECT_EQ(gamepadButtonName(GamepadButton::LeftBumper), "leftshoulder");
    EXPECT_EQ(gamepadButtonName(GamepadButton::DpadLeft), "dpleft");
    EXPECT_EQ(gamepadButtonName(GamepadButton::RightTrigger), "righttrigger");
    EXPECT_EQ(gamepadButtonFromName("start"), GamepadButton::Start);
    EXPECT_EQ(gamepadButtonFromName("lefttrigger"), GamepadButton::LeftTrigger);
    EXPECT_EQ(gamepadButtonFromName("z"), std::nullopt);
    EXPECT_EQ(gamepadAxisName(GamepadAxis::RightY), "righty");
    EXPECT_EQ(gamepadAxisFromName("lefttrigger"), GamepadAxis::LeftTrigger);
    EXPECT_EQ(gamepadAxisName(GamepadAxis{6}), "");
    EXPECT_EQ(gamepadAxisName(GamepadAxis{-1}), "");
}

} // namespace
} // namespace e2d::input
