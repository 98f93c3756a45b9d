// SPDX-License-Identifier: MIT
// World::step() behaviour: falling, resting, input checks, non-finite bodies, sleep and wake,
// events, determinism, continuous collision, kinematic bodies, both solver modes.
#include "world_step_util.hpp"
#include "world_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>

namespace e2d::physics::test {
namespace {

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();

TEST(WorldStep, FreeFallFollowsSymplecticEuler) {
    World world;
    BodyId ball = addBall(world, {0.0f, 10.0f}, 0.5f);
    for (int i = 0; i < 60; ++i) {
        world.step(kStep);
    }
    // Sub-stepped semi-implicit Euler: v = g t exactly, y = y0 - g h^2 n(n+1)/2 with
    // n = 240 sub-steps of h = 1/240.
    float h = kStep / 4.0f;
    EXPECT_NEAR(world.linearVelocity(ball).y, -10.0f, 1e-4f);
    EXPECT_NEAR(world.transform(ball).p.y, 10.0f - 10.0f * h * h * 240.0f * 241.0f / 2.0f, 1e-3f);
}

TEST(WorldStep, BoxComesToRestOnTheGround) {
    World world;
    addGround(world);
    BodyId box = addBox(world, {0.0f, 2.0f}, 0.5f);
    for (int i = 0; i < 180; ++i) {
        world.step(kStep);
    }
    EXPECT_NEAR(world.transform(box).p.y, 0.5f, 0.01f);
    EXPECT_NEAR(world.transform(box).p.x, 0.0f, 1e-4f);
    EXPECT_LT(length(world.linearVelocity(box)), 0.01f);
    EXPECT_EQ(world.contactCount(), 1);
}

TEST(WorldStep, RejectsBadInputAndChangesNothing) {
    World world;
    BodyId box = addBox(world, {0.0f, 2.0f}, 0.5f);
    E2D_EXPECT_ERROR(world.step(-1.0f),
                     "physics::World::step(): timeStep must be finite and >= 0, got -1");
    E2D_EXPECT_ERROR(world.step(kNan), "physics::World::step(): timeStep must be finite");
    E2D_EXPECT_ERROR(world.applyForce(box, {kNan, 0.0f}, {0.0f, 0.0f}),
                     "physics::World::applyForce(): force must be finite, got (nan, 0)");
    E2D_EXPECT_ERROR(world.applyLinearImpulseToCenter(box, {0.0f, INFINITY}),
                     "physics::World::applyLinearImpulseToCenter(): impulse must be finite");
    E2D_EXPECT_ERROR(world.applyTorque(box, kNan),
                     "physics::World::applyTorque(): torque must be finite");
    E2D_EXPECT_ERROR(world.setLinearDamping(box, -1.0f),
                     "physics::World::setLinearDamping(): damping must be finite and >= 0, got -1");
    E2D_EXPECT_ERROR(world.setMassData(box, {0.0f, {0.0f, 0.0f}, 1.0f}),
                     "physics::World::setMassData(): massData.mass must be finite and > 0, got 0");
    EXPECT_EQ(world.linearVelocity(box), Vec2(0.0f, 0.0f));
    EXPECT_EQ(world.angularVelocity(box), 0.0f);
    EXPECT_FLOAT_EQ(world.massData(box).mass, 1.0f);

    WorldDef def;
    def.solver.subSteps = 0;
    E2D_EXPECT_ERROR(World{def},
                     "physics::World::World(): def.solver.subSteps must be in [1, 64], got 0");
    def = {};
    def.solver.contactHertz = -5.0f;
    E2D_EXPECT_ERROR(
        World{def},
        "physics::World::World(): def.solver.contactHertz must be finite and > 0, got -5");
    def = {};
    def.solver.jointHertz = 0.0f;
    E2D_EXPECT_ERROR(
        World{def}, "physics::World::World(): def.solver.jointHertz must be finite and > 0, got 0");
    def = {};
    def.solver.jointDampingRatio = kNan;
    E2D_EXPECT_ERROR(World{def}, "def.solver.jointDampingRatio must be finite and >= 0");
    def = {};
    def.solver.timeToSleep = kNan;
    E2D_EXPECT_ERROR(World{def}, "def.solver.timeToSleep must be finite and > 0");
    BodyDef bd;
    bd.linearDamping = -0.5f;
    E2D_EXPECT_ERROR(
        world.createBody(bd),
        "physics::World::createBody(): def.linearDamping must be finite and >= 0, got -0.5");
}

TEST(WorldStep, MassComesFromDensity) {
    World world;
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    BodyId body = world.createBody(bd);
    ShapeDef sd;
    sd.density = 2.0f;
    world.createShape(body, sd, makeOffsetBox(1.0f, 0.5f, {1.0f, 0.0f}, 0.0f));
    MassData md = world.massData(body);
    // 2 x 1 box at density 2: mass 4, centre (1, 0), I = m (w^2 + h^2) / 12 = 4 * 5 / 12.
    EXPECT_FLOAT_EQ(md.mass, 4.0f);
    EXPECT_NEAR(md.center.x, 1.0f, 1e-6f);
    EXPECT_NEAR(md.rotationalInertia, 4.0f * 5.0f / 12.0f, 1e-4f);
    world.setFixedRotation(body, true);
    EXPECT_EQ(world.massData(body).rotationalInertia, 0.0f);
}

TEST(WorldStep, DynamicBodyWithoutDensityHasUnitMassAndDoesNotRotate) {
    // As in Box2D 2.4: a dynamic body whose shapes give no mass (density 0, or segments, which
    // have no area) gets 1 kg at its origin and no rotational inertia, so it falls and slides
    // but never turns; setMassData() gives it a real one.
    World world;
    addGround(world);
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = {0.0f, 1.0f};
    BodyId weightless = world.createBody(bd);
    ShapeDef sd;
    sd.density = 0.0f;
    world.createShape(weightless, sd, makeBox(0.5f, 0.5f));
    bd.position = {5.0f, 1.0f};
    BodyId stick = world.createBody(bd);
    world.createShape(stick, {}, Segment{{-0.5f, 0.0f}, {0.5f, 0.0f}});
    for (BodyId body : {weightless, stick}) {
        MassData md = world.massData(body);
        EXPECT_EQ(md.mass, 1.0f);
        EXPECT_EQ(md.center, Vec2(0.0f, 0.0f));
        EXPECT_EQ(md.rotationalInertia, 0.0f);
    }
    // Off-centre impulses do not spin them.
    world.applyLinearImpulse(weightless, {0.0f, 1.0f}, {0.5f, 0.0f});
    EXPECT_EQ(world.angularVelocity(weightless), 0.0f);
    EXPECT_EQ(world.linearVelocity(weightless).y, 1.0f); // 1 N*s on 1 kg
    for (int i = 0; i < 120; ++i) {
        world.step(kStep);
    }
    EXPECT_NEAR(world.transform(weightless).p.y, 0.5f, 0.01f);
    EXPECT_LT(world.transform(stick).p.y, 0.1f);
    EXPECT_GT(world.transform(stick).p.y, -0.05f);
    EXPECT_EQ(world.transform(stick).q.angle(), 0.0f);
}

TEST(WorldStep, ImpulsesAndForcesChangeVelocity) {
    World world{WorldDef{.gravity = {0.0f, 0.0f}}};
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    BodyId body = world.createBody(bd);
    ShapeDef sd;
    sd.density = 0.25f; // 2 x 2 box: mass 1
    world.createShape(body, sd, makeBox(1.0f, 1.0f));
    world.applyLinearImpulseToCenter(body, {2.0f, 0.0f});
    EXPECT_FLOAT_EQ(world.linearVelocity(body).x, 2.0f);
    // An impulse off centre also spins: dw = r x J / I, I = m (4 + 4) / 12 = 2/3.
    world.applyLinearImpulse(body, {0.0f, 1.0f}, {1.0f, 0.0f});
    EXPECT_NEAR(world.angularVelocity(body), 1.5f, 1e-5f);
    world.applyLinearImpulse(body, {0.0f, -1.0f}, {1.0f, 0.0f});
    world.applyForceToCenter(body, {60.0f, 0.0f});
    world.step(kStep);
    // F dt / m = 1 m/s more; the force is gone after the step.
    EXPECT_NEAR(world.linearVelocity(body).x, 3.0f, 1e-5f);
    world.step(kStep);
    EXPECT_NEAR(world.linearVelocity(body).x, 3.0f, 1e-5f);
}

TEST(WorldStep, NonFiniteBodyIsDisabledAndTheRestContinues) {
    World world;
    addGround(world);
    BodyId good = addBox(world, {0.0f, 2.0f}, 0.5f);
    BodyId bad = addBox(world, {3.0f, 2.0f}, 0.5f);
    // Finite but absurd: the solver's arithmetic overflows into infinity.
    world.setGravityScale(bad, 3.0e38f);
    world.step(kStep);
    ASSERT_EQ(world.nonFiniteBodies().size(), 1u);
    EXPECT_EQ(world.nonFiniteBodies()[0], bad);
    EXPECT_FALSE(world.isBodyEnabled(bad));
    EXPECT_TRUE(isFinite(world.transform(bad).p));
    for (int i = 0; i < 120; ++i) {
        world.step(kStep);
    }
    EXPECT_TRUE(world.nonFiniteBodies().empty());
    EXPECT_NEAR(world.transform(good).p.y, 0.5f, 0.01f);
}

TEST(WorldStep, TimeStepsBeyondKMaxTimeStepAreRejected) {
    // step(100) used to leave a box 234 m below the floor, asleep in mid-air.
    World world;
    addGround(world);
    BodyId box = addBox(world, {0.0f, 3.0f}, 0.5f);
    EXPECT_EQ(test::errorOf([&] { world.step(100.0f); }),
              "physics::World::step(): timeStep must be <= kMaxTimeStep (0.25 s), got 100: longer "
              "steps sink bodies into what they rest on; call step() several times");
    E2D_EXPECT_ERROR(world.step(0.2500001f), "timeStep must be <= kMaxTimeStep (0.25 s)");
    EXPECT_EQ(world.transform(box).p, Vec2(0.0f, 3.0f));
    // At the limit itself the box still lands and rests within the slop of the floor.
    for (int i = 0; i < 40; ++i) {
        world.step(kMaxTimeStep);
    }
    EXPECT_NEAR(world.transform(box).p.y, 0.5f, kLinearSlop);
    EXPECT_FALSE(world.isAwake(box));
}

TEST(WorldStep, HugeInitialVelocitiesAreCappedNotStopped) {
    // Beyond about 1.8e19 m/s the speed's square overflows; the cap used to scale by
    // 400 / inf = 0 and stop the body dead (1e18 was capped, 1e20 and 1e30 stopped).
    for (float speed : {1.0e18f, 1.0e20f, 1.0e30f, 3.0e38f}) {
        for (Vec2 direction : {Vec2{1.0f, 0.0f}, Vec2{0.6f, -0.8f}}) {
            World world{WorldDef{.gravity = {0.0f, 0.0f}}};
            BodyDef bd;
            bd.type = BodyType::Dynamic;
            bd.linearVelocity = speed * direction;
            BodyId body = world.createBody(bd);
            world.createShape(body, {}, Circle{{0.0f, 0.0f}, 0.5f});
            world.step(kStep);
            const float cap = world.solverDef().maxLinearSpeed;
            Vec2 v = world.linearVelocity(body);
            EXPECT_NEAR(v.x, cap * direction.x, 1e-3f) << speed;
            EXPECT_NEAR(v.y, cap * direction.y, 1e-3f) << speed;
            EXPECT_NEAR(world.transform(body).p.x, cap * direction.x * kStep, 1e-3f) << speed;
            EXPECT_TRUE(world.isBodyEnabled(body));
        }
    }
}

TEST(WorldStep, BodyLeavingTheCoordinateRangeIsDisabledAndReported) {
    // A body carried past kHuge used to go on without an event, and calls made from its own
    // position then threw (setTransform, ray casts).
    for (Vec2 direction : {Vec2{1.0f, 0.0f}, Vec2{0.0f, -1.0f}}) {
        World world{WorldDef{.gravity = {0.0f, 0.0f}}};
        BodyId stay = addBall(world, {0.0f, 0.0f}, 0.5f);
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        bd.position = (kHuge - 10.0f) * direction;
        bd.linearVelocity = 400.0f * direction; // 6.7 m per step: out in the second step
        BodyId runaway = world.createBody(bd);
        world.createShape(runaway, {}, Circle{{0.0f, 0.0f}, 0.5f});
        world.step(kStep);
        EXPECT_TRUE(world.outOfRangeBodies().empty());
        Vec2 last = world.transform(runaway).p;
        world.step(kStep);
        ASSERT_EQ(world.outOfRangeBodies().size(), 1u);
        EXPECT_EQ(world.outOfRangeBodies()[0], runaway);
        EXPECT_TRUE(world.nonFiniteBodies().empty());
        EXPECT_FALSE(world.isBodyEnabled(runaway));
        EXPECT_EQ(world.transform(runaway).p, last);
        EXPECT_EQ(world.linearVelocity(runaway), Vec2(0.0f, 0.0f));
        // Calls from where it is work, and it can be brought back.
        EXPECT_NO_THROW((void)world.castRayClosest(last, -direction));
        world.setTransform(runaway, last, 0.0f);
        world.setTransform(runaway, {5.0f, 0.0f}, 0.0f);
        world.setBodyEnabled(runaway, true);
        world.step(kStep);
        EXPECT_TRUE(world.outOfRangeBodies().empty());
        EXPECT_TRUE(world.isBodyEnabled(runaway));
        EXPECT_TRUE(world.isBodyEnabled(stay));
    }
}

TEST(WorldStep, NonFiniteBodyDoesNotTakeItsNeighboursWithIt) {
    for (SolverMode mode : {SolverMode::SoftStep, SolverMode::Classic}) {
        WorldDef def;
        def.solver.mode = mode;
        World world{def};
        addGround(world);
        BodyId below = addBox(world, {0.0f, 0.5f}, 0.5f);
        BodyId bad = addBox(world, {0.0f, 1.5f}, 0.5f);
        for (int i = 0; i < 5; ++i) {
            world.step(kStep);
        }
        // Its velocity overflows while it rests on `below`: only it is disabled and reported
        // (it used to pass NaN through the contact to the box beneath).
        world.setGravityScale(bad, 3.0e38f);
        world.step(kStep);
        ASSERT_EQ(world.nonFiniteBodies().size(), 1u) << static_cast<int>(mode);
        EXPECT_EQ(world.nonFiniteBodies()[0], bad);
        EXPECT_FALSE(world.isBodyEnabled(bad));
        EXPECT_TRUE(world.isBodyEnabled(below));
        EXPECT_NEAR(world.transform(below).p.y, 0.5f, 0.01f);
        for (int i = 0; i < 30; ++i) {
            world.step(kStep);
        }
        EXPECT_TRUE(world.isBodyEnabled(below));
        EXPECT_NEAR(world.transform(below).p.y, 0.5f, 0.01f);
    }
}

TEST(WorldStep, NonFiniteBodyBouncingOffANeighbourLeavesItFinite) {
    // A bouncy ball falls onto a box; at every step of the approach and the impact in turn,
    // its gravity scale becomes absurd. Restitution used to turn the overflowed gravity into
    // NaN impulses on the box too.
    for (int absurdAt = 0; absurdAt < 16; ++absurdAt) {
        World world;
        addGround(world);
        BodyId box = addBox(world, {0.0f, 0.5f}, 0.5f);
        BodyId ball = addBall(world, {0.0f, 2.0f}, 0.25f, 0.8f);
        world.setLinearVelocity(ball, {0.0f, -5.0f});
        for (int i = 0; i < absurdAt; ++i) {
            world.step(kStep);
        }
        world.setGravityScale(ball, 3.0e38f);
        world.step(kStep);
        ASSERT_EQ(world.nonFiniteBodies().size(), 1u) << "at step " << absurdAt;
        EXPECT_EQ(world.nonFiniteBodies()[0], ball);
        EXPECT_TRUE(world.isBodyEnabled(box)) << "at step " << absurdAt;
    }
}

TEST(WorldStep, AbsurdSpinSetOnABodyDoesNotReachItsNeighbour) {
    // Finite but absurd velocities set by hand on a bouncy ball resting on a box: the contact's
    // restitution target is computed from them before the integrator caps them; no overflowed
    // impulse may reach the box underneath.
    for (SolverMode mode : {SolverMode::SoftStep, SolverMode::Classic}) {
        for (int which = 0; which < 2; ++which) {
            WorldDef def;
            def.solver.mode = mode;
            World world{def};
            addGround(world);
            BodyId below = addBox(world, {0.0f, 0.5f}, 0.5f);
            BodyId above = addBall(world, {0.0f, 1.25f}, 0.25f, 0.8f);
            world.step(kStep); // touching, so the next step has a contact between them
            if (which == 0) {
                world.setAngularVelocity(above, 3.0e38f);
            } else {
                world.setLinearVelocity(above, {3.0e38f, -3.0e38f});
            }
            world.step(kStep);
            EXPECT_TRUE(world.isBodyEnabled(below)) << static_cast<int>(mode) << "/" << which;
            EXPECT_TRUE(isFinite(world.transform(below).p))
                << static_cast<int>(mode) << "/" << which;
            EXPECT_TRUE(isFinite(world.linearVelocity(below)))
                << static_cast<int>(mode) << "/" << which;
        }
    }
}

TEST(WorldStep, AbsurdVelocityOfAKinematicBodyGivesFiniteHitEvents) {
    // A kinematic box set moving at 3e38 m/s into a dynamic one: a contact that read the raw
    // velocity took an infinite approach speed (the dot product overflows) into its hit event
    // (the fuzzer found it). Velocities are capped before the contacts read them, as
    // integration caps them.
    for (SolverMode mode : {SolverMode::SoftStep, SolverMode::Classic}) {
        WorldDef def;
        def.gravity = {0.0f, 0.0f};
        def.solver.mode = mode;
        def.solver.hitEventThreshold = 0.0f;
        World world{def};
        BodyDef kd;
        kd.type = BodyType::Kinematic;
        BodyId mover = world.createBody(kd);
        world.createShape(mover, ShapeDef{}, Circle{{0.0f, 0.0f}, 0.5f});
        // Touching along the diagonal: dot(normal, v) of a 3e38 m/s velocity along it
        // overflows.
        BodyId target = addBall(world, {0.707f, 0.707f}, 0.5f);
        world.step(kStep); // touching: the next step starts with their contact
        world.setLinearVelocity(mover, {3.0e38f, 3.0e38f});
        world.step(kStep);
        for (const ContactHitEvent& e : world.hitEvents()) {
            EXPECT_TRUE(isFinite(e.point) && isFinite(e.normal) && std::isfinite(e.approachSpeed))
                << static_cast<int>(mode) << ": " << e.approachSpeed;
        }
        EXPECT_TRUE(world.isBodyEnabled(target)) << static_cast<int>(mode);
        EXPECT_TRUE(isFinite(world.linearVelocity(target))) << static_cast<int>(mode);
        // Capped like any body: at most maxLinearSpeed.
        EXPECT_LE(length(world.linearVelocity(mover)), def.solver.maxLinearSpeed * 1.0001f);
    }
}

TEST(WorldStep, HugeSpinKeepsAUnitRotation) {
    for (SolverMode mode : {SolverMode::SoftStep, SolverMode::Classic}) {
        WorldDef def;
        def.solver.mode = mode;
        World world{def};
        BodyId spinner = addBox(world, {0.0f, 5.0f}, 0.5f);
        // Finite but absurd: the rotation integrator used to overflow into q = (0, 0), a
        // finite transform that collapses the shapes, and nothing reported it.
        world.setAngularVelocity(spinner, 3.0e38f);
        world.step(kStep);
        Rot q = world.transform(spinner).q;
        EXPECT_NEAR(q.c * q.c + q.s * q.s, 1.0f, 1e-5f) << static_cast<int>(mode);
        // Capped at a quarter turn per integration step: (pi / 2) / h.
        float h = mode == SolverMode::SoftStep ? kStep / 4.0f : kStep;
        EXPECT_NEAR(world.angularVelocity(spinner), 0.5f * 3.14159265f / h, 1e-2f);
    }
}

TEST(WorldStep, PinnedSpeckInsideAHugeBodyStaysFinite) {
    // A 2 mm circle, locked in x and y but free to spin, deep inside a spinning 960 m circle
    // 1e16 times heavier: both in the fuzzer's ranges. Their contact normal passes through the
    // speck's centre to the last bit, so its rotation was left out of the normal's effective
    // mass, which the huge body alone set; the rounding in cross(rA, p) of that impulse (rA:
    // the ~180 m from the speck to the middle of the overlap) then spun the speck by 1e18
    // rad/s, and both bodies went non-finite (the fuzzer found it). Found by a random search of
    // such scenes; each case failed within a few steps.
    struct Case {
        SolverMode mode;
        Vec2 pin;        // the speck's body origin
        Vec2 offset;     // its circle's centre, local
        float spin;      // its angular velocity, rad/s
        float depth;     // how deep it lies inside the huge circle, metres
        float direction; // from the speck to the huge circle's centre, radians
        float speed;     // the huge body's speed towards the speck, m/s
        float hugeSpin;  // the huge body's angular velocity, rad/s
    };
    const Case cases[] = {
        {SolverMode::SoftStep,
         {5.95277691f, -9.36087608f},
         {0.00075999659f, 0.000869744457f},
         65.0879211f,
         362.536804f,
         3.25049019f,
         469.255219f,
         -22.9791737f},
        {SolverMode::SoftStep,
         {-5.13361883f, -3.16447449f},
         {-0.000310487521f, 0.000338362763f},
         -138.414307f,
         304.808533f,
         1.68463409f,
         334.679077f,
         32.7662354f},
        {SolverMode::SoftStep,
         {-4.03797436f, -2.90747738f},
         {-0.000679377583f, 0.000582433422f},
         -53.1849213f,
         350.797729f,
         5.60484076f,
         92.1571274f,
         -37.1915855f},
        {SolverMode::Classic,
         {4.47270775f, 0.862781525f},
         {0.000245522358f, 0.000161634642f},
         -11.8714752f,
         270.34433f,
         0.401989043f,
         56.6076355f,
         -26.0926952f},
        {SolverMode::Classic,
         {-5.16437483f, 4.7872057f},
         {-0.000201998278f, 0.000188973383f},
         -148.506439f,
         239.620209f,
         0.781189263f,
         482.195984f,
         -31.4690876f},
    };
    for (std::size_t k = 0; k < std::size(cases); ++k) {
        const Case& c = cases[k];
        WorldDef def;
        def.gravity = {0.0f, 0.0f};
        def.solver.mode = c.mode;
        World world{def};
        BodyDef pd;
        pd.type = BodyType::Dynamic;
        pd.position = c.pin;
        pd.angularVelocity = c.spin;
        pd.lockX = true;
        pd.lockY = true;
        BodyId speck = world.createBody(pd);
        ShapeDef sd;
        sd.density = 0.002f;
        sd.friction = 0.9f;
        world.createShape(speck, sd, Circle{c.offset, 0.002f});
        Vec2 dir{std::cos(c.direction), std::sin(c.direction)};
        BodyDef hd;
        hd.type = BodyType::Dynamic;
        hd.position = c.pin + (960.0f - c.depth) * dir;
        hd.linearVelocity = -c.speed * dir;
        hd.angularVelocity = c.hugeSpin;
        BodyId huge = world.createBody(hd);
        sd.density = 300.0f;
        world.createShape(huge, sd, Circle{{0.0f, 0.0f}, 960.0f});
        int nonFiniteAt = -1;
        for (int i = 0; i < 30 && nonFiniteAt < 0; ++i) {
            world.step(kStep);
            nonFiniteAt = world.nonFiniteBodies().empty() ? -1 : i;
        }
        EXPECT_EQ(nonFiniteAt, -1) << "case " << k;
        EXPECT_TRUE(world.isBodyEnabled(speck) && world.isBodyEnabled(huge)) << "case " << k;
        EXPECT_EQ(world.linearVelocity(speck), Vec2(0.0f, 0.0f)) << "case " << k;
    }
}

TEST(WorldStep, IslandFallsAsleepAndWakesOnImpulse) {
    World world;
    addGround(world);
    BodyId a = addBox(world, {0.0f, 0.5f}, 0.5f);
    BodyId b = addBox(world, {0.0f, 1.5f}, 0.5f);
    BodyId far = addBox(world, {10.0f, 0.5f}, 0.5f);
    int steps = 0;
    while (world.isAwake(a) && steps < 600) {
        world.step(kStep);
        ++steps;
    }
    EXPECT_FALSE(world.isAwake(a));
    EXPECT_FALSE(world.isAwake(b));
    // timeToSleep 0.5 s = 30 steps at least.
    EXPECT_GE(steps, 30);
    EXPECT_EQ(world.awakeBodyCount(), 0);
    Transform before = world.transform(b);
    world.step(kStep);
    EXPECT_EQ(world.transform(b).p, before.p); // asleep: not integrated

    world.applyLinearImpulseToCenter(a, {0.1f, 0.0f});
    EXPECT_TRUE(world.isAwake(a));
    EXPECT_TRUE(world.isAwake(b)); // the island wakes together
    EXPECT_FALSE(world.isAwake(far));
}

TEST(WorldStep, SleepCanBeDisabledPerWorldAndPerBody) {
    WorldDef def;
    def.solver.enableSleep = false;
    World noSleep{def};
    addGround(noSleep);
    BodyId box = addBox(noSleep, {0.0f, 0.5f}, 0.5f);
    World perBody;
    addGround(perBody);
    BodyId insomniac = addBox(perBody, {0.0f, 0.5f}, 0.5f);
    perBody.setSleepEnabled(insomniac, false);
    for (int i = 0; i < 120; ++i) {
        noSleep.step(kStep);
        perBody.step(kStep);
    }
    EXPECT_TRUE(noSleep.isAwake(box));
    EXPECT_TRUE(perBody.isAwake(insomniac));
}

TEST(WorldStep, SleepingBodyWakesWhenHitOrWhenItsSupportGoes) {
    World world;
    BodyId ground = addGround(world);
    BodyId box = addBox(world, {0.0f, 0.5f}, 0.5f);
    for (int i = 0; i < 60; ++i) {
        world.step(kStep);
    }
    ASSERT_FALSE(world.isAwake(box));
    BodyId falling = addBox(world, {0.0f, 3.0f}, 0.5f);
    bool woke = false;
    for (int i = 0; i < 60 && !woke; ++i) {
        world.step(kStep);
        woke = world.isAwake(box);
    }
    EXPECT_TRUE(woke);
    for (int i = 0; i < 120; ++i) {
        world.step(kStep);
    }
    ASSERT_FALSE(world.isAwake(box));
    ASSERT_FALSE(world.isAwake(falling));
    world.destroyBody(ground);
    EXPECT_TRUE(world.isAwake(box));
    world.step(kStep);
    EXPECT_LT(world.linearVelocity(box).y, 0.0f);
}

TEST(WorldStep, AStackWokenByAHitIsSolvedWholeInThatStep) {
    // The stack's own contacts come first in contact order, and the narrow phase passes them
    // while both their bodies still sleep; the falling box's contact, later, wakes the stack.
    // The solver must still get all three contacts in that step, not only the waking one.
    World world;
    addGround(world);
    BodyId lower = addBox(world, {0.0f, 0.5f}, 0.5f);
    BodyId upper = addBox(world, {0.0f, 1.5f}, 0.5f);
    for (int i = 0; i < 120; ++i) {
        world.step(kStep);
    }
    ASSERT_FALSE(world.isAwake(lower));
    ASSERT_FALSE(world.isAwake(upper));
    addBox(world, {0.0f, 4.0f}, 0.5f);
    int step = 0;
    while (!world.isAwake(lower) && step < 120) {
        world.step(kStep);
        ++step;
    }
    ASSERT_TRUE(world.isAwake(lower));
    EXPECT_EQ(world.stepCounters().contactConstraints, 3);
    EXPECT_GT(world.transform(lower).p.y, 0.49f); // held up by the ground in that step
}

TEST(WorldStep, SetTransformWakes) {
    World world;
    addGround(world);
    BodyId box = addBox(world, {0.0f, 0.5f}, 0.5f);
    for (int i = 0; i < 60; ++i) {
        world.step(kStep);
    }
    ASSERT_FALSE(world.isAwake(box));
    world.setTransform(box, {0.0f, 3.0f}, 0.0f);
    EXPECT_TRUE(world.isAwake(box));
}

TEST(WorldStep, BeginAndEndTouchEvents) {
    World world;
    addGround(world);
    BodyId box = addBox(world, {0.0f, 1.0f}, 0.5f);
    ShapeId boxShape = world.bodyShapes(box)[0];
    int begins = 0;
    int step = 0;
    for (; step < 60 && begins == 0; ++step) {
        world.step(kStep);
        begins = static_cast<int>(world.contactBeginEvents().size());
    }
    ASSERT_EQ(begins, 1);
    ContactBeginTouchEvent e = world.contactBeginEvents()[0];
    EXPECT_TRUE(e.shapeA == boxShape || e.shapeB == boxShape);
    EXPECT_GT(e.manifold.pointCount, 0);
    world.step(kStep);
    EXPECT_TRUE(world.contactBeginEvents().empty()); // reported once

    world.setTransform(box, {0.0f, 1.0f}, 0.0f); // lift 0.5 m: no longer touching
    world.step(kStep);
    ASSERT_EQ(world.contactEndEvents().size(), 1u);
    EXPECT_TRUE(world.contactEndEvents()[0].shapeA == boxShape ||
                world.contactEndEvents()[0].shapeB == boxShape);

    // Destroying a touching shape also ends its contact.
    for (int i = 0; i < 60; ++i) {
        world.step(kStep);
    }
    world.destroyShape(boxShape);
    world.step(kStep);
    EXPECT_EQ(world.contactEndEvents().size(), 1u);
}

TEST(WorldStep, SensorEventsWithoutCollision) {
    World world{WorldDef{.gravity = {0.0f, 0.0f}}};
    BodyId zone = world.createBody({});
    ShapeDef sensorDef;
    sensorDef.isSensor = true;
    ShapeId sensor = world.createShape(zone, sensorDef, makeBox(1.0f, 1.0f));
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = {-3.0f, 0.0f};
    bd.linearVelocity = {6.0f, 0.0f};
    BodyId ball = world.createBody(bd);
    ShapeId ballShape = world.createShape(ball, {}, Circle{{0.0f, 0.0f}, 0.25f});
    int begins = 0;
    int ends = 0;
    for (int i = 0; i < 90; ++i) {
        world.step(kStep);
        for (const SensorBeginTouchEvent& e : world.sensorBeginEvents()) {
            EXPECT_EQ(e.sensorShape, sensor);
            EXPECT_EQ(e.visitorShape, ballShape);
            ++begins;
        }
        for (const SensorEndTouchEvent& e : world.sensorEndEvents()) {
            EXPECT_EQ(e.sensorShape, sensor);
            ++ends;
        }
        EXPECT_TRUE(world.contactBeginEvents().empty());
    }
    EXPECT_EQ(begins, 1);
    EXPECT_EQ(ends, 1);
    // Passed straight through: a sensor is not solid.
    EXPECT_NEAR(world.linearVelocity(ball).x, 6.0f, 1e-5f);
}

TEST(WorldStep, HitEventReportsApproachSpeed) {
    World world{WorldDef{.gravity = {0.0f, 0.0f}}};
    addGround(world);
    BodyId ball = addBall(world, {0.0f, 1.0f}, 0.5f);
    world.setLinearVelocity(ball, {0.0f, -3.0f});
    bool hit = false;
    for (int i = 0; i < 30 && !hit; ++i) {
        world.step(kStep);
        for (const ContactHitEvent& e : world.hitEvents()) {
            hit = true;
            EXPECT_NEAR(e.approachSpeed, 3.0f, 1e-3f);
            EXPECT_NEAR(std::abs(e.normal.y), 1.0f, 1e-5f);
            EXPECT_NEAR(e.point.y, 0.0f, 0.02f);
        }
    }
    EXPECT_TRUE(hit);
}

std::uint64_t runPile() {
    World world;
    addGround(world);
    std::vector<BodyId> bodies;
    Random random(7);
    for (int i = 0; i < 40; ++i) {
        Vec2 p{random.uniform(-3.0f, 3.0f), 1.0f + 0.8f * static_cast<float>(i)};
        if (i % 2 == 0) {
            bodies.push_back(addBox(world, p, random.uniform(0.2f, 0.5f), 0.6f, 1.0f,
                                    random.uniform(-1.0f, 1.0f)));
        } else {
            bodies.push_back(addBall(world, p, random.uniform(0.2f, 0.5f), 0.3f));
        }
    }
    for (int i = 0; i < 1000; ++i) {
        world.step(kStep);
    }
    return transformsHash(world, bodies);
}

TEST(WorldStep, DeterministicAcrossRuns) { EXPECT_EQ(runPile(), runPile()); }

TEST(WorldStep, BulletDoesNotTunnelThroughAThinWall) {
    World world{WorldDef{.gravity = {0.0f, 0.0f}}};
    BodyId wall = world.createBody({.position = {5.0f, 0.0f}});
    world.createShape(wall, {}, makeBox(0.005f, 2.0f)); // 1 cm thick
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.linearVelocity = {500.0f, 0.0f};
    BodyId bullet = world.createBody(bd);
    world.createShape(bullet, {}, Circle{{0.0f, 0.0f}, 0.05f});
    for (int i = 0; i < 30; ++i) {
        world.step(kStep);
        ASSERT_LT(world.transform(bullet).p.x, 5.0f) << "step " << i;
    }
    EXPECT_LT(world.transform(bullet).p.x, 5.0f - 0.05f + kLinearSlop);
    EXPECT_GT(world.transform(bullet).p.x, 4.9f);
}

TEST(WorldStep, BulletStopsAtAThinMovingBodyAndAPlainFastBodyDoesNot) {
    // A 1 cm plank, dynamic (heavy, drifting) or kinematic, and a ball fired at 500 m/s: only
    // the bullet flag sweeps against moving bodies (a plain fast body sweeps against static
    // shapes only and jumps 8.3 m per step, past the plank).
    for (BodyType plankType : {BodyType::Dynamic, BodyType::Kinematic}) {
        for (bool bullet : {true, false}) {
            World world{WorldDef{.gravity = {0.0f, 0.0f}}};
            BodyDef pd;
            pd.type = plankType;
            pd.position = {5.0f, 0.0f};
            pd.linearVelocity = {0.0f, 0.1f};
            BodyId plank = world.createBody(pd);
            ShapeDef heavy;
            heavy.density = 1000.0f;
            world.createShape(plank, heavy, makeBox(0.005f, 2.0f));
            BodyDef bd;
            bd.type = BodyType::Dynamic;
            bd.isBullet = bullet;
            bd.linearVelocity = {500.0f, 0.0f};
            BodyId ball = world.createBody(bd);
            world.createShape(ball, {}, Circle{{0.0f, 0.0f}, 0.05f});
            for (int i = 0; i < 10; ++i) {
                world.step(kStep);
            }
            float x = world.transform(ball).p.x;
            if (bullet) {
                EXPECT_LT(x, world.transform(plank).p.x) << static_cast<int>(plankType);
            } else {
                EXPECT_GT(x, 10.0f) << static_cast<int>(plankType);
            }
        }
    }
}

TEST(WorldStep, KinematicBodyMovesByVelocityOnly) {
    World world;
    BodyDef bd;
    bd.type = BodyType::Kinematic;
    bd.linearVelocity = {1.0f, 0.0f};
    bd.angularVelocity = 0.5f;
    BodyId platform = world.createBody(bd);
    world.createShape(platform, {}, makeBox(2.0f, 0.25f));
    BodyId box = addBox(world, {0.0f, 0.75f}, 0.5f, 0.6f, 100.0f);
    for (int i = 0; i < 60; ++i) {
        world.step(kStep);
    }
    // No gravity, no push back from the heavy box: exactly v t and w t.
    EXPECT_NEAR(world.transform(platform).p.x, 1.0f, 1e-4f);
    EXPECT_NEAR(world.transform(platform).p.y, 0.0f, 1e-6f);
    EXPECT_NEAR(world.transform(platform).q.angle(), 0.5f, 1e-4f);
    EXPECT_EQ(world.linearVelocity(platform), Vec2(1.0f, 0.0f));
    EXPECT_TRUE(world.isAwake(box));
}

TEST(WorldStep, BothSolverModesHoldAStack) {
    for (SolverMode mode : {SolverMode::SoftStep, SolverMode::Classic}) {
        WorldDef def;
        def.solver.mode = mode;
        World world{def};
        addGround(world);
        std::vector<BodyId> boxes;
        for (int i = 0; i < 10; ++i) {
            boxes.push_back(addBox(world, {0.0f, 0.5f + static_cast<float>(i)}, 0.5f));
        }
        for (int i = 0; i < 300; ++i) {
            world.step(kStep);
        }
        Vec2 top = world.transform(boxes.back()).p;
        // Classic solves each box's two normal impulses as one 2x2 block: without it (point
        // by point) the top box drifted 4.2 cm here (13 cm at worst) before sleeping.
        EXPECT_NEAR(top.x, 0.0f, 0.01f) << static_cast<int>(mode);
        EXPECT_NEAR(top.y, 9.5f, 0.1f) << static_cast<int>(mode);
        EXPECT_LT(maxPenetration(world), 0.02f) << static_cast<int>(mode);
    }
}

TEST(WorldStep, LockedAxisKeepsItsCoordinate) {
    World world;
    addGround(world);
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = {0.0f, 3.0f};
    bd.lockY = true;
    bd.linearVelocity = {1.0f, -5.0f};
    BodyId body = world.createBody(bd);
    world.createShape(body, {}, makeBox(0.5f, 0.5f));
    for (int i = 0; i < 60; ++i) {
        world.step(kStep);
    }
    EXPECT_EQ(world.transform(body).p.y, 3.0f);
    EXPECT_NEAR(world.transform(body).p.x, 1.0f, 1e-4f);
}

} // namespace
} // namespace e2d::physics::test
