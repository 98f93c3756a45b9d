// SPDX-License-Identifier: MIT
// The seeds of fuzz_snapshot (fuzz/corpus/fuzz_snapshot/, written by make_snapshot_seeds) are
// snapshots this build accepts: after a format version bump, the fuzzer would otherwise start
// from inputs that the header refuses. Regenerate them as fuzz/README.md says.
#include <e2d/physics/world.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace e2d::physics::test {
namespace {

using Bytes = std::vector<std::uint8_t>;

constexpr std::size_t kHeaderBytes = kSnapshotHeaderBytes;

Bytes readSeed(const std::string& name) {
    const std::string path = std::string(E2D_PHYSICS_SNAPSHOT_SEEDS) + "/" + name;
    std::ifstream in(path, std::ios::binary);
    EXPECT_TRUE(in) << "cannot open " << path;
    return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

class SnapshotSeeds : public ::testing::TestWithParam<const char*> {};

// <name>-whole is 0x01 then a snapshot that restores and saves back byte for byte;
// <name>-payload is an even byte then the same snapshot without its header (the fuzzer seals
// it with a valid header, which gives the same snapshot back).
TEST_P(SnapshotSeeds, AreAcceptedSnapshots) {
    const std::string name = GetParam();
    const Bytes whole = readSeed(name + "-whole");
    const Bytes payload = readSeed(name + "-payload");
    ASSERT_GT(whole.size(), 1 + kHeaderBytes);
    ASSERT_GE(payload.size(), 1u);
    EXPECT_EQ(whole[0] & 1, 1);
    EXPECT_EQ(payload[0] & 1, 0);
    const Bytes snapshot(whole.begin() + 1, whole.end());
    EXPECT_EQ(Bytes(payload.begin() + 1, payload.end()),
              Bytes(snapshot.begin() + kHeaderBytes, snapshot.end()));

    World world;
    ASSERT_NO_THROW(world.restoreSnapshot(snapshot)) << "regenerate the seeds (fuzz/README.md)";
    EXPECT_EQ(world.saveSnapshot(), snapshot);
    EXPECT_NO_THROW(world.step(1.0f / 60.0f));
}

INSTANTIATE_TEST_SUITE_P(Corpus, SnapshotSeeds,
                         ::testing::Values("empty", "resting", "asleep", "joints-chain-sensor"),
                         [](const ::testing::TestParamInfo<const char*>& param) {
                             std::string name = param.param;
                             for (char& c : name) {
                                 if (c == '-') {
                                     c = '_';
                                 }
                             }
                             return name;
                         });

} // namespace
} // namespace e2d::physics::test
