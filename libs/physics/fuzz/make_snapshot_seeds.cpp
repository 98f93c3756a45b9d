// SPDX-License-Identifier: MIT
// Writes the seeds of fuzz_snapshot (corpus/fuzz_snapshot/): four small worlds, each saved
// with World::saveSnapshot() and written twice, as the fuzzer reads its input:
//   <name>-whole    0x01, then the whole snapshot (header and all);
//   <name>-payload  0x00, then the snapshot without its 32-byte header (the fuzzer seals it
//                   with a valid header and checksum).
// Run it again whenever kSnapshotFormatVersion changes: older seeds are refused at the header.
//   make_snapshot_seeds <directory>
// Each snapshot is checked to restore into a fresh world before it is written.
#include <e2d/core/error.hpp>
#include <e2d/physics/world.hpp>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace {

using namespace e2d::physics;
using Bytes = std::vector<std::uint8_t>;

constexpr std::size_t kHeaderBytes = kSnapshotHeaderBytes;
constexpr float kStep = 1.0f / 60.0f;

// A fixed world tag: otherwise every world gets one derived at run time, which the snapshot
// holds, and the seeds would differ from run to run.
WorldDef seedDef() {
    WorldDef def;
    def.tag = 1;
    return def;
}

void stepWorld(World& world, int steps) {
    for (int i = 0; i < steps; ++i) {
        world.step(kStep);
    }
}

BodyId addGround(World& world) {
    const BodyId ground = world.createBody({});
    world.createShape(ground, {}, makeOffsetBox(4.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    return ground;
}

BodyId addBox(World& world, Vec2 position, float half) {
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = position;
    const BodyId body = world.createBody(def);
    world.createShape(body, {}, makeBox(half, half));
    return body;
}

void addHinge(World& world, BodyId a, BodyId b, Vec2 anchorA, Vec2 anchorB) {
    RevoluteJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.localAnchorA = anchorA;
    def.localAnchorB = anchorB;
    world.createJoint(def);
}

// Three boxes on the ground, stepped until their contacts carry impulses; with contact
// recycling on and sleep off, some manifolds are recycled (their origins are in the snapshot).
Bytes resting() {
    WorldDef def = seedDef();
    def.solver.contactRecycleDistance = 0.02f;
    def.solver.enableSleep = false;
    World world(def);
    addGround(world);
    for (int i = 0; i < 3; ++i) {
        addBox(world, {-1.5f + 1.5f * static_cast<float>(i), 0.5f}, 0.5f);
    }
    stepWorld(world, 40);
    if (world.stepCounters().manifoldsRecycled == 0) {
        throw e2d::core::Error("make_snapshot_seeds: resting: no manifold was recycled");
    }
    return world.saveSnapshot();
}

// A stack of three boxes left to fall asleep.
Bytes asleep() {
    World world(seedDef());
    addGround(world);
    std::vector<BodyId> pile;
    for (int i = 0; i < 3; ++i) {
        pile.push_back(addBox(world, {0.0f, 0.5f + 1.0f * static_cast<float>(i)}, 0.5f));
    }
    for (int i = 0; i < 600 && world.isAwake(pile.front()); ++i) {
        world.step(kStep);
    }
    for (BodyId body : pile) {
        if (world.isAwake(body)) {
            throw e2d::core::Error("make_snapshot_seeds: asleep: the pile did not fall asleep");
        }
    }
    return world.saveSnapshot();
}

// A chain ground with a sensor on it, a pendulum of two links (revolute joints) and a disc
// tied to the ground by a distance joint, stepped a little.
Bytes jointsChainSensor() {
    World world(seedDef());
    const BodyId ground = world.createBody({});
    ChainDef chain;
    chain.points = {{-4.0f, 1.0f}, {-2.0f, 0.0f}, {2.0f, 0.0f}, {4.0f, 1.0f}};
    world.createChain(ground, chain);
    ShapeDef sensor;
    sensor.isSensor = true;
    world.createShape(ground, sensor, makeOffsetBox(1.0f, 0.5f, {0.0f, 0.5f}, 0.0f));

    const BodyId first = addBox(world, {1.0f, 4.0f}, 0.25f);
    const BodyId second = addBox(world, {2.0f, 4.0f}, 0.25f);
    addHinge(world, ground, first, {0.0f, 4.0f}, {-1.0f, 0.0f});
    addHinge(world, first, second, {0.5f, 0.0f}, {-0.5f, 0.0f});

    BodyDef discDef;
    discDef.type = BodyType::Dynamic;
    discDef.position = {-1.0f, 1.0f};
    const BodyId disc = world.createBody(discDef);
    world.createShape(disc, {}, Circle{{0.0f, 0.0f}, 0.3f});
    DistanceJointDef rope;
    rope.bodyA = ground;
    rope.bodyB = disc;
    rope.localAnchorA = {-1.0f, 3.0f};
    rope.length = 2.0f;
    world.createJoint(rope);

    stepWorld(world, 20);
    return world.saveSnapshot();
}

void writeFile(const std::string& path, std::uint8_t first, const std::uint8_t* data,
               std::size_t size) {
    std::ofstream out(path, std::ios::binary);
    out.put(static_cast<char>(first));
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) {
        throw e2d::core::Error("make_snapshot_seeds: cannot write '" + path + "'");
    }
}

void writeSeeds(const std::string& directory, const std::string& name, const Bytes& snapshot) {
    World check;
    check.restoreSnapshot(snapshot); // throws if this build refuses its own snapshot
    writeFile(directory + "/" + name + "-whole", 0x01, snapshot.data(), snapshot.size());
    writeFile(directory + "/" + name + "-payload", 0x00, snapshot.data() + kHeaderBytes,
              snapshot.size() - kHeaderBytes);
    std::printf("%s: %zu bytes\n", name.c_str(), snapshot.size());
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s <directory>\n", argv[0]);
        return 2;
    }
    const std::string directory = argv[1];
    try {
        writeSeeds(directory, "empty", World(seedDef()).saveSnapshot());
        writeSeeds(directory, "resting", resting());
        writeSeeds(directory, "asleep", asleep());
        writeSeeds(directory, "joints-chain-sensor", jointsChainSensor());
    } catch (const e2d::core::Error& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
