// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string>

namespace e2d::engine {

/// Where the time of one frame went, milliseconds (wall clock, measured by the Game's loop).
struct FrameTimes {
    /// Scene and systems' beginFrame (input polling and event delivery included).
    double input = 0.0;
    /// Every fixed step: the scene's fixedUpdate and the systems' (physics included).
    double fixedSteps = 0.0;
    /// The physics system's share of fixedSteps.
    double physics = 0.0;
    /// The scene's update and the systems' update (audio included).
    double update = 0.0;
    /// The audio system's share of update.
    double audio = 0.0;
    /// Debug draw, interpolation and drawing (buffer swap included).
    double render = 0.0;
    /// The whole frame.
    double total = 0.0;
};

/// The Game loop's profile: the last frame, running sums and counters.
struct FrameProfile {
    /// Frames run so far.
    std::int64_t frames = 0;
    /// Fixed steps run so far.
    std::int64_t fixedSteps = 0;
    /// Frames longer than maxFrameTime (config), which were counted as maxFrameTime.
    std::int64_t spikes = 0;
    /// Seconds of game time dropped because a frame needed more than maxStepsPerFrame steps.
    double droppedSeconds = 0.0;
    /// Scene changes applied.
    std::int64_t sceneChanges = 0;
    /// The last frame's times.
    FrameTimes last;
    /// Sums over every frame (divide by `frames` for means).
    FrameTimes sum;
    /// The longest frame, ms.
    double maxFrameMs = 0.0;

    /// Mean times per frame (zeros before the first frame).
    [[nodiscard]] FrameTimes mean() const noexcept;
    /// One line per phase with mean ms, plus the counters, for printing at exit.
    [[nodiscard]] std::string toString() const;
};

} // namespace e2d::engine
