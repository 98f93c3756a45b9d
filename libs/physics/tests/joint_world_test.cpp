// SPDX-License-Identifier: MIT
// Joints in the world: lifetime, handles, validation, collideConnected, sleeping, determinism.
#include "joint_test_util.hpp"
#include "world_step_util.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <thread>
#include <vector>

namespace e2d::physics::test {
namespace {

RevoluteJointDef hinge(BodyId a, BodyId b, Vec2 anchorA = {0.0f, 0.0f},
                       Vec2 anchorB = {0.0f, 0.0f}) {
    RevoluteJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.localAnchorA = anchorA;
    def.localAnchorB = anchorB;
    return def;
}

TEST(JointWorld, DestroyedWithEitherBody) {
    World world;
    BodyId a = addStatic(world);
    BodyId b = addDisc(world, {1.0f, 0.0f}, 0.2f);
    BodyId c = addDisc(world, {2.0f, 0.0f}, 0.2f);
    JointId ab = world.createJoint(hinge(a, b, {}, {-1.0f, 0.0f}));
    JointId bc = world.createJoint(hinge(b, c, {}, {-1.0f, 0.0f}));
    JointId ac = world.createJoint(WeldJointDef{.bodyA = a, .bodyB = c});
    EXPECT_EQ(world.jointCount(), 3);
    EXPECT_EQ(world.bodyJoints(b), (std::vector<JointId>{bc, ab}));
    EXPECT_EQ(world.jointBodyA(bc), b);
    EXPECT_EQ(world.jointBodyB(bc), c);
    EXPECT_EQ(world.jointType(ac), JointType::Weld);
    world.destroyBody(b);
    EXPECT_FALSE(world.isValid(ab));
    EXPECT_FALSE(world.isValid(bc));
    EXPECT_TRUE(world.isValid(ac));
    EXPECT_EQ(world.jointCount(), 1);
    EXPECT_EQ(world.bodyJoints(a), std::vector<JointId>{ac});
    world.destroyBody(a);
    EXPECT_FALSE(world.isValid(ac));
    EXPECT_EQ(world.jointCount(), 0);
    world.step(kJointStep); // nothing left refers to them
}

TEST(JointWorld, StaleAndNullJointIdsAreErrors) {
    World world;
    BodyId a = addStatic(world);
    BodyId b = addDisc(world, {1.0f, 0.0f}, 0.2f);
    JointId j = world.createJoint(hinge(a, b));
    world.destroyJoint(j);
    EXPECT_FALSE(world.isValid(j));
    E2D_EXPECT_ERROR(
        (void)world.jointType(j),
        "physics::World::jointType(): stale or null JointId (index1 1, generation 1, world ");
    E2D_EXPECT_ERROR(world.destroyJoint(j),
                     "physics::World::destroyJoint(): stale or null JointId");
    E2D_EXPECT_ERROR((void)world.jointReactionForce(JointId{}),
                     "physics::World::jointReactionForce(): stale or null JointId (index1 0");
    // The slot is reused with a new generation: the old id stays stale.
    JointId again = world.createJoint(hinge(a, b));
    EXPECT_EQ(again.index1, j.index1);
    EXPECT_NE(again.generation, j.generation);
    EXPECT_FALSE(world.isValid(j));
    EXPECT_TRUE(world.isValid(again));
}

TEST(JointWorld, DefsAreValidatedWithFunctionFieldAndValue) {
    World world;
    BodyId a = addStatic(world);
    BodyId b = addDisc(world, {1.0f, 0.0f}, 0.2f);
    E2D_EXPECT_ERROR(world.createJoint(hinge(a, a)),
                     "physics::World::createJoint(): revolute def.bodyA and def.bodyB must differ");
    E2D_EXPECT_ERROR(world.createJoint(hinge(a, BodyId{})),
                     "physics::World::createJoint(): stale or null BodyId");
    E2D_EXPECT_ERROR(
        world.createJoint(hinge(a, addStatic(world))),
        "physics::World::createJoint(): revolute def.bodyA or def.bodyB must be dynamic");
    RevoluteJointDef r = hinge(a, b);
    r.lowerAngle = 1.0f;
    r.upperAngle = 0.5f;
    E2D_EXPECT_ERROR(world.createJoint(r), "physics::World::createJoint(): revolute def.lowerAngle "
                                           "must be <= def.upperAngle, got 1 > 0.5");
    DistanceJointDef d{.bodyA = a, .bodyB = b};
    d.length = 0.0f;
    E2D_EXPECT_ERROR(world.createJoint(d),
                     "physics::World::createJoint(): distance def.length must be >= kLinearSlop");
    d.length = 1.0f;
    d.hertz = -2.0f;
    E2D_EXPECT_ERROR(
        world.createJoint(d),
        "physics::World::createJoint(): distance def.hertz must be finite and >= 0, got -2");
    PrismaticJointDef p{.bodyA = a, .bodyB = b};
    p.localAxisA = {0.0f, 0.0f};
    E2D_EXPECT_ERROR(
        world.createJoint(p),
        "physics::World::createJoint(): prismatic def.localAxisA must be non-zero, got (0, 0)");
    MouseJointDef m{.bodyA = a, .bodyB = b};
    m.hertz = 0.0f;
    E2D_EXPECT_ERROR(world.createJoint(m),
                     "physics::World::createJoint(): mouse def.hertz must be > 0, got 0");
    MotorJointDef mo{.bodyA = a, .bodyB = b};
    mo.correctionFactor = 2.0f;
    E2D_EXPECT_ERROR(
        world.createJoint(mo),
        "physics::World::createJoint(): motor def.correctionFactor must be in [0, 1], got 2");
    WheelJointDef w{.bodyA = a, .bodyB = b};
    w.maxMotorTorque = NAN;
    E2D_EXPECT_ERROR(
        world.createJoint(w),
        "physics::World::createJoint(): wheel def.maxMotorTorque must be finite and >= 0, got nan");
    WeldJointDef we{.bodyA = a, .bodyB = b};
    we.linearHertz = INFINITY;
    E2D_EXPECT_ERROR(
        world.createJoint(we),
        "physics::World::createJoint(): weld def.linearHertz must be finite and >= 0, got inf");
    EXPECT_EQ(world.jointCount(), 0); // nothing half-made
    JointId j = world.createJoint(hinge(a, b));
    E2D_EXPECT_ERROR(world.setMouseJointTarget(j, {0.0f, 0.0f}),
                     "physics::World::setMouseJointTarget(): not supported by a revolute joint");
    E2D_EXPECT_ERROR(world.setJointLimits(j, 1.0f, -1.0f),
                     "physics::World::setJointLimits(): lower must be <= upper, got 1 > -1");
    E2D_EXPECT_ERROR(
        (void)world.jointValue(world.createJoint(we = WeldJointDef{.bodyA = a, .bodyB = b})),
        "physics::World::jointValue(): a weld joint has no angle, translation or length");
}

// Two overlapping boxes joined: no contact between them unless collideConnected.
TEST(JointWorld, CollideConnectedDecidesWhetherTheEndsCollide) {
    for (bool collide : {false, true}) {
        World world(WorldDef{.gravity = {0.0f, 0.0f}});
        BodyId a = addPlank(world, {0.0f, 0.0f}, 0.5f, 0.5f);
        BodyId b = addPlank(world, {0.6f, 0.0f}, 0.5f, 0.5f);
        world.step(kJointStep);
        ASSERT_EQ(world.contactCount(), 1);
        RevoluteJointDef def = hinge(a, b, {0.3f, 0.0f}, {-0.3f, 0.0f});
        def.collideConnected = collide;
        JointId j = world.createJoint(def);
        EXPECT_EQ(world.contactCount(), collide ? 1 : 0);
        run(world, 0.5f);
        EXPECT_EQ(world.contactCount(), collide ? 1 : 0);
        // Not colliding: the overlap stays. Colliding: they are pushed apart around the hinge.
        const float gap = world.transform(b).p.x - world.transform(a).p.x;
        if (collide) {
            // (A rigid hinge between two equal boxes holds them nearly symmetric: they part slowly.)
            EXPECT_GT(std::abs(world.transform(b).q.angle() - world.transform(a).q.angle()) + gap,
                      0.601f);
        } else {
            EXPECT_NEAR(gap, 0.6f, 1e-3f);
        }
        world.destroyJoint(j);
        world.step(kJointStep);
        EXPECT_EQ(world.contactCount(), 1) << "the pair is found again once the joint goes";
    }
}

// A chain of links hanging from a static anchor.
std::vector<BodyId> hangChain(World& world, int links, float linkLength, Vec2 top) {
    BodyId anchor = addStatic(world, top);
    std::vector<BodyId> bodies;
    BodyId prev = anchor;
    for (int i = 0; i < links; ++i) {
        Vec2 center = top + Vec2{(i + 0.5f) * linkLength, 0.0f};
        BodyId link = addPlank(world, center, 0.5f * linkLength, 0.05f);
        world.createJoint(hinge(prev, link,
                                i == 0 ? Vec2{0.0f, 0.0f} : Vec2{0.5f * linkLength, 0.0f},
                                {-0.5f * linkLength, 0.0f}));
        bodies.push_back(link);
        prev = link;
    }
    return bodies;
}

class JointScene : public JointModes {};

// A chain swings down onto a pile of boxes (contacts and joints in the same islands) the same
// way twice, bit for bit.
TEST_P(JointScene, SameRunTwiceGivesTheSameHash) {
    auto once = [&] {
        World world(worldDef());
        addGround(world);
        std::vector<BodyId> bodies = hangChain(world, 20, 0.5f, {-5.0f, 8.0f});
        for (int i = 0; i < 10; ++i) {
            bodies.push_back(addBox(
                world,
                {-2.0f + 0.45f * static_cast<float>(i % 5), 0.5f + static_cast<float>(i / 5)},
                0.2f));
        }
        run(world, 4.0f);
        return transformsHash(world, bodies);
    };
    EXPECT_EQ(once(), once());
}

// A chain released horizontally swings down; none of its joints comes apart by more than
// 2 cm at the whip (soft step; 12 cm in classic mode, which has no sub-steps) and, hanging,
// it stretches less than 1 cm over its 10 m.
TEST_P(JointScene, SwingingChainStaysTogether) {
    World world(worldDef());
    addGround(world);
    std::vector<BodyId> chain = hangChain(world, 20, 0.5f, {0.0f, 12.0f});
    float worstGap = 0.0f;
    for (int step = 0; step < 300; ++step) {
        world.step(kJointStep);
        for (BodyId link : chain) {
            for (JointId j : world.bodyJoints(link)) {
                worstGap =
                    std::max(worstGap, length(world.jointAnchorA(j) - world.jointAnchorB(j)));
            }
        }
    }
    EXPECT_LT(worstGap, GetParam() == SolverMode::SoftStep ? 0.04f : 0.12f);
}

// A chain of 20 vertical links hanging at rest. The soft step's rigid parts are springs of
// 60 Hz at the sub-step rate (joint.hpp): a joint carrying force F between effective masses
// m_eff stretches by F / (m_eff w^2), w = 2 pi 60. The top joint carries 20 links' weight on one
// link's mass, joint k below it (20 - k) weights on half a link's mass: 400 m g / (m w^2) in all.
// Classic mode (position iterations) stretches less than that, and not at all is impossible.
TEST_P(JointScene, HangingChainStretchesAsItsSoftJointsPredict) {
    WorldDef def = worldDef();
    def.solver.jointSolver = JointSolver::Soft; // Box2D v3's soft rows (the default is rigid)
    World world(def);
    BodyId anchor = addStatic(world, {0.0f, 12.0f});
    BodyId prev = anchor;
    BodyId last;
    for (int i = 0; i < 20; ++i) {
        last = addPlank(world, {0.0f, 12.0f - 0.25f - 0.5f * static_cast<float>(i)}, 0.05f, 0.25f);
        world.createJoint(
            hinge(prev, last, i == 0 ? Vec2{0.0f, 0.0f} : Vec2{0.0f, -0.25f}, {0.0f, 0.25f}));
        prev = last;
    }
    run(world, 2.0f);
    const float stretch = 2.0f - (world.transform(last).p.y - 0.25f);
    const float omega = 2.0f * kPi * 60.0f;
    const float predicted = 400.0f * 10.0f / (omega * omega);
    if (GetParam() == SolverMode::SoftStep) {
        EXPECT_NEAR(stretch, predicted, 0.1f * predicted);
    } else {
        EXPECT_GT(stretch, 0.0f);
        EXPECT_LT(stretch, predicted);
    }
    // Straight down: no sideways drift.
    EXPECT_NEAR(world.transform(last).p.x, 0.0f, 1e-3f);
}

TEST_P(JointScene, JointedBodiesSleepAndWakeTogether) {
    World world(worldDef());
    addGround(world);
    BodyId a = addBox(world, {0.0f, 0.5f}, 0.5f);
    BodyId b = addBox(world, {3.0f, 0.5f}, 0.5f);
    JointId rope = world.createJoint(DistanceJointDef{.bodyA = a, .bodyB = b, .length = 3.0f});
    run(world, 2.0f);
    EXPECT_FALSE(world.isAwake(a));
    EXPECT_FALSE(world.isAwake(b));
    // Waking one wakes the other through the joint.
    world.applyLinearImpulseToCenter(a, {0.0f, 5.0f});
    EXPECT_TRUE(world.isAwake(b));
    run(world, 3.0f);
    EXPECT_FALSE(world.isAwake(a));
    // A motor change wakes them.
    world.setJointSpring(rope, 1.0f, 0.5f);
    EXPECT_TRUE(world.isAwake(a) && world.isAwake(b));
    // Putting one to sleep sleeps the other.
    world.setAwake(b, false);
    EXPECT_FALSE(world.isAwake(a));
    // A box dropped on one wakes both.
    addBox(world, {3.0f, 3.0f}, 0.3f);
    run(world, 1.0f);
    EXPECT_TRUE(world.isAwake(a));
}

E2D_JOINT_MODES(JointScene);

} // namespace
} // namespace e2d::physics::test

namespace e2d::physics::test {
namespace {

// What a debug renderer gets: the bodies' origins, the anchors, a slider's axis and limits.
TEST(JointWorld, DebugDataDescribesEveryJointForDrawing) {
    World world(WorldDef{.gravity = {0.0f, 0.0f}});
    BodyId ground = addStatic(world, {1.0f, 2.0f});
    BodyId a = addDisc(world, {3.0f, 2.0f}, 0.2f, 1.0f, kPi / 2.0f);
    BodyId b = addDisc(world, {5.0f, 2.0f}, 0.2f);
    RevoluteJointDef r = hinge(ground, a, {1.0f, 0.0f}, {0.0f, 1.0f});
    r.enableLimit = true;
    r.lowerAngle = -0.5f;
    r.upperAngle = 0.5f;
    JointId hingeId = world.createJoint(r);
    PrismaticJointDef p{.bodyA = a, .bodyB = b, .localAnchorA = {0.0f, -1.0f}};
    p.localAxisA = {2.0f, 0.0f};
    p.enableLimit = true;
    p.lowerTranslation = -0.25f;
    p.upperTranslation = 0.75f;
    JointId sliderId = world.createJoint(p);
    JointId mouseId =
        world.createJoint(MouseJointDef{.bodyA = ground, .bodyB = b, .target = {6.0f, 7.0f}});
    world.destroyJoint(hingeId); // a hole in the slots is skipped
    hingeId = world.createJoint(r);

    const std::vector<JointDebugData> all = world.jointDebugData();
    ASSERT_EQ(all.size(), 3u);
    auto find = [&](JointId id) {
        for (const JointDebugData& d : all) {
            if (d.id == id) {
                return d;
            }
        }
        ADD_FAILURE() << "joint missing";
        return JointDebugData{};
    };
    auto near = [](Vec2 x, Vec2 y) { return length(x - y) < 1e-5f; };
    const JointDebugData h = find(hingeId);
    EXPECT_EQ(h.type, JointType::Revolute);
    EXPECT_TRUE(near(h.originA, {1.0f, 2.0f}));
    EXPECT_TRUE(near(h.originB, {3.0f, 2.0f}));
    EXPECT_TRUE(near(h.anchorA, {2.0f, 2.0f}));
    // B is turned a quarter turn: its local (0, 1) points along world -x.
    EXPECT_TRUE(near(h.anchorB, {2.0f, 2.0f}));
    EXPECT_TRUE(h.limitEnabled);
    EXPECT_EQ(h.lower, -0.5f);
    EXPECT_EQ(h.upper, 0.5f);
    EXPECT_EQ(h.axis, Vec2(0.0f, 0.0f));
    const JointDebugData s = find(sliderId);
    EXPECT_EQ(s.type, JointType::Prismatic);
    // A's local (0, -1) and axis (1, 0) turned a quarter turn: world (1, 0) and (0, 1).
    EXPECT_TRUE(near(s.anchorA, {4.0f, 2.0f}));
    EXPECT_TRUE(near(s.axis, {0.0f, 1.0f}));
    EXPECT_TRUE(near(s.anchorB, {5.0f, 2.0f}));
    EXPECT_EQ(s.lower, -0.25f);
    EXPECT_EQ(s.upper, 0.75f);
    const JointDebugData m = find(mouseId);
    EXPECT_TRUE(near(m.anchorA, {6.0f, 7.0f}));
    EXPECT_TRUE(near(m.anchorB, {5.0f, 2.0f}));
    EXPECT_FALSE(m.limitEnabled);
    // The picture follows the bodies.
    world.setTransform(b, {5.0f, 3.0f}, 0.0f);
    for (const JointDebugData& d : world.jointDebugData()) {
        if (d.id == mouseId) {
            EXPECT_TRUE(near(d.anchorB, {5.0f, 3.0f}));
            EXPECT_TRUE(near(d.originB, {5.0f, 3.0f}));
        }
    }
}

} // namespace
} // namespace e2d::physics::test

namespace e2d::physics::test {
namespace {

// The soft step's wide solver keeps its schedule (blocks of bodies, the joints of each) while
// the constraints stay the same. Two copies of a scene with joints and contacts get the same
// changes, some of which keep the number of constraints (a joint made as a contact ends, a joint
// destroyed and another made in its place, a chain link put to sleep and woken); the second copy
// also puts a far body to sleep and wakes it step after step, so it schedules every step anew.
// A kept schedule that should not have been shows as a bit difference.
TEST(JointWorld, WideScheduleKeptWithJointsMatchesANewOneEveryStep) {
    struct Scene {
        World world{WorldDef{.solver = {.enableSleep = false}}};
        std::vector<BodyId> chain;
        std::vector<BodyId> boxes;
        BodyId far;
        BodyId floater; // weightless, touching nothing: in no block of contacts
        JointId extra;
        std::vector<BodyId> all;
    };
    auto build = [](Scene& s) {
        addGround(s.world);
        s.chain = hangChain(s.world, 8, 0.5f, {-6.0f, 5.0f});
        for (int i = 0; i < 4; ++i) {
            s.boxes.push_back(addBox(s.world, {2.0f * static_cast<float>(i), 0.5f}, 0.5f));
        }
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        bd.gravityScale = 0.0f;
        bd.position = {60.0f, 60.0f};
        s.far = s.world.createBody(bd);
        s.world.createShape(s.far, {}, makeBox(0.5f, 0.5f));
        bd.position = {1.0f, 4.0f};
        s.floater = s.world.createBody(bd);
        s.world.createShape(s.floater, {}, makeBox(0.25f, 0.25f));
        s.all = s.chain;
        s.all.insert(s.all.end(), s.boxes.begin(), s.boxes.end());
        s.all.push_back(s.floater);
    };
    auto change = [](Scene& s, int step) {
        World& w = s.world;
        switch (step) {
        case 20: // box 3 onto box 2 (a contact with the ground ends, one with box 2 begins)
            w.setTransform(s.boxes[3], {4.0f, 1.5f}, 0.0f);
            break;
        case 40: // box 0 holds the floater on a rod: a joint across two blocks, same contacts
            s.extra = w.createJoint(
                DistanceJointDef{.bodyA = s.boxes[0], .bodyB = s.floater, .length = 3.5f});
            break;
        case 60: // the rod goes, a rod from box 1 takes its place
            w.destroyJoint(s.extra);
            s.extra = w.createJoint(
                DistanceJointDef{.bodyA = s.boxes[1], .bodyB = s.floater, .length = 3.5f});
            break;
        case 80:
            w.setAwake(s.chain[3], false);
            break; // the whole chain sleeps
        case 90:
            w.setAwake(s.chain[7], true);
            break; // and wakes through its joints
        case 100:
            w.destroyBody(s.boxes[1]);
            s.boxes.erase(s.boxes.begin() + 1);
            break;
        default:
            break;
        }
        s.all = s.chain;
        s.all.insert(s.all.end(), s.boxes.begin(), s.boxes.end());
        s.all.push_back(s.floater);
    };
    Scene kept;
    Scene fresh;
    build(kept);
    build(fresh);
    for (int i = 0; i < 150; ++i) {
        change(kept, i);
        change(fresh, i);
        fresh.world.setAwake(fresh.far, i % 2 != 0);
        kept.world.step(kJointStep);
        fresh.world.step(kJointStep);
        ASSERT_EQ(transformsHash(kept.world, kept.all), transformsHash(fresh.world, fresh.all))
            << "step " << i;
    }
    EXPECT_NEAR(kept.world.transform(kept.boxes[2]).p.y, 1.5f, 0.05f);
}

// The step keeps its joints' levels, order and groups while the joints with a moving side,
// their bodies and their kinds stay the same (StepCounters::jointRepacks 0), and refreshes the
// kept groups' lanes from the prepared joints. Two copies of a net of plain hinges, a chain
// and a few boxes get the same changes (a hinge gets a motor and loses it, a hinge destroyed
// and made again in its place, the chain put to sleep and woken, a box destroyed); the second
// copy also puts a far pendulum to sleep and wakes it step after step, so it sorts and packs
// its joints every step. A kept order or lane that should not have been shows as a bit
// difference in the bodies or the reactions. Param: 0 soft step (wide solver), 1 soft step
// with rolling resistance (scalar solver), 2 classic, 3 and 4 the soft step with the joint
// models GaussSeidel and Soft (0 and 1 run the default, Direct: its solve and its position
// passes go by connected group of joints in slot order, so the pendulum's sleep changes
// nothing for the net or the chain).
class JointOrderKept : public ::testing::TestWithParam<int> {};

TEST_P(JointOrderKept, MatchesANewOneEveryStep) {
    struct Scene {
        World world;
        std::vector<BodyId> net;
        std::vector<JointId> netJoints;
        std::vector<BodyId> chain;
        std::vector<BodyId> boxes;
        BodyId pendulum;
        JointId remade;
        std::vector<BodyId> all;
        std::vector<JointId> joints;
        int repackSteps = 0;
    };
    const int config = GetParam();
    auto build = [&](Scene& s) {
        WorldDef def;
        def.solver.enableSleep = false;
        def.solver.mode = config == 2 ? SolverMode::Classic : SolverMode::SoftStep;
        if (config >= 3) { // the soft step's other joint models (the default is Direct)
            def.solver.jointSolver = config == 3 ? JointSolver::GaussSeidel : JointSolver::Soft;
        }
        s.world = World(def);
        addGround(s.world);
        // A net of 4 x 12 discs hanging from its top corners: levels of many plain hinges.
        constexpr int kRows = 4;
        constexpr int kCols = 12;
        for (int r = 0; r < kRows; ++r) {
            for (int c = 0; c < kCols; ++c) {
                s.net.push_back(addDisc(
                    s.world,
                    {-12.0f + 0.5f * static_cast<float>(c), 9.0f - 0.5f * static_cast<float>(r)},
                    0.2f));
                const BodyId b = s.net.back();
                if (c > 0) {
                    s.netJoints.push_back(s.world.createJoint(
                        hinge(s.net[s.net.size() - 2], b, {0.25f, 0.0f}, {-0.25f, 0.0f})));
                }
                if (r > 0) {
                    s.netJoints.push_back(s.world.createJoint(
                        hinge(s.net[s.net.size() - 1 - kCols], b, {0.0f, -0.25f}, {0.0f, 0.25f})));
                }
            }
        }
        s.netJoints.push_back(
            s.world.createJoint(hinge(addStatic(s.world, {-12.0f, 9.0f}), s.net.front())));
        s.netJoints.push_back(s.world.createJoint(
            hinge(addStatic(s.world, {-12.0f + 0.5f * (kCols - 1), 9.0f}), s.net[kCols - 1])));
        s.chain = hangChain(s.world, 8, 0.5f, {2.0f, 5.0f});
        for (int i = 0; i < 3; ++i) {
            s.boxes.push_back(addBox(s.world, {5.0f + 1.5f * static_cast<float>(i), 0.5f}, 0.5f));
        }
        if (config == 1) {
            // Rolling resistance on a resting ball: the scalar solver.
            BodyDef bd;
            bd.type = BodyType::Dynamic;
            bd.position = {-3.0f, 0.5f};
            const BodyId ball = s.world.createBody(bd);
            ShapeDef sd;
            sd.rollingResistance = 0.1f;
            s.world.createShape(ball, sd, Circle{{0.0f, 0.0f}, 0.5f});
            s.boxes.push_back(ball);
        }
        s.pendulum = addDisc(s.world, {61.0f, 60.0f}, 0.2f);
        s.world.createJoint(
            hinge(addStatic(s.world, {60.0f, 60.0f}), s.pendulum, {}, {-1.0f, 0.0f}));
    };
    auto collect = [](Scene& s) {
        s.all = s.net;
        s.all.insert(s.all.end(), s.chain.begin(), s.chain.end());
        s.all.insert(s.all.end(), s.boxes.begin(), s.boxes.end());
        s.joints = s.netJoints;
        for (BodyId link : s.chain) {
            for (JointId j : s.world.bodyJoints(link)) {
                if (std::find(s.joints.begin(), s.joints.end(), j) == s.joints.end()) {
                    s.joints.push_back(j);
                }
            }
        }
    };
    auto change = [&](Scene& s, int step) {
        World& w = s.world;
        switch (step) {
        case 20:
            w.enableJointMotor(s.netJoints[7], true);
            break; // no longer a plain hinge
        case 35:
            w.enableJointMotor(s.netJoints[7], false);
            break;
        case 50: { // the chain's third hinge made again: the same slot, bodies and kind
            const JointId old = w.bodyJoints(s.chain[2]).back();
            const BodyId a = w.jointBodyA(old);
            const BodyId b = w.jointBodyB(old);
            w.destroyJoint(old);
            s.remade = w.createJoint(hinge(a, b, {0.25f, 0.0f}, {-0.25f, 0.0f}));
            break;
        }
        case 70:
            w.setAwake(s.chain[3], false);
            break; // the whole chain sleeps
        case 85:
            w.setAwake(s.chain[7], true);
            break; // and wakes through its joints
        case 100:
            w.destroyBody(s.boxes[1]);
            s.boxes.erase(s.boxes.begin() + 1);
            break;
        default:
            break;
        }
        collect(s);
    };
    auto reactions = [](const Scene& s) {
        std::vector<float> r;
        for (JointId j : s.joints) {
            const Vec2 f = s.world.jointReactionForce(j);
            r.insert(r.end(), {f.x, f.y, s.world.jointReactionTorque(j)});
        }
        return r;
    };
    Scene kept;
    Scene fresh;
    build(kept);
    build(fresh);
    for (int i = 0; i < 150; ++i) {
        change(kept, i);
        change(fresh, i);
        fresh.world.setAwake(fresh.pendulum, i % 2 != 0);
        kept.world.step(kJointStep);
        fresh.world.step(kJointStep);
        kept.repackSteps += kept.world.stepCounters().jointRepacks > 0 ? 1 : 0;
        fresh.repackSteps += fresh.world.stepCounters().jointRepacks > 0 ? 1 : 0;
        ASSERT_EQ(transformsHash(kept.world, kept.all), transformsHash(fresh.world, fresh.all))
            << "step " << i;
        const std::vector<float> a = reactions(kept);
        const std::vector<float> b = reactions(fresh);
        ASSERT_EQ(a.size(), b.size());
        ASSERT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0) << "step " << i;
    }
    // The changes (and the chain's sleep) repack a few steps; the far pendulum every one.
    EXPECT_LE(kept.repackSteps, 10);
    EXPECT_GE(kept.repackSteps, 4);
    EXPECT_EQ(fresh.repackSteps, 150);
    // The net hangs, still joined: its corners' neighbours stay within a few cm of 0.5 m.
    const float gap =
        length(kept.world.transform(kept.net[1]).p - kept.world.transform(kept.net[0]).p);
    EXPECT_NEAR(gap, 0.5f, 0.05f);
}

INSTANTIATE_TEST_SUITE_P(Solvers, JointOrderKept, ::testing::Values(0, 1, 2, 3, 4));

// Worlds with joints stepped on several threads at once match one stepped alone, bit for bit.
TEST(JointWorld, WorldsWithJointsOnSeveralThreadsMatchRunningAlone) {
    auto once = [] {
        World world;
        addGround(world);
        std::vector<BodyId> bodies = hangChain(world, 30, 0.4f, {-6.0f, 10.0f});
        for (int i = 0; i < 12; ++i) {
            bodies.push_back(addBox(
                world, {-3.0f + 0.5f * static_cast<float>(i % 6), 0.5f + static_cast<float>(i / 6)},
                0.2f));
        }
        run(world, 3.0f);
        return transformsHash(world, bodies);
    };
    const std::uint64_t alone = once();
    std::uint64_t results[3] = {0, 0, 0};
    std::vector<std::thread> threads;
    for (int t = 0; t < 3; ++t) {
        threads.emplace_back([t, &results, &once] { results[t] = once(); });
    }
    for (std::thread& th : threads) {
        th.join();
    }
    for (std::uint64_t r : results) {
        EXPECT_EQ(r, alone);
    }
}

} // namespace
} // namespace e2d::physics::test
