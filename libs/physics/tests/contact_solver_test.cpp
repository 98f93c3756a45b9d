// SPDX-License-Identifier: MIT
// The contact solver over plain arrays: bodies against the ground plane y = 0, with manifolds
// built by hand (no narrow phase), so the solver is checked on its own.
#include "../src/body_solver.hpp"
#include "../src/contact_solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace e2d::physics::detail {
namespace {

constexpr float kDt = 1.0f / 60.0f;
constexpr float kG = 10.0f;

// One dynamic body: a box (half-extents hx, hy) or a disc (radius r, hx == 0).
struct PlaneBody {
    BodySim sim;
    BodyState state;
    float hx = 0.0f;
    float hy = 0.0f;
    float radius = 0.0f;
    Manifold cache{}; // last step's manifold against the ground, for warm starting
};

PlaneBody makeBox(Vec2 position, float hx, float hy, float density = 1.0f) {
    PlaneBody b;
    float mass = density * 4.0f * hx * hy;
    float inertia = mass * (4.0f * hx * hx + 4.0f * hy * hy) / 12.0f;
    b.sim.transform.p = position;
    b.sim.center = position;
    b.sim.invMass = {1.0f / mass, 1.0f / mass};
    b.sim.invInertia = 1.0f / inertia;
    b.hx = hx;
    b.hy = hy;
    return b;
}

PlaneBody makeDisc(Vec2 position, float radius, float density = 1.0f) {
    PlaneBody b;
    float mass = density * 3.14159265f * radius * radius;
    float inertia = 0.5f * mass * radius * radius;
    b.sim.transform.p = position;
    b.sim.center = position;
    b.sim.invMass = {1.0f / mass, 1.0f / mass};
    b.sim.invInertia = 1.0f / inertia;
    b.radius = radius;
    return b;
}

// The body's manifold against the ground (shape A, static, origin at 0): normal +y, points
// midway between the surfaces, speculative margin kSpeculativeDistance.
Manifold groundManifold(const PlaneBody& b) {
    Manifold m;
    m.normal = {0.0f, 1.0f};
    const Transform& xf = b.sim.transform;
    auto addPoint = [&](Vec2 surface, std::uint16_t id) {
        float s = surface.y;
        if (s > kSpeculativeDistance || m.pointCount == 2) {
            return;
        }
        ManifoldPoint& mp = m.points[m.pointCount++];
        mp.point = {surface.x, 0.5f * s};
        mp.anchorA = mp.point;
        mp.anchorB = mp.point - xf.p;
        mp.separation = s;
        mp.id = id;
        for (int j = 0; j < b.cache.pointCount; ++j) {
            if (b.cache.points[j].id == id) {
                mp.normalImpulse = b.cache.points[j].normalImpulse;
                mp.tangentImpulse = b.cache.points[j].tangentImpulse;
            }
        }
    };
    if (b.radius > 0.0f) {
        addPoint(xf.p - Vec2{0.0f, b.radius}, 0);
    } else {
        // The two lowest corners.
        Vec2 corners[4] = {{-b.hx, -b.hy}, {b.hx, -b.hy}, {b.hx, b.hy}, {-b.hx, b.hy}};
        int lowest = 0;
        for (int i = 1; i < 4; ++i) {
            if (transformPoint(xf, corners[i]).y < transformPoint(xf, corners[lowest]).y) {
                lowest = i;
            }
        }
        int next = (lowest + 1) % 4;
        int prev = (lowest + 3) % 4;
        int second =
            transformPoint(xf, corners[next]).y < transformPoint(xf, corners[prev]).y ? next : prev;
        addPoint(transformPoint(xf, corners[lowest]), static_cast<std::uint16_t>(lowest));
        addPoint(transformPoint(xf, corners[second]), static_cast<std::uint16_t>(second));
    }
    return m;
}

struct Harness {
    std::vector<PlaneBody> bodies;
    SolverDef def{};
    ContactMaterial material{0.6f, 0.0f, 0.0f};
    Vec2 gravity{0.0f, -kG};

    void step() {
        std::vector<BodySim> sims;
        std::vector<BodyState> states;
        std::vector<ContactConstraint> constraints;
        std::vector<Manifold> manifolds;
        ContactSoftness softness = makeContactSoftness(def, kDt);
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            PlaneBody& b = bodies[i];
            b.sim.center0 = b.sim.center;
            b.sim.rotation0 = b.sim.transform.q;
            b.state.deltaPosition = {0.0f, 0.0f};
            b.state.deltaRotation = {};
            sims.push_back(b.sim);
            states.push_back(b.state);
            Manifold m = groundManifold(b);
            manifolds.push_back(m);
            if (m.pointCount > 0) {
                ContactBodyView ground;
                ContactBodyView body{rotate(b.sim.transform.q, b.sim.localCenter),
                                     b.state.linearVelocity,
                                     b.state.angularVelocity,
                                     b.sim.invMass,
                                     b.sim.invInertia,
                                     static_cast<int>(i)};
                ContactConstraint c;
                prepareContact(c, m, ground, body, material, softness.vsStatic);
                c.pressAcceleration = -gravity.y; // normal +y
                c.contactIndex = static_cast<int>(i);
                constraints.push_back(c);
            }
        }
        SolverStep s{sims, states, constraints, gravity, kDt, &def};
        if (def.mode == SolverMode::SoftStep) {
            solveSoftStep(s);
        } else {
            solveClassic(s);
        }
        finalizePositions(sims, states);
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            bodies[i].sim = sims[i];
            bodies[i].state = states[i];
            bodies[i].cache = manifolds[i];
        }
        for (const ContactConstraint& c : constraints) {
            Manifold& m = bodies[static_cast<std::size_t>(c.contactIndex)].cache;
            for (int j = 0; j < c.pointCount; ++j) {
                m.points[j].normalImpulse = c.points[j].normalImpulse;
                m.points[j].tangentImpulse = c.points[j].tangentImpulse;
            }
        }
    }
};

TEST(Softness, MatchesTheClosedForm) {
    // omega = 2 pi 30, zeta = 10, h = 1/240: a1 = 2 zeta + h omega, a2 = h omega a1.
    float omega = 2.0f * 3.14159265f * 30.0f;
    float h = 1.0f / 240.0f;
    float a1 = 20.0f + h * omega;
    float a2 = h * omega * a1;
    Softness s = makeSoftness(30.0f, 10.0f, h);
    EXPECT_NEAR(s.biasRate, omega / a1, 1e-4f);
    EXPECT_NEAR(s.massScale, a2 / (1.0f + a2), 1e-6f);
    EXPECT_NEAR(s.impulseScale, 1.0f / (1.0f + a2), 1e-6f);
    Softness rigid = makeSoftness(0.0f, 1.0f, h);
    EXPECT_EQ(rigid.massScale, 1.0f);
    EXPECT_EQ(rigid.impulseScale, 0.0f);
}

TEST(ContactSoftness, CapsHertzAtAQuarterOfTheSubStepRate) {
    SolverDef def;
    def.contactHertz = 1000.0f;
    def.subSteps = 4;
    ContactSoftness s = makeContactSoftness(def, kDt);
    // Sub-step rate 240 Hz: capped at 60 Hz, static contacts at 120 Hz.
    Softness expected = makeSoftness(60.0f, def.contactDampingRatio, kDt / 4.0f);
    Softness expectedStatic = makeSoftness(120.0f, def.contactDampingRatio, kDt / 4.0f);
    EXPECT_FLOAT_EQ(s.dynamic.biasRate, expected.biasRate);
    EXPECT_FLOAT_EQ(s.vsStatic.biasRate, expectedStatic.biasRate);
}

TEST(PushOut, OverlapBeyondWhatTheLoadExplainsIsPushedApart) {
    // A soft contact at rest carries lambda = m h w^2 s per sub-step at overlap s (m = 1 / K: two
    // unit masses that cannot turn, m = 0.5 kg). 38 Hz, 4 sub-steps.
    const float h = kDt / 4.0f;
    const float omega = 2.0f * 3.14159265f * 38.0f;
    const Softness soft = makeSoftness(38.0f, 12.5f, h);
    ContactBodyView a;
    a.invMass = {1.0f, 1.0f};
    ContactBodyView b = a; // K = 1/m_A + 1/m_B = 2 (no rotation)
    auto manifold = [](float separation, float impulse) {
        Manifold m;
        m.normal = {0.0f, 1.0f};
        m.pointCount = 1;
        m.points[0].separation = separation;
        m.points[0].normalImpulse = impulse;
        return m;
    };
    // Shallower than the slop: never, whatever it carries.
    EXPECT_FALSE(isPushedApart(manifold(-0.9f * kLinearSlop, 0.0f), a, b, soft));
    // Spawned 4 cm deep, carrying nothing: pushed apart.
    EXPECT_TRUE(isPushedApart(manifold(-0.04f, 0.0f), a, b, soft));
    // 4 cm deep under the load that rests there: not.
    const float restImpulse = 0.5f * h * omega * omega * 0.04f;
    EXPECT_FALSE(isPushedApart(manifold(-0.04f, restImpulse), a, b, soft));
    // The margin: a load that explains 1 / kPushOutRestMargin of the overlap beyond the slop
    // still does; 80 % of that load does not.
    const float share = 0.5f * h * omega * omega * (0.04f - kLinearSlop) / kPushOutRestMargin;
    EXPECT_FALSE(isPushedApart(manifold(-0.04f, 1.01f * share), a, b, soft));
    EXPECT_TRUE(isPushedApart(manifold(-0.04f, 0.8f * share), a, b, soft));
    // A rigid contact (no softness) has nothing to push apart.
    EXPECT_FALSE(isPushedApart(manifold(-0.04f, 0.0f), a, b, makeSoftness(0.0f, 1.0f, h)));
}

TEST(IntegrateVelocities, AppliesGravityForceDampingAndSpeedCap) {
    BodySim sim;
    sim.invMass = {0.5f, 0.5f};
    sim.invInertia = 2.0f;
    sim.force = {4.0f, 0.0f};
    sim.torque = 1.0f;
    sim.linearDamping = 1.0f;
    BodyState state;
    state.linearVelocity = {1.0f, 0.0f};
    std::vector<BodySim> sims{sim};
    std::vector<BodyState> states{state};
    integrateVelocities(sims, states, {0.0f, -10.0f}, 0.5f, 400.0f);
    // v = h a + v0 / (1 + h c): x = 0.5 * 2 + 1 / 1.5, y = -5; w = h I^-1 torque = 1.
    EXPECT_NEAR(states[0].linearVelocity.x, 1.0f + 1.0f / 1.5f, 1e-6f);
    EXPECT_NEAR(states[0].linearVelocity.y, -5.0f, 1e-6f);
    EXPECT_NEAR(states[0].angularVelocity, 1.0f, 1e-6f);

    states[0].linearVelocity = {300.0f, 400.0f};
    sims[0].force = {};
    sims[0].linearDamping = 0.0f;
    integrateVelocities(sims, states, {0.0f, 0.0f}, 0.01f, 100.0f);
    EXPECT_NEAR(length(states[0].linearVelocity), 100.0f, 1e-3f);
    EXPECT_NEAR(states[0].linearVelocity.x, 60.0f, 1e-3f);
}

TEST(IntegrateVelocities, CapsTheRotationPerStepAndFlagsOverflow) {
    BodySim sim;
    sim.invMass = {1.0f, 1.0f};
    sim.invInertia = 1.0f;
    BodySim absurd = sim;
    absurd.gravityScale = 3.0e38f; // g s overflows to infinity
    std::vector<BodySim> sims{sim, absurd};
    std::vector<BodyState> states(2);
    states[0].angularVelocity = -1000.0f;
    states[1].linearVelocity = {1.0f, 2.0f};
    integrateVelocities(sims, states, {0.0f, -10.0f}, 0.01f, 400.0f);
    // A quarter turn per step at most: (pi / 2) / 0.01.
    EXPECT_NEAR(states[0].angularVelocity, -0.5f * 3.14159265f / 0.01f, 1e-3f);
    EXPECT_EQ(states[0].flags & kNonFinite, 0u);
    // The overflowed body is held still for the solver and flagged for the world.
    EXPECT_NE(states[1].flags & kNonFinite, 0u);
    EXPECT_EQ(states[1].linearVelocity, Vec2(0.0f, 0.0f));
    EXPECT_EQ(states[1].angularVelocity, 0.0f);
}

TEST(IntegrateVelocities, LockedAxisAndKinematicIgnoreGravity) {
    BodySim locked;
    locked.invMass = {0.0f, 1.0f};
    BodySim kinematic;
    std::vector<BodySim> sims{locked, kinematic};
    std::vector<BodyState> states(2);
    states[1].linearVelocity = {2.0f, 0.0f};
    integrateVelocities(sims, states, {-3.0f, -10.0f}, 0.1f, 400.0f);
    EXPECT_EQ(states[0].linearVelocity.x, 0.0f);
    EXPECT_NEAR(states[0].linearVelocity.y, -1.0f, 1e-6f);
    EXPECT_EQ(states[1].linearVelocity.x, 2.0f);
    EXPECT_EQ(states[1].linearVelocity.y, 0.0f);
}

TEST(IntegratePositions, CapsWhatTheConstraintsAddedBeforeMoving) {
    // The constraints run between integrateVelocities() and integratePositions() and may leave
    // any speed (4e7 m/s for a 2e-8 kg body in the fuzzer's tiny-body-out-of-range): no body
    // moves further than maxLinearSpeed * h, nor turns more than a quarter turn.
    std::vector<BodyState> states(2);
    states[0].linearVelocity = {3.0e7f, -4.0e7f};
    states[0].angularVelocity = 3.0e6f;
    states[1].linearVelocity = {3.0f, -4.0f}; // under the cap: moved as it is
    states[1].angularVelocity = 2.0f;
    const float h = 0.01f;
    integratePositions(states, h, 400.0f);
    EXPECT_NEAR(states[0].deltaPosition.x, 400.0f * 0.6f * h, 1e-4f);
    EXPECT_NEAR(states[0].deltaPosition.y, -400.0f * 0.8f * h, 1e-4f);
    EXPECT_NEAR(length(states[0].linearVelocity), 400.0f, 1e-2f);
    EXPECT_NEAR(states[0].angularVelocity, 0.5f * 3.14159265f / h, 1e-2f);
    EXPECT_EQ(states[1].deltaPosition, Vec2(3.0f * h, -4.0f * h));
    EXPECT_EQ(states[1].linearVelocity, Vec2(3.0f, -4.0f));
    EXPECT_EQ(states[1].angularVelocity, 2.0f);
    // The same for the bodies of one block.
    std::vector<BodyState> block(3);
    block[2].linearVelocity = {0.0f, 1.0e9f};
    const std::vector<int> indices{2};
    integratePositions(block, indices, h, 100.0f);
    EXPECT_NEAR(block[2].deltaPosition.y, 100.0f * h, 1e-4f);
}

TEST(SoftStep, BoxRestsOnTheGround) {
    Harness h;
    h.bodies.push_back(makeBox({0.0f, 0.5f}, 0.5f, 0.5f));
    for (int i = 0; i < 300; ++i) {
        h.step();
    }
    const PlaneBody& b = h.bodies[0];
    // Soft contacts hold a resting box within a slop of the surface, not moving.
    EXPECT_NEAR(b.sim.center.y, 0.5f, kLinearSlop);
    EXPECT_NEAR(b.sim.center.x, 0.0f, 1e-5f);
    EXPECT_NEAR(b.sim.transform.q.s, 0.0f, 1e-5f);
    EXPECT_LT(length(b.state.linearVelocity), 1e-3f);
    // The stored impulses carry the weight: sum = m g dt.
    float total = b.cache.points[0].normalImpulse + b.cache.points[1].normalImpulse;
    EXPECT_NEAR(total, 1.0f * kG * kDt / static_cast<float>(h.def.subSteps), 1e-3f);
}

TEST(SoftStep, SpeculativeContactStopsExactlyAtTheSurface) {
    Harness h;
    h.gravity = {0.0f, 0.0f};
    h.bodies.push_back(makeDisc({0.0f, 0.51f}, 0.5f));
    h.bodies[0].state.linearVelocity = {0.0f, -3.0f}; // would move 5 cm this step
    h.step();
    // The 1 cm gap closes and no more: the disc stops on the surface.
    EXPECT_NEAR(h.bodies[0].sim.center.y, 0.5f, 1e-4f);
    EXPECT_NEAR(h.bodies[0].state.linearVelocity.y, 0.0f, 1e-3f);
}

TEST(SoftStep, RestitutionReflectsThePreStepNormalVelocity) {
    Harness h;
    h.gravity = {0.0f, 0.0f};
    h.material.restitution = 0.5f;
    h.bodies.push_back(makeDisc({0.0f, 0.5f}, 0.5f));
    h.bodies[0].state.linearVelocity = {0.0f, -4.0f};
    h.step();
    EXPECT_NEAR(h.bodies[0].state.linearVelocity.y, 2.0f, 1e-3f);

    // Below the threshold (1 m/s) nothing bounces.
    h.bodies[0] = makeDisc({0.0f, 0.5f}, 0.5f);
    h.bodies[0].state.linearVelocity = {0.0f, -0.8f};
    h.step();
    EXPECT_NEAR(h.bodies[0].state.linearVelocity.y, 0.0f, 1e-3f);
}

TEST(SoftStep, ElasticBounceReturnsToTheDropHeight) {
    // Whatever the sub-step the impact falls in, and even when the ball arrives overlapping
    // (no speculative margin for its speed here), e = 1 brings it back to the drop height:
    // restitution keeps the integrator's invariant v^2 + 2 g s - g h v.
    Harness h;
    h.def.enableSleep = false;
    h.material.restitution = 1.0f;
    h.bodies.push_back(makeDisc({0.0f, 1.5f}, 0.5f));
    float peak = 0.0f;
    int bounces = 0;
    bool rising = false;
    for (int i = 0; i < 200; ++i) {
        h.step();
        float vy = h.bodies[0].state.linearVelocity.y;
        float bottom = h.bodies[0].sim.center.y - 0.5f;
        if (vy > 0.0f) {
            rising = true;
            peak = std::max(peak, bottom);
        } else if (rising) {
            rising = false;
            ++bounces;
            EXPECT_NEAR(peak, 1.0f, 0.01f) << "bounce " << bounces;
            peak = 0.0f;
        }
    }
    EXPECT_GE(bounces, 2);
}

TEST(SoftStep, SlidingBoxDeceleratesAtMuG) {
    Harness h;
    h.material.friction = 0.3f;
    h.bodies.push_back(makeBox({0.0f, 0.5f}, 0.5f, 0.5f));
    for (int i = 0; i < 60; ++i) {
        h.step(); // settle
    }
    h.bodies[0].state.linearVelocity = {5.0f, 0.0f};
    for (int i = 0; i < 60; ++i) {
        h.step();
    }
    // v(1 s) = 5 - mu g t = 2.
    EXPECT_NEAR(h.bodies[0].state.linearVelocity.x, 2.0f, 0.02f);
    EXPECT_NEAR(h.bodies[0].sim.transform.q.s, 0.0f, 1e-3f);
}

TEST(SoftStep, RollingResistanceSlowsARollingDisc) {
    Harness free;
    Harness resisted;
    resisted.material.rollingResistance = 0.05f;
    for (Harness* h : {&free, &resisted}) {
        h->bodies.push_back(makeDisc({0.0f, 0.5f}, 0.5f));
        h->bodies[0].state.linearVelocity = {2.0f, 0.0f};
        h->bodies[0].state.angularVelocity = -4.0f; // rolling without slipping
        for (int i = 0; i < 60; ++i) {
            h->step();
        }
    }
    EXPECT_NEAR(free.bodies[0].state.linearVelocity.x, 2.0f, 1e-3f);
    // Rolling resistance torque c m g about the contact on a disc with I_contact = 3/2 m r^2
    // gives a = c g / (3/2 r) = 0.05 * 10 / 0.75 = 0.667 m/s^2.
    EXPECT_NEAR(resisted.bodies[0].state.linearVelocity.x, 2.0f - 0.667f, 0.03f);
}

TEST(SoftStep, HeadOnElasticCollisionSwapsVelocities) {
    // Two equal discs, A moving right at 1 m/s, B left at 1 m/s, touching along x.
    SolverDef def;
    BodySim a;
    a.invMass = {1.0f, 1.0f};
    a.invInertia = 1.0f;
    a.center = {-0.5f, 0.0f};
    a.center0 = a.center;
    a.transform.p = a.center;
    BodySim b = a;
    b.center = {0.5f, 0.0f};
    b.center0 = b.center;
    b.transform.p = b.center;
    std::vector<BodySim> sims{a, b};
    std::vector<BodyState> states(2);
    states[0].linearVelocity = {1.0f, 0.0f};
    states[1].linearVelocity = {-1.0f, 0.0f};
    Manifold m;
    m.normal = {1.0f, 0.0f};
    m.pointCount = 1;
    m.points[0].anchorA = {0.5f, 0.0f};
    m.points[0].anchorB = {-0.5f, 0.0f};
    for (SolverMode mode : {SolverMode::SoftStep, SolverMode::Classic}) {
        def.mode = mode;
        std::vector<BodyState> st = states;
        std::vector<BodySim> sm = sims;
        ContactBodyView va{{}, st[0].linearVelocity, 0.0f, {1.0f, 1.0f}, 1.0f, 0};
        ContactBodyView vb{{}, st[1].linearVelocity, 0.0f, {1.0f, 1.0f}, 1.0f, 1};
        std::vector<ContactConstraint> cs(1);
        prepareContact(cs[0], m, va, vb, {0.0f, 1.0f, 0.0f}, makeContactSoftness(def, kDt).dynamic);
        SolverStep step{sm, st, cs, {0.0f, 0.0f}, kDt, &def};
        if (mode == SolverMode::SoftStep) {
            solveSoftStep(step);
        } else {
            solveClassic(step);
        }
        EXPECT_NEAR(st[0].linearVelocity.x, -1.0f, 1e-3f) << static_cast<int>(mode);
        EXPECT_NEAR(st[1].linearVelocity.x, 1.0f, 1e-3f) << static_cast<int>(mode);
        EXPECT_NEAR(st[0].linearVelocity.x + st[1].linearVelocity.x, 0.0f, 1e-5f);
    }
}

TEST(Classic, BoxRestsOnTheGround) {
    Harness h;
    h.def.mode = SolverMode::Classic;
    h.bodies.push_back(makeBox({0.0f, 0.5f}, 0.5f, 0.5f));
    for (int i = 0; i < 300; ++i) {
        h.step();
    }
    const PlaneBody& b = h.bodies[0];
    // The position iterations allow a slop of overlap.
    EXPECT_NEAR(b.sim.center.y, 0.5f, 2.0f * kLinearSlop);
    EXPECT_NEAR(b.sim.transform.q.s, 0.0f, 1e-4f);
    EXPECT_LT(length(b.state.linearVelocity), 0.02f);
}

TEST(Classic, OverlapIsCorrectedByPositionIterations) {
    Harness h;
    h.def.mode = SolverMode::Classic;
    h.gravity = {0.0f, 0.0f};
    h.bodies.push_back(makeBox({0.0f, 0.4f}, 0.5f, 0.5f)); // 10 cm deep
    for (int i = 0; i < 30; ++i) {
        h.step();
    }
    // Baumgarte 0.2 per iteration removes the overlap down to about a slop.
    EXPECT_GT(h.bodies[0].sim.center.y, 0.5f - 2.0f * kLinearSlop);
    EXPECT_LT(h.bodies[0].sim.center.y, 0.5f + kLinearSlop);
}

TEST(SoftStep, LockedAxisIsNotPushed) {
    Harness h;
    h.gravity = {0.0f, 0.0f};
    h.bodies.push_back(makeDisc({0.0f, 0.45f}, 0.5f)); // 5 cm deep
    h.bodies[0].sim.invMass.y = 0.0f;                  // y locked
    h.bodies[0].state.linearVelocity = {1.0f, 0.0f};
    for (int i = 0; i < 10; ++i) {
        h.step();
    }
    EXPECT_EQ(h.bodies[0].sim.center.y, 0.45f);
    EXPECT_NEAR(h.bodies[0].state.linearVelocity.y, 0.0f, 1e-6f);
}

// A unit-mass body (inverse inertia 1/2) on static ground, touching at rB = (-1, -1/2) and
// (1, -1/2) from its centre, normal +y, no friction: the 2-point manifold of the block tests.
// With rn = cross(r, n) = r.x = -1 and 1, K = [1 + 1/2, 1 - 1/2; 1 - 1/2, 1 + 1/2]
// = [3/2, 1/2; 1/2, 3/2].
ContactConstraint twoPointConstraint(Vec2 velocity, float angularVelocity, float invInertia) {
    Manifold m;
    m.normal = {0.0f, 1.0f};
    m.pointCount = 2;
    for (int i = 0; i < 2; ++i) {
        ManifoldPoint& mp = m.points[i];
        mp.point = {i == 0 ? -1.0f : 1.0f, 0.0f};
        mp.anchorA = mp.point;                    // ground origin at (0, 0)
        mp.anchorB = mp.point - Vec2{0.0f, 0.5f}; // body centre at (0, 0.5)
        mp.separation = 0.0f;
        mp.id = static_cast<std::uint16_t>(i);
    }
    ContactBodyView ground;
    ContactBodyView body{{0.0f, 0.0f}, velocity, angularVelocity, {1.0f, 1.0f}, invInertia, 0};
    ContactConstraint c;
    prepareContact(c, m, ground, body, {0.0f, 0.0f, 0.0f}, {});
    return c;
}

float normalVelocity(const ContactConstraint& c, const BodyState& s, int i) {
    Vec2 v = s.linearVelocity + cross(s.angularVelocity, c.points[i].anchorB);
    return dot(v, c.normal);
}

TEST(ClassicBlock, BothPointsPushSolvedExactlyInOneIteration) {
    // v = (0, -1), w = 1/4: vn = -1 + w * rn = (-5/4, -3/4). Both push, K x = -vn:
    // x = K^-1 (5/4, 3/4) = (1/2) [3/2 -1/2; -1/2 3/2] (5/4, 3/4) = (3/4, 1/4) (det K = 2).
    // Point by point, one pass would give (5/6, 2/9) and leave vn1 = 1/9.
    std::vector<ContactConstraint> cs{twoPointConstraint({0.0f, -1.0f}, 0.25f, 0.5f)};
    std::vector<BodyState> states(1);
    states[0].linearVelocity = {0.0f, -1.0f};
    states[0].angularVelocity = 0.25f;
    prepareClassic(cs, states, 1.0f);
    ASSERT_EQ(cs[0].pointCount, 2);
    EXPECT_TRUE(cs[0].blockSolve);
    solveVelocitiesClassic(cs, states, 60.0f);
    EXPECT_NEAR(cs[0].points[0].normalImpulse, 0.75f, 1e-6f);
    EXPECT_NEAR(cs[0].points[1].normalImpulse, 0.25f, 1e-6f);
    EXPECT_NEAR(normalVelocity(cs[0], states[0], 0), 0.0f, 1e-6f);
    EXPECT_NEAR(normalVelocity(cs[0], states[0], 1), 0.0f, 1e-6f);
    // v_y = -1 + (3/4 + 1/4), w = 1/4 + (1/2)(-1 * 3/4 + 1 * 1/4).
    EXPECT_NEAR(states[0].linearVelocity.y, 0.0f, 1e-6f);
    EXPECT_NEAR(states[0].angularVelocity, 0.0f, 1e-6f);
}

TEST(ClassicBlock, OnlyTheApproachingPointPushes) {
    // v = (0, -1), w = 1: vn = (-2, 0). Both pushing needs x = K^-1 (2, 0) = (3/2, -1/2) < 0;
    // the first alone: x1 = 2 / (3/2) = 4/3, then vn2 = (1/2)(4/3) = 2/3 >= 0: that case wins.
    std::vector<ContactConstraint> cs{twoPointConstraint({0.0f, -1.0f}, 1.0f, 0.5f)};
    std::vector<BodyState> states(1);
    states[0].linearVelocity = {0.0f, -1.0f};
    states[0].angularVelocity = 1.0f;
    prepareClassic(cs, states, 1.0f);
    solveVelocitiesClassic(cs, states, 60.0f);
    EXPECT_NEAR(cs[0].points[0].normalImpulse, 4.0f / 3.0f, 1e-6f);
    EXPECT_EQ(cs[0].points[1].normalImpulse, 0.0f);
    EXPECT_NEAR(normalVelocity(cs[0], states[0], 0), 0.0f, 1e-6f);
    EXPECT_NEAR(normalVelocity(cs[0], states[0], 1), 2.0f / 3.0f, 1e-6f);
}

TEST(ClassicBlock, SeparatingPointsReleaseTheirWarmStart) {
    // Moving away at 1 m/s with a warm start of (1/4, 1/4) already applied: b = vn - K x_old
    // = (1, 1) - (1/2, 1/2) >= 0, so the answer is x = 0 and vn = b = (1/2, 1/2).
    std::vector<ContactConstraint> cs{twoPointConstraint({0.0f, 1.0f}, 0.0f, 0.5f)};
    cs[0].points[0].normalImpulse = 0.25f;
    cs[0].points[1].normalImpulse = 0.25f;
    std::vector<BodyState> states(1);
    states[0].linearVelocity = {0.0f, 1.0f};
    prepareClassic(cs, states, 1.0f);
    solveVelocitiesClassic(cs, states, 60.0f);
    EXPECT_EQ(cs[0].points[0].normalImpulse, 0.0f);
    EXPECT_EQ(cs[0].points[1].normalImpulse, 0.0f);
    EXPECT_NEAR(states[0].linearVelocity.y, 0.5f, 1e-6f);
}

TEST(ClassicBlock, RedundantPointsFallBackToOne) {
    // No rotation (inverse inertia 0): K = [1 1; 1 1] is singular, so one point carries the
    // whole load, and it takes the second point's warm start with it.
    std::vector<ContactConstraint> cs{twoPointConstraint({0.0f, -1.0f}, 0.0f, 0.0f)};
    cs[0].points[0].normalImpulse = 0.125f;
    cs[0].points[1].normalImpulse = 0.375f;
    std::vector<BodyState> states(1);
    states[0].linearVelocity = {0.0f, -1.0f};
    prepareClassic(cs, states, 1.0f);
    EXPECT_FALSE(cs[0].blockSolve);
    ASSERT_EQ(cs[0].pointCount, 1);
    EXPECT_EQ(cs[0].points[0].normalImpulse, 0.5f);
    warmStartContacts(cs, states); // v_y = -1 + 1/8 + 3/8
    EXPECT_NEAR(states[0].linearVelocity.y, -0.5f, 1e-6f);
    solveVelocitiesClassic(cs, states, 60.0f);
    EXPECT_NEAR(cs[0].points[0].normalImpulse, 1.0f, 1e-6f);
    EXPECT_NEAR(states[0].linearVelocity.y, 0.0f, 1e-6f);
}

TEST(ClassicBlock, ConditionGuardAtTheThreshold) {
    // Points d apart on a body of inverse inertia i: K = [1 + i d^2/4, 1 - i d^2/4; ...],
    // det K = i d^2, k11^2 / det grows like 1 / (i d^2): close points are dropped to one.
    auto blockFor = [](float halfGap) {
        Manifold m;
        m.normal = {0.0f, 1.0f};
        m.pointCount = 2;
        m.points[0].anchorA = {-halfGap, 0.0f};
        m.points[0].anchorB = {-halfGap, -0.5f};
        m.points[1].anchorA = {halfGap, 0.0f};
        m.points[1].anchorB = {halfGap, -0.5f};
        m.points[1].id = 1;
        ContactBodyView body{{0.0f, 0.0f}, {0.0f, 0.0f}, 0.0f, {1.0f, 1.0f}, 1.0f, 0};
        std::vector<ContactConstraint> cs(1);
        prepareContact(cs[0], m, {}, body, {}, {});
        std::vector<BodyState> states(1);
        prepareClassic(cs, states, 1.0f);
        return cs[0].blockSolve;
    };
    // halfGap 0.1: k11 = 1.01, det = 0.04, ratio 25.5; halfGap 0.01: k11 ~ 1, det = 4e-4,
    // ratio ~2500 > 1000.
    EXPECT_TRUE(blockFor(0.1f));
    EXPECT_FALSE(blockFor(0.01f));
}

TEST(ClassicBlock, UnderflowingDeterminantIsNotABlock) {
    // A body that cannot translate (both axes locked) with 2.7e15 kg m^2 of inertia, on static
    // ground at two points 445 m below its centre, 3.4 mm and 62 mm to either side (a 1000 m
    // box of density 1000 the fuzzer locked): K = i [rn1^2, rn1 rn2; rn1 rn2, rn2^2], entries
    // 1e-21 to 1e-18, rank one. det K underflowed into denormals, passed the condition guard
    // as rounding garbage, and 1 / det made the inverse infinite: NaN velocities.
    auto sunkenGiant = [] {
        Manifold m;
        m.normal = {0.0f, 1.0f};
        m.pointCount = 2;
        const float side[2] = {0.0034f, -0.062f};
        for (int i = 0; i < 2; ++i) {
            ManifoldPoint& mp = m.points[i];
            mp.point = {side[i], 0.0f};
            mp.anchorA = mp.point;
            mp.anchorB = mp.point - Vec2{0.0f, 445.0f};
            mp.separation = -1.0f;
            mp.id = static_cast<std::uint16_t>(i);
        }
        // 1 m deep: the soft step pushes both points out; the spin brings the second one in.
        ContactBodyView body{{0.0f, 0.0f}, {0.0f, 0.0f}, 10.0f, {0.0f, 0.0f}, 3.75e-16f, 0};
        std::vector<ContactConstraint> cs(1);
        prepareContact(cs[0], m, {}, body, {0.5f, 0.0f, 0.0f}, makeSoftness(30.0f, 10.0f, kDt));
        return cs;
    };
    for (int classic = 0; classic < 2; ++classic) {
        std::vector<ContactConstraint> cs = sunkenGiant();
        EXPECT_FALSE(cs[0].blockSolve) << classic;
        std::vector<BodyState> states(1);
        states[0].angularVelocity = 10.0f;
        if (classic != 0) {
            prepareClassic(cs, states, 1.0f);
            warmStartContacts(cs, states);
            solveVelocitiesClassic(cs, states, 1.0f / kDt);
        } else {
            warmStartContacts(cs, states);
            solveContacts(cs, states, 1.0f / kDt, true, 3.0f);
        }
        EXPECT_TRUE(std::isfinite(states[0].angularVelocity)) << classic;
        EXPECT_EQ(states[0].linearVelocity, Vec2(0.0f, 0.0f)) << classic;
        EXPECT_TRUE(std::isfinite(cs[0].points[0].normalImpulse)) << classic;
    }
}

TEST(IntegrateRotation, AHugeAngleTurnsExactlyInsteadOfCollapsing) {
    // The first-order step q + da perp(q) overflows for a huge da; renormalising that used to
    // give q = (0, 0), a finite rotation nothing reports.
    for (float da : {1.0e20f, 3.0e38f, -1.0e30f}) {
        Rot q = integrateRotation(Rot{1.0f, 0.0f}, da);
        EXPECT_NEAR(q.c * q.c + q.s * q.s, 1.0f, 1e-5f) << da;
        EXPECT_FLOAT_EQ(q.c, std::cos(da)) << da;
        EXPECT_FLOAT_EQ(q.s, std::sin(da)) << da;
    }
    // A small one is the first-order step, renormalised, as before.
    Rot small = integrateRotation(Rot{1.0f, 0.0f}, 0.01f);
    EXPECT_FLOAT_EQ(small.s, 0.01f / std::sqrt(1.0f + 0.0001f));
    // A non-finite angle gives a non-finite rotation, which the world's check catches.
    Rot bad = integrateRotation(Rot{1.0f, 0.0f}, INFINITY);
    EXPECT_FALSE(std::isfinite(bad.c) && std::isfinite(bad.s));
}

// A unit box (mass 1, inverse inertia 6) sunk 0.2 m into the ground, frictionless, at rest,
// touching at x = -0.5 and x = 0.5: one biased solve pushes it out at the capped speed, 3 m/s.
ContactConstraint sunkenBox(const ContactSoftness& softness) {
    Manifold m;
    m.normal = {0.0f, 1.0f};
    m.pointCount = 2;
    const Vec2 center{0.0f, 0.3f};
    for (int i = 0; i < 2; ++i) {
        ManifoldPoint& mp = m.points[i];
        mp.point = {i == 0 ? -0.5f : 0.5f, -0.1f};
        mp.anchorA = mp.point;
        mp.anchorB = mp.point - center;
        mp.separation = -0.2f;
        mp.id = static_cast<std::uint16_t>(i);
    }
    ContactBodyView ground;
    ContactBodyView box{{0.0f, 0.0f}, {0.0f, 0.0f}, 0.0f, {1.0f, 1.0f}, 6.0f, 0};
    ContactConstraint c;
    prepareContact(c, m, ground, box, {0.0f, 0.0f, 0.0f}, softness.vsStatic);
    return c;
}

// One biased solve of `c` on a body at rest, points in order and reversed.
struct SolvedBothOrders {
    std::vector<ContactConstraint> forward;
    std::vector<BodyState> forwardState;
    std::vector<ContactConstraint> reversed;
    std::vector<BodyState> reversedState;
};

SolvedBothOrders solveBothPointOrders(const ContactConstraint& c, float invH) {
    SolvedBothOrders r{{c}, std::vector<BodyState>(1), {c}, std::vector<BodyState>(1)};
    solveContacts(r.forward, r.forwardState, invH, true, 3.0f, false, false);
    solveContacts(r.reversed, r.reversedState, invH, true, 3.0f, false, true);
    return r;
}

TEST(SoftStep, TouchingPairIsSolvedAsABlockWithoutOrderBias) {
    // K = [2.5 -0.5; -0.5 2.5] (1 + 6 r_i r_j with r = -0.5, 0.5); both points push:
    // x = -K^-1 (-3, -3) = (1.5, 1.5), times the mass scale. The box rises straight, and the
    // point order makes no difference at all.
    ContactSoftness softness = makeContactSoftness(SolverDef{}, kDt);
    ContactConstraint c = sunkenBox(softness);
    ASSERT_TRUE(c.blockSolve);
    EXPECT_FLOAT_EQ(c.blockK.a11, 2.5f);
    EXPECT_FLOAT_EQ(c.blockK.a12, -0.5f);
    const float invH = 4.0f / kDt;

    const auto [forward, forwardState, reversed, reversedState] = solveBothPointOrders(c, invH);

    const float s = softness.vsStatic.massScale;
    EXPECT_FLOAT_EQ(forward[0].points[0].normalImpulse, 1.5f * s);
    EXPECT_EQ(forward[0].points[0].normalImpulse, forward[0].points[1].normalImpulse);
    EXPECT_EQ(forwardState[0].angularVelocity, 0.0f);
    EXPECT_FLOAT_EQ(forwardState[0].linearVelocity.y, 3.0f * s);
    EXPECT_EQ(reversedState[0].linearVelocity.y, forwardState[0].linearVelocity.y);
    EXPECT_EQ(reversedState[0].angularVelocity, 0.0f);
    EXPECT_EQ(reversed[0].points[0].normalImpulse, forward[0].points[0].normalImpulse);
    EXPECT_EQ(reversed[0].points[1].normalImpulse, forward[0].points[1].normalImpulse);

    // Relaxing (no bias): the rigid block solution, which stops both points exactly.
    std::vector<BodyState> moving(1);
    moving[0].linearVelocity = {0.0f, -1.0f};
    moving[0].angularVelocity = 2.0f;
    std::vector<ContactConstraint> relaxed{c};
    solveContacts(relaxed, moving, invH, false, 3.0f, false, false);
    for (const ContactConstraintPoint& cp : relaxed[0].points) {
        Vec2 v = moving[0].linearVelocity + cross(moving[0].angularVelocity, cp.anchorB);
        EXPECT_NEAR(v.y, 0.0f, 1e-5f);
    }
}

TEST(SoftStep, PointByPointReversedOrderMirrorsTheOrderBias) {
    // Without the block (an ill-conditioned K, e.g. a body that cannot rotate), Gauss-Seidel
    // solves the left point first, P0 = m_n s 3 with m_n = 1 / (1 + 6 * 0.25) = 0.4 and s the
    // mass scale; that push tips the right point down by 0.5 P0, so it gets more,
    // P1 = m_n s (3 + 0.5 P0), and the box spins at w = 6 * 0.5 * (P1 - P0). Solved right
    // to left, the result is the mirror image: the solver alternates the two orders.
    ContactSoftness softness = makeContactSoftness(SolverDef{}, kDt);
    ContactConstraint c = sunkenBox(softness);
    c.blockSolve = false;
    const float invH = 4.0f / kDt;

    const auto [forward, forwardState, reversed, reversedState] = solveBothPointOrders(c, invH);

    const float s = softness.vsStatic.massScale;
    const float p0 = 0.4f * s * 3.0f;
    const float p1 = 0.4f * s * (3.0f + 0.5f * p0);
    EXPECT_NEAR(forwardState[0].angularVelocity, 3.0f * (p1 - p0), 1e-4f);
    EXPECT_NEAR(forwardState[0].linearVelocity.y, p0 + p1, 1e-4f);
    EXPECT_EQ(reversedState[0].angularVelocity, -forwardState[0].angularVelocity);
    EXPECT_EQ(reversedState[0].linearVelocity.y, forwardState[0].linearVelocity.y);
    EXPECT_EQ(reversed[0].points[0].normalImpulse, forward[0].points[1].normalImpulse);
    EXPECT_EQ(reversed[0].points[1].normalImpulse, forward[0].points[0].normalImpulse);
}

} // namespace
} // namespace e2d::physics::detail
