// SPDX-License-Identifier: MIT
#pragma once

#include "scenario.hpp"

#include <glm/vec2.hpp>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace e2d::validation {

/// One body as the metrics see it, in SceneDesc order.
struct BodyState {
    glm::vec2 position{0.0f};  ///< body origin, metres
    float angle = 0.0f;        ///< radians
    glm::vec2 velocity{0.0f};  ///< centre-of-mass velocity, m/s
    float angularVelocity = 0.0f;
    float mass = 0.0f;         ///< kg; 0 for static and kinematic bodies
    float inertia = 0.0f;      ///< about the centre of mass, kg m^2
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
