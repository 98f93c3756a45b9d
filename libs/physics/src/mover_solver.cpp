// SPDX-License-Identifier: MIT
#include "mover_solver.hpp"

#include <algorithm>
#include <cmath>

namespace e2d::physics::detail {

namespace {
constexpr int kMaxSweeps = 20;
// A sweep whose pushes add up to less than this changed nothing that matters, metres.
constexpr float kSettled = 1.0e-5f;
} // namespace

PlaneSolution solvePlanes(Vec2 desired, std::span<MoverConstraint> constraints) {
    for (MoverConstraint& c : constraints) {
        c.push = 0.0f;
    }
    PlaneSolution solution;
    solution.delta = desired;
    for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
        solution.iterations = sweep + 1;
        float total = 0.0f;
        for (MoverConstraint& c : constraints) {
            const float along = dot(c.normal, c.direction); // > 0 by construction
            const float error = c.need - dot(c.normal, solution.delta);
            const float push = std::max(c.push + error / along, 0.0f);
            const float change = push - c.push;
            c.push = push;
            solution.delta += change * c.direction;
            total += std::fabs(change);
        }
        if (total < kSettled) {
            solution.converged = true;
            break;
        }
    }
    return solution;
}

} // namespace e2d::physics::detail
