// SPDX-License-Identifier: MIT
#include <e2d/engine/frame_profile.hpp>

#include <cstdio>

namespace e2d::engine {

FrameTimes FrameProfile::mean() const noexcept {
    if (frames == 0) {
        return {};
    }
    const double n = static_cast<double>(frames);
    return {sum.input / n, sum.fixedSteps / n, sum.physics / n, sum.update / n,
            sum.audio / n, sum.render / n,     sum.total / n};
}

std::string FrameProfile::toString() const {
    const FrameTimes m = mean();
    char buffer[512];
    std::snprintf(
        buffer, sizeof buffer,
        "frame profile: %lld frames, %lld fixed steps, %lld spikes clamped, %.3f s dropped, "
        "%lld scene changes\n"
        "  mean ms per frame: input %.3f, fixed steps %.3f (physics %.3f), update %.3f "
        "(audio %.3f), render %.3f, total %.3f; longest frame %.3f ms",
        static_cast<long long>(frames), static_cast<long long>(fixedSteps),
        static_cast<long long>(spikes), droppedSeconds, static_cast<long long>(sceneChanges),
        m.input, m.fixedSteps, m.physics, m.update, m.audio, m.render, m.total, maxFrameMs);
    return buffer;
}

} // namespace e2d::engine
