// SPDX-License-Identifier: MIT
#include <e2d/render/animation.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace e2d::render {
namespace {

constexpr double kBoundaryTolerance = 1.0e-9;

[[noreturn]] void fail(const char* function, const std::string& what) {
    throw core::Error(std::string("render::Animation") + function + ": " + what);
}

void checkSpeed(const char* function, const char* field, double speed) {
    if (!std::isfinite(speed) || speed < 0.0) {
        fail(function,
             std::string(field) + " must be finite and >= 0, got " + core::formatNumber(speed));
    }
}

} // namespace

Animation::Animation(const AnimationDef& def) : def_(def) {
    if (def.frameCount < 1) {
        fail("::Animation()", "frameCount must be >= 1, got " + std::to_string(def.frameCount));
    }
    if (!std::isfinite(def.frameDuration) || def.frameDuration <= 0.0) {
        fail("::Animation()",
             "frameDuration must be finite and > 0, got " + core::formatNumber(def.frameDuration));
    }
    if (def.startFrame < 0 || def.startFrame >= def.frameCount) {
        fail("::Animation()", "startFrame must be in [0, " + std::to_string(def.frameCount) +
                                  "), got " + std::to_string(def.startFrame));
    }
    checkSpeed("::Animation()", "speed", def.speed);
    restart();
}

void Animation::restart() {
    setFrame(def_.startFrame);
    advanced_ = 0;
}

void Animation::setFrame(int frame) {
    if (frame < 0 || frame >= def_.frameCount) {
        fail("::setFrame()", "frame must be in [0, " + std::to_string(def_.frameCount) + "), got " +
                                 std::to_string(frame));
    }
    frame_ = frame;
    phase_ = frame;
    elapsed_ = 0.0;
    finished_ = false;
}

void Animation::setSpeed(double speed) {
    checkSpeed("::setSpeed()", "speed", speed);
    def_.speed = speed;
}

void Animation::update(double dt) {
    if (!std::isfinite(dt) || dt < 0.0) {
        fail("::update()", "dt must be finite and >= 0, got " + core::formatNumber(dt));
    }
    if (finished_) {
        return;
    }
    elapsed_ += dt * def_.speed;
    // The seed advanced only when the time was strictly greater than one frame, so an update of
    // exactly one frame duration showed the same frame twice; here reaching the boundary is enough.
    const double steps = std::floor(elapsed_ / def_.frameDuration + kBoundaryTolerance);
    if (steps < 1.0) {
        return;
    }
    elapsed_ = std::max(0.0, elapsed_ - steps * def_.frameDuration);
    advance(steps);
}

void Animation::advance(double steps) {
    const std::int64_t n = def_.frameCount;
    // Counts saturate rather than overflow on absurd time steps.
    const double cap = 4.0e18;
    advanced_ = static_cast<std::int64_t>(std::min(cap, static_cast<double>(advanced_) + steps));
    switch (def_.mode) {
    case AnimationMode::Loop:
        frame_ = static_cast<int>(
            (frame_ + static_cast<std::int64_t>(std::fmod(steps, static_cast<double>(n)))) % n);
        break;
    case AnimationMode::Once: {
        // The last frame is shown for its duration too: finished one step after reaching it.
        const double toEnd = static_cast<double>(n - 1 - frame_);
        if (steps > toEnd) {
            frame_ = static_cast<int>(n - 1);
            finished_ = true;
            elapsed_ = 0.0;
        } else {
            frame_ += static_cast<int>(steps);
        }
        break;
    }
    case AnimationMode::PingPong: {
        if (n == 1) {
            break;
        }
        const std::int64_t period = 2 * (n - 1);
        phase_ =
            (phase_ + static_cast<std::int64_t>(std::fmod(steps, static_cast<double>(period)))) %
            period;
        frame_ = static_cast<int>(phase_ < n ? phase_ : period - phase_);
        break;
    }
    }
}

} // namespace e2d::render
