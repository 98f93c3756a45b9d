// SPDX-License-Identifier: MIT
#include <e2d/core/fixed_stepper.hpp>

#include <e2d/core/error.hpp>

#include "format.hpp"

#include <cmath>
#include <string>

namespace e2d::core {

FixedStepper::FixedStepper(double step, int maxStepsPerFrame) : step_(step), maxSteps_(maxStepsPerFrame) {
    if (!std::isfinite(step) || step <= 0.0) {
        throw Error("core::FixedStepper::FixedStepper(): step must be finite and > 0, got " +
                    detail::formatNumber(step));
    }
    if (maxStepsPerFrame < 1) {
        throw Error("core::FixedStepper::FixedStepper(): maxStepsPerFrame must be >= 1, got " +
                    std::to_string(maxStepsPerFrame));
    }
}

int FixedStepper::advance(double frameDt) {
    if (!std::isfinite(frameDt) || frameDt < 0.0) {
        throw Error("core::FixedStepper::advance(): frameDt must be finite and >= 0, got " +
                    detail::formatNumber(frameDt));
    }
    accumulator_ += frameDt;
    int steps = 0;
    while (accumulator_ >= step_ && steps < maxSteps_) {
        accumulator_ -= step_;
        ++steps;
    }
    dropped_ = 0.0;
    if (accumulator_ >= step_) {
        // Keep the sub-step remainder so alpha() stays continuous; drop whole steps only.
        const double kept = std::fmod(accumulator_, step_);
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
