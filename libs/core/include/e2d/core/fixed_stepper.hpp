// SPDX-License-Identifier: MIT
#pragma once

namespace e2d::core {

/// Fixed-timestep accumulator: turns variable frame times into a whole number of fixed steps.
///
/// Each frame adds its duration; `advance()` says how many steps of `step()` seconds to run
/// now. At most `maxStepsPerFrame()` steps run per frame; time beyond that is dropped (the
/// game slows down instead of falling into a "spiral of death" where each frame has more
/// steps to catch up than the last). `alpha()` is the fraction of a step left over, for
/// interpolating rendered positions between the last two physics states.
///
/// A step is due once the accumulated time is within `kTolerance` steps of a whole step, so
/// frames exactly one step long (1/60 s frames with a 1/60 s step, which are not exact in
/// binary) give exactly one step each, forever.
class FixedStepper {
public:
    /// Fraction of a step by which the accumulator may fall short and still run it.
    static constexpr double kTolerance = 1e-6;

    /// `step` seconds per fixed step (finite, > 0), `maxStepsPerFrame` >= 1.
    /// Throws core::Error naming the bad argument.
    FixedStepper(double step, int maxStepsPerFrame);

    /// Adds `frameDt` seconds (finite, >= 0, else core::Error) and returns the number of fixed
    /// steps to run now, in [0, maxStepsPerFrame].
    int advance(double frameDt);

    /// Leftover time divided by the step, in [0, 1).
    [[nodiscard]] double alpha() const noexcept { return accumulator_ / step_; }
    /// Leftover time in seconds, in [0, step).
    [[nodiscard]] double accumulated() const noexcept { return accumulator_; }
    /// Seconds thrown away by the last `advance()` because of the step limit.
    [[nodiscard]] double droppedTime() const noexcept { return dropped_; }
    /// Seconds thrown away since construction or the last `reset()`.
    [[nodiscard]] double totalDroppedTime() const noexcept { return totalDropped_; }

    [[nodiscard]] double step() const noexcept { return step_; }
    [[nodiscard]] int maxStepsPerFrame() const noexcept { return maxSteps_; }

    /// Forgets leftover and dropped time (e.g. after loading a scene).
    void reset() noexcept;

private:
    double step_;
    int maxSteps_;
    double accumulator_ = 0.0;
    double dropped_ = 0.0;
    double totalDropped_ = 0.0;
};

} // namespace e2d::core
