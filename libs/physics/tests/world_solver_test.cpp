// SPDX-License-Identifier: MIT
// Solver behaviour seen through the World: warm starting by feature id, the restitution
// threshold, friction and restitution mixing rules, hit events (approach speed along the
// normal, point, threshold), several worlds stepping at once on different threads, and the
// wide solver's schedule kept from step to step.
#include "world_step_util.hpp"
#include "world_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <thread>
#include <vector>

namespace e2d::physics::test {
namespace {

TEST(WorldSolver, RestingImpulsesPersistByFeatureId) {
    World world;
    addGround(world);
    BodyId box = addBox(world, {0.0f, 0.5f}, 0.5f); // mass 1
    for (int i = 0; i < 20; ++i) {
        world.step(kStep);
    }
    std::uint16_t ids[2] = {0, 0};
    float impulses[2] = {0.0f, 0.0f};
    int contacts = 0;
    world.forEachTouchingContact([&](const ContactData& c) {
        ++contacts;
        ASSERT_EQ(c.manifold->pointCount, 2);
        for (int i = 0; i < 2; ++i) {
            ids[i] = c.manifold->points[i].id;
            impulses[i] = c.manifold->points[i].normalImpulse;
            EXPECT_TRUE(c.manifold->points[i].persisted);
        }
    });
    ASSERT_EQ(contacts, 1);
    EXPECT_NE(ids[0], ids[1]);
    // Warm-started sub-step impulses carry the weight: m g h in total, half at each corner.
    float h = kStep / 4.0f;
    EXPECT_NEAR(impulses[0] + impulses[1], 10.0f * h, 1e-3f * 10.0f * h * 10.0f);
    EXPECT_NEAR(impulses[0], impulses[1], 0.05f * 10.0f * h);
    // Next step, each id keeps its own impulse (matched by id, not by slot).
    world.step(kStep);
    world.forEachTouchingContact([&](const ContactData& c) {
        for (int i = 0; i < c.manifold->pointCount; ++i) {
            int j = c.manifold->points[i].id == ids[0] ? 0 : 1;
            EXPECT_EQ(c.manifold->points[i].id, ids[j]);
            EXPECT_NEAR(c.manifold->points[i].normalImpulse, impulses[j], 0.02f * 10.0f * h);
        }
    });
    EXPECT_NEAR(world.transform(box).p.y, 0.5f, kLinearSlop);
}

// Highest point a ball reaches after hitting the ground once at `speed`.
float reboundHeight(float speed, float threshold, float restitution) {
    WorldDef def{.gravity = {0.0f, 0.0f}};
    def.solver.restitutionThreshold = threshold;
    World world{def};
    addGround(world, 0.6f, restitution);
    BodyId ball = addBall(world, {0.0f, 0.6f}, 0.5f, restitution);
    world.setLinearVelocity(ball, {0.0f, -speed});
    float highest = 0.0f;
    for (int i = 0; i < 60; ++i) {
        world.step(kStep);
        highest = std::max(highest, world.linearVelocity(ball).y);
    }
    return highest; // no gravity: the rebound speed
}

TEST(WorldSolver, RestitutionOnlyAboveTheThresholdSpeed) {
    // Elastic ball at 0.8 m/s: below the default 1 m/s threshold it stops, above a 0.5 m/s
    // threshold it rebounds at 0.8 m/s.
    EXPECT_LT(reboundHeight(0.8f, 1.0f, 1.0f), 0.01f);
    EXPECT_NEAR(reboundHeight(0.8f, 0.5f, 1.0f), 0.8f, 0.8f * 0.02f);
    // e = 0.5 at 4 m/s rebounds at 2 m/s.
    EXPECT_NEAR(reboundHeight(4.0f, 1.0f, 0.5f), 2.0f, 2.0f * 0.02f);
}

TEST(WorldSolver, MixingRulesAreConfigurable) {
    EXPECT_FLOAT_EQ(mix(MixingRule::GeometricMean, 0.25f, 1.0f), 0.5f);
    EXPECT_FLOAT_EQ(mix(MixingRule::Average, 0.25f, 1.0f), 0.625f);
    EXPECT_FLOAT_EQ(mix(MixingRule::Min, 0.25f, 1.0f), 0.25f);
    EXPECT_FLOAT_EQ(mix(MixingRule::Max, 0.25f, 1.0f), 1.0f);
    EXPECT_FLOAT_EQ(mix(MixingRule::Multiply, 0.25f, 1.0f), 0.25f);

    // A box (mu 0.5) sliding at 3 m/s on ice (mu 0): the geometric mean gives no friction,
    // Max gives mu = 0.5, so it decelerates at mu g = 5 m/s^2 (0.3 s: 1.5 m/s).
    for (MixingRule rule : {MixingRule::GeometricMean, MixingRule::Max}) {
        WorldDef def;
        def.solver.frictionMixing = rule;
        World world{def};
        addGround(world, 0.0f);
        BodyId box = addBox(world, {0.0f, 0.5f}, 0.5f, 0.5f);
        for (int i = 0; i < 10; ++i) {
            world.step(kStep); // settle onto the ground
        }
        world.setLinearVelocity(box, {3.0f, 0.0f});
        for (int i = 0; i < 18; ++i) {
            world.step(kStep);
        }
        float expected = rule == MixingRule::Max ? 3.0f - 5.0f * 0.3f : 3.0f;
        EXPECT_NEAR(world.linearVelocity(box).x, expected, 0.02f) << static_cast<int>(rule);
    }
}

TEST(WorldSolver, RestitutionMixingDecidesWhoBounces) {
    // An elastic ball (e = 1) on a dead ground (e = 0) at 3 m/s: Max (the default) bounces it
    // back at 3 m/s, Min not at all.
    for (MixingRule rule : {MixingRule::Max, MixingRule::Min}) {
        WorldDef def{.gravity = {0.0f, 0.0f}};
        def.solver.restitutionMixing = rule;
        World world{def};
        addGround(world, 0.6f, 0.0f);
        BodyId ball = addBall(world, {0.0f, 0.6f}, 0.5f, 1.0f);
        world.setLinearVelocity(ball, {0.0f, -3.0f});
        for (int i = 0; i < 30; ++i) {
            world.step(kStep);
        }
        float expected = rule == MixingRule::Max ? 3.0f : 0.0f;
        EXPECT_NEAR(world.linearVelocity(ball).y, expected, 0.06f) << static_cast<int>(rule);
    }
}

TEST(WorldSolver, LinearSpeedIsCappedByTheWorld) {
    WorldDef def{.gravity = {0.0f, 0.0f}};
    def.solver.maxLinearSpeed = 50.0f;
    World world{def};
    BodyId fast = addBall(world, {0.0f, 0.0f}, 0.5f);
    world.setLinearVelocity(fast, {300.0f, 400.0f});
    world.step(kStep);
    // Same direction, 50 m/s: (30, 40).
    EXPECT_NEAR(world.linearVelocity(fast).x, 30.0f, 1e-3f);
    EXPECT_NEAR(world.linearVelocity(fast).y, 40.0f, 1e-3f);
}

TEST(WorldSolver, HitEventCarriesTheNormalApproachSpeedAndPoint) {
    World world{WorldDef{.gravity = {0.0f, 0.0f}}};
    addGround(world);
    // 4 m/s along x, 3 m/s down: the approach speed is the normal part, 3, not 5.
    BodyId ball = addBall(world, {2.0f, 1.0f}, 0.5f, 0.0f, 0.0f);
    world.setLinearVelocity(ball, {4.0f, -3.0f});
    // And one too slow to report (0.5 m/s < the 1 m/s threshold).
    BodyId slow = addBall(world, {-5.0f, 0.51f}, 0.5f);
    world.setLinearVelocity(slow, {0.0f, -0.5f});
    int hits = 0;
    for (int i = 0; i < 30; ++i) {
        world.step(kStep);
        for (const ContactHitEvent& e : world.hitEvents()) {
            ++hits;
            EXPECT_TRUE(e.shapeA == world.bodyShapes(ball)[0] ||
                        e.shapeB == world.bodyShapes(ball)[0]);
            EXPECT_NEAR(e.approachSpeed, 3.0f, 1e-3f);
            EXPECT_NEAR(std::abs(e.normal.y), 1.0f, 1e-5f);
            // Touches down after (1 - 0.5) / 3 s, 4 m/s * 1/6 s = 0.67 m further along x,
            // within a step's travel (4/60 m).
            EXPECT_NEAR(e.point.y, 0.0f, 0.02f);
            EXPECT_NEAR(e.point.x, 2.0f + 4.0f / 6.0f, 4.0f / 60.0f + 0.02f);
        }
    }
    EXPECT_EQ(hits, 1);
}

TEST(WorldSolver, BothCollisionAlgorithmsRestPolygonsOnTheGround) {
    for (CollisionAlgorithm algorithm : {CollisionAlgorithm::Sat, CollisionAlgorithm::GjkEpa}) {
        WorldDef def;
        def.collisionAlgorithm = algorithm;
        World world{def};
        addGround(world);
        BodyId box = addBox(world, {0.0f, 1.0f}, 0.5f, 0.6f, 1.0f, 0.2f);
        // A regular hexagon of circumradius 0.5, resting on an edge: its centre ends
        // 0.5 cos 30 deg above the ground.
        std::vector<Vec2> hexagon;
        for (int i = 0; i < 6; ++i) {
            float a = 3.14159265f / 3.0f * static_cast<float>(i);
            hexagon.push_back({0.5f * std::cos(a), 0.5f * std::sin(a)});
        }
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        bd.position = {3.0f, 1.0f};
        BodyId hex = world.createBody(bd);
        world.createShape(hex, {}, makePolygon(hexagon));
        for (int i = 0; i < 180; ++i) {
            world.step(kStep);
        }
        const char* name = algorithm == CollisionAlgorithm::Sat ? "sat" : "gjk-epa";
        EXPECT_NEAR(world.transform(box).p.y, 0.5f, 0.01f) << name;
        EXPECT_NEAR(std::abs(world.transform(box).q.s), 0.0f, 1e-3f) << name << ": lands flat";
        EXPECT_NEAR(world.transform(hex).p.y, 0.5f * std::sqrt(3.0f) / 2.0f, 0.01f) << name;
        EXPECT_LT(maxPenetration(world), 0.01f) << name;
    }
}

TEST(WorldSolver, SleepToleranceIsTheWorlds) {
    // A puck gliding at 3 cm/s on ice sleeps under the default 5 cm/s tolerance, not under
    // a 1 cm/s one.
    for (float tolerance : {0.05f, 0.01f}) {
        WorldDef def;
        def.solver.linearSleepTolerance = tolerance;
        World world{def};
        addGround(world, 0.0f);
        BodyId puck = addBall(world, {0.0f, 0.25f}, 0.25f, 0.0f, 0.0f);
        world.setLinearVelocity(puck, {0.03f, 0.0f});
        for (int i = 0; i < 60; ++i) {
            world.step(kStep);
        }
        EXPECT_EQ(world.isAwake(puck), tolerance < 0.03f) << tolerance;
    }
}

// Classic mode's position iterations push an overlap out down to classicAllowedPenetration,
// each iteration by classicPositionBias times what is beyond it.
WorldDef classicDef(float allowedPenetration, float positionBias, Vec2 gravity = {0.0f, -10.0f}) {
    WorldDef def;
    def.gravity = gravity;
    def.solver.mode = SolverMode::Classic;
    def.solver.enableSleep = false;
    def.solver.classicAllowedPenetration = allowedPenetration;
    def.solver.classicPositionBias = positionBias;
    return def;
}

TEST(WorldSolver, ClassicBoxSettlesWithTheAllowedPenetration) {
    // A unit box spawned 10 cm into the ground. The velocity iterations keep it still (it
    // rests, nothing approaches); the position iterations lift it until the overlap left is
    // the allowed one, where their correction is zero.
    const auto restingOverlap = [](float allowed) {
        World world{classicDef(allowed, 0.2f)};
        addGround(world);
        BodyId box = addBox(world, {0.0f, 0.4f}, 0.5f);
        for (int i = 0; i < 300; ++i) {
            world.step(kStep);
        }
        EXPECT_NEAR(world.transform(box).q.s, 0.0f, 1e-4f) << allowed << ": stays flat";
        EXPECT_LT(length(world.linearVelocity(box)), 1e-3f) << allowed;
        return 0.5f - world.transform(box).p.y; // the ground's top is y = 0
    };
    const float deep = restingOverlap(0.02f);
    const float shallow = restingOverlap(kLinearSlop);
    EXPECT_NEAR(deep, 0.02f, 1e-3f);
    EXPECT_NEAR(shallow, kLinearSlop, 1e-3f);
    EXPECT_GT(deep - shallow, 0.01f);
    // Nothing left to correct: 0 allowed pushes the overlap out entirely.
    EXPECT_NEAR(restingOverlap(0.0f), 0.0f, 1e-3f);
}

TEST(WorldSolver, ClassicPositionBiasSetsHowFastAnOverlapIsPushedOut) {
    // A weightless ball of radius 0.5 spawned 10 cm into the ground: one contact point whose
    // arm is along the normal, so each position iteration removes exactly bias times the
    // overlap beyond the allowed one (the ground is static). Each step runs up to 3
    // iterations and stops after one that started with at most 3 times the allowed overlap.
    constexpr float kStartOverlap = 0.1f;
    constexpr int kSteps = 6;
    const auto expected = [](float bias, float allowed) {
        float excess = kStartOverlap - allowed;
        for (int step = 0; step < kSteps; ++step) {
            for (int i = 0; i < 3; ++i) {
                const float before = excess;
                excess -= bias * excess;
                if (before + allowed <= 3.0f * allowed) {
                    break;
                }
            }
        }
        return allowed + excess;
    };
    const auto overlapAfter = [](float bias, float allowed) {
        World world{classicDef(allowed, bias, {0.0f, 0.0f})};
        addGround(world);
        BodyId ball = addBall(world, {0.0f, 0.5f - kStartOverlap}, 0.5f);
        for (int i = 0; i < kSteps; ++i) {
            world.step(kStep);
        }
        EXPECT_EQ(world.linearVelocity(ball), Vec2(0.0f, 0.0f))
            << bias << ": moved by position only";
        return 0.5f - world.transform(ball).p.y;
    };
    const float fast = overlapAfter(0.2f, kLinearSlop);
    const float slow = overlapAfter(0.05f, kLinearSlop);
    EXPECT_NEAR(fast, expected(0.2f, kLinearSlop), 1e-5f);
    EXPECT_NEAR(slow, expected(0.05f, kLinearSlop), 1e-5f);
    EXPECT_GT(slow, fast + 0.03f);
    // With 2 cm allowed, the iterations of a step stop once the overlap is 6 cm or less.
    EXPECT_NEAR(overlapAfter(0.2f, 0.02f), expected(0.2f, 0.02f), 1e-5f);
    // Bias 0: contacts get no position correction, the overlap stays.
    EXPECT_NEAR(overlapAfter(0.0f, kLinearSlop), kStartOverlap, 1e-6f);
}

TEST(WorldSolver, SoftStepIgnoresTheClassicPositionSettings) {
    // A leaning column of boxes spawned 5 cm into the ground and 10 cm into each other.
    const auto pile = [](float allowed, float bias) {
        WorldDef def;
        def.solver.classicAllowedPenetration = allowed;
        def.solver.classicPositionBias = bias;
        World world{def};
        addGround(world);
        std::vector<BodyId> bodies;
        for (int i = 0; i < 6; ++i) {
            const float k = static_cast<float>(i);
            bodies.push_back(addBox(world, {0.1f * k, 0.45f + 0.9f * k}, 0.5f)); // overlapping
        }
        for (int i = 0; i < 120; ++i) {
            world.step(kStep);
        }
        return transformsHash(world, bodies);
    };
    EXPECT_EQ(pile(kLinearSlop, 0.2f), pile(0.05f, 0.05f));
}

// A random pile stepped n times in a world of the given mode; a hash of the final transforms.
std::uint64_t pileHash(SolverMode mode, int steps) {
    WorldDef def;
    def.solver.mode = mode;
    World world{def};
    addGround(world);
    std::vector<BodyId> bodies;
    Random random(11);
    for (int i = 0; i < 24; ++i) {
        Vec2 p{random.uniform(-2.0f, 2.0f), 1.0f + 0.8f * static_cast<float>(i)};
        if (i % 2 == 0) {
            bodies.push_back(addBox(world, p, random.uniform(0.2f, 0.5f), 0.6f, 1.0f,
                                    random.uniform(-1.0f, 1.0f)));
        } else {
            bodies.push_back(addBall(world, p, random.uniform(0.2f, 0.5f), 0.3f));
        }
    }
    for (int i = 0; i < steps; ++i) {
        world.step(kStep);
    }
    return transformsHash(world, bodies);
}

TEST(WorldSolver, WorldsOnSeveralThreadsMatchRunningAlone) {
    constexpr int kSteps = 240;
    const std::uint64_t soft = pileHash(SolverMode::SoftStep, kSteps);
    const std::uint64_t classic = pileHash(SolverMode::Classic, kSteps);
    EXPECT_NE(soft, classic);
    // Four worlds at once, two of each mode, on their own threads.
    std::uint64_t results[4] = {0, 0, 0, 0};
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([t, &results] {
            results[t] = pileHash(t % 2 == 0 ? SolverMode::SoftStep : SolverMode::Classic, kSteps);
        });
    }
    for (std::thread& th : threads) {
        th.join();
    }
    EXPECT_EQ(results[0], soft);
    EXPECT_EQ(results[1], classic);
    EXPECT_EQ(results[2], soft);
    EXPECT_EQ(results[3], classic);
}

// The soft step keeps last step's wide schedule while the constraints stay the same. Two
// copies of a scene get the same changes, several of which keep the number of constraints: a
// box moves from the ground onto another (a contact ends as another begins), the middle box of
// a weightless row squeezed from both ends turns rigid and back, a box sleeps and wakes, another is disabled and
// enabled, a rolling-resistance ball (scalar solve) comes and goes. The second copy also has a
// far weightless box put to sleep and woken step after step, so it schedules every step anew: a
// schedule kept when it should not have been (two constraints on one body in one level, or in
// the wrong order) shows as a difference.
TEST(WorldSolver, KeptWideScheduleMatchesANewOneEveryStep) {
    struct Scene {
        World world{WorldDef{.solver = {.enableSleep = false}}};
        std::vector<BodyId> row;   // boxes on the ground, apart
        std::vector<BodyId> chain; // weightless boxes in a row, touching
        BodyId spare;
        BodyId ball;
        BodyId far;
        std::vector<BodyId> all;
    };
    auto build = [](Scene& s) {
        addGround(s.world);
        for (int i = 0; i < 6; ++i) {
            s.row.push_back(addBox(s.world, {-10.0f + 2.0f * static_cast<float>(i), 0.5f}, 0.5f));
        }
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        bd.gravityScale = 0.0f;
        for (int i = 0; i < 3; ++i) {
            bd.position = {static_cast<float>(i), 10.0f};
            s.chain.push_back(s.world.createBody(bd));
            s.world.createShape(s.chain.back(), {}, makeBox(0.5f, 0.5f));
        }
        s.spare = addBox(s.world, {20.0f, 0.5f}, 0.5f);
        bd.gravityScale = 1.0f;
        bd.position = {8.0f, 0.5f};
        bd.enabled = false;
        s.ball = s.world.createBody(bd);
        ShapeDef rolling;
        rolling.rollingResistance = 0.1f;
        s.world.createShape(s.ball, rolling, Circle{{0.0f, 0.0f}, 0.5f});
        bd.gravityScale = 0.0f;
        bd.position = {60.0f, 60.0f};
        bd.enabled = true;
        s.far = s.world.createBody(bd);
        s.world.createShape(s.far, {}, makeBox(0.5f, 0.5f));
        s.all = s.row;
        s.all.insert(s.all.end(), s.chain.begin(), s.chain.end());
        s.all.push_back(s.spare);
        s.all.push_back(s.ball);
    };
    auto change = [](Scene& s, int step) {
        World& w = s.world;
        switch (step) {
        case 30:
            w.setTransform(s.row[5], {-10.0f, 1.5f}, 0.0f);
            break; // onto row[0]
        case 50:   // rigid, scheduled so (the spare box's contact goes)
            w.setFixedRotation(s.chain[1], true);
            w.setPositionLocks(s.chain[1], true, true);
            w.setBodyEnabled(s.spare, false);
            break;
        case 60:
            w.setBodyEnabled(s.spare, true);
            break;
        case 70: // moving again, and pushed from both sides
            w.setFixedRotation(s.chain[1], false);
            w.setPositionLocks(s.chain[1], false, false);
            w.setLinearVelocity(s.chain[0], {1.0f, 0.0f});
            w.setLinearVelocity(s.chain[2], {-1.0f, 0.0f});
            break;
        case 90:
            w.setAwake(s.row[1], false);
            break;
        case 100:
            w.setAwake(s.row[1], true);
            break;
        case 110:
            w.setBodyEnabled(s.row[2], false);
            break;
        case 120:
            w.setBodyEnabled(s.row[2], true);
            break;
        case 130:
            w.setBodyEnabled(s.ball, true);
            break;
        case 140:
            w.setBodyEnabled(s.ball, false);
            break;
        default:
            break;
        }
    };
    Scene kept;
    Scene fresh;
    build(kept);
    build(fresh);
    for (int i = 0; i < 180; ++i) {
        for (Scene* s : {&kept, &fresh}) {
            change(*s, i);
            // The row squeezed from both ends: its contacts always push.
            s->world.applyForceToCenter(s->chain[0], {5.0f, 0.0f});
            s->world.applyForceToCenter(s->chain[2], {-5.0f, 0.0f});
        }
        fresh.world.setAwake(fresh.far, i % 2 != 0);
        kept.world.step(kStep);
        fresh.world.step(kStep);
        ASSERT_EQ(transformsHash(kept.world, kept.all), transformsHash(fresh.world, fresh.all))
            << "step " << i;
    }
    // The moved box rests on the other.
    EXPECT_NEAR(kept.world.transform(kept.row[5]).p.y, 1.5f, 0.05f);
}

} // namespace
} // namespace e2d::physics::test
