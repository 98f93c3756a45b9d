// SPDX-License-Identifier: MIT
// Linked into the engine's game tests. Mesa dlopen()s its driver (swrast_dri.so, llvmpipe) for
// a GLFW window and dlclose()s it when GLFW closes the display, after which LeakSanitizer
// reports the driver's one-time allocations as leaks (from an unloaded module). Opening the
// driver once more with RTLD_NODELETE keeps it loaded until exit, so its allocations stay
// reachable. Where the file does not exist nothing happens.
#include <dlfcn.h>

#include <initializer_list>

namespace {

bool keepMesaDriverLoaded() {
    for (const char* path : {"/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so", "/usr/lib/dri/swrast_dri.so"}) {
        if (dlopen(path, RTLD_LAZY | RTLD_LOCAL | RTLD_NODELETE) != nullptr) {
            return true;
        }
    }
    return false;
}

[[maybe_unused]] const bool kDriverKept = keepMesaDriverLoaded();

} // namespace
