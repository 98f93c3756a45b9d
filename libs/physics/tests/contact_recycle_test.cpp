// SPDX-License-Identifier: MIT
// Contact recycling (SolverDef::contactRecycleDistance): a pair that barely moved keeps its
// manifold, moved with the bodies, instead of running the collision routine; one that moved
// farther, or would this step, is collided again; a feature the old manifold did not have is
// found before it overlaps.
#include <e2d/physics/world.hpp>

#include "world_step_util.hpp"
#include "world_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace e2d::physics::test {
namespace {

constexpr float kRecycle = 0.02f;

WorldDef recyclingDef(Vec2 gravity) {
    WorldDef def;
    def.gravity = gravity;
    def.solver.enableSleep = false;
    def.solver.contactRecycleDistance = kRecycle;
    return def;
}

// The world's one touching contact and the routine's manifold for its shapes at the bodies'
// transforms `xfA` and `xfB` (where they were when the step collided them).
struct Compared {
    Manifold world;
    Manifold fresh;
};

Compared compare(const World& world, const Transform& xfGround, const Transform& xfBox,
                 BodyId ground) {
    Compared out{};
    int touching = 0;
    world.forEachTouchingContact([&](const ContactData& c) {
        ++touching;
        out.world = *c.manifold;
        const bool groundIsA = world.shapeBody(c.shapeA) == ground;
        out.fresh = collide(world.shapeGeometry(c.shapeA), groundIsA ? xfGround : xfBox,
                            world.shapeGeometry(c.shapeB), groundIsA ? xfBox : xfGround,
                            CollisionAlgorithm::Sat, kSpeculativeDistance);
    });
    EXPECT_EQ(touching, 1);
    return out;
}

// A unit box resting 1 mm into the ground, without gravity, collided once.
struct RestingBox {
    World world{recyclingDef({0.0f, 0.0f})};
    BodyId ground = addGround(world);
    BodyId box = addBox(world, {0.0f, 0.499f}, 0.5f);

    RestingBox() { world.step(kStep); }

    // Puts the box at `position`, `angle`, still, and steps: the manifold the step used.
    Compared stepAt(Vec2 position, float angle, Vec2 velocity = {0.0f, 0.0f}) {
        world.setTransform(box, position, angle);
        world.setLinearVelocity(box, velocity);
        world.setAngularVelocity(box, 0.0f);
        const Transform xfBox = world.transform(box);
        world.step(kStep);
        return compare(world, world.transform(ground), xfBox, ground);
    }
};

TEST(ContactRecycle, ARecycledManifoldFollowsTheBodies) {
    RestingBox scene;
    // Down 2 mm and turned 2 mrad a step: 10 mm of relative motion after three steps.
    for (int k = 1; k <= 3; ++k) {
        const float fk = static_cast<float>(k);
        const Compared m = scene.stepAt({0.0f, 0.499f - 0.002f * fk}, 0.002f * fk);
        SCOPED_TRACE(k);
        EXPECT_EQ(scene.world.stepCounters().manifoldsRecycled, 1);
        ASSERT_EQ(m.world.pointCount, 2);
        ASSERT_EQ(m.fresh.pointCount, 2);
        EXPECT_NEAR(m.world.normal.x, m.fresh.normal.x, 1e-4f);
        EXPECT_NEAR(m.world.normal.y, m.fresh.normal.y, 1e-4f);
        for (int i = 0; i < 2; ++i) {
            // The same corner: the id, the depth to the float's rounding, the point within the
            // recycle distance (it is midway between the two surfaces' material points).
            const ManifoldPoint& w = m.world.points[i];
            const ManifoldPoint* f =
                m.fresh.points[0].id == w.id ? &m.fresh.points[0] : &m.fresh.points[1];
            ASSERT_EQ(f->id, w.id);
            EXPECT_NEAR(w.separation, f->separation, 2e-5f);
            EXPECT_LT(distance(w.point, f->point), kRecycle);
            EXPECT_NEAR(distance(w.anchorA - w.anchorB, f->anchorA - f->anchorB), 0.0f, 1e-5f);
            EXPECT_TRUE(w.persisted);
        }
    }
}

TEST(ContactRecycle, APairThatMovesBeyondTheDistanceIsCollidedAgain) {
    struct Move {
        const char* what;
        Vec2 position;
        float angle;
        Vec2 velocity;
    };
    const Move moves[] = {
        {"translated 25 mm", {0.0f, 0.474f}, 0.0f, {0.0f, 0.0f}},
        // 40 mrad on a corner 0.71 m from the centre: 28 mm.
        {"turned 40 mrad", {0.0f, 0.499f}, 0.04f, {0.0f, 0.0f}},
        // Still, but this step would carry it 25 mm.
        {"about to move 25 mm", {0.0f, 0.499f}, 0.0f, {0.0f, -1.5f}},
    };
    for (const Move& move : moves) {
        SCOPED_TRACE(move.what);
        RestingBox scene;
        const Compared m = scene.stepAt(move.position, move.angle, move.velocity);
        EXPECT_EQ(scene.world.stepCounters().manifoldsRecycled, 0);
        ASSERT_EQ(m.world.pointCount, m.fresh.pointCount);
        for (int i = 0; i < m.world.pointCount; ++i) {
            // Bit for bit the routine's (the moving case's margin is wider: not compared).
            if (move.velocity.y == 0.0f) {
                EXPECT_EQ(m.world.points[i].separation, m.fresh.points[i].separation);
                EXPECT_EQ(m.world.points[i].point.x, m.fresh.points[i].point.x);
                EXPECT_EQ(m.world.points[i].point.y, m.fresh.points[i].point.y);
            }
        }
    }
}

// A box resting on one corner, its second corner 0.5 mm beyond the speculative distance above
// the ground, tips onto that corner under gravities of 1 to 30 m/s^2: slowly enough that the
// one-point manifold is recycled on one step or more at every speed. At every step, each corner
// the routine finds overlapping at the step's start or end pose is in the manifold the step
// solved with (a rule without the step's own motion, dt * closing, misses the corner at the end
// of a step at 8 m/s^2 and up; one without the rotation's chord keeps the one point while the
// corner sinks up to 20 cm), and the box ends flat on both corners.
TEST(ContactRecycle, ATippingBoxsSecondCornerIsNeverMissed) {
    const auto run = [](float gravity, float recycle, int& recycledWhileTipping) {
        WorldDef def = recyclingDef({0.0f, -gravity});
        def.solver.contactRecycleDistance = recycle;
        World world{def};
        const BodyId ground = addGround(world);
        const float gap = kSpeculativeDistance + 0.0005f;
        const float angle = std::asin(gap);
        const Vec2 corner = rotate(Rot{std::cos(angle), std::sin(angle)}, {-0.5f, -0.5f});
        const BodyId box = addBox(world, {-corner.x, -corner.y}, 0.5f, 0.6f, 1.0f, angle);
        const auto overlapping = [](const Manifold& m) {
            int count = 0;
            for (int i = 0; i < m.pointCount; ++i) {
                count += m.points[i].separation <= 0.0f ? 1 : 0;
            }
            return count;
        };
        float deepest = 0.0f;
        recycledWhileTipping = 0;
        for (int step = 0; step < 60; ++step) {
            const Transform xfStart = world.transform(box);
            world.step(kStep);
            const Compared start = compare(world, world.transform(ground), xfStart, ground);
            const Compared end =
                compare(world, world.transform(ground), world.transform(box), ground);
            if (world.stepCounters().manifoldsRecycled == 1 && start.world.pointCount == 1) {
                ++recycledWhileTipping;
            }
            EXPECT_GE(start.world.pointCount, overlapping(start.fresh)) << "start of step " << step;
            EXPECT_GE(start.world.pointCount, overlapping(end.fresh)) << "end of step " << step;
            deepest = std::max(deepest, maxPenetration(world));
        }
        const Compared last = compare(world, world.transform(ground), world.transform(box), ground);
        EXPECT_EQ(last.world.pointCount, 2) << "flat on both corners";
        return deepest;
    };
    int recycledWhileTipping = 0;
    for (float gravity : {1.0f, 2.0f, 4.0f, 8.0f, 12.0f, 25.0f, 30.0f}) {
        SCOPED_TRACE(gravity);
        int recycled = 0;
        int collidedOnly = 0;
        const float withRecycling = run(gravity, kRecycle, recycled);
        const float without = run(gravity, 0.0f, collidedOnly);
        EXPECT_GE(recycled, 1) << "the one-point manifold was recycled while the box tipped";
        EXPECT_EQ(collidedOnly, 0);
        EXPECT_LT(withRecycling, without + 1e-3f);
        recycledWhileTipping += recycled;
    }
    EXPECT_GE(recycledWhileTipping, 20);
}

TEST(ContactRecycle, SensorsAndRoundShapesAreAlwaysCollided) {
    World world{recyclingDef({0.0f, -10.0f})};
    addGround(world);
    addBall(world, {0.0f, 0.25f}, 0.25f);
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = {3.0f, 0.5f};
    BodyId boxInSensor = world.createBody(bd);
    world.createShape(boxInSensor, {}, makeBox(0.5f, 0.5f));
    BodyDef sensorDef;
    sensorDef.position = {3.0f, 0.5f};
    ShapeDef sensorShape;
    sensorShape.isSensor = true;
    world.createShape(world.createBody(sensorDef), sensorShape, makeBox(1.0f, 1.0f));
    int recycled = 0;
    for (int step = 0; step < 30; ++step) {
        world.step(kStep);
        recycled += world.stepCounters().manifoldsRecycled;
    }
    // Only the box on the ground: the ball's and the sensor's contacts are collided each step.
    EXPECT_GT(recycled, 20);
    EXPECT_LE(recycled, 30);
}

// Box2D 2.4's recipe collides every contact every step: a classic world recycles nothing, the
// same stack in the soft step does.
TEST(ContactRecycle, ClassicModeNeverRecycles) {
    const auto recycledOnAStack = [](SolverMode mode) {
        WorldDef def = recyclingDef({0.0f, -10.0f});
        def.solver.mode = mode;
        World world{def};
        addGround(world);
        for (int i = 0; i < 3; ++i) {
            addBox(world, {0.0f, 0.5f + static_cast<float>(i)}, 0.5f);
        }
        int recycled = 0;
        for (int step = 0; step < 60; ++step) {
            world.step(kStep);
            recycled += world.stepCounters().manifoldsRecycled;
        }
        EXPECT_EQ(world.stepCounters().contactConstraints, 3);
        return recycled;
    };
    EXPECT_EQ(recycledOnAStack(SolverMode::Classic), 0);
    EXPECT_GT(recycledOnAStack(SolverMode::SoftStep), 60);
}

TEST(ContactRecycle, TheDistanceIsChecked) {
    for (float bad : {-0.001f, 0.2f, std::nanf("")}) {
        WorldDef def;
        def.solver.contactRecycleDistance = bad;
        const std::string message = errorOf([&] { World world{def}; });
        EXPECT_NE(message.find("physics::World::World(): def.solver.contactRecycleDistance must "
                               "be finite and in [0, 0.1], got"),
                  std::string::npos)
            << message;
    }
}

} // namespace
} // namespace e2d::physics::test
