// SPDX-License-Identifier: MIT
// End to end: a visible GLFW window under Xvfb receives real X input sent by xdotool, and
// Input delivers it in order with the right keys, code points and positions.
// CTest runs this through scripts/with-display.sh (private Xvfb, key auto-repeat slowed).
#include <e2d/core/error.hpp>
#include <e2d/input/input.hpp>

#include <GLFW/glfw3.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace e2d::input {
namespace {

using ::testing::ElementsAre;
using namespace std::chrono_literals;

std::string describe(const Event& e) {
    std::string s(toString(e.type));
    switch (e.type) {
    case EventType::KeyDown:
    case EventType::KeyUp:
    case EventType::KeyRepeat:
        return s + " " + std::string(keyName(Key(e.code))) + " mods=" + std::to_string(e.mods);
    case EventType::Text:
        return s + " U+" + std::to_string(e.code);
    case EventType::MouseButtonDown:
    case EventType::MouseButtonUp:
        return s + " " + std::string(mouseButtonName(MouseButton(e.code))) + " @" +
               std::to_string(int(e.screen.x)) + "," + std::to_string(int(e.screen.y));
    case EventType::MouseMove:
        return s + " @" + std::to_string(int(e.screen.x)) + "," + std::to_string(int(e.screen.y));
    case EventType::Scroll:
        return s + " " + std::to_string(int(e.delta.x)) + "," + std::to_string(int(e.delta.y));
    default:
        return s;
    }
}

// Runs a shell command and returns its standard output.
std::string output(const std::string& command) {
    std::string out;
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr) {
        return out;
    }
    std::array<char, 256> buffer{};
    while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr) {
        out += buffer.data();
    }
    pclose(pipe);
    while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) {
        out.pop_back();
    }
    return out;
}

class WindowInput : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_EQ(std::system("command -v xdotool >/dev/null"), 0)
            << "xdotool is missing (Debian package xdotool)";
        // Xvfb resets when its last client leaves (the previous test's glfwTerminate) and
        // refuses connections for a moment while it does: retry for up to 2 s.
        bool initialised = false;
        const char* why = nullptr;
        for (int attempt = 0; attempt < 40 && !initialised; ++attempt) {
            initialised = glfwInit() == GLFW_TRUE;
            if (!initialised) {
                glfwGetError(&why);
                std::this_thread::sleep_for(50ms);
            }
        }
        ASSERT_TRUE(initialised) << "glfwInit failed: " << (why != nullptr ? why : "?");
        glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
        glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
        // Unique per process, so parallel tests (ctest -j) never find each other's window.
        title_ = "e2d-input-e2e-" + std::to_string(getpid());
        window_ = glfwCreateWindow(kWidth, kHeight, title_.c_str(), nullptr, nullptr);
        ASSERT_NE(window_, nullptr);
        InputDef def;
        def.window = window_;
        def.pollGamepads = false;
        // A camera: 4 pixels per unit, origin at the window centre, y up.
        def.screenToWorld = [](glm::vec2 s) {
            return glm::vec2((s.x - kWidth / 2.0f) / 4.0f, (kHeight / 2.0f - s.y) / 4.0f);
        };
        input_ = std::make_unique<Input>(std::move(def));
        windowId_ = output("xdotool search --sync --name '^" + title_ + "$' | head -n 1");
        ASSERT_FALSE(windowId_.empty()) << "xdotool did not find the window";
        // GLFW focuses a window when it is shown; wait until X says so.
        ASSERT_TRUE(pumpUntil([&] {
            return glfwGetWindowAttrib(window_, GLFW_FOCUSED) == GLFW_TRUE;
        })) << "the window never got focus";
        events_.clear();
    }

    void TearDown() override {
        input_.reset();
        if (window_ != nullptr) {
            glfwDestroyWindow(window_);
        }
        glfwTerminate();
    }

    void xdotool(const std::string& args) {
        ASSERT_EQ(std::system(("xdotool " + args).c_str()), 0) << "xdotool " << args;
    }

    // Pumps GLFW and delivers frames until `done` or 5 s; the frames' events are collected.
    bool pumpUntil(const std::function<bool()>& done) {
        const auto deadline = std::chrono::steady_clock::now() + 5s;
        while (std::chrono::steady_clock::now() < deadline) {
            glfwPollEvents();
            input_->beginFrame();
            events_.insert(events_.end(), input_->events().begin(), input_->events().end());
            if (done()) {
                return true;
            }
            std::this_thread::sleep_for(5ms);
        }
        return false;
    }

    bool pumpUntilSeen(EventType type, int code) {
        return pumpUntil([&] {
            for (const Event& e : events_) {
                if (e.type == type && e.code == code) {
                    return true;
                }
            }
            return false;
        });
    }

    // The collected events of the given types, described.
    std::vector<std::string> seen(std::initializer_list<EventType> types) const {
        std::vector<std::string> out;
        for (const Event& e : events_) {
            if (std::find(types.begin(), types.end(), e.type) != types.end()) {
                out.push_back(describe(e));
            }
        }
        return out;
    }

    static constexpr int kWidth = 320;
    static constexpr int kHeight = 240;
    std::string title_;
    GLFWwindow* window_ = nullptr;
    std::unique_ptr<Input> input_;
    std::string windowId_;
    std::vector<Event> events_;
};

constexpr auto kKeys = {EventType::KeyDown, EventType::KeyUp, EventType::KeyRepeat,
                        EventType::Text};

TEST_F(WindowInput, KeysWithModifiersAndTheirTextArriveInOrder) {
    xdotool("key a");
    xdotool("key shift+x");
    xdotool("key ctrl+s");
    ASSERT_TRUE(pumpUntil([&] {
        return std::count_if(events_.begin(), events_.end(),
                             [](const Event& e) { return e.type == EventType::KeyUp; }) == 5;
    }));
    // X11 reports the modifiers held before the event (so shift's own press has none and its
    // release has shift), and xdotool releases a chord's keys in the order it pressed them.
    EXPECT_THAT(seen(kKeys),
                ElementsAre("KeyDown a mods=0", "Text U+97", "KeyUp a mods=0",            //
                            "KeyDown left_shift mods=0", "KeyDown x mods=1", "Text U+88", //
                            "KeyUp left_shift mods=1", "KeyUp x mods=0",                  //
                            "KeyDown left_control mods=0", "KeyDown s mods=2",            //
                            "KeyUp left_control mods=2", "KeyUp s mods=0")); // no text with ctrl
    EXPECT_FALSE(input_->isKeyDown(Key::A));
    EXPECT_FALSE(input_->isKeyDown(Key::LeftControl));
}

TEST_F(WindowInput, TypedTextArrivesAsCodePoints) {
    xdotool("type --delay 20 'Hi, e2d! {~}'");
    ASSERT_TRUE(pumpUntilSeen(EventType::Text, '}'));
    std::u32string text;
    for (const Event& e : events_) {
        if (e.type == EventType::Text) {
            text.push_back(static_cast<char32_t>(e.code));
        }
    }
    // ASCII only: xdotool types a character outside the keymap by remapping a spare key code
    // for a moment, and GLFW 3.3 looks the key up in the mapping it read at start (key -1, no
    // text). Code points beyond ASCII are covered through handleChar() in the unit tests.
    EXPECT_EQ(text, U"Hi, e2d! {~}");
}

TEST_F(WindowInput, AHeldKeyDoesNotRepeatAndIsDownUntilReleased) {
    xdotool("keydown Right");
    ASSERT_TRUE(pumpUntilSeen(EventType::KeyDown, GLFW_KEY_RIGHT));
    EXPECT_TRUE(input_->isKeyDown(Key::Right));
    // Held for 0.6 s: with Xvfb's auto-repeat delay at 5 s no repeat may arrive.
    const auto until = std::chrono::steady_clock::now() + 600ms;
    pumpUntil([&] { return std::chrono::steady_clock::now() >= until; });
    EXPECT_TRUE(input_->isKeyDown(Key::Right));
    xdotool("keyup Right");
    ASSERT_TRUE(pumpUntilSeen(EventType::KeyUp, GLFW_KEY_RIGHT));
    EXPECT_THAT(seen(kKeys), ElementsAre("KeyDown right mods=0", "KeyUp right mods=0"));
    EXPECT_FALSE(input_->isKeyDown(Key::Right));
}

TEST_F(WindowInput, LosingFocusReleasesTheHeldKeysAndButtons) {
    xdotool("mousemove --window " + windowId_ + " 50 60");
    xdotool("keydown q");
    xdotool("mousedown 1");
    ASSERT_TRUE(pumpUntilSeen(EventType::MouseButtonDown, GLFW_MOUSE_BUTTON_LEFT));
    ASSERT_TRUE(input_->isKeyDown(Key::Q));
    events_.clear();
    // A second window takes the focus when shown (no window manager needed).
    GLFWwindow* other = glfwCreateWindow(100, 100, (title_ + "-other").c_str(), nullptr, nullptr);
    ASSERT_NE(other, nullptr);
    ASSERT_TRUE(pumpUntilSeen(EventType::FocusLost, 0));
    EXPECT_THAT(seen({EventType::KeyUp, EventType::MouseButtonUp, EventType::FocusLost}),
                ElementsAre("KeyUp q mods=0", "MouseButtonUp left @50,60", "FocusLost"));
    EXPECT_FALSE(input_->isKeyDown(Key::Q));
    EXPECT_FALSE(input_->isMouseButtonDown(MouseButton::Left));
    EXPECT_FALSE(input_->focused());
    xdotool("keyup q");
    xdotool("mouseup 1");
    glfwDestroyWindow(other);
}

TEST_F(WindowInput, MouseMovesClicksAndScrollArriveWithPositions) {
    xdotool("mousemove --window " + windowId_ + " 100 120");
    ASSERT_TRUE(pumpUntil([&] { return input_->mousePosition() == glm::vec2(100.0f, 120.0f); }));
    xdotool("click 1");
    xdotool("mousemove --window " + windowId_ + " 200 40");
    xdotool("click 3");
    xdotool("click 4");
    xdotool("click 5");
    ASSERT_TRUE(pumpUntil([&] {
        return std::count_if(events_.begin(), events_.end(),
                             [](const Event& e) { return e.type == EventType::Scroll; }) == 2;
    }));
    EXPECT_THAT(seen({EventType::MouseButtonDown, EventType::MouseButtonUp, EventType::Scroll}),
                ElementsAre("MouseButtonDown left @100,120", "MouseButtonUp left @100,120", //
                            "MouseButtonDown right @200,40", "MouseButtonUp right @200,40", //
                            "Scroll 0,1", "Scroll 0,-1"));
    // The last move ends where xdotool put the pointer; world positions follow the camera.
    const auto last = std::find_if(events_.rbegin(), events_.rend(),
                                   [](const Event& e) { return e.type == EventType::MouseMove; });
    ASSERT_NE(last, events_.rend());
    EXPECT_EQ(last->screen, glm::vec2(200.0f, 40.0f));
    EXPECT_EQ(last->world, glm::vec2((200.0f - 160.0f) / 4.0f, (120.0f - 40.0f) / 4.0f));
    for (const Event& e : events_) {
        if (e.type == EventType::MouseButtonDown && e.code == GLFW_MOUSE_BUTTON_LEFT) {
            EXPECT_EQ(e.world, glm::vec2((100.0f - 160.0f) / 4.0f, 0.0f));
        }
    }
    EXPECT_EQ(input_->mousePosition(), glm::vec2(200.0f, 40.0f));
}

TEST_F(WindowInput, TheInputOwnsTheUserPointerAndGivesTheOldOneBack) {
    int mine = 0;
    input_->detach();
    EXPECT_EQ(Input::fromWindow(window_), nullptr);
    glfwSetWindowUserPointer(window_, &mine);
    input_->attach(window_);
    EXPECT_EQ(Input::fromWindow(window_), input_.get());
    EXPECT_EQ(input_->userData(), &mine);
    Input second;
    EXPECT_THROW(second.attach(window_), core::Error);
    input_->detach();
    EXPECT_EQ(glfwGetWindowUserPointer(window_), &mine);
    EXPECT_EQ(Input::fromWindow(window_), nullptr);
    second.attach(window_);
    EXPECT_EQ(Input::fromWindow(window_), &second);
    second.detach();
}

TEST_F(WindowInput, CapturedCursorGivesRelativeMotion) {
    input_->setCursorMode(CursorMode::Captured);
    EXPECT_EQ(glfwGetInputMode(window_, GLFW_CURSOR), GLFW_CURSOR_DISABLED);
    pumpUntil([] { return true; });
    events_.clear();
    xdotool("mousemove_relative -- 7 5");
    ASSERT_TRUE(pumpUntil([&] { return !seen({EventType::MouseMove}).empty(); }));
    glm::vec2 motion(0.0f);
    for (const Event& e : events_) {
        motion += e.type == EventType::MouseMove ? e.delta : glm::vec2(0.0f);
    }
    EXPECT_EQ(motion, glm::vec2(7.0f, 5.0f));
    input_->setCursorMode(CursorMode::Hidden);
    EXPECT_EQ(glfwGetInputMode(window_, GLFW_CURSOR), GLFW_CURSOR_HIDDEN);
    input_->setCursorMode(CursorMode::Normal);
    EXPECT_EQ(glfwGetInputMode(window_, GLFW_CURSOR), GLFW_CURSOR_NORMAL);
}

} // namespace
} // namespace e2d::input
