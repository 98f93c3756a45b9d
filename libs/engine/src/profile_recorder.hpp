// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/game_loop.hpp>
#include <e2d/engine/frame_profile.hpp>

#include <chrono>
#include <cstdint>

namespace e2d::engine::detail {

/// Fills a FrameProfile from the game loop's frames: wall-clock milliseconds per phase, the
/// shares of two systems (physics in the fixed steps, audio in the update), and the loop's
/// counters. Also keeps the frame number scenes read through GameSystem::frame().
class ProfileRecorder final : public core::FrameObserver {
public:
    ProfileRecorder(FrameProfile& profile, std::int64_t& frame, const core::System& physics,
                    const core::System& audio) noexcept
        : profile_(profile), frame_(frame), physics_(physics), audio_(audio) {}

    void frameStarted(std::int64_t index) override;
    void phaseStarted(core::FramePhase phase) override;
    void phaseEnded(core::FramePhase phase) override;
    void systemStarted(core::FramePhase phase, const core::System& system) override;
    void systemEnded(core::FramePhase phase, const core::System& system) override;
    void frameEnded(const core::FrameInfo& info) override;

private:
    using Stopwatch = std::chrono::steady_clock;
    static double msSince(Stopwatch::time_point start) noexcept;

    FrameProfile& profile_;
    std::int64_t& frame_;
    const core::System& physics_;
    const core::System& audio_;
    FrameTimes times_;
    Stopwatch::time_point frameStart_;
    Stopwatch::time_point phaseStart_;
    Stopwatch::time_point systemStart_;
};

} // namespace e2d::engine::detail
