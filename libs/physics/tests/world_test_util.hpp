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

#define E2D_EXPECT_ERROR(statement, needle)                                                       \
    EXPECT_PRED_FORMAT2(::testing::IsSubstring, needle,                                           \
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

/// A hash of the bodies' transforms, bit for bit (FNV-1a over the four floats' bits).
inline std::uint64_t transformsHash(const World& world, const std::vector<BodyId>& bodies) {
    std::uint64_t h = 1469598103934665603ull;
    for (BodyId id : bodies) {
        Transform xf = world.transform(id);
        float values[4] = {xf.p.x, xf.p.y, xf.q.c, xf.q.s};
        std::uint32_t bits[4];
        std::memcpy(bits, values, sizeof(bits));
        for (std::uint32_t b : bits) {
            h = (h ^ b) * 1099511628211ull;
        }
    }
    return h;
}

} // namespace e2d::physics::test
