// SPDX-License-Identifier: MIT
// Attaching an Input to a GLFW window: its callbacks, the user pointer, the cursor mode.
#include <e2d/input/input.hpp>

#include <e2d/core/error.hpp>

#include <GLFW/glfw3.h>

#include "saved_callbacks.hpp"

namespace e2d::input {

namespace {

Input& inputOf(GLFWwindow* window) {
    return *static_cast<Input*>(glfwGetWindowUserPointer(window));
}

void keyCallback(GLFWwindow* window, int key, int scancode, int action, int mods) {
    inputOf(window).handleKey(key, scancode, action, mods);
}

void charCallback(GLFWwindow* window, unsigned int codepoint) {
    inputOf(window).handleChar(static_cast<char32_t>(codepoint));
}

void mouseButtonCallback(GLFWwindow* window, int button, int action, int mods) {
    inputOf(window).handleMouseButton(button, action, mods);
}

void cursorPosCallback(GLFWwindow* window, double x, double y) {
    inputOf(window).handleCursorPos(x, y);
}

void scrollCallback(GLFWwindow* window, double dx, double dy) {
    inputOf(window).handleScroll(dx, dy);
}

void focusCallback(GLFWwindow* window, int focused) {
    inputOf(window).handleFocus(focused == GLFW_TRUE);
}

int glfwCursorMode(CursorMode mode) {
    switch (mode) {
    case CursorMode::Hidden:
        return GLFW_CURSOR_HIDDEN;
    case CursorMode::Captured:
        return GLFW_CURSOR_DISABLED;
    case CursorMode::Normal:
        break;
    }
    return GLFW_CURSOR_NORMAL;
}

} // namespace

Input* Input::fromWindow(GLFWwindow* window) noexcept {
    if (window == nullptr) {
        return nullptr;
    }
    // Only an Input installs keyCallback, so it tells whether the user pointer is an Input
    // without trusting whatever else may be stored there.
    const GLFWkeyfun current = glfwSetKeyCallback(window, nullptr);
    glfwSetKeyCallback(window, current);
    return current == &keyCallback ? static_cast<Input*>(glfwGetWindowUserPointer(window))
                                   : nullptr;
}

void Input::attach(GLFWwindow* window) {
    if (window == window_) {
        return;
    }
    if (window != nullptr && fromWindow(window) != nullptr) {
        throw core::Error("input::Input::attach(): the window already has an Input attached");
    }
    if (window_ != nullptr) {
        restoreCallbacks();
        window_ = nullptr;
    }
    if (window == nullptr) {
        return;
    }
    window_ = window;
    installCallbacks();
    double x = 0.0;
    double y = 0.0;
    glfwGetCursorPos(window_, &x, &y);
    queuedCursor_ = glm::vec2(static_cast<float>(x), static_cast<float>(y));
    mouse_ = queuedCursor_;
    mouseWorld_ = toWorld(mouse_);
    focused_ = glfwGetWindowAttrib(window_, GLFW_FOCUSED) == GLFW_TRUE;
    glfwSetInputMode(window_, GLFW_CURSOR, glfwCursorMode(cursorMode_));
}

void Input::installCallbacks() {
    saved_ = std::make_unique<SavedCallbacks>();
    saved_->userPointer = glfwGetWindowUserPointer(window_);
    userData_ = saved_->userPointer;
    glfwSetWindowUserPointer(window_, this);
    saved_->key = glfwSetKeyCallback(window_, &keyCallback);
    saved_->character = glfwSetCharCallback(window_, &charCallback);
    saved_->mouseButton = glfwSetMouseButtonCallback(window_, &mouseButtonCallback);
    saved_->cursorPos = glfwSetCursorPosCallback(window_, &cursorPosCallback);
    saved_->scroll = glfwSetScrollCallback(window_, &scrollCallback);
    saved_->focus = glfwSetWindowFocusCallback(window_, &focusCallback);
}

void Input::restoreCallbacks() {
    glfwSetKeyCallback(window_, saved_->key);
    glfwSetCharCallback(window_, saved_->character);
    glfwSetMouseButtonCallback(window_, saved_->mouseButton);
    glfwSetCursorPosCallback(window_, saved_->cursorPos);
    glfwSetScrollCallback(window_, saved_->scroll);
    glfwSetWindowFocusCallback(window_, saved_->focus);
    // Whatever other code set as userData() meanwhile is what it gets back.
    glfwSetWindowUserPointer(window_, userData_);
    saved_.reset();
}

void Input::setCursorMode(CursorMode mode) {
    cursorMode_ = mode;
    if (window_ == nullptr) {
        return;
    }
    glfwSetInputMode(window_, GLFW_CURSOR, glfwCursorMode(mode));
    if (mode == CursorMode::Captured && glfwRawMouseMotionSupported() == GLFW_TRUE) {
        glfwSetInputMode(window_, GLFW_RAW_MOUSE_MOTION, GLFW_TRUE);
    }
    // GLFW may move the (virtual) cursor when the mode changes: measure the next motion from
    // where it is now, so the switch is not reported as a jump.
    double x = 0.0;
    double y = 0.0;
    glfwGetCursorPos(window_, &x, &y);
    queuedCursor_ = glm::vec2(static_cast<float>(x), static_cast<float>(y));
}

} // namespace e2d::input
