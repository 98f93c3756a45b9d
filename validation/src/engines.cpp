// SPDX-License-Identifier: MIT
#include "engine.hpp"
#include "engine_box2d.hpp"
#include "engine_e2d.hpp"

#include <sstream>

namespace e2d::validation {

std::unique_ptr<Engine> makeEngine(const scenes::SceneDesc& scene, const EngineConfig& config) {
    if (config.engine == "box2d") {
        return makeBox2DEngine(scene, config);
    }
    if (config.engine == "e2d") {
        return makeE2dEngine(scene, config);
    }
    throw EngineError("engine \"" + config.engine + "\" is not available in this build (have: box2d, e2d)");
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

std::string EngineConfig::family() const {
    if (engine == "e2d") {
        return "e2d " + solver + " " + collision;
    }
    return engine;
}

std::string EngineConfig::describe() const {
    std::ostringstream out;
    const char* on = "on";
    const char* off = "off";
    if (engine == "e2d" && solver == "soft") {
        out << "sub-steps " << subSteps << ", extra relax " << relaxIterations;
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
