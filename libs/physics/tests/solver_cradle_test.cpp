// SPDX-License-Identifier: MIT
// Newton's cradle in zero gravity with the default soft step: a ball strikes a row of touching
// elastic balls. Whatever the solver makes of the simultaneous impacts, an elastic collision
// must not create energy, and no impulse may create momentum.
#include "world_step_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace e2d::physics::test {
namespace {

struct Cradle {
    World world;
    std::vector<BodyId> balls;
    float mass = 0.0f;

    Cradle(int count, float speed) : world{makeDef()} {
        ShapeDef sd;
        sd.friction = 0.0f;
        sd.restitution = 1.0f;
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        // The striker starts 0.5 m short of the row; the row's balls (radius 0.5) touch.
        bd.position = {-1.5f, 0.0f};
        bd.linearVelocity = {speed, 0.0f};
        balls.push_back(world.createBody(bd));
        bd.linearVelocity = {0.0f, 0.0f};
        for (int i = 1; i < count; ++i) {
            bd.position = {static_cast<float>(i - 1), 0.0f};
            balls.push_back(world.createBody(bd));
        }
        for (BodyId b : balls) {
            world.createShape(b, sd, Circle{{0.0f, 0.0f}, 0.5f});
        }
        mass = world.massData(balls[0]).mass;
    }

    static WorldDef makeDef() {
        WorldDef def;
        def.gravity = {0.0f, 0.0f};
        def.solver.enableSleep = false;
        return def;
    }

    Vec2 momentum() const {
        Vec2 p{0.0f, 0.0f};
        for (BodyId b : balls) {
            p += mass * world.linearVelocity(b);
        }
        return p;
    }

    // Circles on one line, hit head-on, never spin: linear energy is all of it.
    float energy() const {
        float e = 0.0f;
        for (BodyId b : balls) {
            e += 0.5f * mass * dot(world.linearVelocity(b), world.linearVelocity(b));
        }
        return e;
    }
};

TEST(SolverCradle, ElasticChainNeverGainsEnergyAndKeepsMomentum) {
    for (int count = 2; count <= 6; ++count) {
        for (float speed : {0.5f, 1.5f, 2.0f, 4.0f, 10.0f}) {
            Cradle cradle{count, speed};
            // Only the striker moves at the start: p0 = m v along x, e0 = m v^2 / 2.
            const float p0 = cradle.mass * speed;
            const float e0 = 0.5f * cradle.mass * speed * speed;
            ASSERT_NEAR(cradle.energy(), e0, 1e-6f * e0);
            float highest = e0;
            for (int i = 0; i < 120; ++i) {
                cradle.world.step(kStep);
                highest = std::max(highest, cradle.energy());
            }
            SCOPED_TRACE(testing::Message() << count << " balls at " << speed << " m/s");
            // The striker did reach the row: the last ball moves away from it.
            EXPECT_GT(cradle.world.linearVelocity(cradle.balls.back()).x, 0.0f);
            EXPECT_LE(highest, e0 * (1.0f + 1e-3f));
            Vec2 p = cradle.momentum();
            EXPECT_NEAR(p.x, p0, 1e-4f * p0);
            EXPECT_NEAR(p.y, 0.0f, 1e-4f * p0);
        }
    }
}

// Two balls are an ordinary elastic collision: the striker stops, the other leaves at its speed.
TEST(SolverCradle, TwoEqualBallsSwapVelocities) {
    Cradle cradle{2, 3.0f};
    for (int i = 0; i < 60; ++i) {
        cradle.world.step(kStep);
    }
    EXPECT_NEAR(cradle.world.linearVelocity(cradle.balls[0]).x, 0.0f, 0.03f);
    EXPECT_NEAR(cradle.world.linearVelocity(cradle.balls[1]).x, 3.0f, 0.03f);
}

} // namespace
} // namespace e2d::physics::test
