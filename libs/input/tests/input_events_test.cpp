// SPDX-License-Identifier: MIT
// Events fed through the entry points GLFW's callbacks use; no window.
#include <e2d/core/error.hpp>
#include <e2d/core/log.hpp>
#include <e2d/input/actions.hpp>
#include <e2d/input/input.hpp>

#include <GLFW/glfw3.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace e2d::input {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

std::vector<std::string> describe(const Input& input) {
    std::vector<std::string> out;
    for (const Event& e : input.events()) {
        std::string s(toString(e.type));
        switch (e.type) {
        case EventType::KeyDown:
        case EventType::KeyUp:
        case EventType::KeyRepeat:
            s += " " + std::string(keyName(Key(e.code))) + " m" + std::to_string(e.mods) + " s" +
                 std::to_string(e.scancode);
            break;
        case EventType::Text:
            s += " U+" + std::to_string(e.code);
            break;
        case EventType::MouseButtonDown:
        case EventType::MouseButtonUp:
        case EventType::MouseMove:
        case EventType::Scroll:
            s += " " + std::to_string(e.code) + " @" + std::to_string(int(e.screen.x)) + "," +
                 std::to_string(int(e.screen.y));
            break;
        default:
            break;
        }
        out.push_back(s);
    }
    return out;
}

// Polling, bindings and names take the events' enums; a bare number (a GLFW code,
// `button == 0`) does not compile. `Code` is the argument type tried.
template <class Code>
concept PollsKeys = requires(const Input& in, Code c) {
    in.isKeyDown(c);
};
template <class Code>
concept PollsMouseButtons = requires(const Input& in, Code c) {
    in.wasMouseButtonPressed(c);
};
template <class Code>
concept PollsPadButtons = requires(const Input& in, Code c) {
    in.isGamepadButtonDown(0, c);
};
template <class Code>
concept PollsPadAxes = requires(const Input& in, Code c) {
    in.gamepadAxis(0, c);
};
template <class Code>
concept BindsKeys = requires(Code c) {
    Binding::key(c);
};
template <class Code>
concept NamesKeys = requires(Code c) {
    keyName(c);
};
static_assert(PollsKeys<Key> && !PollsKeys<int>);
static_assert(PollsMouseButtons<MouseButton> && !PollsMouseButtons<int>);
static_assert(PollsPadButtons<GamepadButton> && !PollsPadButtons<int>);
static_assert(PollsPadAxes<GamepadAxis> && !PollsPadAxes<int>);
static_assert(BindsKeys<Key> && !BindsKeys<int>);
static_assert(NamesKeys<Key> && !NamesKeys<int>);

TEST(InputEvents, NothingIsDeliveredUntilTheFrameStarts) {
    Input input;
    input.handleKey(GLFW_KEY_A, 38, GLFW_PRESS, 0);
    EXPECT_TRUE(input.events().empty());
    EXPECT_FALSE(input.isKeyDown(Key::A));
    input.beginFrame();
    EXPECT_EQ(input.events().size(), 1u);
    EXPECT_TRUE(input.isKeyDown(Key::A));
}

TEST(InputEvents, AFrameDeliversEveryKindInTheOrderItWasQueued) {
    Input input;
    input.handleCursorPos(10.0, 20.0);
    input.handleKey(GLFW_KEY_X, 53, GLFW_PRESS, GLFW_MOD_SHIFT);
    input.handleChar(U'X');
    input.handleMouseButton(GLFW_MOUSE_BUTTON_RIGHT, GLFW_PRESS, 0);
    input.handleKey(GLFW_KEY_X, 53, GLFW_REPEAT, GLFW_MOD_SHIFT);
    input.handleCursorPos(15.0, 25.0);
    input.handleScroll(0.0, -1.0);
    input.handleMouseButton(GLFW_MOUSE_BUTTON_RIGHT, GLFW_RELEASE, 0);
    input.handleKey(GLFW_KEY_X, 53, GLFW_RELEASE, 0);
    input.handleChar(U'\u00e9');
    input.beginFrame();
    EXPECT_THAT(describe(input),
                ElementsAre("MouseMove 0 @10,20", "KeyDown x m1 s53", "Text U+88",
                            "MouseButtonDown 1 @10,20", "KeyRepeat x m1 s53", "MouseMove 0 @15,25",
                            "Scroll 0 @15,25", "MouseButtonUp 1 @15,25", "KeyUp x m0 s53",
                            "Text U+233"));
    EXPECT_EQ(input.text(), U"X\u00e9");
    // The next frame starts empty.
    input.beginFrame();
    EXPECT_TRUE(input.events().empty());
    EXPECT_TRUE(input.text().empty());
}

TEST(InputEvents, PressedAndReleasedInTheSameFrameCountsBoth) {
    Input input;
    input.handleKey(GLFW_KEY_SPACE, 65, GLFW_PRESS, 0);
    input.handleKey(GLFW_KEY_SPACE, 65, GLFW_RELEASE, 0);
    input.handleMouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
    input.handleMouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0);
    input.beginFrame();
    EXPECT_TRUE(input.wasKeyPressed(Key::Space));
    EXPECT_TRUE(input.wasKeyReleased(Key::Space));
    EXPECT_FALSE(input.isKeyDown(Key::Space));
    EXPECT_TRUE(input.wasMouseButtonPressed(MouseButton::Left));
    EXPECT_TRUE(input.wasMouseButtonReleased(MouseButton::Left));
    EXPECT_FALSE(input.isMouseButtonDown(MouseButton::Left));
    input.beginFrame();
    EXPECT_FALSE(input.wasKeyPressed(Key::Space));
    EXPECT_FALSE(input.wasKeyReleased(Key::Space));
    EXPECT_FALSE(input.wasMouseButtonPressed(MouseButton::Left));
}

TEST(InputEvents, EdgesLastOneFrameAndHeldStaysDown) {
    Input input;
    input.handleKey(GLFW_KEY_W, 25, GLFW_PRESS, 0);
    input.beginFrame();
    EXPECT_TRUE(input.wasKeyPressed(Key::W));
    input.handleKey(GLFW_KEY_W, 25, GLFW_REPEAT, 0);
    input.beginFrame();
    EXPECT_TRUE(input.isKeyDown(Key::W));
    EXPECT_FALSE(input.wasKeyPressed(Key::W)); // a repeat is not a press
    input.handleKey(GLFW_KEY_W, 25, GLFW_RELEASE, 0);
    input.beginFrame();
    EXPECT_FALSE(input.isKeyDown(Key::W));
    EXPECT_TRUE(input.wasKeyReleased(Key::W));
    EXPECT_FALSE(input.isKeyDown(Key::Unknown));
    EXPECT_FALSE(input.isKeyDown(Key{static_cast<int>(Key::Menu) + 1}));
    EXPECT_FALSE(input.wasMouseButtonPressed(MouseButton{99}));
}

TEST(InputEvents, FocusLossReleasesEverythingHeldBeforeReportingIt) {
    Input input;
    input.handleCursorPos(5.0, 6.0);
    input.handleKey(GLFW_KEY_A, 38, GLFW_PRESS, 0);
    input.handleKey(GLFW_KEY_LEFT_SHIFT, 50, GLFW_PRESS, GLFW_MOD_SHIFT);
    input.handleMouseButton(GLFW_MOUSE_BUTTON_MIDDLE, GLFW_PRESS, 0);
    input.beginFrame();
    ASSERT_TRUE(input.isKeyDown(Key::A));
    input.handleFocus(false);
    // GLFW sends its own releases after the focus callback: they must not be reported twice.
    input.handleKey(GLFW_KEY_A, 38, GLFW_RELEASE, 0);
    input.handleMouseButton(GLFW_MOUSE_BUTTON_MIDDLE, GLFW_RELEASE, 0);
    input.beginFrame();
    EXPECT_THAT(describe(input), ElementsAre("KeyUp a m0 s38", "KeyUp left_shift m0 s50",
                                             "MouseButtonUp 2 @5,6", "FocusLost"));
    EXPECT_FALSE(input.isKeyDown(Key::A));
    EXPECT_FALSE(input.isKeyDown(Key::LeftShift));
    EXPECT_FALSE(input.isMouseButtonDown(MouseButton::Middle));
    EXPECT_TRUE(input.wasKeyReleased(Key::A));
    EXPECT_FALSE(input.focused());
    input.handleFocus(true);
    input.beginFrame();
    EXPECT_THAT(describe(input), ElementsAre("FocusGained"));
    EXPECT_TRUE(input.focused());
}

TEST(InputEvents, MouseEventsCarryWorldPositionsFromTheConverter) {
    InputDef def;
    // A camera 2 pixels per unit, centred on a 200x100 window, y up.
    def.screenToWorld = [](glm::vec2 s) {
        return glm::vec2((s.x - 100.0f) / 2.0f, (50.0f - s.y) / 2.0f);
    };
    Input input(def);
    input.handleCursorPos(140.0, 30.0);
    input.handleMouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
    input.handleScroll(1.0, 0.0);
    input.beginFrame();
    ASSERT_EQ(input.events().size(), 3u);
    for (const Event& e : input.events()) {
        EXPECT_EQ(e.screen, glm::vec2(140.0f, 30.0f)) << toString(e.type);
        EXPECT_EQ(e.world, glm::vec2(20.0f, 10.0f)) << toString(e.type);
    }
    EXPECT_EQ(input.mouseWorldPosition(), glm::vec2(20.0f, 10.0f));
    input.setScreenToWorld({});
    input.handleCursorPos(1.0, 2.0);
    input.beginFrame();
    EXPECT_EQ(input.events()[0].world, glm::vec2(1.0f, 2.0f));
}

TEST(InputEvents, MouseDeltaAndScrollSumOverTheFrame) {
    Input input;
    input.handleCursorPos(10.0, 10.0);
    input.beginFrame();
    input.handleCursorPos(13.0, 8.0);
    input.handleCursorPos(20.0, 9.0);
    input.handleScroll(0.0, 1.0);
    input.handleScroll(0.5, 2.0);
    input.beginFrame();
    EXPECT_EQ(input.mousePosition(), glm::vec2(20.0f, 9.0f));
    EXPECT_EQ(input.mouseDelta(), glm::vec2(10.0f, -1.0f));
    EXPECT_EQ(input.events()[0].delta, glm::vec2(3.0f, -2.0f));
    EXPECT_EQ(input.scroll(), glm::vec2(0.5f, 3.0f));
    input.beginFrame();
    EXPECT_EQ(input.mouseDelta(), glm::vec2(0.0f));
    EXPECT_EQ(input.scroll(), glm::vec2(0.0f));
    EXPECT_EQ(input.mousePosition(), glm::vec2(20.0f, 9.0f));
}

TEST(InputEvents, AFullQueueDropsTheRestAndSaysSo) {
    std::vector<std::string> logged;
    core::Logger logger(core::LogLevel::Info,
                        [&](core::LogLevel, std::string_view m) { logged.emplace_back(m); });
    InputDef def;
    def.maxQueuedEvents = 3;
    def.logger = &logger;
    Input input(def);
    for (int i = 0; i < 5; ++i) {
        input.handleChar(static_cast<char32_t>('a' + i));
    }
    input.beginFrame();
    EXPECT_EQ(input.text(), U"abc");
    EXPECT_EQ(input.droppedEvents(), 2u);
    ASSERT_EQ(logged.size(), 1u);
    EXPECT_THAT(logged[0], HasSubstr("2 events dropped"));
    input.beginFrame();
    EXPECT_EQ(logged.size(), 1u);
}

TEST(InputEvents, BadSettingsAreRefusedByName) {
    const auto message = [](InputDef def) {
        try {
            Input input(std::move(def));
        } catch (const core::Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    InputDef def;
    def.stickDeadZone = 1.0f;
    EXPECT_EQ(message(def), "input::Input::Input(): stickDeadZone must be in [0, 1), got 1");
    def = {};
    def.triggerDeadZone = -0.5f;
    EXPECT_EQ(message(def), "input::Input::Input(): triggerDeadZone must be in [0, 1), got -0.5");
    def = {};
    def.triggerPressThreshold = 0.0f;
    EXPECT_EQ(message(def),
              "input::Input::Input(): triggerPressThreshold must be in (0, 1], got 0");
    def = {};
    def.maxQueuedEvents = 0;
    EXPECT_EQ(message(def), "input::Input::Input(): maxQueuedEvents must be >= 1, got 0");
}

TEST(InputEvents, CursorModeIsRememberedWithoutAWindow) {
    Input input;
    EXPECT_EQ(input.cursorMode(), CursorMode::Normal);
    input.setCursorMode(CursorMode::Captured);
    EXPECT_EQ(input.cursorMode(), CursorMode::Captured);
    EXPECT_EQ(Input::fromWindow(nullptr), nullptr);
}

} // namespace
} // namespace e2d::input
