// SPDX-License-Identifier: MIT
// Large worlds: the solver's precision does not depend on the distance to the origin. A float
// position far away is coarse (8 mm at 100 km), but the motion below that resolution is kept
// (BodyMotion::positionResidual) and the constraints work from the motion since the start of
// the step, so a scene behaves there as it does at the origin, up to the float step in which
// the reported positions are rounded.
#include "world_step_util.hpp"

#include <e2d/physics/constants.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace e2d::physics::test {
namespace {

// The gap between adjacent floats at |x| (x a power of two or not), metres.
float floatStep(float x) { return std::nextafter(std::fabs(x), INFINITY) - std::fabs(x); }

struct Pyramid {
    BodyId top;
    std::vector<BodyId> boxes;
};

// Box2D's benchmark pyramid of unit boxes, `base` wide, on a static ground whose top is at
// origin.y (the validation's far_pyramid scene).
Pyramid addPyramid(World& world, Vec2 origin, int base) {
    BodyDef gd;
    gd.position = origin;
    BodyId ground = world.createBody(gd);
    world.createShape(ground, {}, makeOffsetBox(100.0f, 1.0f, {0.0f, -1.0f}, 0.0f));
    Pyramid p;
    for (int row = 0; row < base; ++row) {
        const int count = base - row;
        for (int i = 0; i < count; ++i) {
            const float x = (static_cast<float>(i) - 0.5f * static_cast<float>(count - 1)) * 1.0f;
            p.top = addBox(world, origin + Vec2{x, 0.5f + static_cast<float>(row)}, 0.5f);
            p.boxes.push_back(p.top);
        }
    }
    return p;
}

WorldDef worldDef(SolverMode mode, bool sleep) {
    WorldDef def;
    def.solver.mode = mode;
    def.solver.enableSleep = sleep;
    return def;
}

class FarPyramid : public ::testing::TestWithParam<SolverMode> {};

TEST_P(FarPyramid, ComesToRestAsAtTheOrigin) {
    // The validation's far_pyramid: at (99 000, -80 000) the apex used to wander 0.11 m and
    // never fall asleep (0.076 m/s after 20 s): each step's small motions rounded away, and
    // the contacts pushed against the rounding.
    const Vec2 origin{99000.0f, -80000.0f};
    World world{worldDef(GetParam(), true)};
    const Pyramid p = addPyramid(world, origin, 10);
    const Vec2 start = world.transform(p.top).p;
    for (int i = 0; i < 1200; ++i) {
        world.step(kStep);
    }
    const Vec2 end = world.transform(p.top).p;
    const float grid = floatStep(origin.x);
    EXPECT_LE(std::fabs(end.x - start.x), 2.0f * grid);
    EXPECT_LT(start.y - end.y, 0.02f);
    EXPECT_LT(length(world.linearVelocity(p.top)), 0.01f);
    EXPECT_EQ(world.awakeBodyCount(), 0);
}

TEST_P(FarPyramid, ComesToRestAtTheCoordinateLimit) {
    // At (0.99, -0.8) kHuge a float step is 3.1 cm: the pile still stands and falls asleep, its
    // apex within a float step of where it started.
    const Vec2 origin{0.99f * kHuge, -0.8f * kHuge};
    World world{worldDef(GetParam(), true)};
    const Pyramid p = addPyramid(world, origin, 10);
    const Vec2 start = world.transform(p.top).p;
    for (int i = 0; i < 1200; ++i) {
        world.step(kStep);
    }
    const Vec2 end = world.transform(p.top).p;
    const float grid = floatStep(origin.x);
    EXPECT_LE(length(end - start), grid) << "float step there " << grid << " m";
    EXPECT_EQ(world.awakeBodyCount(), 0);
    EXPECT_TRUE(world.outOfRangeBodies().empty());
}

TEST_P(FarPyramid, MovesAsAtTheOriginWithoutSleeping) {
    // The same pyramid awake at the origin and at (99 000, -80 000): every box ends where its
    // twin at the origin does, within one float step there (8 mm; the reported positions are
    // rounded to it), however its small motions added up.
    World nearWorld{worldDef(GetParam(), false)};
    World farWorld{worldDef(GetParam(), false)};
    const Vec2 origin{99000.0f, -80000.0f};
    const Pyramid nearPile = addPyramid(nearWorld, {0.0f, 0.0f}, 10);
    const Pyramid farPile = addPyramid(farWorld, origin, 10);
    for (int i = 0; i < 300; ++i) {
        nearWorld.step(kStep);
        farWorld.step(kStep);
    }
    const float grid = floatStep(origin.x);
    float worst = 0.0f;
    for (std::size_t k = 0; k < nearPile.boxes.size(); ++k) {
        const Vec2 nearAt = nearWorld.transform(nearPile.boxes[k]).p;
        const Vec2 farAt = farWorld.transform(farPile.boxes[k]).p - origin;
        worst = std::max(worst, length(farAt - nearAt));
    }
    EXPECT_LE(worst, grid) << "float step there " << grid << " m";
    EXPECT_LT(length(farWorld.linearVelocity(farPile.top)), 0.01f);
}

INSTANTIATE_TEST_SUITE_P(Modes, FarPyramid,
                         ::testing::Values(SolverMode::SoftStep, SolverMode::Classic),
                         [](const ::testing::TestParamInfo<SolverMode>& mode) {
                             return mode.param == SolverMode::SoftStep ? std::string("SoftStep")
                                                                       : std::string("Classic");
                         });

TEST(WorldFar, MotionBelowTheFloatStepAddsUp) {
    // 1 mm/s at x = 99 000 m: 17 um a step, 1/470 of the float step there (7.8 mm), so a
    // float position alone never moves. After 10 s the body is 1 cm on, to within one float
    // step.
    WorldDef def;
    def.gravity = {0.0f, 0.0f};
    def.solver.enableSleep = false; // 1 mm/s is below the sleep tolerance
    World world{def};
    const Vec2 start{99000.0f, 0.0f};
    BodyId box = addBox(world, start, 0.5f);
    world.setLinearVelocity(box, {0.001f, -0.002f});
    for (int i = 0; i < 600; ++i) {
        world.step(kStep);
    }
    const Vec2 moved = world.transform(box).p - start;
    const float grid = floatStep(start.x);
    EXPECT_NEAR(moved.x, 0.01f, grid);
    EXPECT_NEAR(moved.y, -0.02f, 1e-5f); // y = 0 is fine-grained
    EXPECT_GT(moved.x, 0.0f);
}

TEST(WorldFar, SetTransformDropsTheMotionBelowTheFloatStep) {
    // What the body had moved below the float step belongs to its old place: 2.5 mm up at
    // y = 99 000 m (a third of a float step there), then set at y = 5 m (a fine grid) and held
    // still, it stays exactly where it was put instead of 2.5 mm higher.
    WorldDef def;
    def.gravity = {0.0f, 0.0f};
    World world{def};
    BodyId box = addBox(world, {0.0f, 99000.0f}, 0.5f);
    world.setLinearVelocity(box, {0.0f, 0.003f});
    for (int i = 0; i < 50; ++i) {
        world.step(kStep);
    }
    EXPECT_EQ(world.transform(box).p.y, 99000.0f); // not a float step yet
    const Vec2 target{0.0f, 5.0f};
    world.setTransform(box, target, 0.0f);
    world.setLinearVelocity(box, {0.0f, 0.0f});
    for (int i = 0; i < 10; ++i) {
        world.step(kStep);
    }
    EXPECT_EQ(world.transform(box).p.x, target.x);
    EXPECT_EQ(world.transform(box).p.y, target.y);
}

} // namespace
} // namespace e2d::physics::test
