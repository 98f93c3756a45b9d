// SPDX-License-Identifier: MIT
// Islands and sleeping: a sleeping pile does no solver or narrow-phase work, and an island
// wakes when a neighbour changes (impulse, contact, support disabled, moved or destroyed).
#include "world_step_util.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace e2d::physics::test {
namespace {

// A pyramid of `base` boxes (half-size 0.5) on the ground; returns its boxes.
std::vector<BodyId> addPyramid(World& world, int base, float x0 = 0.0f) {
    std::vector<BodyId> boxes;
    for (int row = 0; row < base; ++row) {
        for (int j = row; j < base; ++j) {
            float x = x0 + static_cast<float>(row + 1) * 0.5f + static_cast<float>(j - row) -
                      0.5f * static_cast<float>(base);
            boxes.push_back(addBox(world, {x, 0.5f + static_cast<float>(row)}, 0.5f));
        }
    }
    return boxes;
}

bool allAsleep(const World& world, const std::vector<BodyId>& bodies) {
    for (BodyId id : bodies) {
        if (world.isAwake(id)) {
            return false;
        }
    }
    return true;
}

void stepUntilAsleep(World& world, const std::vector<BodyId>& bodies) {
    for (int i = 0; i < 600 && !allAsleep(world, bodies); ++i) {
        world.step(kStep);
    }
    ASSERT_TRUE(allAsleep(world, bodies));
}

TEST(WorldSleep, SleepingPileCostsNothingPerStep) {
    World world;
    addGround(world);
    std::vector<BodyId> pile = addPyramid(world, 5); // 15 boxes
    world.step(kStep);
    // Awake: every box in the solver; 15 boxes touch through 5 ground and 18 box-box contacts
    // (each row of n boxes: n - 1 neighbours side by side, 2 (n - 1) onto the row below).
    StepCounters awake = world.stepCounters();
    EXPECT_EQ(awake.solverBodies, 15);
    EXPECT_GE(awake.contactConstraints, 5 + 10);
    EXPECT_GE(awake.manifoldUpdates, awake.contactConstraints);

    stepUntilAsleep(world, pile);
    world.step(kStep);
    StepCounters asleep = world.stepCounters();
    EXPECT_EQ(asleep.solverBodies, 0);
    EXPECT_EQ(asleep.contactConstraints, 0);
    EXPECT_EQ(asleep.manifoldUpdates, 0);

    // One awake ball elsewhere costs its own work only: one body, its one ground contact.
    BodyId ball = addBall(world, {30.0f, 0.25f}, 0.25f);
    world.step(kStep);
    world.step(kStep);
    StepCounters one = world.stepCounters();
    EXPECT_TRUE(world.isAwake(ball));
    EXPECT_EQ(one.solverBodies, 1);
    EXPECT_EQ(one.contactConstraints, 1);
    EXPECT_EQ(one.manifoldUpdates, 1);
    EXPECT_TRUE(allAsleep(world, pile));
}

TEST(WorldSleep, StepWithZeroTimeSolvesNothing) {
    World world;
    addGround(world);
    addBox(world, {0.0f, 0.5f}, 0.5f);
    world.step(0.0f);
    EXPECT_EQ(world.stepCounters().solverBodies, 0);
    EXPECT_EQ(world.stepCounters().contactConstraints, 0);
    EXPECT_EQ(world.stepCounters().manifoldUpdates, 1);
}

struct Stack {
    World world;
    BodyId ground;
    BodyId bottom;
    BodyId top;
};

// Two boxes on the ground, asleep.
void makeSleepingStack(Stack& s) {
    s.ground = addGround(s.world);
    s.bottom = addBox(s.world, {0.0f, 0.5f}, 0.5f);
    s.top = addBox(s.world, {0.0f, 1.5f}, 0.5f);
    stepUntilAsleep(s.world, {s.bottom, s.top});
}

TEST(WorldSleep, IslandWakesWhenItsSupportIsDisabled) {
    Stack s;
    makeSleepingStack(s);
    s.world.setBodyEnabled(s.bottom, false);
    EXPECT_TRUE(s.world.isAwake(s.top));
    s.world.step(kStep);
    EXPECT_LT(s.world.linearVelocity(s.top).y, 0.0f) << "falls once its support is gone";
}

TEST(WorldSleep, IslandWakesWhenItsSupportIsDestroyedOrMoved) {
    {
        Stack s;
        makeSleepingStack(s);
        s.world.destroyShape(s.world.bodyShapes(s.bottom)[0]);
        EXPECT_TRUE(s.world.isAwake(s.top));
    }
    {
        Stack s;
        makeSleepingStack(s);
        s.world.setTransform(s.bottom, {5.0f, 0.5f}, 0.0f);
        EXPECT_TRUE(s.world.isAwake(s.top));
        s.world.step(kStep);
        EXPECT_LT(s.world.linearVelocity(s.top).y, 0.0f);
    }
    {
        Stack s;
        makeSleepingStack(s);
        s.world.setLinearVelocity(s.bottom, {1.0f, 0.0f});
        EXPECT_TRUE(s.world.isAwake(s.top)) << "the island wakes together";
    }
}

TEST(WorldSleep, KinematicBodyRunningIntoASleepingIslandWakesIt) {
    Stack s;
    makeSleepingStack(s);
    BodyDef kd;
    kd.type = BodyType::Kinematic;
    kd.position = {-3.0f, 0.5f};
    kd.linearVelocity = {2.0f, 0.0f};
    BodyId pusher = s.world.createBody(kd);
    s.world.createShape(pusher, {}, makeBox(0.5f, 0.5f));
    bool woke = false;
    for (int i = 0; i < 90 && !woke; ++i) {
        s.world.step(kStep);
        woke = s.world.isAwake(s.bottom);
    }
    EXPECT_TRUE(woke);
    // Reached after (3 - 1) / 2 = 1 s, within a step of the contact appearing.
    EXPECT_GT(s.world.transform(pusher).p.x, -1.0f - 0.2f);
}

// The narrow phase goes through the contacts in slot order; a sleeping contact after the one
// that wakes its island is updated in that same step, and listed for the solver once.
TEST(WorldSleep, IslandWokenInTheNarrowPhaseHasItsLaterContactsUpdated) {
    World world;
    addGround(world);
    // A box away from the pile takes the first contact slot, freed again below: the ball's
    // contact, made last, reuses it and so comes before every contact of the pile.
    BodyId first = addBox(world, {-20.0f, 0.5f}, 0.5f);
    world.step(kStep);
    std::vector<BodyId> pile = addPyramid(world, 3); // 6 boxes
    world.step(kStep);
    world.destroyBody(first);
    stepUntilAsleep(world, pile);
    const BodyId top = pile.back();
    addBall(world, world.transform(top).p + Vec2{0.0f, 2.0f}, 0.25f);
    bool woke = false;
    for (int i = 0; i < 120 && !woke; ++i) {
        world.step(kStep);
        woke = world.isAwake(top);
    }
    ASSERT_TRUE(woke);
    // Every touching contact in the solver was updated in the step (the ball's and the pile's,
    // woken by it), none twice.
    StepCounters wake = world.stepCounters();
    EXPECT_GE(wake.contactConstraints, 1 + 3 + 4);
    EXPECT_GE(wake.manifoldUpdates, wake.contactConstraints);
}

} // namespace
} // namespace e2d::physics::test
