// SPDX-License-Identifier: MIT
// Linked into the engine's game tests, several of which run more than one game (one window
// after another) in one process. Xvfb resets itself when its last client disconnects, and a
// window opened while it resets fails ("cannot open the game window"): keeping one X
// connection of our own open for the life of the process means it never resets. libX11 is
// reached through dlopen (it is there wherever GLFW runs on X11) so nothing more is linked.
// Without DISPLAY (the no-display test) nothing happens.
#include <dlfcn.h>

#include <cstdlib>

namespace {

void* openDisplay() {
    if (std::getenv("DISPLAY") == nullptr) {
        return nullptr;
    }
    void* x11 = dlopen("libX11.so.6", RTLD_LAZY | RTLD_LOCAL | RTLD_NODELETE);
    if (x11 == nullptr) {
        return nullptr;
    }
    using OpenDisplay = void* (*)(const char*);
    const auto open = reinterpret_cast<OpenDisplay>(dlsym(x11, "XOpenDisplay"));
    return open != nullptr ? open(nullptr) : nullptr;
}

// Kept in a global so that the connection stays reachable (LeakSanitizer).
[[maybe_unused]] void* const kDisplay = openDisplay();

} // namespace
