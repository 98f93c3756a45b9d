// SPDX-License-Identifier: MIT
#pragma once

#include "engine.hpp"

namespace e2d::validation {

/// Box2D 2.4 through e2d_scenes' builder. Uses velocityIterations, positionIterations,
/// continuous, sleeping and warmStarting of `config`; everything else is Box2D's default.
[[nodiscard]] std::unique_ptr<Engine> makeBox2DEngine(const scenes::SceneDesc& scene,
                                                      const EngineConfig& config);

/// Box2D's translation notes and fixed settings, for the report.
[[nodiscard]] std::string box2DNotes();

} // namespace e2d::validation
