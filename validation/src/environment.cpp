// SPDX-License-Identifier: MIT
#include "report.hpp"

#include <box2d/b2_common.h>

#include <chrono>
#include <ctime>
#include <fstream>
#include <thread>

#ifndef E2D_VALIDATION_VERSION
#define E2D_VALIDATION_VERSION "unknown"
#endif
#ifndef E2D_VALIDATION_BOX2D_VERSION
#define E2D_VALIDATION_BOX2D_VERSION "unknown"
#endif
#ifndef E2D_VALIDATION_BUILD_TYPE
#define E2D_VALIDATION_BUILD_TYPE "unknown"
#endif
#ifndef E2D_VALIDATION_FLAGS
#define E2D_VALIDATION_FLAGS "unknown"
#endif

namespace e2d::validation {
namespace {

std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            if (colon != std::string::npos) {
                return line.substr(line.find_first_not_of(' ', colon + 1));
            }
        }
    }
    return "unknown";
}

} // namespace

Environment collectEnvironment() {
    Environment env;
    env.e2dVersion = E2D_VALIDATION_VERSION;
    // The package's version; Box2D 2.4.1's own b2_version still says 2.4.0.
    env.box2dVersion = std::string(E2D_VALIDATION_BOX2D_VERSION) + " (b2_version " +
                       std::to_string(b2_version.major) + "." + std::to_string(b2_version.minor) +
                       "." + std::to_string(b2_version.revision) + ")";
#if defined(__clang__)
    env.compiler = "clang " __clang_version__;
#elif defined(__GNUC__)
    env.compiler = "g++ " __VERSION__;
#else
    env.compiler = "unknown";
#endif
    env.buildType = E2D_VALIDATION_BUILD_TYPE;
    env.flags = E2D_VALIDATION_FLAGS;
    env.cpu = cpuModel();
    env.cores = static_cast<int>(std::thread::hardware_concurrency());
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
    env.date = text;
    return env;
}

} // namespace e2d::validation
