// SPDX-License-Identifier: MIT
#include <e2d/render/window.hpp>

#include "error_format.hpp"

#include <GLFW/glfw3.h>

#include <string>

namespace e2d::render {

GlfwInstance::GlfwInstance() {
    if (glfwInit() != GLFW_TRUE) {
        const char* description = nullptr;
        glfwGetError(&description);
        detail::fail("render::GlfwInstance", std::string("glfwInit() failed: ") +
                                                 (description != nullptr ? description : "no reason given"));
    }
}

GlfwInstance::~GlfwInstance() { glfwTerminate(); }

} // namespace e2d::render
