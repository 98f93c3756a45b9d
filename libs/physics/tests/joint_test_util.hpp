// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/world.hpp>

#include "world_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

// Scenes shared by the joint_*_test.cpp files.
namespace e2d::physics::test {

inline constexpr float kJointStep = 1.0f / 60.0f;
inline constexpr float kPi = 3.14159265358979f;

/// Joint tests run in both solver modes.
class JointModes : public ::testing::TestWithParam<SolverMode> {
protected:
    [[nodiscard]] WorldDef worldDef(Vec2 gravity = {0.0f, -10.0f}) const {
        WorldDef def;
        def.gravity = gravity;
        def.solver.mode = GetParam();
        return def;
    }
};

inline std::string modeName(const ::testing::TestParamInfo<SolverMode>& info) {
    return info.param == SolverMode::SoftStep ? "SoftStep" : "Classic";
}

#define E2D_JOINT_MODES(Suite)                                                                     \
    INSTANTIATE_TEST_SUITE_P(BothModes, Suite,                                                     \
                             ::testing::Values(SolverMode::SoftStep, SolverMode::Classic),         \
                             ::e2d::physics::test::modeName)

inline BodyId addStatic(World& world, Vec2 position = {0.0f, 0.0f}) {
    BodyDef bd;
    bd.position = position;
    return world.createBody(bd);
}

/// A dynamic disc of `radius` and `density` at `position`.
inline BodyId addDisc(World& world, Vec2 position, float radius, float density = 1.0f,
                      float angle = 0.0f) {
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = position;
    bd.angle = angle;
    BodyId body = world.createBody(bd);
    ShapeDef sd;
    sd.density = density;
    world.createShape(body, sd, Circle{{0.0f, 0.0f}, radius});
    return body;
}

/// A dynamic box of half extents (hx, hy).
inline BodyId addPlank(World& world, Vec2 position, float hx, float hy, float density = 1.0f,
                       float angle = 0.0f) {
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = position;
    bd.angle = angle;
    BodyId body = world.createBody(bd);
    ShapeDef sd;
    sd.density = density;
    world.createShape(body, sd, makeBox(hx, hy));
    return body;
}

inline void run(World& world, float seconds) {
    const int steps = static_cast<int>(std::lround(seconds / kJointStep));
    for (int i = 0; i < steps; ++i) {
        world.step(kJointStep);
    }
}

} // namespace e2d::physics::test
