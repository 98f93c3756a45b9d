// SPDX-License-Identifier: MIT
#pragma once

#include <functional>

namespace e2d::core {

/// Game time with a time scale, read from an injectable time source.
///
/// All values are seconds. `unscaledTime()` is real time since construction; `time()` is
/// scaled time, accumulated piecewise: changing the scale affects only the time that passes
/// after the change, so `time()` never jumps. A source that goes backwards is treated as
/// standing still.
class Clock {
public:
    /// Returns the current time in seconds; only differences matter.
    using TimeSource = std::function<double()>;

    /// Uses std::chrono::steady_clock.
    Clock();
    /// Uses `source` (e.g. a manual time for tests or replays). Throws core::Error if empty.
    explicit Clock(TimeSource source);

    /// Scaled seconds since construction.
    [[nodiscard]] double time() const;
    /// Real seconds since construction.
    [[nodiscard]] double unscaledTime() const;

    /// Multiplier applied to time passing from now on. Default 1; 0 pauses.
    [[nodiscard]] double timeScale() const noexcept { return scale_; }
    /// Throws core::Error unless `scale` is finite and >= 0.
    void setTimeScale(double scale);

    /// Scaled seconds since the previous tick (or since construction for the first one).
    double tick();
    /// Real seconds between the last two ticks (0 before the first tick).
    [[nodiscard]] double unscaledDelta() const noexcept { return unscaledDelta_; }

private:
    double now() const;

    TimeSource source_;
    double start_ = 0.0;
    double scale_ = 1.0;
    double scaledBase_ = 0.0;     // scaled time at the last scale change
    double scaleChangedAt_ = 0.0; // unscaled time of the last scale change
    double lastTickScaled_ = 0.0;
    double lastTickUnscaled_ = 0.0;
    double unscaledDelta_ = 0.0;
    mutable double latest_ = 0.0; // highest source reading, so time never runs backwards
};

} // namespace e2d::core
