// SPDX-License-Identifier: MIT
#include <e2d/input/input.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/core/log.hpp>
#include <e2d/input/input_script.hpp>

#include <GLFW/glfw3.h>

#include "saved_callbacks.hpp"

#include <cmath>
#include <string>

namespace e2d::input {

namespace {

bool validKey(int key) noexcept { return key >= 0 && key <= kKeyLast; }

bool validButton(int button) noexcept { return button >= 0 && button < kMouseButtonCount; }

} // namespace

std::string_view toString(EventType type) noexcept {
    switch (type) {
    case EventType::KeyDown:
        return "KeyDown";
    case EventType::KeyUp:
        return "KeyUp";
    case EventType::KeyRepeat:
        return "KeyRepeat";
    case EventType::Text:
        return "Text";
    case EventType::MouseButtonDown:
        return "MouseButtonDown";
    case EventType::MouseButtonUp:
        return "MouseButtonUp";
    case EventType::MouseMove:
        return "MouseMove";
    case EventType::Scroll:
        return "Scroll";
    case EventType::FocusGained:
        return "FocusGained";
    case EventType::FocusLost:
        return "FocusLost";
    case EventType::GamepadConnected:
        return "GamepadConnected";
    case EventType::GamepadDisconnected:
        return "GamepadDisconnected";
    case EventType::GamepadButtonDown:
        return "GamepadButtonDown";
    case EventType::GamepadButtonUp:
        return "GamepadButtonUp";
    case EventType::GamepadAxis:
        return "GamepadAxis";
    case EventType::JoystickConnected:
        return "JoystickConnected";
    case EventType::JoystickDisconnected:
        return "JoystickDisconnected";
    }
    return "?";
}

Input::Input(InputDef def) : def_(std::move(def)) {
    const auto check = [](bool ok, const char* field, const std::string& rule, float value) {
        if (!ok) {
            throw core::Error(std::string("input::Input::Input(): ") + field + " must be " + rule +
                              ", got " + core::formatNumber(value));
        }
    };
    check(def_.stickDeadZone >= 0.0f && def_.stickDeadZone < 1.0f, "stickDeadZone", "in [0, 1)",
          def_.stickDeadZone);
    check(def_.triggerDeadZone >= 0.0f && def_.triggerDeadZone < 1.0f, "triggerDeadZone",
          "in [0, 1)", def_.triggerDeadZone);
    check(def_.triggerPressThreshold > 0.0f && def_.triggerPressThreshold <= 1.0f,
          "triggerPressThreshold", "in (0, 1]", def_.triggerPressThreshold);
    if (def_.maxQueuedEvents < 1) {
        throw core::Error("input::Input::Input(): maxQueuedEvents must be >= 1, got 0");
    }
    queue_.reserve(256);
    events_.reserve(256);
    GLFWwindow* window = def_.window;
    def_.window = nullptr;
    attach(window);
}

Input::~Input() { attach(nullptr); }

void Input::setScreenToWorld(std::function<glm::vec2(glm::vec2)> converter) {
    def_.screenToWorld = std::move(converter);
}

glm::vec2 Input::toWorld(glm::vec2 screen) const {
    return def_.screenToWorld ? def_.screenToWorld(screen) : screen;
}

// Callback side ------------------------------------------------------------------------------

void Input::queue(const Event& event) {
    if (queue_.size() >= def_.maxQueuedEvents) {
        ++dropped_;
        return;
    }
    queue_.push_back(event);
}

void Input::handleKey(int key, int scancode, int action, int mods) {
    Event e;
    e.type = action == GLFW_PRESS     ? EventType::KeyDown
             : action == GLFW_RELEASE ? EventType::KeyUp
                                      : EventType::KeyRepeat;
    e.code = key;
    e.scancode = scancode;
    e.mods = mods;
    queue(e);
}

void Input::handleChar(char32_t codepoint) {
    Event e;
    e.type = EventType::Text;
    e.code = static_cast<int>(codepoint);
    queue(e);
}

void Input::handleMouseButton(int button, int action, int mods) {
    Event e;
    e.type = action == GLFW_PRESS ? EventType::MouseButtonDown : EventType::MouseButtonUp;
    e.code = button;
    e.mods = mods;
    e.screen = queuedCursor_;
    queue(e);
}

void Input::handleCursorPos(double x, double y) {
    Event e;
    e.type = EventType::MouseMove;
    e.screen = glm::vec2(static_cast<float>(x), static_cast<float>(y));
    e.delta = e.screen - queuedCursor_;
    queuedCursor_ = e.screen;
    queue(e);
}

void Input::handleScroll(double dx, double dy) {
    Event e;
    e.type = EventType::Scroll;
    e.delta = glm::vec2(static_cast<float>(dx), static_cast<float>(dy));
    e.screen = queuedCursor_;
    queue(e);
}

void Input::handleFocus(bool focused) {
    Event e;
    e.type = focused ? EventType::FocusGained : EventType::FocusLost;
    queue(e);
}

// Delivery -----------------------------------------------------------------------------------

void Input::play(ScriptedInput script) {
    script_ = std::make_unique<ScriptedInput>(std::move(script));
    scriptFrame_ = 0;
}

void Input::beginFrame() {
    if (script_) {
        script_->feed(*this, scriptFrame_++);
    }
    for (int key : touchedKeys_) {
        keys_[static_cast<std::size_t>(key)].pressed = false;
        keys_[static_cast<std::size_t>(key)].released = false;
    }
    touchedKeys_.clear();
    for (KeyState& b : buttons_) {
        b.pressed = false;
        b.released = false;
    }
    for (Pad& pad : pads_) {
        pad.pressed.fill(false);
        pad.released.fill(false);
    }
    events_.clear();
    text_.clear();
    mouseDelta_ = glm::vec2(0.0f);
    scroll_ = glm::vec2(0.0f);

    for (const Event& e : queue_) {
        deliver(e);
    }
    queue_.clear();

    if (dropped_ != droppedReported_) {
        if (def_.logger != nullptr) {
            def_.logger->warning(
                "input::Input::beginFrame(): " + core::formatNumber(dropped_ - droppedReported_) +
                " events dropped (more than maxQueuedEvents = " +
                core::formatNumber(def_.maxQueuedEvents) + " queued in one frame)");
        }
        droppedReported_ = dropped_;
    }

    if (def_.pollGamepads && window_ != nullptr && !(script_ && script_->drivesGamepads())) {
        pollJoysticks();
    }
    for (int slot = 0; slot < kMaxGamepads; ++slot) {
        PendingPad& pending = pendingPads_[static_cast<std::size_t>(slot)];
        if (pending.fed) {
            applyPad(slot, pending);
            pending.fed = false;
        }
    }
}

void Input::deliver(Event e) {
    switch (e.type) {
    case EventType::KeyDown:
    case EventType::KeyUp:
        if (validKey(e.code)) {
            KeyState& k = keys_[static_cast<std::size_t>(e.code)];
            const bool down = e.type == EventType::KeyDown;
            // An up for a key that is not down was already released (focus loss) or was
            // pressed before the Input attached: nothing to report.
            if (!down && !k.down) {
                return;
            }
            if (!k.pressed && !k.released) {
                touchedKeys_.push_back(e.code);
            }
            k.down = down;
            (down ? k.pressed : k.released) = true;
            if (down) {
                k.scancode = e.scancode;
            }
        }
        break;
    case EventType::MouseButtonDown:
    case EventType::MouseButtonUp:
        if (validButton(e.code)) {
            KeyState& b = buttons_[static_cast<std::size_t>(e.code)];
            const bool down = e.type == EventType::MouseButtonDown;
            if (!down && !b.down) {
                return;
            }
            b.down = down;
            (down ? b.pressed : b.released) = true;
        }
        e.world = toWorld(e.screen);
        break;
    case EventType::MouseMove:
        mouse_ = e.screen;
        mouseDelta_ += e.delta;
        e.world = toWorld(e.screen);
        mouseWorld_ = e.world;
        break;
    case EventType::Scroll:
        scroll_ += e.delta;
        e.world = toWorld(e.screen);
        break;
    case EventType::Text:
        text_.push_back(static_cast<char32_t>(e.code));
        break;
    case EventType::FocusLost:
        releaseEverything();
        focused_ = false;
        break;
    case EventType::FocusGained:
        focused_ = true;
        break;
    default:
        break;
    }
    events_.push_back(e);
}

void Input::releaseEverything() {
    for (int key = 0; key <= kKeyLast; ++key) {
        KeyState& k = keys_[static_cast<std::size_t>(key)];
        if (k.down) {
            Event up;
            up.type = EventType::KeyUp;
            up.code = key;
            up.scancode = k.scancode;
            deliver(up);
        }
    }
    for (int button = 0; button < kMouseButtonCount; ++button) {
        if (buttons_[static_cast<std::size_t>(button)].down) {
            Event up;
            up.type = EventType::MouseButtonUp;
            up.code = button;
            up.screen = mouse_;
            deliver(up);
        }
    }
}

// Polling ------------------------------------------------------------------------------------

bool Input::isKeyDown(Key key) const noexcept {
    const int code = static_cast<int>(key);
    return validKey(code) && keys_[static_cast<std::size_t>(code)].down;
}

bool Input::wasKeyPressed(Key key) const noexcept {
    const int code = static_cast<int>(key);
    return validKey(code) && keys_[static_cast<std::size_t>(code)].pressed;
}

bool Input::wasKeyReleased(Key key) const noexcept {
    const int code = static_cast<int>(key);
    return validKey(code) && keys_[static_cast<std::size_t>(code)].released;
}

bool Input::isMouseButtonDown(MouseButton button) const noexcept {
    const int code = static_cast<int>(button);
    return validButton(code) && buttons_[static_cast<std::size_t>(code)].down;
}

bool Input::wasMouseButtonPressed(MouseButton button) const noexcept {
    const int code = static_cast<int>(button);
    return validButton(code) && buttons_[static_cast<std::size_t>(code)].pressed;
}

bool Input::wasMouseButtonReleased(MouseButton button) const noexcept {
    const int code = static_cast<int>(button);
    return validButton(code) && buttons_[static_cast<std::size_t>(code)].released;
}

} // namespace e2d::input
