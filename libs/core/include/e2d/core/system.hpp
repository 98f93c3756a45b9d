// SPDX-License-Identifier: MIT
#pragma once

namespace e2d::core {

/// A subsystem the engine plugs into the loop (physics, rendering, audio, input, ...).
///
/// GameLoop calls, per frame: `beginFrame()`, then `fixedUpdate()` once per fixed step (after
/// the scene's fixedUpdate), `update()` (after the scene's update) and `render()`. Every hook
/// is optional (no-op by default).
class System {
public:
    virtual ~System() = default;

    /// Once, before the first scene starts.
    virtual void init() {}
    /// Start of each frame, before any fixed step (poll input here).
    virtual void beginFrame() {}
    /// Once per fixed step; `step` is the fixed timestep in seconds.
    virtual void fixedUpdate(double step) { static_cast<void>(step); }
    /// Once per frame; `dt` is the scaled frame time in seconds.
    virtual void update(double dt) { static_cast<void>(dt); }
    /// Once per frame, last; `alpha` in [0, 1) is how far the game is between the last fixed
    /// step and the next one, for interpolation.
    virtual void render(double alpha) { static_cast<void>(alpha); }
    /// Between the old scene's termination and the new scene's creation: drop everything
    /// that belonged to the old scene.
    virtual void clear() {}
    /// Once, after the last scene ended.
    virtual void shutdown() {}

protected:
    System() = default;
    System(const System&) = default;
    System& operator=(const System&) = default;
};

} // namespace e2d::core
