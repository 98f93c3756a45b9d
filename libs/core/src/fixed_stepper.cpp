// SPDX-License-Identifier: MIT
#include <e2d/core/fixed_stepper.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace e2d::core {

FixedStepper::FixedStepper(double step, int maxStepsPerFrame)
    : step_(step), maxSteps_(maxStepsPerFrame) {
    if (!std::isfinite(step) || step <= 0.0) {
        throw Error("core::FixedStepper::FixedStepper(): step must be finite and > 0, got " +
                    formatNumber(step));
    }
    if (maxStepsPerFrame < 1) {
        throw Error("core::FixedStepper::FixedStepper(): maxStepsPerFrame must be >= 1, got " +
                    std::to_string(maxStepsPerFrame));
    }
}

int FixedStepper::advance(double frameDt) {
    if (!std::isfinite(frameDt) || frameDt < 0.0) {
        throw Error("core::FixedStepper::advance(): frameDt must be finite and >= 0, got " +
                    formatNumber(frameDt));
    }
    accumulator_ += frameDt;
    // A step is due when the accumulator is within a millionth of a step of it: frames of
    // exactly one step (1/60 s at 60 Hz) then run exactly one step each, although 1/60 is not
    // representable and the sums drift by rounding. Time within the tolerance is not carried
    // over (at most step / 10^6 per step).
    const double due = step_ * (1.0 - kTolerance);
    int steps = 0;
    while (accumulator_ >= due && steps < maxSteps_) {
        accumulator_ = std::max(0.0, accumulator_ - step_);
        ++steps;
    }
    dropped_ = 0.0;
    if (accumulator_ >= due) {
        // Keep the sub-step remainder so alpha() stays continuous; drop whole steps only.
        double kept = std::fmod(accumulator_, step_);
        if (kept >= due) {
            kept = 0.0;
        }
        dropped_ = accumulator_ - kept;
        accumulator_ = kept;
        totalDropped_ += dropped_;
    }
    return steps;
}

void FixedStepper::reset() noexcept {
    accumulator_ = 0.0;
    dropped_ = 0.0;
    totalDropped_ = 0.0;
}

} // namespace e2d::core
