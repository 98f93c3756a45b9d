// SPDX-License-Identifier: MIT
#pragma once

#include <string_view>

namespace e2d::core {

class Clock;
class FixedStepper;
class SceneDirector;

/// What one `GameLoop::frame()` did.
struct FrameInfo {
    /// Scaled seconds since the previous frame.
    double dt = 0.0;
    /// Fixed steps run this frame.
    int fixedSteps = 0;
    /// Interpolation factor handed to the systems' render(), in [0, 1).
    double alpha = 0.0;
    /// True if a requested scene change was applied at the start of the frame.
    bool sceneChanged = false;
};

/// The frame sequence of a game loop, without any window, so it runs headless.
///
/// `frame()`: apply a pending scene change; `Scene::beginFrame()` (deferred objects and
/// components); systems' `beginFrame()`; tick the clock (scaled dt); run the fixed steps the
/// stepper grants, each one scene `dispatchFixedUpdate` then systems' `fixedUpdate`; scene
/// `dispatchUpdate`; systems' `update`; systems' `render(alpha)`. The systems are the ones
/// registered with the director, in registration order. The loop does not own anything;
/// everything passed in must outlive it.
class GameLoop {
public:
    GameLoop(SceneDirector& director, FixedStepper& stepper, Clock& clock) noexcept
        : director_(director), stepper_(stepper), clock_(clock) {}

    /// Calls every system's `init()`, then starts `firstScene`. Returns false (error logged)
    /// if the scene name is unknown. Throws core::Error if already started.
    bool start(std::string_view firstScene);
    /// Runs one frame (see the class description).
    FrameInfo frame();
    /// True between `start()` and `shutdown()` unless the game asked to terminate.
    [[nodiscard]] bool running() const noexcept;
    /// Terminates the current scene, then calls every system's `shutdown()` in reverse
    /// order. Does nothing if not started.
    void shutdown();

private:
    SceneDirector& director_;
    FixedStepper& stepper_;
    Clock& clock_;
    bool started_ = false;
};

} // namespace e2d::core
