// SPDX-License-Identifier: MIT
// Accuracy targets the soft step does not meet yet: tall stacks and pyramids (see the measured
// values in the lead's report). They hold the real targets and fail until the solver meets them.
#include "world_step_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace e2d::physics::test {
namespace {

float runTallStack(bool sleep, int steps, float* topX, float* topY) {
    WorldDef def;
    def.solver.enableSleep = sleep;
    World world{def};
    addGround(world);
    std::vector<BodyId> boxes;
    for (int i = 0; i < 20; ++i) {
        boxes.push_back(addBox(world, {0.0f, 0.5f + static_cast<float>(i)}, 0.5f));
    }
    float deepest = 0.0f;
    for (int i = 0; i < steps; ++i) {
        world.step(kStep);
        if (i % 30 == 0) {
            deepest = std::max(deepest, maxPenetration(world));
        }
    }
    *topX = world.transform(boxes.back()).p.x;
    *topY = world.transform(boxes.back()).p.y;
    return std::max(deepest, maxPenetration(world));
}

TEST(SolverAccuracyPending, TallStackStandsForAMinute) {
    float x = 0.0f;
    float y = 0.0f;
    float deepest = runTallStack(true, 3600, &x, &y);
    EXPECT_LT(std::abs(x), 0.01f);
    EXPECT_GT(y, 19.5f - 0.2f);
    EXPECT_LT(deepest, 0.01f);
}

TEST(SolverAccuracyPending, PyramidStandsForAMinute) {
    World world;
    addGround(world);
    const int base = 20;
    BodyId top;
    for (int row = 0; row < base; ++row) {
        int count = base - row;
        for (int i = 0; i < count; ++i) {
            float x = (static_cast<float>(i) - 0.5f * static_cast<float>(count - 1)) * 1.0f;
            top = addBox(world, {x, 0.5f + static_cast<float>(row)}, 0.5f);
        }
    }
    Vec2 start = world.transform(top).p;
    float deepest = 0.0f;
    for (int i = 0; i < 3600; ++i) {
        world.step(kStep);
        if (i % 120 == 0) {
            deepest = std::max(deepest, maxPenetration(world));
        }
    }
    Vec2 end = world.transform(top).p;
    EXPECT_LT(std::abs(end.x - start.x), 0.01f);
    EXPECT_LT(start.y - end.y, 0.1f);
    EXPECT_LT(deepest, 0.01f);
    EXPECT_EQ(world.awakeBodyCount(), 0); // the pile fell asleep and costs nothing
}

TEST(SolverAccuracyPending, TallStackStandsForAMinuteWithoutSleeping) {
    WorldDef def;
    def.solver.enableSleep = false;
    World world{def};
    addGround(world);
    std::vector<BodyId> boxes;
    for (int i = 0; i < 20; ++i) {
        boxes.push_back(addBox(world, {0.0f, 0.5f + static_cast<float>(i)}, 0.5f));
    }
    float deepest = 0.0f;
    for (int i = 0; i < 3600; ++i) {
        world.step(kStep);
        if (i % 30 == 0) {
            deepest = std::max(deepest, maxPenetration(world));
        }
    }
    EXPECT_LT(std::abs(world.transform(boxes.back()).p.x), 0.01f);
    EXPECT_GT(world.transform(boxes.back()).p.y, 19.5f - 0.2f);
    EXPECT_LT(deepest, 0.01f);
}

TEST(SolverAccuracyPending, PyramidStandsWithoutSleeping) {
    // 10 s rather than 60 s: without sleep a Debug build needs about 0.3 s per simulated second.
    WorldDef def;
    def.solver.enableSleep = false;
    World world{def};
    addGround(world);
    const int base = 20;
    BodyId top;
    for (int row = 0; row < base; ++row) {
        int count = base - row;
        for (int i = 0; i < count; ++i) {
            float x = (static_cast<float>(i) - 0.5f * static_cast<float>(count - 1)) * 1.0f;
            top = addBox(world, {x, 0.5f + static_cast<float>(row)}, 0.5f);
        }
    }
    Vec2 start = world.transform(top).p;
    float deepest = 0.0f;
    for (int i = 0; i < 600; ++i) {
        world.step(kStep);
        if (i % 60 == 0) {
            deepest = std::max(deepest, maxPenetration(world));
        }
    }
    Vec2 end = world.transform(top).p;
    EXPECT_LT(std::abs(end.x - start.x), 0.01f);
    EXPECT_LT(start.y - end.y, 0.1f);
    EXPECT_LT(deepest, 0.01f);
}

} // namespace
} // namespace e2d::physics::test
