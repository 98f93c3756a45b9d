// SPDX-License-Identifier: MIT
// World::restoreSnapshot() on arbitrary bytes. The first byte picks how the rest is used:
// odd, as a whole snapshot (header and all: the header's checks and the checksum are what
// stop it); even, as a payload that gets a valid header and checksum around it, so the
// reader and the consistency checks behind the checksum see every mutation. Either the
// restore throws core::Error (and the world keeps its state: its snapshot is unchanged), or
// it succeeds, saving again gives the same bytes, and the world steps without fault (ASan and
// UBSan watch). Anything else aborts.
#include <e2d/core/error.hpp>
#include <e2d/physics/world.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

using namespace e2d::physics;

void check(bool condition, int line = __builtin_LINE()) {
    if (!condition) {
        std::fprintf(stderr, "fuzz_snapshot.cpp:%d: check failed\n", line);
        std::abort();
    }
}

void put(std::vector<std::uint8_t>& bytes, std::uint64_t value, int width) {
    for (int i = 0; i < width; ++i) {
        bytes.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
    }
}

// The header World::saveSnapshot() writes (see world_snapshot.cpp) around `payload`.
std::vector<std::uint8_t> sealed(const std::uint8_t* payload, std::size_t size) {
    std::vector<std::uint8_t> bytes{'E', '2', 'D', 'S', 'N', 'A', 'P', '\0'};
    put(bytes, kSnapshotFormatVersion, 4);
    put(bytes, static_cast<std::uint32_t>(kMaxPolygonVertices) | (4u << 8) | (4u << 16), 4);
    put(bytes, size, 8);
    std::uint64_t h = 1469598103934665603ull;
    for (std::size_t i = 0; i < size; ++i) {
        h = (h ^ payload[i]) * 1099511628211ull;
    }
    put(bytes, h, 8);
    bytes.insert(bytes.end(), payload, payload + size);
    return bytes;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) {
        return 0;
    }
    const std::vector<std::uint8_t> input = (data[0] & 1) != 0
                                                ? std::vector<std::uint8_t>(data + 1, data + size)
                                                : sealed(data + 1, size - 1);

    World world;
    const BodyId body = world.createBody({});
    const std::vector<std::uint8_t> before = world.saveSnapshot();
    try {
        world.restoreSnapshot(input);
    } catch (const e2d::core::Error&) {
        check(world.saveSnapshot() == before);
        check(world.isValid(body));
        return 0;
    }
    // Accepted: the state is exactly the bytes, and it steps.
    check(world.saveSnapshot() == input);
    try {
        for (int i = 0; i < 3; ++i) {
            world.step(1.0f / 60.0f);
        }
        (void)world.saveSnapshot();
    } catch (const e2d::core::Error& e) {
        std::fprintf(stderr, "an accepted snapshot failed to step: %s\n", e.what());
        std::abort();
    }
    return 0;
}
