// SPDX-License-Identifier: MIT
// InputSystem in a core loop: events reach the scene's components through core's events.
#include <e2d/core/clock.hpp>
#include <e2d/core/component.hpp>
#include <e2d/core/fixed_stepper.hpp>
#include <e2d/core/game_loop.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/log.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/core/scene_director.hpp>
#include <e2d/core/scene_registry.hpp>
#include <e2d/input/actions.hpp>
#include <e2d/input/input.hpp>
#include <e2d/input/input_system.hpp>

#include <GLFW/glfw3.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include <memory>
#include <string>
#include <vector>

namespace e2d::input {
namespace {

using ::testing::ElementsAre;

class Listener : public core::Component,
                 public core::Handles<KeyDown, KeyUp, KeyRepeat, TextEntered, MouseButtonDown,
                                      MouseButtonUp, MouseMoved, MouseScrolled, FocusGained,
                                      FocusLost, GamepadConnected, GamepadDisconnected,
                                      GamepadButtonDown, GamepadButtonUp, GamepadAxisMoved> {
public:
    explicit Listener(std::vector<std::string>& log) : log_(log) {}
    void onInitialize() override {
        // Components find the system through their scene.
        system_ = &scene()->system<InputSystem>();
    }
    void update(double) override {
        if (system_->actions()->pressed("jump")) {
            log_.push_back("jump pressed");
        }
    }
    static std::string n(auto code) { return std::to_string(static_cast<int>(code)); }
    void on(const KeyDown& e) override {
        log_.push_back("keyDown " + n(e.key) + " " + n(e.scancode) + " " + n(e.mods));
    }
    void on(const KeyUp& e) override { log_.push_back("keyUp " + n(e.key)); }
    void on(const KeyRepeat& e) override { log_.push_back("keyRepeat " + n(e.key)); }
    void on(const TextEntered& e) override {
        log_.push_back("text " + std::to_string(std::uint32_t(e.codepoint)));
    }
    void on(const MouseButtonDown& e) override {
        log_.push_back("mouseDown " + n(e.button) + " " + n(e.screen.x) + " " + n(e.world.x));
    }
    void on(const MouseButtonUp& e) override { log_.push_back("mouseUp " + n(e.button)); }
    void on(const MouseMoved& e) override {
        log_.push_back("move " + n(e.screen.y) + " " + n(e.world.y));
    }
    void on(const MouseScrolled& e) override { log_.push_back("scroll " + n(e.offset.y)); }
    void on(const FocusGained&) override { log_.push_back("focus in"); }
    void on(const FocusLost&) override { log_.push_back("focus out"); }
    void on(const GamepadConnected& e) override { log_.push_back("padConnected " + n(e.gamepad)); }
    void on(const GamepadDisconnected& e) override {
        log_.push_back("padDisconnected " + n(e.gamepad));
    }
    void on(const GamepadButtonDown& e) override {
        log_.push_back("padDown " + n(e.gamepad) + " " + n(e.button));
    }
    void on(const GamepadButtonUp& e) override {
        log_.push_back("padUp " + n(e.gamepad) + " " + n(e.button));
    }
    void on(const GamepadAxisMoved& e) override {
        log_.push_back("padAxis " + n(e.gamepad) + " " + n(e.axis) + " " + n(e.value * 100));
    }

private:
    std::vector<std::string>& log_;
    InputSystem* system_ = nullptr;
};

class ListenerScene : public core::Scene {
public:
    explicit ListenerScene(std::vector<std::string>& log) : log_(log) {}

protected:
    void onInitialize() override { createGameObject().addComponent<Listener>(log_); }

private:
    std::vector<std::string>& log_;
};

TEST(InputSystem, EventsReachComponentsInOrderThroughCoreEvents) {
    std::vector<std::string> log;
    core::Logger logger(core::LogLevel::Off);
    core::SceneRegistry registry;
    registry.add("main", [&log] {
        return std::unique_ptr<core::Scene>(std::make_unique<ListenerScene>(log));
    });
    core::SceneDirector director(registry, logger);
    InputDef def;
    def.screenToWorld = [](glm::vec2 s) { return s * 10.0f; };
    Input input(def);
    ActionMap actions;
    actions.bind(actions.add("jump"), Binding::key(Key::Space));
    InputSystem system(input, director, &actions);
    director.addSystem(system);
    core::FixedStepper stepper(1.0 / 60.0, 5);
    core::Clock clock;
    core::GameLoop loop(director, stepper, clock);
    ASSERT_TRUE(loop.start("main"));

    input.handleKey(GLFW_KEY_SPACE, 65, GLFW_PRESS, GLFW_MOD_CONTROL);
    input.handleKey(GLFW_KEY_SPACE, 65, GLFW_REPEAT, GLFW_MOD_CONTROL);
    input.handleChar(U' ');
    input.handleCursorPos(3.0, 4.0);
    input.handleMouseButton(GLFW_MOUSE_BUTTON_RIGHT, GLFW_PRESS, 0);
    input.handleScroll(0.0, -2.0);
    input.handleKey(GLFW_KEY_SPACE, 65, GLFW_RELEASE, 0);
    JoystickSnapshot pad;
    pad.present = true;
    pad.gamepad = true;
    pad.axes = {0.0f, 1.0f, 0.0f, 0.0f, -1.0f, -1.0f};
    pad.buttons[GLFW_GAMEPAD_BUTTON_B] = GLFW_PRESS;
    input.handleJoystick(5, pad);
    loop.frame();
    EXPECT_THAT(log, ElementsAre("keyDown 32 65 2", "keyRepeat 32", "text 32", "move 4 40",
                                 "mouseDown 1 3 30", "scroll -2", "keyUp 32", "padConnected 5",
                                 "padDown 5 1", "padAxis 5 1 100", "jump pressed"));
    log.clear();

    input.handleFocus(false);
    input.handleJoystick(5, JoystickSnapshot{});
    loop.frame();
    EXPECT_THAT(log, ElementsAre("mouseUp 1", "focus out", "padUp 5 1", "padDisconnected 5"));
    loop.shutdown();
}

TEST(InputSystem, KeyRepeatCanBeKeptFromTheScene) {
    std::vector<std::string> log;
    core::Logger logger(core::LogLevel::Off);
    core::SceneRegistry registry;
    registry.add("main", [&log] {
        return std::unique_ptr<core::Scene>(std::make_unique<ListenerScene>(log));
    });
    core::SceneDirector director(registry, logger);
    Input input;
    InputSystemDef def;
    def.keyRepeat = false;
    InputSystem system(input, director, nullptr, def);
    director.addSystem(system);
    ASSERT_TRUE(director.start("main"));
    input.handleKey(GLFW_KEY_A, 38, GLFW_PRESS, 0);
    input.handleKey(GLFW_KEY_A, 38, GLFW_REPEAT, 0);
    input.handleKey(GLFW_KEY_A, 38, GLFW_REPEAT, 0);
    input.handleKey(GLFW_KEY_A, 38, GLFW_RELEASE, 0);
    system.beginFrame();
    EXPECT_THAT(log, ElementsAre("keyDown 65 38 0", "keyUp 65"));
    // Polling still sees the repeats.
    EXPECT_EQ(std::count_if(input.events().begin(), input.events().end(),
                            [](const Event& e) { return e.type == EventType::KeyRepeat; }),
              2);
    director.stop();
}

TEST(InputSystem, EventsCarryTypedKeysButtonsAndAxes) {
    // The enums are GLFW's codes under names.
    static_assert(static_cast<int>(Key::Space) == GLFW_KEY_SPACE);
    static_assert(static_cast<int>(Key::A) == GLFW_KEY_A);
    static_assert(static_cast<int>(Key::Escape) == GLFW_KEY_ESCAPE);
    static_assert(static_cast<int>(Key::KeypadEnter) == GLFW_KEY_KP_ENTER);
    static_assert(static_cast<int>(Key::Menu) == GLFW_KEY_LAST);
    static_assert(static_cast<int>(MouseButton::Middle) == GLFW_MOUSE_BUTTON_MIDDLE);
    static_assert(static_cast<int>(GamepadButton::DpadLeft) == GLFW_GAMEPAD_BUTTON_DPAD_LEFT);
    static_assert(static_cast<int>(GamepadButton::LeftTrigger) == GLFW_GAMEPAD_BUTTON_LAST + 1);
    static_assert(static_cast<int>(GamepadAxis::RightTrigger) == GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER);

    struct Typed : core::Scene, core::Handles<KeyDown, MouseButtonUp, GamepadAxisMoved> {
        std::vector<std::string> seen;
        void on(const KeyDown& e) override {
            if (e.key == Key::Escape && (e.mods & kModShift) != 0)
                seen.push_back("shift+escape");
        }
        void on(const MouseButtonUp& e) override {
            if (e.button == MouseButton::Middle)
                seen.push_back("middle up");
        }
        void on(const GamepadAxisMoved& e) override {
            if (e.axis == GamepadAxis::LeftTrigger)
                seen.push_back("left trigger");
        }
    } scene;
    Input input;
    input.handleKey(GLFW_KEY_ESCAPE, 9, GLFW_PRESS, GLFW_MOD_SHIFT);
    input.handleMouseButton(GLFW_MOUSE_BUTTON_MIDDLE, GLFW_PRESS, 0);
    input.handleMouseButton(GLFW_MOUSE_BUTTON_MIDDLE, GLFW_RELEASE, 0);
    JoystickSnapshot pad;
    pad.present = true;
    pad.gamepad = true;
    pad.axes = {0.0f, 0.0f, 0.0f, 0.0f, 1.0f, -1.0f};
    input.handleJoystick(0, pad);
    InputSystem system(input, [&scene] { return static_cast<core::Scene*>(&scene); });
    system.beginFrame();
    EXPECT_THAT(scene.seen, ElementsAre("shift+escape", "middle up", "left trigger"));
}

TEST(InputSystem, WithoutASceneEventsAreStillDeliveredToPolling) {
    Input input;
    InputSystem system(input, [] { return static_cast<core::Scene*>(nullptr); });
    input.handleKey(GLFW_KEY_Z, 52, GLFW_PRESS, 0);
    system.beginFrame();
    EXPECT_TRUE(input.wasKeyPressed(Key::Z));
    EXPECT_EQ(system.actions(), nullptr);
}

} // namespace
} // namespace e2d::input
