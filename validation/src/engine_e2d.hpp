// SPDX-License-Identifier: MIT
#pragma once

#include "engine.hpp"

namespace e2d::validation {

/// e2d's physics::World. Uses solver ("soft" or "classic"), collision ("sat" or "gjk"),
/// subSteps, relaxIterations, velocityIterations, positionIterations, speculativeDistance,
/// continuous and sleeping of `config`; everything else is e2d's default (SolverDef).
[[nodiscard]] std::unique_ptr<Engine> makeE2dEngine(const scenes::SceneDesc& scene,
                                                    const EngineConfig& config);

/// e2d's translation notes and fixed settings, for the report.
[[nodiscard]] std::string e2dNotes();

} // namespace e2d::validation
