// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/input/input.hpp>

#include <GLFW/glfw3.h>

namespace e2d::input {

// What the window had before the Input attached, put back on detach.
struct Input::SavedCallbacks {
    void* userPointer = nullptr;
    GLFWkeyfun key = nullptr;
    GLFWcharfun character = nullptr;
    GLFWmousebuttonfun mouseButton = nullptr;
    GLFWcursorposfun cursorPos = nullptr;
    GLFWscrollfun scroll = nullptr;
    GLFWwindowfocusfun focus = nullptr;
};

} // namespace e2d::input
