// SPDX-License-Identifier: MIT
// Uses the installed input library: a GLFW window, an Input attached to it, an event through
// the callback entry point, an action loaded from bindings text, a mapping line checked.
#include <e2d/input/actions.hpp>
#include <e2d/input/gamepad_mappings.hpp>
#include <e2d/input/input.hpp>

#include <GLFW/glfw3.h>

#include <cstdio>
#include <string>

int main() {
    using namespace e2d::input;
    if (glfwInit() != GLFW_TRUE) {
        std::fprintf(stderr, "consumer: glfwInit failed (no display?)\n");
        return 1;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    GLFWwindow* window = glfwCreateWindow(64, 64, "e2d consumer", nullptr, nullptr);
    int status = 1;
    if (window != nullptr) {
        InputDef def;
        def.window = window;
        Input input(def);
        ActionMap actions;
        actions.loadFromString("jump = key:space, button:a\n");
        input.handleKey(GLFW_KEY_SPACE, 65, GLFW_PRESS, 0);
        glfwPollEvents();
        input.beginFrame();
        actions.update(input);
        const MappingLoadResult mappings = loadGamepadMappings(
            "03000000de280000ff11000001000000,Consumer Pad,a:b0,leftx:a0,platform:Linux,");
        if (Input::fromWindow(window) == &input && actions.pressed("jump") &&
            mappings.loaded == 1) {
            std::printf("consumer: input attached, 'jump' pressed by %s, %d mapping loaded\n",
                        std::string(keyName(Key::Space)).c_str(), mappings.loaded);
            status = 0;
        } else {
            std::fprintf(stderr, "consumer: input did not work\n");
        }
        input.detach();
        glfwDestroyWindow(window);
    }
    glfwTerminate();
    return status;
}
