// SPDX-License-Identifier: MIT
// Linked into every test binary that opens OpenGL contexts (render's and the engine's tests;
// the apps and the render example under the asan preset). Mesa loads its driver
// (swrast_dri.so, llvmpipe) with dlopen() and unloads it when GLFW closes the X display; the
// driver's static allocations, still reachable through the driver's own globals, then look
// leaked to LeakSanitizer, which fails every GL test under the asan preset (checked: with the
// driver kept loaded, no leak is reported). Loading it once more with RTLD_NODELETE keeps it
// in memory until the process exits. Nothing happens where the file is not there.
#include <dlfcn.h>

#include <initializer_list>

namespace {

bool pinMesaDriver() {
    for (const char* path :
         {"/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so", "/usr/lib/dri/swrast_dri.so"}) {
        if (dlopen(path, RTLD_LAZY | RTLD_LOCAL | RTLD_NODELETE) != nullptr) {
            return true;
        }
    }
    return false;
}

[[maybe_unused]] const bool kMesaDriverPinned = pinMesaDriver();

} // namespace
