// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/world.hpp>

#include <vector>

namespace e2d::physics::detail {

// What World::setPreSolveCallback() and setPairFilterCallback() installed, and the move events
// of the last step (world_hooks.cpp).
struct Hooks {
    PreSolveCallback preSolve;
    PairFilterCallback pairFilter;
    std::vector<BodyMoveEvent> moveEvents;
};

} // namespace e2d::physics::detail
