// SPDX-License-Identifier: MIT
// Newton's cradle in zero gravity: a ball strikes a row of touching elastic balls. The impacts
// travel through the row as a sequence of binary collisions (contact_impacts.hpp): with equal
// balls the striker stops and only the last ball leaves, at the striker's speed. Whatever
// happens, an elastic collision must not create energy, no impulse may create momentum, and a
// resting row must stay at rest.
#include "world_step_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace e2d::physics::test {
namespace {

struct Cradle {
    World world;
    std::vector<BodyId> balls;
    std::vector<float> masses;

    // A striker of density densities[0] at `speed` towards a row of touching balls (radius
    // 0.5) of the other densities; the striker starts 0.5 m short of the row.
    Cradle(const std::vector<float>& densities, float speed, SolverMode mode = SolverMode::SoftStep)
        : world{makeDef(mode)} {
        ShapeDef sd;
        sd.friction = 0.0f;
        sd.restitution = 1.0f;
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        bd.position = {-1.5f, 0.0f};
        bd.linearVelocity = {speed, 0.0f};
        for (float density : densities) {
            BodyId ball = world.createBody(bd);
            sd.density = density;
            world.createShape(ball, sd, Circle{{0.0f, 0.0f}, 0.5f});
            balls.push_back(ball);
            masses.push_back(world.massData(ball).mass);
            bd.position = {static_cast<float>(balls.size() - 1), 0.0f};
            bd.linearVelocity = {0.0f, 0.0f};
        }
    }
    // `count` equal balls.
    Cradle(int count, float speed, SolverMode mode = SolverMode::SoftStep)
        : Cradle(std::vector<float>(static_cast<std::size_t>(count), 1.0f), speed, mode) {}

    static WorldDef makeDef(SolverMode mode) {
        WorldDef def;
        def.gravity = {0.0f, 0.0f};
        def.solver.enableSleep = false;
        def.solver.mode = mode;
        return def;
    }

    float velocity(std::size_t i) const { return world.linearVelocity(balls[i]).x; }

    Vec2 momentum() const {
        Vec2 p{0.0f, 0.0f};
        for (std::size_t i = 0; i < balls.size(); ++i) {
            p += masses[i] * world.linearVelocity(balls[i]);
        }
        return p;
    }

    // Circles on one line, hit head-on, never spin: linear energy is all of it.
    float energy() const {
        float e = 0.0f;
        for (std::size_t i = 0; i < balls.size(); ++i) {
            const Vec2 v = world.linearVelocity(balls[i]);
            e += 0.5f * masses[i] * dot(v, v);
        }
        return e;
    }
};

TEST(SolverCradle, ElasticChainNeverGainsEnergyAndKeepsMomentum) {
    for (SolverMode mode : {SolverMode::SoftStep, SolverMode::Classic}) {
        for (int count = 2; count <= 6; ++count) {
            for (float speed : {0.5f, 1.5f, 2.0f, 4.0f, 10.0f}) {
                Cradle cradle{count, speed, mode};
                // Only the striker moves at the start: p0 = m v along x, e0 = m v^2 / 2.
                const float p0 = cradle.masses[0] * speed;
                const float e0 = 0.5f * cradle.masses[0] * speed * speed;
                ASSERT_NEAR(cradle.energy(), e0, 1e-6f * e0);
                float highest = e0;
                for (int i = 0; i < 120; ++i) {
                    cradle.world.step(kStep);
                    highest = std::max(highest, cradle.energy());
                }
                SCOPED_TRACE(testing::Message() << count << " balls at " << speed << " m/s, mode "
                                                << static_cast<int>(mode));
                // The striker did reach the row: the last ball moves away from it.
                EXPECT_GT(cradle.velocity(cradle.balls.size() - 1), 0.0f);
                EXPECT_LE(highest, e0 * (1.0f + 1e-3f));
                Vec2 p = cradle.momentum();
                EXPECT_NEAR(p.x, p0, 1e-4f * p0);
                EXPECT_NEAR(p.y, 0.0f, 1e-4f * p0);
            }
        }
    }
}

// Two balls are an ordinary elastic collision: the striker stops, the other leaves at its speed.
TEST(SolverCradle, TwoEqualBallsSwapVelocities) {
    Cradle cradle{2, 3.0f};
    for (int i = 0; i < 60; ++i) {
        cradle.world.step(kStep);
    }
    EXPECT_NEAR(cradle.velocity(0), 0.0f, 0.03f);
    EXPECT_NEAR(cradle.velocity(1), 3.0f, 0.03f);
}

// Five equal balls: the momentum travels through the row; the last ball leaves at the
// striker's speed and every other ball, the striker too, is left at rest. In both solver
// modes (the merged solve gave the striker -0.35 m/s and the last ball 0.92 in the soft step,
// -0.57 and 0.90 in the classic mode).
TEST(SolverCradle, LastBallLeavesAtTheStrikersSpeedTheOthersRest) {
    for (SolverMode mode : {SolverMode::SoftStep, SolverMode::Classic}) {
        SCOPED_TRACE(testing::Message() << "mode " << static_cast<int>(mode));
        Cradle cradle{5, 2.0f, mode};
        const float e0 = cradle.energy();
        for (int i = 0; i < 120; ++i) {
            cradle.world.step(kStep);
        }
        for (std::size_t i = 0; i + 1 < cradle.balls.size(); ++i) {
            EXPECT_NEAR(cradle.velocity(i), 0.0f, 0.02f) << "ball " << i;
        }
        EXPECT_NEAR(cradle.velocity(4), 2.0f, 0.02f);
        EXPECT_NEAR(cradle.momentum().x, cradle.masses[0] * 2.0f, 1e-4f);
        EXPECT_NEAR(cradle.energy(), e0, 1e-3f * e0);
    }
}

// Unequal masses: the sequence of binary collisions in closed form. For an elastic pair
// (m1 at u, m2 at rest) u1' = u (m1 - m2) / (m1 + m2), u2' = 2 u m1 / (m1 + m2).
TEST(SolverCradle, UnequalMassesFollowTheSequenceOfBinaryCollisions) {
    const float v = 6.0f; // every impact of the sequences below is above the 1 m/s threshold
    {
        // 1 : 2 : 1. Striker -> heavy: -v/3, 2v/3; heavy -> last: 2v/9, 8v/9. Nothing approaches.
        Cradle cradle{{1.0f, 2.0f, 1.0f}, v};
        for (int i = 0; i < 90; ++i) {
            cradle.world.step(kStep);
        }
        EXPECT_NEAR(cradle.velocity(0), -v / 3.0f, 0.01f * v);
        EXPECT_NEAR(cradle.velocity(1), 2.0f * v / 9.0f, 0.01f * v);
        EXPECT_NEAR(cradle.velocity(2), 8.0f * v / 9.0f, 0.01f * v);
    }
    {
        // 2 : 1 : 1. Striker -> second: v/3, 4v/3; second -> last: 0, 4v/3; the striker
        // catches the second again: v/9, 4v/9. A single sweep would leave the striker at v/3
        // pressing into the row.
        Cradle cradle{{2.0f, 1.0f, 1.0f}, v};
        const float e0 = cradle.energy();
        for (int i = 0; i < 90; ++i) {
            cradle.world.step(kStep);
        }
        EXPECT_NEAR(cradle.velocity(0), v / 9.0f, 0.01f * v);
        EXPECT_NEAR(cradle.velocity(1), 4.0f * v / 9.0f, 0.01f * v);
        EXPECT_NEAR(cradle.velocity(2), 4.0f * v / 3.0f, 0.01f * v);
        EXPECT_NEAR(cradle.energy(), e0, 1e-3f * e0);
    }
}

// Struck from both ends in the same step: the impulses cross in the row and each striker
// leaves the way it came, at its speed; the row stays at rest. (Breadth first from both
// struck contacts, the sweeps pass each impulse through the other.)
TEST(SolverCradle, StruckFromBothEndsBothStrikersBounceBack) {
    Cradle cradle{6, 2.0f};
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = {5.5f, 0.0f}; // as far from the row's far end as the first striker
    bd.linearVelocity = {-2.0f, 0.0f};
    ShapeDef sd;
    sd.friction = 0.0f;
    sd.restitution = 1.0f;
    cradle.balls.push_back(cradle.world.createBody(bd));
    cradle.world.createShape(cradle.balls.back(), sd, Circle{{0.0f, 0.0f}, 0.5f});
    cradle.masses.push_back(cradle.world.massData(cradle.balls.back()).mass);
    const float e0 = cradle.energy();
    for (int i = 0; i < 60; ++i) {
        cradle.world.step(kStep);
    }
    EXPECT_NEAR(cradle.velocity(0), -2.0f, 0.02f);
    for (std::size_t i = 1; i + 1 < cradle.balls.size(); ++i) {
        EXPECT_NEAR(cradle.velocity(i), 0.0f, 0.02f) << "ball " << i;
    }
    EXPECT_NEAR(cradle.velocity(cradle.balls.size() - 1), 2.0f, 0.02f);
    EXPECT_NEAR(cradle.energy(), e0, 1e-3f * e0);
}

// A row of touching elastic balls at rest, and an elastic column standing on elastic ground
// under gravity: nothing is struck, nothing may start to move.
TEST(SolverCradle, RestingElasticRowsStayAtRest) {
    {
        Cradle cradle{6, 0.0f};
        for (int i = 0; i < 120; ++i) {
            cradle.world.step(kStep);
        }
        for (std::size_t i = 0; i < cradle.balls.size(); ++i) {
            EXPECT_EQ(cradle.velocity(i), 0.0f) << "ball " << i;
        }
    }
    {
        WorldDef def;
        def.solver.enableSleep = false;
        World world{def};
        addGround(world, 0.6f, 1.0f);
        ShapeDef sd;
        sd.restitution = 1.0f;
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        std::vector<BodyId> boxes;
        for (int i = 0; i < 5; ++i) {
            bd.position = {0.0f, 0.5f + static_cast<float>(i)};
            boxes.push_back(world.createBody(bd));
            world.createShape(boxes.back(), sd, makeBox(0.5f, 0.5f));
        }
        for (int i = 0; i < 180; ++i) {
            world.step(kStep);
        }
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            EXPECT_LT(length(world.linearVelocity(boxes[i])), 0.01f) << "box " << i;
            EXPECT_NEAR(world.transform(boxes[i]).p.x, 0.0f, 0.01f) << "box " << i;
        }
    }
}

// The impacts are planned per block of the wide solver (islands gathered up to about 4096
// constraints), on the worker that solves it: 520 cradles of ten balls (4680 contacts, two
// blocks or more), each striker touching its row at the start, end bit for bit the same on 1,
// 2 and 3 workers and on 4 and 8 lanes.
TEST(SolverCradle, EveryWorkerCountGivesTheSameImpacts) {
    constexpr int kRows = 520;
    constexpr int kBalls = 10;
    auto run = [](int workers, int lanes) {
        WorldDef def = Cradle::makeDef(SolverMode::SoftStep);
        def.workerCount = workers;
        def.simdLanes = lanes;
        World world{def};
        ShapeDef sd;
        sd.friction = 0.0f;
        sd.restitution = 1.0f;
        std::vector<BodyId> balls;
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        for (int row = 0; row < kRows; ++row) {
            for (int i = 0; i < kBalls; ++i) {
                bd.position = {static_cast<float>(i), 2.0f * static_cast<float>(row)};
                bd.linearVelocity = {i == 0 ? 2.0f + 0.01f * static_cast<float>(row) : 0.0f, 0.0f};
                balls.push_back(world.createBody(bd));
                sd.density = 1.0f + 0.5f * static_cast<float>((i + row) % 3);
                world.createShape(balls.back(), sd, Circle{{0.0f, 0.0f}, 0.5f});
            }
        }
        world.step(kStep);
        EXPECT_GT(world.stepCounters().contactConstraints, 4096);
        for (int i = 0; i < 4; ++i) {
            world.step(kStep);
        }
        std::vector<float> state;
        for (BodyId b : balls) {
            const Vec2 p = world.transform(b).p;
            const Vec2 v = world.linearVelocity(b);
            state.insert(state.end(), {p.x, p.y, v.x, v.y});
        }
        return state;
    };
    const std::vector<float> alone = run(1, 4);
    // The rows were struck: every last ball left.
    for (int row = 0; row < kRows; ++row) {
        ASSERT_GT(alone[static_cast<std::size_t>(4 * (kBalls * row + kBalls - 1) + 2)], 0.5f);
    }
    for (auto [workers, lanes] : {std::pair{1, 8}, std::pair{2, 4}, std::pair{3, 8}}) {
        EXPECT_EQ(run(workers, lanes), alone) << workers << " workers, " << lanes << " lanes";
    }
}

} // namespace
} // namespace e2d::physics::test
