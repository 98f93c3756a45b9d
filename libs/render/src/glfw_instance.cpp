// SPDX-License-Identifier: MIT
#include <e2d/render/window.hpp>

#include <e2d/core/error_text.hpp>

#include <GLFW/glfw3.h>

#include <chrono>
#include <string>
#include <thread>

namespace e2d::render {

namespace {

// GLFW's own answer, so GLFW initialised by any code counts: functions that need an
// initialised library report GLFW_NOT_INITIALIZED otherwise (no e2d code installs an error
// callback that would see it).
bool glfwInitialised() {
    glfwGetError(nullptr); // this thread's earlier error, if any, is not ours to read
    static_cast<void>(glfwGetTime());
    return glfwGetError(nullptr) != GLFW_NOT_INITIALIZED;
}

} // namespace

GlfwInstance::GlfwInstance() {
    // A second instance would initialise nothing, and its glfwTerminate() would destroy the
    // first one's windows under it.
    if (glfwInitialised()) {
        core::throwError(
            "render::GlfwInstance",
            "GLFW is already initialised in this process (GLFW's state is process-wide: a Game run "
            "while another Game runs, or a second GlfwInstance); windows open at the same time "
            "share "
            "one instance (WindowDef::glfw = firstWindow.glfw())");
    }
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
            core::throwError("render::GlfwInstance", "glfwInit() failed: " + reason);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20 * attempt));
    }
}

GlfwInstance::~GlfwInstance() { glfwTerminate(); }

} // namespace e2d::render
