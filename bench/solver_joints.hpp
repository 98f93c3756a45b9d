// SPDX-License-Identifier: MIT
#pragma once

namespace e2d::bench {

/// Registers the joint scenes of the solver benchmark (step/joint_grid_100x100/<engine>,
/// step/chain_400/<engine>; solver_joints.cpp), each world stepped `settleSteps` times before
/// it is timed.
void registerJointBenchmarks(int settleSteps);

} // namespace e2d::bench
