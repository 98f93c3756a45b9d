// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string_view>

namespace e2d::core {

class Clock;
class FixedStepper;
class SceneDirector;
class System;

/// What one `GameLoop::frame()` did.
struct FrameInfo {
    /// The frame's number, 0 for the first frame after `start()`.
    std::int64_t index = 0;
    /// Seconds the frame advanced the game: the clock's scaled time since the previous frame
    /// (or GameLoopDef::fixedFrameTime), at most GameLoopDef::maxFrameTime.
    double dt = 0.0;
    /// Fixed steps run this frame.
    int fixedSteps = 0;
    /// Interpolation factor handed to the systems' render(), in [0, 1).
    double alpha = 0.0;
    /// True if a requested scene change was applied at the start of the frame.
    bool sceneChanged = false;
    /// True if the frame was longer than GameLoopDef::maxFrameTime and counted as that long.
    bool spike = false;
    /// Seconds of game time dropped because the frame needed more than the stepper's
    /// maxStepsPerFrame steps.
    double droppedTime = 0.0;
};

/// The parts of a frame, in the order they run.
enum class FramePhase {
    /// `Scene::beginFrame()` and the systems' `beginFrame()` (input is polled and delivered).
    Begin,
    /// Every fixed step: the scene's `fixedUpdate`, then the systems'.
    FixedSteps,
    /// The scene's `update`, then the systems'.
    Update,
    /// The systems' `render(alpha)`.
    Render,
};

/// Watches a GameLoop's frames without changing them: a frame profile measures its phases and
/// systems here. Every method does nothing by default; all are called on the loop's thread.
class FrameObserver {
public:
    virtual ~FrameObserver() = default;
    /// Before anything of frame `index` happens (its scene change included).
    virtual void frameStarted(std::int64_t /*index*/) {}
    virtual void phaseStarted(FramePhase /*phase*/) {}
    virtual void phaseEnded(FramePhase /*phase*/) {}
    /// Around each call of a system in a phase (`beginFrame`, each `fixedUpdate`, `update`,
    /// `render`).
    virtual void systemStarted(FramePhase /*phase*/, const System& /*system*/) {}
    virtual void systemEnded(FramePhase /*phase*/, const System& /*system*/) {}
    /// After the frame's last render call.
    virtual void frameEnded(const FrameInfo& /*info*/) {}

protected:
    FrameObserver() = default;
    FrameObserver(const FrameObserver&) = default;
    FrameObserver& operator=(const FrameObserver&) = default;
};

/// How a GameLoop measures its frames. The constructor validates every field.
struct GameLoopDef {
    /// Longest frame the loop accepts, seconds, > 0: a longer one (a stall, a debugger stop)
    /// counts as this long (FrameInfo::spike), so one stall cannot ask for a burst of steps.
    /// Default 0.25.
    double maxFrameTime = 0.25;
    /// Seconds every frame lasts, ignoring the clock (headless runs: 1/60, so frame numbers
    /// are game time); 0 reads the clock. >= 0, default 0.
    double fixedFrameTime = 0.0;
    /// Frames after which `running()` turns false (a headless run of N frames); 0: no limit.
    /// >= 0, default 0.
    std::int64_t frameLimit = 0;
    /// Told about every frame and phase (not owned; must outlive the loop); nullptr: none.
    FrameObserver* observer = nullptr;
};

/// The game loop: the frame sequence of every e2d game, engine::Game's included, without any
/// window, so it runs headless.
///
/// `frame()`: apply a pending scene change (the stepper's leftover time is then forgotten);
/// `Scene::beginFrame()` (deferred objects and components); systems' `beginFrame()`; the frame
/// time (clock's scaled dt, or `fixedFrameTime`), clamped to `maxFrameTime`; the fixed steps
/// the stepper grants, each one scene `dispatchFixedUpdate` then systems' `fixedUpdate`; scene
/// `dispatchUpdate`; systems' `update`; systems' `render(alpha)`. The systems are the ones
/// registered with the director, in registration order. The loop owns nothing; everything
/// passed in must outlive it.
class GameLoop {
public:
    /// Throws core::Error naming a field of `def` that is out of range.
    GameLoop(SceneDirector& director, FixedStepper& stepper, Clock& clock, GameLoopDef def = {});

    /// Calls every system's `init()`, then starts `firstScene`. Returns false (error logged)
    /// if the scene name is unknown. Throws core::Error if already started.
    bool start(std::string_view firstScene);
    /// Runs one frame (see the class description).
    FrameInfo frame();
    /// Runs frames while `running()`.
    void run();
    /// Calls the systems' `render()` again with the last frame's alpha (a last picture of a
    /// game that ended: nothing moves).
    void render();
    /// True between `start()` and `shutdown()` unless the game asked to terminate or the
    /// frame limit was reached.
    [[nodiscard]] bool running() const noexcept;
    /// Frames run since `start()`.
    [[nodiscard]] std::int64_t frames() const noexcept { return frames_; }
    /// Terminates the current scene, then calls every system's `shutdown()` in reverse
    /// order. Does nothing if not started.
    void shutdown();

private:
    SceneDirector& director_;
    FixedStepper& stepper_;
    Clock& clock_;
    GameLoopDef def_;
    std::int64_t frames_ = 0;
    double lastAlpha_ = 0.0;
    bool started_ = false;
};

} // namespace e2d::core
