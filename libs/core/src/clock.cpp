// SPDX-License-Identifier: MIT
#include <e2d/core/clock.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace e2d::core {

namespace {

double steadySeconds() {
    using Seconds = std::chrono::duration<double>;
    return std::chrono::duration_cast<Seconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

} // namespace

Clock::Clock() : Clock(TimeSource(steadySeconds)) {}

Clock::Clock(TimeSource source) : source_(std::move(source)) {
    if (!source_) {
        throw Error("core::Clock::Clock(): time source must not be empty");
    }
    start_ = source_();
    latest_ = start_;
}

double Clock::now() const {
    latest_ = std::max(latest_, source_());
    return latest_ - start_;
}

double Clock::unscaledTime() const { return now(); }

double Clock::time() const { return scaledBase_ + (now() - scaleChangedAt_) * scale_; }

void Clock::setTimeScale(double scale) {
    if (!std::isfinite(scale) || scale < 0.0) {
        throw Error("core::Clock::setTimeScale(): scale must be finite and >= 0, got " +
                    formatNumber(scale));
    }
    const double t = now();
    scaledBase_ += (t - scaleChangedAt_) * scale_;
    scaleChangedAt_ = t;
    scale_ = scale;
}

double Clock::tick() {
    const double unscaled = now();
    const double scaled = scaledBase_ + (unscaled - scaleChangedAt_) * scale_;
    const double dt = std::max(0.0, scaled - lastTickScaled_);
    unscaledDelta_ = unscaled - lastTickUnscaled_;
    lastTickScaled_ = scaled;
    lastTickUnscaled_ = unscaled;
    return dt;
}

} // namespace e2d::core
