// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <span>
#include <vector>

// A small dense linear complementarity problem, the joint limits' part of the direct solve
// (joint_direct.cpp): the limits of a connected group of joints, with the group's equality rows
// eliminated (the Schur complement), are a few tens of rows, coupled through every link between
// them.
namespace e2d::physics::detail {

// What solveDenseLcp() keeps between calls (its arrays' capacity).
struct DenseLcpScratch {
    std::vector<std::uint8_t> free;      // x_i solved for (w_i = 0), else x_i = 0
    std::vector<int> index;              // the free rows, in order
    std::vector<double> factor;          // LDL^T of A restricted to the free rows (row major)
    std::vector<double> pivot;           // D's inverse (0 for a row dependent on earlier ones)
    std::vector<std::uint8_t> dependent; // per row: free, but its pivot collapsed (x = 0)
    std::vector<double> w;
};

// Finds x >= 0 with w = A x + q >= 0 and x_i w_i = 0 for every i, A (m x m, row major)
// symmetric positive semi-definite: block principal pivoting (Judice and Pires 1994) from the
// rows x starts positive on, every infeasible row changing sides at once while their number
// falls, then one at a time, the highest first (Murty's rule, finite for a positive definite
// A). A row whose pivot collapses (dependent on the others) is held at 0. False when
// `maxRounds` were not enough; x is the last round's, clamped to >= 0.
bool solveDenseLcp(int m, std::span<const double> a, std::span<const double> q, std::span<double> x,
                   int maxRounds, DenseLcpScratch& scratch);

} // namespace e2d::physics::detail
