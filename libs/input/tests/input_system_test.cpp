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

#include <memory>
#include <string>
#include <vector>

namespace e2d::input {
namespace {

using ::testing::ElementsAre;

class Listener : public core::Component {
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
    void onButtonDown(int key) override { log_.push_back("buttonDown " + std::to_string(key)); }
    void onKeyDown(int key, int mods) override { log_.push_back("keyDown " + std::to_string(key) + " " + std::to_string(mods)); }
    void onButtonUp(int key) override { log_.push_back("buttonUp " + std::to_string(key)); }
    void onKeyUp(int key, int) override { log_.push_back("keyUp " + std::to_string(key)); }
    void onKeyRepeat(int key, int) override { log_.push_back("keyRepeat " + std::to_string(key)); }
    void onTextInput(char32_t c) override { log_.push_back("text " + std::to_string(std::uint32_t(c))); }
    void onMouseButtonDown(int b, glm::vec2 s, glm::vec2 w) override {
        log_.push_back("mouseDown " + std::to_string(b) + " " + std::to_string(int(s.x)) + " " + std::to_string(int(w.x)));
    }
    void onMouseButtonUp(int b, glm::vec2, glm::vec2) override { log_.push_back("mouseUp " + std::to_string(b)); }
    void onMouseMove(glm::vec2 s, glm::vec2 w) override {
        log_.push_back("move " + std::to_string(int(s.y)) + " " + std::to_string(int(w.y)));
    }
    void onScroll(glm::vec2 o, glm::vec2, glm::vec2) override { log_.push_back("scroll " + std::to_string(int(o.y))); }
    void onFocusChanged(bool f) override { log_.push_back(std::string("focus ") + (f ? "in" : "out")); }
    void onControllerConnected(int c) override { log_.push_back("padConnected " + std::to_string(c)); }
    void onControllerDisconnected(int c) override { log_.push_back("padDisconnected " + std::to_string(c)); }
    void onControllerButtonDown(int c, int b) override {
        log_.push_back("padDown " + std::to_string(c) + " " + std::to_string(b));
    }
    void onControllerButtonUp(int c, int b) override { log_.push_back("padUp " + std::to_string(c) + " " + std::to_string(b)); }
    void onControllerAxis(int c, int a, float v) override {
        log_.push_back("padAxis " + std::to_string(c) + " " + std::to_string(a) + " " + std::to_string(int(v * 100)));
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
    registry.add("main", [&log] { return std::unique_ptr<core::Scene>(std::make_unique<ListenerScene>(log)); });
    core::SceneDirector director(registry, logger);
    InputDef def;
    def.screenToWorld = [](glm::vec2 s) { return s * 10.0f; };
    Input input(def);
    ActionMap actions;
    actions.bind(actions.add("jump"), Binding::key(GLFW_KEY_SPACE));
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
    EXPECT_THAT(log, ElementsAre("buttonDown 32", "keyDown 32 2", "keyRepeat 32", "text 32", "move 4 40",
                                 "mouseDown 1 3 30", "scroll -2", "buttonUp 32", "keyUp 32", "padConnected 5",
                                 "padDown 5 1", "padAxis 5 1 100", "jump pressed"));
    log.clear();

    input.handleFocus(false);
    input.handleJoystick(5, JoystickSnapshot{});
    loop.frame();
    EXPECT_THAT(log, ElementsAre("mouseUp 1", "focus out", "padUp 5 1", "padDisconnected 5"));
    loop.shutdown();
}

TEST(InputSystem, WithoutASceneEventsAreStillDeliveredToPolling) {
    Input input;
    InputSystem system(input, [] { return static_cast<core::Scene*>(nullptr); });
    input.handleKey(GLFW_KEY_Z, 52, GLFW_PRESS, 0);
    system.beginFrame();
    EXPECT_TRUE(input.wasKeyPressed(GLFW_KEY_Z));
    EXPECT_EQ(system.actions(), nullptr);
}

} // namespace
} // namespace e2d::input
