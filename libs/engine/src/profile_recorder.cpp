// SPDX-License-Identifier: MIT
#include "profile_recorder.hpp"

#include <algorithm>

namespace e2d::engine::detail {

double ProfileRecorder::msSince(Stopwatch::time_point start) noexcept {
    return std::chrono::duration<double, std::milli>(Stopwatch::now() - start).count();
}

void ProfileRecorder::frameStarted(std::int64_t index) {
    frame_ = index;
    times_ = {};
    frameStart_ = Stopwatch::now();
}

void ProfileRecorder::phaseStarted(core::FramePhase /*phase*/) { phaseStart_ = Stopwatch::now(); }

void ProfileRecorder::phaseEnded(core::FramePhase phase) {
    const double ms = msSince(phaseStart_);
    switch (phase) {
    case core::FramePhase::Begin:
        times_.input = ms;
        break;
    case core::FramePhase::FixedSteps:
        times_.fixedSteps = ms;
        break;
    case core::FramePhase::Update:
        times_.update = ms;
        break;
    case core::FramePhase::Render:
        times_.render = ms;
        break;
    }
}

void ProfileRecorder::systemStarted(core::FramePhase /*phase*/, const core::System& system) {
    if (&system == &physics_ || &system == &audio_) {
        systemStart_ = Stopwatch::now();
    }
}

void ProfileRecorder::systemEnded(core::FramePhase phase, const core::System& system) {
    if (phase == core::FramePhase::FixedSteps && &system == &physics_) {
        times_.physics += msSince(systemStart_);
    } else if (phase == core::FramePhase::Update && &system == &audio_) {
        times_.audio += msSince(systemStart_);
    }
}

void ProfileRecorder::frameEnded(const core::FrameInfo& info) {
    times_.total = msSince(frameStart_);
    FrameProfile& p = profile_;
    ++p.frames;
    p.fixedSteps += info.fixedSteps;
    p.spikes += info.spike ? 1 : 0;
    p.droppedSeconds += info.droppedTime;
    p.sceneChanges += info.sceneChanged ? 1 : 0;
    p.last = times_;
    p.sum.input += times_.input;
    p.sum.fixedSteps += times_.fixedSteps;
    p.sum.physics += times_.physics;
    p.sum.update += times_.update;
    p.sum.audio += times_.audio;
    p.sum.render += times_.render;
    p.sum.total += times_.total;
    p.maxFrameMs = std::max(p.maxFrameMs, times_.total);
}

} // namespace e2d::engine::detail
