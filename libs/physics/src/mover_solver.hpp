// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/character_mover.hpp>

#include <span>

namespace e2d::physics::detail {

/// The plane solver's answer.
struct PlaneSolution {
    Vec2 delta{0.0f, 0.0f}; ///< the displacement closest to the desired one the planes allow
    int iterations = 0;
    bool converged = false; ///< false when the sweeps ran out before the pushes settled
};

/// The displacement nearest `desired` that meets every constraint (dot(normal, delta) >= need),
/// found by Gauss-Seidel sweeps: each violated constraint pushes along its direction, and a
/// constraint's accumulated push never goes negative (a plane pushes, it never pulls). Sets
/// each constraint's `push`.
PlaneSolution solvePlanes(Vec2 desired, std::span<MoverConstraint> constraints);

} // namespace e2d::physics::detail
