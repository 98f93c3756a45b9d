// SPDX-License-Identifier: MIT
#include <e2d/input/names.hpp>

#include <GLFW/glfw3.h>

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace e2d::input {
namespace {

TEST(Names, KeysBothWays) {
    EXPECT_EQ(keyName(GLFW_KEY_SPACE), "space");
    EXPECT_EQ(keyName(GLFW_KEY_A), "a");
    EXPECT_EQ(keyName(GLFW_KEY_LEFT_SHIFT), "left_shift");
    EXPECT_EQ(keyName(GLFW_KEY_KP_ENTER), "kp_enter");
    EXPECT_EQ(keyName(GLFW_KEY_F25), "f25");
    EXPECT_EQ(keyName(GLFW_KEY_MENU), "menu");
    EXPECT_EQ(keyFromName("space"), GLFW_KEY_SPACE);
    EXPECT_EQ(keyFromName("SPACE"), GLFW_KEY_SPACE);
    EXPECT_EQ(keyFromName("Page_Down"), GLFW_KEY_PAGE_DOWN);
    EXPECT_EQ(keyFromName("9"), GLFW_KEY_9);
    EXPECT_EQ(keyFromName("spcae"), std::nullopt);
    EXPECT_EQ(keyFromName(""), std::nullopt);
    EXPECT_EQ(keyName(GLFW_KEY_UNKNOWN), "");
    EXPECT_EQ(keyName(33), ""); // a gap in GLFW's codes
    EXPECT_EQ(keyName(100000), "");
}

TEST(Names, EveryKeyCodeHasAUniqueNameThatMapsBack) {
    std::set<std::string> seen;
    int named = 0;
    for (int key = -1; key <= GLFW_KEY_LAST + 1; ++key) {
        const std::string_view name = keyName(key);
        if (name.empty()) {
            continue;
        }
        ++named;
        EXPECT_TRUE(seen.insert(std::string(name)).second) << name;
        EXPECT_EQ(keyFromName(name), key) << name;
    }
    // glfw3.h defines 120 named keys (GLFW_KEY_SPACE .. GLFW_KEY_MENU).
    EXPECT_EQ(named, 120);
}

TEST(Names, MouseAndGamepad) {
    EXPECT_EQ(mouseButtonName(GLFW_MOUSE_BUTTON_LEFT), "left");
    EXPECT_EQ(mouseButtonName(GLFW_MOUSE_BUTTON_MIDDLE), "middle");
    EXPECT_EQ(mouseButtonFromName("right"), GLFW_MOUSE_BUTTON_RIGHT);
    EXPECT_EQ(mouseButtonFromName("button1"), GLFW_MOUSE_BUTTON_LEFT);
    EXPECT_EQ(mouseButtonFromName("button8"), GLFW_MOUSE_BUTTON_8);
    EXPECT_EQ(mouseButtonName(8), "");
    EXPECT_EQ(gamepadButtonName(GLFW_GAMEPAD_BUTTON_LEFT_BUMPER), "leftshoulder");
    EXPECT_EQ(gamepadButtonName(GLFW_GAMEPAD_BUTTON_DPAD_LEFT), "dpleft");
    EXPECT_EQ(gamepadButtonName(kGamepadButtonRightTrigger), "righttrigger");
    EXPECT_EQ(gamepadButtonFromName("start"), GLFW_GAMEPAD_BUTTON_START);
    EXPECT_EQ(gamepadButtonFromName("lefttrigger"), kGamepadButtonLeftTrigger);
    EXPECT_EQ(gamepadButtonFromName("z"), std::nullopt);
    EXPECT_EQ(gamepadAxisName(GLFW_GAMEPAD_AXIS_RIGHT_Y), "righty");
    EXPECT_EQ(gamepadAxisFromName("lefttrigger"), GLFW_GAMEPAD_AXIS_LEFT_TRIGGER);
    EXPECT_EQ(gamepadAxisName(6), "");
}

} // namespace
} // namespace e2d::input
