// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/error.hpp>
#include <e2d/physics/world.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

// Helpers shared by the world_*_test.cpp files.
namespace e2d::physics::test {

/// The message of the core::Error that `f` throws, or "no error".
template <class F>
std::string errorOf(F&& f) {
    try {
        f();
    } catch (const core::Error& e) {
        return e.what();
    }
    return "no error";
}

#define E2D_EXPECT_ERROR(statement, needle)                                                        \
    EXPECT_PRED_FORMAT2(::testing::IsSubstring, needle,                                            \
                        ::e2d::physics::test::errorOf([&] { statement; }))

/// Uniform floats from a fixed-seed engine, mapped by hand so that results do not depend on
/// the standard library's distributions.
class Random {
public:
    explicit Random(std::uint32_t seed) : engine_(seed) {}
    /// In [lo, hi).
    float uniform(float lo, float hi) {
        double unit = static_cast<double>(engine_()) / 4294967296.0;
        return lo + static_cast<float>(unit) * (hi - lo);
    }
    /// In [0, n).
    int below(int n) { return static_cast<int>(engine_() % static_cast<std::uint32_t>(n)); }

private:
    std::mt19937 engine_;
};

/// FNV-1a step over a float's bits (one 32-bit word at a time).
inline std::uint64_t hashBits(std::uint64_t h, float value) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, sizeof(bits));
    return (h ^ bits) * 1099511628211ull;
}

inline constexpr std::uint64_t kHashSeed = 1469598103934665603ull;

/// A hash of the bodies' transforms, bit for bit (FNV-1a over the four floats' bits).
inline std::uint64_t transformsHash(const World& world, const std::vector<BodyId>& bodies) {
    std::uint64_t h = kHashSeed;
    for (BodyId id : bodies) {
        Transform xf = world.transform(id);
        for (float v : {xf.p.x, xf.p.y, xf.q.c, xf.q.s}) {
            h = hashBits(h, v);
        }
    }
    return h;
}

/// transformsHash() with the bodies' velocities and awake flags, the world's contact, pair and
/// awake counts and every touching contact's impulses: two worlds that agree on it are in
/// the same state as far as stepping shows.
inline std::uint64_t stateHash(const World& world, const std::vector<BodyId>& bodies) {
    std::uint64_t h = transformsHash(world, bodies);
    for (BodyId id : bodies) {
        const Vec2 v = world.linearVelocity(id);
        h = hashBits(hashBits(hashBits(h, v.x), v.y), world.angularVelocity(id));
        h = (h ^ (world.isAwake(id) ? 1u : 0u)) * 1099511628211ull;
    }
    for (int count : {world.contactCount(), world.candidatePairCount(), world.awakeBodyCount()}) {
        h = (h ^ static_cast<std::uint32_t>(count)) * 1099511628211ull;
    }
    world.forEachTouchingContact([&](const ContactData& c) {
        for (int i = 0; i < c.manifold->pointCount; ++i) {
            h = hashBits(hashBits(h, c.manifold->points[i].normalImpulse),
                         c.manifold->points[i].tangentImpulse);
        }
    });
    return h;
}

} // namespace e2d::physics::test
