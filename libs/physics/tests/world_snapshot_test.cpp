// SPDX-License-Identifier: MIT
// World::saveSnapshot() / restoreSnapshot(): ids, sleep, every joint kind, hooks, identical
// bytes, and refusal of damaged input with the world left as it was.
#include <e2d/physics/world.hpp>

#include "joint_test_util.hpp"
#include "world_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace e2d::physics::test {
namespace {

using Bytes = std::vector<std::uint8_t>;

constexpr float kStep = 1.0f / 60.0f;

void stepWorld(World& world, int steps) {
    for (int i = 0; i < steps; ++i) {
        world.step(kStep);
    }
}

// A small world with something of everything: a ground, a chain, boxes, discs, a capsule, a
// rounded polygon, a sensor, a kinematic platform, a disabled body, a destroyed body and shape
// (free slots), and one joint of every kind.
struct Scene {
    World world;
    std::vector<BodyId> bodies;
    std::vector<JointId> joints;

    explicit Scene(const WorldDef& def = {}) : world(def) {
        BodyId ground = addStatic(world);
        world.createShape(ground, {}, Segment{{-20.0f, 0.0f}, {20.0f, 0.0f}});
        ChainDef chain;
        chain.points = {{30.0f, 2.0f}, {25.0f, 0.5f}, {20.0f, 0.0f}};
        world.createChain(ground, chain);
        bodies.push_back(ground);
        for (int i = 0; i < 4; ++i) {
            bodies.push_back(
                addPlank(world, {-6.0f, 0.5f + 1.0f * static_cast<float>(i)}, 0.5f, 0.5f));
        }
        BodyId doomed = addDisc(world, {12.0f, 3.0f}, 0.3f);
        bodies.push_back(addDisc(world, {-3.0f, 0.5f}, 0.5f));
        world.destroyBody(doomed);
        BodyDef capsuleDef;
        capsuleDef.type = BodyType::Dynamic;
        capsuleDef.position = {-1.0f, 2.0f};
        capsuleDef.angularVelocity = 2.0f;
        BodyId capsule = world.createBody(capsuleDef);
        world.createShape(capsule, {}, Capsule{{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f});
        ShapeId extra = world.createShape(capsule, {}, Circle{{0.0f, 0.5f}, 0.1f});
        world.destroyShape(extra);
        world.createShape(capsule, {}, makeRoundedBox(0.2f, 0.2f, 0.05f));
        bodies.push_back(capsule);
        ShapeDef sensorDef;
        sensorDef.isSensor = true;
        world.createShape(ground, sensorDef, makeOffsetBox(2.0f, 1.0f, {-6.0f, 1.0f}, 0.0f));
        BodyDef platformDef;
        platformDef.type = BodyType::Kinematic;
        platformDef.position = {3.0f, 1.0f};
        platformDef.linearVelocity = {0.5f, 0.0f};
        BodyId platform = world.createBody(platformDef);
        world.createShape(platform, {}, makeBox(1.0f, 0.1f));
        bodies.push_back(platform);
        BodyDef disabledDef;
        disabledDef.type = BodyType::Dynamic;
        disabledDef.enabled = false;
        disabledDef.position = {8.0f, 5.0f};
        BodyId disabled = world.createBody(disabledDef);
        world.createShape(disabled, {}, makeBox(0.3f, 0.3f));
        bodies.push_back(disabled);

        // One joint of every kind, each between a fresh body and the ground or a neighbour.
        BodyId hub = addStatic(world, {0.0f, 8.0f});
        BodyId a = addPlank(world, {1.0f, 8.0f}, 0.5f, 0.1f);
        BodyId b = addDisc(world, {3.0f, 8.0f}, 0.3f);
        BodyId c = addPlank(world, {5.0f, 8.0f}, 0.4f, 0.2f);
        BodyId d = addPlank(world, {7.0f, 8.0f}, 0.4f, 0.2f);
        BodyId e = addDisc(world, {9.0f, 7.5f}, 0.4f);
        BodyId f = addPlank(world, {11.0f, 8.0f}, 0.3f, 0.3f);
        BodyId g = addDisc(world, {13.0f, 8.0f}, 0.2f);
        for (BodyId id : {hub, a, b, c, d, e, f, g}) {
            bodies.push_back(id);
        }
        RevoluteJointDef revolute;
        revolute.bodyA = hub;
        revolute.bodyB = a;
        revolute.localAnchorB = {-1.0f, 0.0f};
        revolute.enableLimit = true;
        revolute.lowerAngle = -0.5f;
        revolute.upperAngle = 0.5f;
        revolute.enableMotor = true;
        revolute.maxMotorTorque = 5.0f;
        revolute.motorSpeed = 1.0f;
        joints.push_back(world.createJoint(revolute));
        DistanceJointDef distance;
        distance.bodyA = a;
        distance.bodyB = b;
        distance.length = 1.5f;
        distance.enableSpring = true;
        distance.hertz = 3.0f;
        distance.dampingRatio = 0.3f;
        distance.enableLimit = true;
        distance.minLength = 1.0f;
        distance.maxLength = 2.0f;
        joints.push_back(world.createJoint(distance));
        PrismaticJointDef prismatic;
        prismatic.bodyA = hub;
        prismatic.bodyB = c;
        prismatic.localAnchorA = {5.0f, 0.0f};
        prismatic.localAxisA = {0.0f, 1.0f};
        prismatic.enableLimit = true;
        prismatic.lowerTranslation = -1.0f;
        prismatic.upperTranslation = 0.5f;
        prismatic.enableMotor = true;
        prismatic.maxMotorForce = 20.0f;
        prismatic.motorSpeed = -0.5f;
        joints.push_back(world.createJoint(prismatic));
        WeldJointDef weld;
        weld.bodyA = c;
        weld.bodyB = d;
        weld.localAnchorA = {1.0f, 0.0f};
        weld.localAnchorB = {-1.0f, 0.0f};
        weld.linearHertz = 5.0f;
        weld.angularHertz = 5.0f;
        joints.push_back(world.createJoint(weld));
        WheelJointDef wheel;
        wheel.bodyA = d;
        wheel.bodyB = e;
        wheel.localAnchorA = {2.0f, -0.5f};
        wheel.enableMotor = true;
        wheel.maxMotorTorque = 3.0f;
        wheel.motorSpeed = 4.0f;
        joints.push_back(world.createJoint(wheel));
        MotorJointDef motor;
        motor.bodyA = hub;
        motor.bodyB = f;
        motor.linearOffset = {11.0f, 0.5f};
        motor.angularOffset = 0.3f;
        motor.maxForce = 50.0f;
        motor.maxTorque = 5.0f;
        joints.push_back(world.createJoint(motor));
        MouseJointDef mouse;
        mouse.bodyA = hub;
        mouse.bodyB = g;
        mouse.target = {14.0f, 9.0f};
        joints.push_back(world.createJoint(mouse));
        // A destroyed joint: a free joint slot and a stale JointId.
        DistanceJointDef gone;
        gone.bodyA = f;
        gone.bodyB = g;
        world.destroyJoint(world.createJoint(gone));
    }
};

// The reaction of every joint, bit for bit, on top of the bodies' state hash.
std::uint64_t sceneHash(const Scene& s) {
    std::uint64_t h = stateHash(s.world, s.bodies);
    for (JointId id : s.joints) {
        const Vec2 force = s.world.jointReactionForce(id);
        h = hashBits(hashBits(hashBits(h, force.x), force.y), s.world.jointReactionTorque(id));
    }
    return h;
}

// Step N, save, step M: the hash; restore (same world and a new one), step M: the same hash
// and the same bytes.
void expectRoundTrip(Scene& s, int before, int after) {
    stepWorld(s.world, before);
    const Bytes snapshot = s.world.saveSnapshot();
    stepWorld(s.world, after);
    const std::uint64_t expected = sceneHash(s);
    const Bytes expectedBytes = s.world.saveSnapshot();

    s.world.restoreSnapshot(snapshot);
    stepWorld(s.world, after);
    EXPECT_EQ(sceneHash(s), expected);
    EXPECT_EQ(s.world.saveSnapshot(), expectedBytes);

    Scene fresh;
    fresh.world.restoreSnapshot(snapshot);
    fresh.bodies = s.bodies;
    fresh.joints = s.joints;
    stepWorld(fresh.world, after);
    EXPECT_EQ(sceneHash(fresh), expected);
    EXPECT_EQ(fresh.world.saveSnapshot(), expectedBytes);
}

TEST(WorldSnapshot, EveryJointKindStepsOnBitForBit) {
    for (SolverMode mode : {SolverMode::SoftStep, SolverMode::Classic}) {
        for (JointSolver joints :
             {JointSolver::Soft, JointSolver::GaussSeidel, JointSolver::Direct}) {
            SCOPED_TRACE(static_cast<int>(mode) * 10 + static_cast<int>(joints));
            WorldDef def;
            def.solver.mode = mode;
            def.solver.jointSolver = joints;
            Scene s(def);
            expectRoundTrip(s, 45, 45);
        }
    }
}

// Recycled manifolds move from where the routine last saw the bodies: that is state too.
TEST(WorldSnapshot, RecycledContactsStepOnBitForBit) {
    WorldDef def;
    def.solver.contactRecycleDistance = 0.02f;
    def.solver.enableSleep = false; // the stack keeps recycling to the end
    Scene s(def);
    expectRoundTrip(s, 45, 45);
    EXPECT_GT(s.world.stepCounters().manifoldsRecycled, 0);
}

// Workers are how a world runs, not its state: a snapshot of a 2-worker world goes on alike in
// a 1-worker one, and the other way round.
TEST(WorldSnapshot, WorkersAreNotState) {
    WorldDef two;
    two.workerCount = 2;
    Scene s(two);
    stepWorld(s.world, 30);
    const Bytes snapshot = s.world.saveSnapshot();
    stepWorld(s.world, 30);
    const std::uint64_t expected = sceneHash(s);
    Scene one;
    one.world.restoreSnapshot(snapshot);
    one.bodies = s.bodies;
    one.joints = s.joints;
    stepWorld(one.world, 30);
    EXPECT_EQ(sceneHash(one), expected);
    const Bytes fromOne = one.world.saveSnapshot();
    s.world.restoreSnapshot(snapshot);
    stepWorld(s.world, 30);
    EXPECT_EQ(s.world.saveSnapshot(), fromOne);
}

TEST(WorldSnapshot, SaveRestoreSaveGivesTheSameBytes) {
    Scene s;
    stepWorld(s.world, 30);
    const Bytes first = s.world.saveSnapshot();
    World other;
    other.restoreSnapshot(first);
    EXPECT_EQ(other.saveSnapshot(), first);
    s.world.restoreSnapshot(first);
    EXPECT_EQ(s.world.saveSnapshot(), first);
    // Two worlds built by the same calls with the same tag save the same bytes.
    WorldDef tagged;
    tagged.tag = 7;
    Scene x(tagged);
    Scene y(tagged);
    stepWorld(x.world, 20);
    stepWorld(y.world, 20);
    EXPECT_EQ(x.world.saveSnapshot(), y.world.saveSnapshot());
}

TEST(WorldSnapshot, IdsOfTheSavedWorldStayValidAndStaleOnesStale) {
    WorldDef def;
    def.tag = 11;
    World world(def);
    const BodyId kept = addDisc(world, {0.0f, 0.0f}, 0.5f);
    const BodyId destroyed = addDisc(world, {2.0f, 0.0f}, 0.5f);
    const ShapeId shape = world.bodyShapes(kept).front();
    world.destroyBody(destroyed);
    const Bytes snapshot = world.saveSnapshot();

    // Made after the save: stale after the restore.
    const BodyId later = addDisc(world, {4.0f, 0.0f}, 0.5f);
    const BodyId reused = addDisc(world, {6.0f, 0.0f}, 0.5f);
    world.restoreSnapshot(snapshot);
    EXPECT_TRUE(world.isValid(kept));
    EXPECT_TRUE(world.isValid(shape));
    EXPECT_FALSE(world.isValid(destroyed));
    EXPECT_FALSE(world.isValid(later));
    EXPECT_FALSE(world.isValid(reused));
    EXPECT_EQ(world.bodyCount(), 1);

    // Into a world of another tag: the saved world's tag comes with the state.
    WorldDef otherDef;
    otherDef.tag = 12;
    World other(otherDef);
    const BodyId foreign = addDisc(other, {0.0f, 0.0f}, 0.5f);
    other.restoreSnapshot(snapshot);
    EXPECT_EQ(other.tag(), 11);
    EXPECT_TRUE(other.isValid(kept));
    EXPECT_EQ(other.transform(kept).p.x, 0.0f);
    EXPECT_FALSE(other.isValid(foreign));
    E2D_EXPECT_ERROR((void)other.transform(destroyed), "stale or null BodyId");

    // Replaying the calls made after the save hands out the same ids again.
    EXPECT_EQ(addDisc(other, {4.0f, 0.0f}, 0.5f), later);
    EXPECT_EQ(addDisc(other, {6.0f, 0.0f}, 0.5f), reused);
}

TEST(WorldSnapshot, SleepingBodiesAndTheirTimers) {
    World world;
    BodyId ground = addStatic(world);
    world.createShape(ground, {}, makeBox(10.0f, 0.5f));
    std::vector<BodyId> bodies{ground};
    for (int i = 0; i < 3; ++i) {
        bodies.push_back(addPlank(world, {-3.0f + 3.0f * static_cast<float>(i), 1.0f}, 0.5f, 0.5f));
    }
    // Saved with the sleep timers running (timeToSleep 0.5 s), none asleep yet.
    stepWorld(world, 20);
    for (BodyId id : bodies) {
        ASSERT_EQ(world.isAwake(id), id != ground);
    }
    const Bytes snapshot = world.saveSnapshot();
    int asleepAt = -1;
    for (int i = 0; i < 300 && asleepAt < 0; ++i) {
        world.step(kStep);
        asleepAt = world.isAwake(bodies[1]) ? -1 : i;
    }
    ASSERT_GE(asleepAt, 0) << "the boxes never fell asleep";
    stepWorld(world, 20);
    const std::uint64_t expected = stateHash(world, bodies);
    ASSERT_FALSE(world.isAwake(bodies[3]));

    World restored;
    restored.restoreSnapshot(snapshot);
    int restoredAsleepAt = -1;
    for (int i = 0; i < 300 && restoredAsleepAt < 0; ++i) {
        restored.step(kStep);
        restoredAsleepAt = restored.isAwake(bodies[1]) ? -1 : i;
    }
    EXPECT_EQ(restoredAsleepAt, asleepAt);
    stepWorld(restored, 20);
    EXPECT_EQ(stateHash(restored, bodies), expected);

    // Saved asleep, restored asleep.
    const Bytes asleep = restored.saveSnapshot();
    World again;
    again.restoreSnapshot(asleep);
    EXPECT_FALSE(again.isAwake(bodies[1]));
    EXPECT_EQ(again.awakeBodyCount(), restored.awakeBodyCount());
}

TEST(WorldSnapshot, HooksAreNotStateAndStayWithTheRestoringWorld) {
    // A one-way platform (pre-solve) and a pair filter keeping discs 1 and 2 apart.
    auto build = [](World& world, std::vector<BodyId>& bodies, int& preSolveCalls) {
        BodyId ground = addStatic(world);
        world.createShape(ground, {}, makeOffsetBox(3.0f, 0.1f, {0.0f, 1.0f}, 0.0f));
        bodies = {ground, addDisc(world, {0.0f, 0.3f}, 0.25f), addDisc(world, {0.1f, 2.0f}, 0.25f),
                  addDisc(world, {0.05f, 3.0f}, 0.25f)};
        world.setLinearVelocity(bodies[1], {0.0f, 8.0f});
        const BodyId first = bodies[1];
        const BodyId second = bodies[2];
        world.setPreSolveCallback([&world, &preSolveCalls](ShapeId, ShapeId b, const Manifold& m) {
            ++preSolveCalls;
            // Solid only for what comes from above (normal from platform up to the disc).
            return !(m.normal.y > 0.5f && world.linearVelocity(world.shapeBody(b)).y > 0.0f);
        });
        world.setPairFilterCallback([&world, first, second](ShapeId a, ShapeId b) {
            const BodyId ba = world.shapeBody(a);
            const BodyId bb = world.shapeBody(b);
            return !((ba == first && bb == second) || (ba == second && bb == first));
        });
    };
    World world;
    std::vector<BodyId> bodies;
    int calls = 0;
    build(world, bodies, calls);
    stepWorld(world, 20);
    const Bytes snapshot = world.saveSnapshot();
    stepWorld(world, 40);
    const std::uint64_t expected = stateHash(world, bodies);
    ASSERT_GT(calls, 0);

    // A world with the same hooks (its own closures) continues exactly.
    World other;
    std::vector<BodyId> otherBodies;
    int otherCalls = 0;
    build(other, otherBodies, otherCalls);
    other.restoreSnapshot(snapshot);
    otherCalls = 0;
    stepWorld(other, 40);
    EXPECT_GT(otherCalls, 0) << "the restoring world's pre-solve callback runs";
    EXPECT_EQ(stateHash(other, bodies), expected);

    // Without the hooks the same snapshot goes elsewhere: they are the caller's, not state.
    World bare;
    bare.restoreSnapshot(snapshot);
    stepWorld(bare, 40);
    EXPECT_NE(stateHash(bare, bodies), expected);
}

TEST(WorldSnapshot, NotInsideACallback) {
    World world;
    addDisc(world, {0.0f, 0.0f}, 1.0f);
    const Bytes snapshot = world.saveSnapshot();
    world.overlapAabb(Aabb{{-2.0f, -2.0f}, {2.0f, 2.0f}}, {}, [&](ShapeId) {
        E2D_EXPECT_ERROR((void)world.saveSnapshot(), "saveSnapshot(): cannot run inside");
        E2D_EXPECT_ERROR(world.restoreSnapshot(snapshot), "restoreSnapshot(): cannot run inside");
        return true;
    });
}

// --- damaged input ---

// A small stepped world's snapshot.
Bytes smallSnapshot() {
    WorldDef def;
    def.tag = 3;
    World world(def);
    BodyId ground = addStatic(world);
    world.createShape(ground, {}, makeBox(4.0f, 0.5f));
    BodyId box = addPlank(world, {0.0f, 1.1f}, 0.5f, 0.5f);
    BodyId disc = addDisc(world, {1.5f, 1.2f}, 0.4f);
    RevoluteJointDef hinge;
    hinge.bodyA = box;
    hinge.bodyB = disc;
    hinge.localAnchorA = {0.75f, 0.0f};
    world.createJoint(hinge);
    stepWorld(world, 10);
    return world.saveSnapshot();
}

// The header's length and checksum made right for the (changed) payload: the checks behind
// the checksum must catch what it no longer does.
void resealSnapshot(Bytes& bytes) {
    std::uint64_t h = kHashSeed;
    for (std::size_t i = kSnapshotHeaderBytes; i < bytes.size(); ++i) {
        h = (h ^ bytes[i]) * 1099511628211ull;
    }
    const std::uint64_t length = bytes.size() - kSnapshotHeaderBytes;
    for (int i = 0; i < 8; ++i) {
        bytes[16 + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(length >> (8 * i));
        bytes[24 + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(h >> (8 * i));
    }
}

// `world` refuses `bytes` with a core::Error from restoreSnapshot() and keeps its state.
void expectRefused(World& world, const Bytes& bytes, const Bytes& before,
                   const std::string& needle) {
    const std::string message = errorOf([&] { world.restoreSnapshot(bytes); });
    EXPECT_NE(message.find("physics::World::restoreSnapshot(): "), std::string::npos) << message;
    EXPECT_NE(message.find(needle), std::string::npos) << message;
    EXPECT_EQ(world.saveSnapshot(), before);
}

TEST(WorldSnapshot, EveryTruncationIsRefused) {
    const Bytes good = smallSnapshot();
    World world;
    addDisc(world, {5.0f, 5.0f}, 1.0f);
    const Bytes before = world.saveSnapshot();
    for (std::size_t length = 0; length < good.size(); ++length) {
        SCOPED_TRACE(length);
        const Bytes cut(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(length));
        expectRefused(world, cut, before, length < kSnapshotHeaderBytes ? "header" : "truncated");
    }
    // Cut short with the header made to match: the reader finds the end of the bytes.
    for (std::size_t length = kSnapshotHeaderBytes; length < good.size(); length += 7) {
        SCOPED_TRACE(length);
        Bytes cut(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(length));
        resealSnapshot(cut);
        expectRefused(world, cut, before, "offset ");
    }
    world.restoreSnapshot(good); // and the good one still works
}

TEST(WorldSnapshot, FlippedBytesAreRefused) {
    const Bytes good = smallSnapshot();
    World world;
    const Bytes before = world.saveSnapshot();
    for (std::size_t i = 0; i < good.size(); ++i) {
        SCOPED_TRACE(i);
        Bytes bad = good;
        bad[i] ^= 0x10;
        expectRefused(world, bad, before, "offset ");
    }
    Bytes trailing = good;
    trailing.push_back(0);
    expectRefused(world, trailing, before, "trailing bytes");
}

TEST(WorldSnapshot, OtherVersionsAndLayoutsAreRefused) {
    const Bytes good = smallSnapshot();
    World world;
    const Bytes before = world.saveSnapshot();
    Bytes newer = good;
    newer[8] = static_cast<std::uint8_t>(kSnapshotFormatVersion + 1);
    expectRefused(world, newer, before,
                  "offset 8, header.version: format version " +
                      std::to_string(kSnapshotFormatVersion + 1) + ", this build reads version " +
                      std::to_string(kSnapshotFormatVersion));
    Bytes layout = good;
    layout[12] = 4; // a build with 4-vertex polygons
    expectRefused(world, layout, before, "offset 12, header.layout");
    Bytes magic = good;
    magic[0] = 'X';
    expectRefused(world, magic, before, "offset 0, header.magic: not a physics::World snapshot");
}

// Behind a valid checksum (a snapshot written by a broken or hostile writer), every byte
// changed either is refused with a message naming a field, or gives a world that steps.
TEST(WorldSnapshot, ChangedPayloadsBehindAValidChecksumAreRefusedOrSafe) {
    const Bytes good = smallSnapshot();
    WorldDef def;
    def.tag = 9;
    World world(def);
    const Bytes before = world.saveSnapshot();
    int refused = 0;
    for (std::size_t i = kSnapshotHeaderBytes; i < good.size(); ++i) {
        for (std::uint8_t value : {std::uint8_t{0x00}, std::uint8_t{0xFF}, std::uint8_t{0x7F}}) {
            Bytes bad = good;
            if (bad[i] == value) {
                continue;
            }
            bad[i] = value;
            resealSnapshot(bad);
            World target(def);
            const std::string message = errorOf([&] { target.restoreSnapshot(bad); });
            if (message == "no error") {
                stepWorld(target, 3); // must not crash (ASan build: no bad access)
            } else {
                ++refused;
                ASSERT_NE(message.find("physics::World::restoreSnapshot(): "), std::string::npos)
                    << message;
                EXPECT_EQ(target.saveSnapshot(), before) << message;
            }
        }
    }
    EXPECT_GT(refused, 100);

    // One such refusal in full: a shape's body index out of range.
    Bytes bad = good;
    const std::string tag = "SHAP";
    const auto at = std::search(bad.begin(), bad.end(), tag.begin(), tag.end()) - bad.begin();
    // SHAP, the shape count (u32), then shape 0: geometry type (u8) and a polygon (8 * 2 + 8 * 2
    // vertices and normals, centroid, radius, count: 36 floats and ints), aabb (4), filter
    // (8 + 8 + 4), userData (8), 4 materials, then body (i32).
    const std::size_t body = static_cast<std::size_t>(at) + 4 + 4 + 1 + 36 * 4 + 16 + 20 + 8 + 16;
    bad[body] = 200;
    resealSnapshot(bad);
    expectRefused(world, bad, before, "shapes[0].body: must name a live body, got 200");
}

} // namespace
} // namespace e2d::physics::test
