// SPDX-License-Identifier: MIT
// Linked into the engine's game tests, several of which run more than one game (one window
// after another) in one process. Xvfb resets itself when its last client disconnects, and a
// window opened while it resets fails ("cannot open the game window"): keeping one X
// connection of our own open for the life of the process means it never resets. libX11 is
// reached through dlopen (it is there wherever GLFW runs on X11) so nothing more is linked.
// Without DISPLAY (the no-display test) nothing happens. The connection is closed at exit
// (before LeakSanitizer looks), when no game runs any more.
#include <dlfcn.h>

#include <cstdlib>

namespace {

using CloseDisplay = int (*)(void*);

struct Connection {
    void* display = nullptr;
    CloseDisplay close = nullptr;
};

Connection& connection() {
    static Connection c;
    return c;
}

void closeAtExit() {
    Connection& c = connection();
    if (c.display != nullptr && c.close != nullptr) {
        c.close(c.display);
        c.display = nullptr;
    }
}

bool openDisplay() {
    if (std::getenv("DISPLAY") == nullptr) {
        return false;
    }
    void* x11 = dlopen("libX11.so.6", RTLD_LAZY | RTLD_LOCAL | RTLD_NODELETE);
    if (x11 == nullptr) {
        return false;
    }
    using OpenDisplay = void* (*)(const char*);
    const auto open = reinterpret_cast<OpenDisplay>(dlsym(x11, "XOpenDisplay"));
    Connection& c = connection();
    c.close = reinterpret_cast<CloseDisplay>(dlsym(x11, "XCloseDisplay"));
    c.display = open != nullptr ? open(nullptr) : nullptr;
    std::atexit(closeAtExit);
    return c.display != nullptr;
}

[[maybe_unused]] const bool kDisplayOpen = openDisplay();

} // namespace
