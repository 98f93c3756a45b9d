// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

namespace e2d::render {

/// What an animation does after its last frame.
enum class AnimationMode {
    /// Starts again at frame 0, forever.
    Loop,
    /// Stays on the last frame and reports finished() once that frame has had its duration.
    Once,
    /// Runs back down to frame 1, then up again: 0 1 2 ... n-1 n-2 ... 1 0 1 ..., forever.
    PingPong,
};

/// How an Animation plays. Animation's constructor validates every field.
struct AnimationDef {
    /// Number of frames, >= 1. Default 1.
    int frameCount = 1;
    /// Time each frame is shown at speed 1, seconds, finite, > 0. Default 0.1.
    double frameDuration = 0.1;
    /// Frame shown first, in [0, frameCount). Default 0.
    int startFrame = 0;
    /// Loop, Once or PingPong. Default Loop.
    AnimationMode mode = AnimationMode::Loop;
    /// Multiplies the time given to update(), finite, >= 0 (0 holds the current frame).
    /// Default 1.
    double speed = 1.0;
};

/// Which frame of a frame-by-frame animation to show: pure timing, no drawing.
///
/// Time accumulates; every full `frameDuration` (at speed 1) moves one frame on, so one long
/// update moves as many frames as fit in it and keeps the remainder (an update of exactly one
/// frame duration moves exactly one frame). A time within 1e-9 of a frame boundary counts as
/// reaching it, so sums of decimal durations do not lose a frame to rounding.
class Animation {
public:
    /// Throws core::Error naming the field and value if `def` is invalid.
    explicit Animation(const AnimationDef& def);

    /// Advances by `dt` seconds (times speed). `dt` must be finite and >= 0 (core::Error
    /// otherwise). Does nothing once a Once animation has finished.
    void update(double dt);

    /// The frame to show, in [0, frameCount).
    [[nodiscard]] int frame() const noexcept { return frame_; }
    /// A Once animation showed its last frame for a full duration. Always false for Loop and
    /// PingPong.
    [[nodiscard]] bool finished() const noexcept { return finished_; }
    /// Seconds (at speed 1) the current frame has been shown, in [0, frameDuration).
    [[nodiscard]] double timeInFrame() const noexcept { return elapsed_; }
    /// Frames moved on since construction or restart(), counting every step (a looping
    /// animation of 4 frames that wrapped once from frame 0 has advanced 4 or more).
    [[nodiscard]] std::int64_t framesAdvanced() const noexcept { return advanced_; }

    [[nodiscard]] const AnimationDef& def() const noexcept { return def_; }
    /// Changes the speed from now on. Finite, >= 0 (core::Error otherwise).
    void setSpeed(double speed);
    /// Back to the start frame, time zero, not finished.
    void restart();
    /// Shows `frame` from now on (in [0, frameCount), core::Error otherwise), time zero, not
    /// finished; a PingPong animation then runs upwards (downwards from the last frame).
    void setFrame(int frame);

private:
    void advance(double steps);

    AnimationDef def_;
    int frame_ = 0;
    // PingPong position in [0, 2 * (frameCount - 1)): frames going up then down.
    std::int64_t phase_ = 0;
    double elapsed_ = 0.0;
    std::int64_t advanced_ = 0;
    bool finished_ = false;
};

} // namespace e2d::render
