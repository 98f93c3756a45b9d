// SPDX-License-Identifier: MIT
// e2d::input alone: an Input on a GLFW window the program made itself (no renderer, no
// OpenGL), and an ActionMap of named actions. Space, the left mouse button or a gamepad's A
// jumps, the arrow keys or the left stick move (actions), Escape quits (a key polled
// directly); every jump and every change of direction is printed. Quits by itself after the seconds given as its argument (default 60).
// Links e2d::input (and so GLFW) only.
#include <e2d/input/actions.hpp>
#include <e2d/input/input.hpp>

#include <GLFW/glfw3.h>

#include <cstdio>
#include <string>

using namespace e2d::input;

int main(int argc, char** argv) {
    const double seconds = argc > 1 ? std::stod(argv[1]) : 60.0;

    // Initialisation: GLFW and a window without an OpenGL context, then the Input on it.
    if (glfwInit() == GLFW_FALSE) {
        std::fprintf(stderr, "input_actions: GLFW could not start (no display?)\n");
        return 1;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    GLFWwindow* window = glfwCreateWindow(480, 240, "e2d input actions", nullptr, nullptr);
    if (window == nullptr) {
        std::fprintf(stderr, "input_actions: no window\n");
        glfwTerminate();
        return 1;
    }
    Input input(InputDef{.window = window});
    // Actions by name, each bound to any mix of keys, buttons and axes: the bindings file
    // format (ActionMap::load reads the same from a file).
    ActionMap actions;
    actions.loadFromString("jump = key:space, mouse:left, button:a\n"
                           "move_x = keys:left/right, axis:leftx\n");
    const ActionId jump = actions.find("jump");
    const ActionId move = actions.find("move_x");

    // The loop: wait for events (at most a frame), deliver them, read the actions.
    int jumps = 0;
    float direction = 0.0f;
    while (glfwWindowShouldClose(window) == GLFW_FALSE && glfwGetTime() < seconds) {
        glfwWaitEventsTimeout(1.0 / 60.0);
        input.beginFrame();    // this frame's events, in order, and the polling state
        actions.update(input); // each action's value, held, pressed and released
        if (actions.pressed(jump)) {
            std::printf("jump %d\n", ++jumps);
        }
        const float now = actions.value(move) > 0.5f    ? 1.0f
                          : actions.value(move) < -0.5f ? -1.0f
                                                        : 0.0f;
        if (now != direction) {
            direction = now;
            std::printf("moving %s\n", now > 0.0f ? "right" : now < 0.0f ? "left" : "nowhere");
        }
        // Polling names keys, buttons and axes with the events' enums.
        if (input.wasKeyPressed(Key::Escape)) {
            break;
        }
    }

    // Shutdown: the Input lets go of the window before the window goes.
    input.detach();
    glfwDestroyWindow(window);
    glfwTerminate();
    std::printf("%d jumps\n", jumps);
    return 0;
}
