// SPDX-License-Identifier: MIT
// Gamepads fed through handleJoystick(), the entry point beginFrame()'s polling uses.
#include <e2d/core/error.hpp>
#include <e2d/input/input.hpp>

#include <GLFW/glfw3.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace e2d::input {
namespace {

using ::testing::ElementsAre;
using ::testing::FloatNear;

constexpr std::string_view kGuid = "030000005e0400008e02000010010000";

JoystickSnapshot pad() {
    JoystickSnapshot s;
    s.present = true;
    s.gamepad = true;
    s.guid = kGuid;
    s.name = "Test Pad";
    s.axes[GLFW_GAMEPAD_AXIS_LEFT_TRIGGER] = -1.0f;
    s.axes[GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER] = -1.0f;
    return s;
}

std::vector<std::string> describe(const Input& input) {
    std::vector<std::string> out;
    for (const Event& e : input.events()) {
        std::string s = std::string(toString(e.type)) + " " + std::to_string(e.gamepad);
        if (e.type == EventType::GamepadButtonDown || e.type == EventType::GamepadButtonUp) {
            s += " " + std::string(gamepadButtonName(GamepadButton(e.code)));
        }
        if (e.type == EventType::GamepadAxis) {
            s += " " + std::string(gamepadAxisName(GamepadAxis(e.code)));
        }
        out.push_back(s);
    }
    return out;
}

TEST(Gamepads, RadialDeadZoneKeepsTheDirectionAndRescalesTheLength) {
    const float dz = 0.2f;
    EXPECT_EQ(Input::applyStickDeadZone({0.1f, 0.1f}, dz), glm::vec2(0.0f)); // length 0.141
    // Each axis alone below the dead zone but the length beyond it: radial, so it moves.
    const glm::vec2 diagonal = Input::applyStickDeadZone({0.18f, 0.18f}, dz);
    const float rawLength = std::sqrt(2.0f) * 0.18f;
    EXPECT_THAT(std::hypot(diagonal.x, diagonal.y),
                FloatNear((rawLength - dz) / (1.0f - dz), 1e-6f));
    EXPECT_FLOAT_EQ(diagonal.x, diagonal.y);
    const glm::vec2 edge = Input::applyStickDeadZone({0.0f, -1.0f}, dz);
    EXPECT_EQ(edge, glm::vec2(0.0f, -1.0f));
    // A corner beyond the unit circle is clamped to length 1.
    const glm::vec2 corner = Input::applyStickDeadZone({1.0f, 1.0f}, dz);
    EXPECT_THAT(std::hypot(corner.x, corner.y), FloatNear(1.0f, 1e-6f));
    EXPECT_EQ(Input::applyStickDeadZone({NAN, 0.5f}, dz), glm::vec2(0.0f));
    // Half way between the dead zone and the edge reads 0.5.
    EXPECT_THAT(Input::applyStickDeadZone({0.6f, 0.0f}, dz).x, FloatNear(0.5f, 1e-6f));
}

TEST(Gamepads, TriggersRestAtZeroAndRescaleAboveTheirDeadZone) {
    EXPECT_EQ(Input::applyTriggerDeadZone(-1.0f, 0.1f), 0.0f);
    EXPECT_EQ(Input::applyTriggerDeadZone(-0.85f, 0.1f), 0.0f);                   // travel 0.075
    EXPECT_THAT(Input::applyTriggerDeadZone(0.1f, 0.1f), FloatNear(0.5f, 1e-6f)); // travel 0.55
    EXPECT_EQ(Input::applyTriggerDeadZone(1.0f, 0.1f), 1.0f);
    EXPECT_EQ(Input::applyTriggerDeadZone(NAN, 0.1f), 0.0f);
}

TEST(Gamepads, ConnectButtonsAxesAndDisconnectArriveAsEvents) {
    Input input;
    JoystickSnapshot s = pad();
    input.handleJoystick(3, s);
    input.beginFrame();
    EXPECT_THAT(describe(input), ElementsAre("JoystickConnected 3", "GamepadConnected 3"));
    EXPECT_TRUE(input.isGamepadConnected(3));
    EXPECT_FALSE(input.isGamepadConnected(2));

    s.buttons[GLFW_GAMEPAD_BUTTON_A] = GLFW_PRESS;
    s.axes[GLFW_GAMEPAD_AXIS_LEFT_X] = 0.6f;
    s.axes[GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER] = 0.5f; // travel 0.75 -> (0.75-0.1)/0.9 = 0.722 >= 0.5
    input.handleJoystick(3, s);
    input.beginFrame();
    EXPECT_THAT(describe(input),
                ElementsAre("GamepadButtonDown 3 a", "GamepadButtonDown 3 righttrigger",
                            "GamepadAxis 3 leftx", "GamepadAxis 3 righttrigger"));
    EXPECT_TRUE(input.isGamepadButtonDown(3, GamepadButton::A));
    EXPECT_TRUE(input.wasGamepadButtonPressed(3, GamepadButton::RightTrigger));
    EXPECT_THAT(input.gamepadAxis(3, GamepadAxis::LeftX), FloatNear(0.5f, 1e-6f));
    EXPECT_THAT(input.gamepadAxis(3, GamepadAxis::RightTrigger), FloatNear(0.65f / 0.9f, 1e-6f));

    // Same state: nothing new, edges gone.
    input.handleJoystick(3, s);
    input.beginFrame();
    EXPECT_TRUE(input.events().empty());
    EXPECT_FALSE(input.wasGamepadButtonPressed(3, GamepadButton::A));
    EXPECT_TRUE(input.isGamepadButtonDown(3, GamepadButton::A));

    // Unplugged while held: the buttons are released first.
    JoystickSnapshot gone;
    input.handleJoystick(3, gone);
    input.beginFrame();
    EXPECT_THAT(describe(input),
                ElementsAre("GamepadButtonUp 3 a", "GamepadButtonUp 3 righttrigger",
                            "GamepadDisconnected 3", "JoystickDisconnected 3"));
    EXPECT_FALSE(input.isGamepadConnected(3));
    EXPECT_FALSE(input.isGamepadButtonDown(3, GamepadButton::A));
    EXPECT_EQ(input.gamepadAxis(3, GamepadAxis::LeftX), 0.0f);
    EXPECT_TRUE(input.joysticks().empty());
}

TEST(Gamepads, SixteenPadsAtOnceAreIndependent) {
    Input input;
    for (int slot = 0; slot < kMaxGamepads; ++slot) {
        JoystickSnapshot s = pad();
        s.buttons[static_cast<std::size_t>(slot % 15)] = GLFW_PRESS;
        input.handleJoystick(slot, s);
    }
    input.beginFrame();
    for (int slot = 0; slot < kMaxGamepads; ++slot) {
        EXPECT_TRUE(input.isGamepadConnected(slot));
        for (int b = 0; b < 15; ++b) {
            EXPECT_EQ(input.isGamepadButtonDown(slot, GamepadButton(b)), b == slot % 15)
                << slot << " " << b;
        }
    }
    EXPECT_EQ(input.joysticks().size(), 16u);
    EXPECT_THROW(input.handleJoystick(16, pad()), core::Error);
    EXPECT_THROW(input.handleJoystick(-1, pad()), core::Error);
    EXPECT_FALSE(input.isGamepadButtonDown(16, GamepadButton::A));
    EXPECT_EQ(input.gamepadAxis(0, GamepadAxis{6}), 0.0f);
}

TEST(Gamepads, AnUnmappedJoystickIsListedAndBecomesAGamepadOnceMapped) {
    Input input;
    JoystickSnapshot s = pad();
    s.gamepad = false;
    s.name = "Mystery Stick";
    input.handleJoystick(0, s);
    input.beginFrame();
    EXPECT_THAT(describe(input), ElementsAre("JoystickConnected 0"));
    EXPECT_FALSE(input.isGamepadConnected(0));
    const std::vector<JoystickInfo> list = input.joysticks();
    ASSERT_EQ(list.size(), 1u);
    EXPECT_EQ(list[0].slot, 0);
    EXPECT_EQ(list[0].guid, kGuid);
    EXPECT_EQ(list[0].name, "Mystery Stick");
    EXPECT_FALSE(list[0].gamepad);

    // A mapping arrives at run time: GLFW now reports it as a gamepad, with its mapped name.
    s.gamepad = true;
    s.name = "Mapped Stick";
    s.buttons[GLFW_GAMEPAD_BUTTON_START] = GLFW_PRESS;
    input.handleJoystick(0, s);
    input.beginFrame();
    EXPECT_THAT(describe(input), ElementsAre("GamepadConnected 0", "GamepadButtonDown 0 start"));
    EXPECT_TRUE(input.joysticks()[0].gamepad);
    EXPECT_EQ(input.joysticks()[0].name, "Mapped Stick");
}

TEST(Gamepads, RestingSticksInsideTheDeadZoneSendNoAxisEvents) {
    InputDef def;
    def.stickDeadZone = 0.25f;
    Input input(def);
    JoystickSnapshot s = pad();
    input.handleJoystick(1, s);
    input.beginFrame();
    for (float jitter : {0.05f, -0.1f, 0.2f, 0.0f}) {
        s.axes[GLFW_GAMEPAD_AXIS_LEFT_X] = jitter;
        s.axes[GLFW_GAMEPAD_AXIS_RIGHT_Y] = -jitter;
        s.axes[GLFW_GAMEPAD_AXIS_LEFT_TRIGGER] = -1.0f + jitter; // travel below 0.1
        input.handleJoystick(1, s);
        input.beginFrame();
        EXPECT_TRUE(input.events().empty()) << jitter;
    }
}

TEST(Gamepads, TriggerButtonFollowsThePressThreshold) {
    InputDef def;
    def.triggerDeadZone = 0.0f;
    def.triggerPressThreshold = 0.8f;
    Input input(def);
    JoystickSnapshot s = pad();
    s.axes[GLFW_GAMEPAD_AXIS_LEFT_TRIGGER] = 0.5f; // 0.75
    input.handleJoystick(0, s);
    input.beginFrame();
    EXPECT_FALSE(input.isGamepadButtonDown(0, GamepadButton::LeftTrigger));
    s.axes[GLFW_GAMEPAD_AXIS_LEFT_TRIGGER] = 0.7f; // 0.85
    input.handleJoystick(0, s);
    input.beginFrame();
    EXPECT_TRUE(input.isGamepadButtonDown(0, GamepadButton::LeftTrigger));
}

} // namespace
} // namespace e2d::input
