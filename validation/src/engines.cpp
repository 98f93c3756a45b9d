// SPDX-License-Identifier: MIT
#include "engine.hpp"
#include "engine_box2d.hpp"
#include "engine_e2d.hpp"

#include <algorithm>
#include <sstream>

namespace e2d::validation {

std::unique_ptr<Engine> makeEngine(const scenes::SceneDesc& scene, const EngineConfig& config) {
    if (config.engine == "box2d") {
        return makeBox2DEngine(scene, config);
    }
    if (config.engine == "e2d") {
        return makeE2dEngine(scene, config);
    }
    throw EngineError("engine \"" + config.engine +
                      "\" is not available in this build (have: box2d, e2d)");
}

std::string translationNotes(const EngineConfig& config) {
    if (config.engine == "box2d") {
        return box2DNotes();
    }
    if (config.engine == "e2d") {
        return e2dNotes();
    }
    return "engine \"" + config.engine + "\" is not available in this build";
}

std::vector<std::string> availableEngines() { return {"box2d", "e2d"}; }

Pushes::Pushes(const scenes::SceneDesc& scene) {
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const scenes::BodyDesc& b = scene.bodies[i];
        if (b.force != glm::vec2(0.0f)) {
            forces_.emplace_back(static_cast<int>(i), b.force);
        }
        for (const auto& [time, impulse] : b.impulses) {
            impulses_.push_back({time, static_cast<int>(i), impulse});
        }
    }
    std::stable_sort(impulses_.begin(), impulses_.end(),
                     [](const Timed& a, const Timed& b) { return a.time < b.time; });
}

void Pushes::apply(double time, const std::function<void(int, glm::vec2)>& force,
                   const std::function<void(int, glm::vec2)>& impulse) {
    for (const auto& [body, f] : forces_) {
        force(body, f);
    }
    // A half-step margin: an impulse at t = 0.5 s goes before the step starting at 0.5 s even
    // when 30 steps of 1/60 s add up to 0.49999 s.
    while (next_ < impulses_.size() && impulses_[next_].time <= time + 1.0e-6) {
        impulse(impulses_[next_].body, impulses_[next_].impulse);
        ++next_;
    }
}

std::string EngineConfig::family() const {
    if (engine == "e2d") {
        // The joint models other than the default are curves of their own (joints family).
        const std::string joints =
            solver == "soft" && jointSolver != "direct" ? " joints " + jointSolver : "";
        return "e2d " + solver + " " + collision + joints;
    }
    return engine;
}

std::string EngineConfig::describe() const {
    std::ostringstream out;
    const char* on = "on";
    const char* off = "off";
    if (engine == "e2d" && solver == "soft") {
        out << "sub-steps " << subSteps << ", extra relax " << relaxIterations << ", joints "
            << jointSolver;
    } else {
        out << "vel " << velocityIterations << ", pos " << positionIterations;
    }
    if (engine == "e2d") {
        out << ", speculative " << speculativeDistance << " m";
    }
    out << ", ccd " << (continuous ? on : off) << ", sleep " << (sleeping ? on : off);
    if (!warmStarting) {
        out << ", warm start off";
    }
    return out.str();
}

void SettingsOverride::applyTo(EngineConfig& config) const {
    config.velocityIterations = velocityIterations.value_or(config.velocityIterations);
    config.positionIterations = positionIterations.value_or(config.positionIterations);
    config.subSteps = subSteps.value_or(config.subSteps);
    config.relaxIterations = relaxIterations.value_or(config.relaxIterations);
    config.continuous = continuous.value_or(config.continuous);
    config.sleeping = sleeping.value_or(config.sleeping);
}

} // namespace e2d::validation
