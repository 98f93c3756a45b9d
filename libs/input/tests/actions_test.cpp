// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
#include <e2d/input/actions.hpp>
#include <e2d/input/input.hpp>

#include <GLFW/glfw3.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace e2d::input {
namespace {

using ::testing::ElementsAre;
using ::testing::FloatNear;

JoystickSnapshot pad(float leftX = 0.0f) {
    JoystickSnapshot s;
    s.present = true;
    s.gamepad = true;
    s.guid = "030000005e0400008e02000010010000";
    s.name = "Pad";
    s.axes = {leftX, 0.0f, 0.0f, 0.0f, -1.0f, -1.0f};
    return s;
}

std::string errorOf(auto&& f) {
    try {
        f();
    } catch (const core::Error& e) {
        return e.what();
    }
    return "no error";
}

struct Frame {
    Input& input;
    ActionMap& actions;
    void operator()() {
        input.beginFrame();
        actions.update(input);
    }
};

TEST(Actions, AKeyActionIsPressedHeldAndReleasedOnTheRightFrames) {
    Input input;
    ActionMap actions;
    const ActionId jump = actions.add("jump");
    actions.bind(jump, Binding::key(Key::Space));
    Frame frame{input, actions};

    frame();
    EXPECT_FALSE(actions.held(jump));
    input.handleKey(GLFW_KEY_SPACE, 65, GLFW_PRESS, 0);
    frame();
    EXPECT_TRUE(actions.pressed(jump));
    EXPECT_TRUE(actions.held(jump));
    EXPECT_FALSE(actions.released(jump));
    EXPECT_EQ(actions.value(jump), 1.0f);
    frame();
    EXPECT_FALSE(actions.pressed(jump));
    EXPECT_TRUE(actions.held(jump));
    input.handleKey(GLFW_KEY_SPACE, 65, GLFW_RELEASE, 0);
    frame();
    EXPECT_TRUE(actions.released(jump));
    EXPECT_FALSE(actions.held(jump));
    EXPECT_EQ(actions.value("jump"), 0.0f);
}

TEST(Actions, ATapWithinOneFrameIsBothPressedAndReleased) {
    Input input;
    ActionMap actions;
    const ActionId fire = actions.add("fire");
    actions.bind(fire, Binding::mouseButton(MouseButton::Left));
    input.handleMouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
    input.handleMouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0);
    Frame{input, actions}();
    EXPECT_TRUE(actions.pressed(fire));
    EXPECT_TRUE(actions.released(fire));
    EXPECT_FALSE(actions.held(fire));
    Frame{input, actions}();
    EXPECT_FALSE(actions.pressed(fire));
    EXPECT_FALSE(actions.released(fire));
}

TEST(Actions, MixedBindingsGiveTheStrongestValue) {
    Input input;
    ActionMap actions;
    const ActionId moveX = actions.add("move_x");
    actions.bind(moveX, Binding::keyAxis(Key::A, Key::D));
    actions.bind(moveX, Binding::gamepadAxis(GamepadAxis::LeftX));
    actions.bind(moveX, Binding::gamepadAxis(GamepadAxis::RightX, true, 2));
    Frame frame{input, actions};

    // Stick at 0.6: 0.5 after the 0.2 dead zone.
    input.handleJoystick(0, pad(0.6f));
    frame();
    EXPECT_THAT(actions.value(moveX), FloatNear(0.5f, 1e-6f));
    EXPECT_TRUE(actions.held(moveX)); // at the 0.5 threshold
    EXPECT_TRUE(actions.pressed(moveX));

    // The key pair says -1, stronger than the stick.
    input.handleKey(GLFW_KEY_A, 38, GLFW_PRESS, 0);
    input.handleJoystick(0, pad(0.6f));
    frame();
    EXPECT_EQ(actions.value(moveX), -1.0f);
    // Both keys: they cancel, the stick wins again.
    input.handleKey(GLFW_KEY_D, 40, GLFW_PRESS, 0);
    input.handleJoystick(0, pad(0.6f));
    frame();
    EXPECT_THAT(actions.value(moveX), FloatNear(0.5f, 1e-6f));
    input.handleKey(GLFW_KEY_A, 38, GLFW_RELEASE, 0);
    input.handleKey(GLFW_KEY_D, 40, GLFW_RELEASE, 0);

    // The inverted right stick of pad 2 only; pad 0's right stick is ignored.
    JoystickSnapshot p0 = pad(0.0f);
    p0.axes[GLFW_GAMEPAD_AXIS_RIGHT_X] = 1.0f;
    input.handleJoystick(0, p0);
    JoystickSnapshot p2 = pad(0.0f);
    p2.axes[GLFW_GAMEPAD_AXIS_RIGHT_X] = 0.36f; // (0.36-0.2)/0.8 = 0.2, inverted -0.2
    input.handleJoystick(2, p2);
    frame();
    EXPECT_THAT(actions.value(moveX), FloatNear(-0.2f, 1e-6f));
    EXPECT_FALSE(actions.held(moveX));
    EXPECT_TRUE(actions.released(moveX));
}

TEST(Actions, AnyPadButtonOrTriggerCounts) {
    Input input;
    ActionMap actions;
    const ActionId shoot = actions.add("shoot");
    actions.bind(shoot, Binding::gamepadButton(GamepadButton::RightTrigger));
    JoystickSnapshot s = pad();
    s.axes[GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER] = 1.0f;
    input.handleJoystick(9, s);
    Frame{input, actions}();
    EXPECT_TRUE(actions.pressed(shoot));
    EXPECT_EQ(actions.value(shoot), 1.0f);
}

TEST(Actions, ListeningBindsTheNextInput) {
    Input input;
    ActionMap actions;
    const ActionId jump = actions.add("jump");
    actions.bind(jump, Binding::key(Key::Space));
    Frame frame{input, actions};

    actions.listen(jump);
    EXPECT_TRUE(actions.listening());
    frame(); // nothing happened yet
    EXPECT_TRUE(actions.listening());
    input.handleCursorPos(5.0, 5.0); // motion is not an input to bind
    input.handleKey(GLFW_KEY_J, 44, GLFW_PRESS, 0);
    input.handleKey(GLFW_KEY_K, 45, GLFW_PRESS, 0);
    frame();
    EXPECT_FALSE(actions.listening());
    EXPECT_EQ(actions.captured(), Binding::key(Key::J));
    EXPECT_THAT(actions.bindings(jump), ElementsAre(Binding::key(Key::J)));
    EXPECT_TRUE(actions.held(jump));

    // Add mode, from a stick pushed left: bound inverted.
    actions.listen(jump, ListenMode::Add);
    input.handleJoystick(4, pad(-0.9f));
    frame();
    EXPECT_THAT(actions.bindings(jump),
                ElementsAre(Binding::key(Key::J), Binding::gamepadAxis(GamepadAxis::LeftX, true)));

    // Escape cancels and binds nothing.
    actions.listen(jump);
    input.handleKey(GLFW_KEY_ESCAPE, 9, GLFW_PRESS, 0);
    frame();
    EXPECT_FALSE(actions.listening());
    EXPECT_FALSE(actions.captured().has_value());
    EXPECT_EQ(actions.bindings(jump).size(), 2u);

    // A gamepad button.
    actions.listen(jump);
    JoystickSnapshot s = pad(-0.9f);
    s.buttons[GLFW_GAMEPAD_BUTTON_Y] = GLFW_PRESS;
    input.handleJoystick(4, s);
    frame();
    EXPECT_THAT(actions.bindings(jump), ElementsAre(Binding::gamepadButton(GamepadButton::Y)));
}

TEST(Actions, BadNamesHandlesAndBindingsAreRefused) {
    ActionMap actions;
    const ActionId a = actions.add("a");
    EXPECT_EQ(errorOf([&] { actions.add("a"); }),
              "input::ActionMap::add(): action 'a' already exists");
    EXPECT_EQ(errorOf([&] { actions.add("has space"); }),
              "input::ActionMap::add(): action name must be letters, digits, '_', '-' or '.', got "
              "'has space'");
    EXPECT_EQ(errorOf([&] { static_cast<void>(actions.held(ActionId{})); }),
              "input::ActionMap::held(): no action with id 0");
    EXPECT_EQ(errorOf([&] { static_cast<void>(actions.pressed("nope")); }),
              "input::ActionMap::pressed(): no action named 'nope'");
    EXPECT_EQ(errorOf([&] { actions.bind(a, Binding::key(Key{9999})); }),
              "input::ActionMap::bind(): key 9999 out of range");
    EXPECT_EQ(errorOf([&] { actions.bind(a, Binding::gamepadButton(GamepadButton::A, 16)); }),
              "input::ActionMap::bind(): gamepad slot 16 out of range");
    EXPECT_EQ(errorOf([] { ActionMap m(ActionMapDef{0.0f}); }),
              "input::ActionMap::ActionMap(): pressThreshold must be in (0, 1], got 0");
    actions.bind(a, Binding::key(Key::Q));
    actions.bind(a, Binding::key(Key::Q));
    EXPECT_EQ(actions.bindings(a).size(), 1u);
}

TEST(Bindings, TextFormsRoundTrip) {
    const Binding all[] = {Binding::key(Key::Space),
                           Binding::keyAxis(Key::Left, Key::Right),
                           Binding::mouseButton(MouseButton::Middle),
                           Binding::gamepadButton(GamepadButton::Start),
                           Binding::gamepadButton(GamepadButton::LeftTrigger, 15),
                           Binding::gamepadAxis(GamepadAxis::LeftY, true),
                           Binding::gamepadAxis(GamepadAxis::RightTrigger, false, 3)};
    const char* text[] = {"key:space",          "keys:left/right",       "mouse:middle",
                          "button:start",       "button@15:lefttrigger", "axis:-lefty",
                          "axis@3:righttrigger"};
    for (std::size_t i = 0; i < std::size(all); ++i) {
        EXPECT_EQ(formatBinding(all[i]), text[i]);
        EXPECT_EQ(parseBinding(text[i]), all[i]) << text[i];
    }
    EXPECT_EQ(parseBinding("key:SPACE"), Binding::key(Key::Space));
}

TEST(Bindings, BadTextSaysWhatIsWrong) {
    const auto message = [](std::string_view t) {
        return errorOf([&] { static_cast<void>(parseBinding(t)); });
    };
    EXPECT_EQ(message("key:spcae"),
              "input::parseBinding(): unknown key name 'spcae' in 'key:spcae'");
    EXPECT_EQ(message("space"), "input::parseBinding(): expected <kind>:<name> (key, keys, mouse, "
                                "button, axis) in 'space'");
    EXPECT_EQ(message("keys:a"),
              "input::parseBinding(): expected keys:<negative>/<positive> in 'keys:a'");
    EXPECT_EQ(message("keys:a/dd"), "input::parseBinding(): unknown key name 'dd' in 'keys:a/dd'");
    EXPECT_EQ(message("mouse:thumb"),
              "input::parseBinding(): unknown mouse button name 'thumb' in 'mouse:thumb'");
    EXPECT_EQ(message("button:z"),
              "input::parseBinding(): unknown gamepad button name 'z' in 'button:z'");
    EXPECT_EQ(message("axis:-"), "input::parseBinding(): unknown gamepad axis name '' in 'axis:-'");
    EXPECT_EQ(message("button@16:a"),
              "input::parseBinding(): gamepad slot must be 0..15, got '16' in 'button@16:a'");
    EXPECT_EQ(
        message("key@1:a"),
        "input::parseBinding(): a gamepad slot (@N) applies to button and axis only in 'key@1:a'");
    EXPECT_EQ(message("joy:a"), "input::parseBinding(): unknown binding kind 'joy' (expected key, "
                                "keys, mouse, button, axis) in 'joy:a'");
    EXPECT_EQ(message("key:"), "input::parseBinding(): missing name after ':' in 'key:'");
}

} // namespace
} // namespace e2d::input
