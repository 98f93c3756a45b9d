// SPDX-License-Identifier: MIT
#include <e2d/render/window.hpp>

#include "error_format.hpp"

#include <GLFW/glfw3.h>

#include <chrono>
#include <string>
#include <thread>

namespace e2d::render {

GlfwInstance::GlfwInstance() {
    // An X server under load sometimes resets a connection opened right after another client
    // closed one (XOpenDisplay fails with ECONNRESET, the next attempt works): a display that
    // exists but could not be opened is tried again a few times before it is an error. A
    // missing DISPLAY or any other failure is reported at once.
    constexpr int kAttempts = 4;
    for (int attempt = 1;; ++attempt) {
        if (glfwInit() == GLFW_TRUE) {
            return;
        }
        const char* description = nullptr;
        glfwGetError(&description);
        const std::string reason = description != nullptr ? description : "no reason given";
        if (attempt == kAttempts || reason.find("Failed to open display") == std::string::npos) {
            detail::fail("render::GlfwInstance", "glfwInit() failed: " + reason);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20 * attempt));
    }
}

GlfwInstance::~GlfwInstance() { glfwTerminate(); }

} // namespace e2d::render
