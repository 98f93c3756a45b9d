// SPDX-License-Identifier: MIT
#pragma once

#include "scenario.hpp"

#include <glm/vec2.hpp>

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace e2d::validation {

/// One body as the metrics see it, in SceneDesc order.
struct BodyState {
    glm::vec2 position{0.0f}; ///< body origin, metres
    float angle = 0.0f;       ///< radians
    glm::vec2 velocity{0.0f}; ///< centre-of-mass velocity, m/s
    float angularVelocity = 0.0f;
    float mass = 0.0f;    ///< kg; 0 for static and kinematic bodies
    float inertia = 0.0f; ///< about the centre of mass, kg m^2
    bool dynamic = false;
    bool awake = true;
};

/// The one interface an engine plugs into the harness through. An Engine owns one world built
/// from a SceneDesc and is used from one thread.
class Engine {
public:
    virtual ~Engine() = default;
    /// Advances the world by the scene's time step.
    virtual void step() = 0;
    [[nodiscard]] virtual int bodyCount() const = 0;
    /// Fills `out` (resized to bodyCount()) with every body's state.
    virtual void readBodies(std::vector<BodyState>& out) const = 0;
    /// The deepest overlap among the current contacts, metres, >= 0, as the engine measures it.
    [[nodiscard]] virtual float maxPenetration() const = 0;
    /// Fills `out` (resized to the scene's joint count) with each joint's two anchors in world
    /// coordinates, metres, in SceneDesc::joints order.
    virtual void readJointAnchors(std::vector<std::pair<glm::vec2, glm::vec2>>& out) const = 0;
};

/// The forces and impulses a scene applies over time (BodyDesc::force, BodyDesc::impulses),
/// handed to an engine adapter before each step.
class Pushes {
public:
    explicit Pushes(const scenes::SceneDesc& scene);
    /// Before the step that starts at `time` seconds: `force(body, f)` for every body with a
    /// constant force, then `impulse(body, j)` for each impulse now due, each once. `body` is
    /// the index in the scene.
    void apply(double time, const std::function<void(int, glm::vec2)>& force,
               const std::function<void(int, glm::vec2)>& impulse);
    [[nodiscard]] bool empty() const { return forces_.empty() && impulses_.empty(); }

private:
    struct Timed {
        float time;
        int body;
        glm::vec2 impulse;
    };
    std::vector<std::pair<int, glm::vec2>> forces_;
    std::vector<Timed> impulses_; // sorted by time
    std::size_t next_ = 0;
};

/// A configuration the harness cannot run (unknown engine, engine not built).
class EngineError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Builds `scene` in the engine `config` names. Throws EngineError for an engine that is not
/// available in this build.
[[nodiscard]] std::unique_ptr<Engine> makeEngine(const scenes::SceneDesc& scene,
                                                 const EngineConfig& config);

/// How a scene is translated for the engine `config` names and what its fixed settings are,
/// in words, for the report.
[[nodiscard]] std::string translationNotes(const EngineConfig& config);

/// The engines this build can run, e.g. {"box2d"}.
[[nodiscard]] std::vector<std::string> availableEngines();

} // namespace e2d::validation
