// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/error.hpp>
#include <e2d/physics/distance.hpp>
#include <e2d/physics/manifold.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>

namespace e2d::physics::test {

inline constexpr float kPi = std::numbers::pi_v<float>;

// Runs `f` and returns the core::Error message it threw ("" if it threw nothing).
template <class F>
std::string errorMessage(F&& f) {
    try {
        f();
    } catch (const core::Error& e) {
        return e.what();
    }
    return {};
}

inline Transform makeTransform(float x, float y, float angle) {
    return {{x, y}, Rot::fromAngle(angle)};
}
inline Transform at(float x, float y, float angle = 0.0f) { return makeTransform(x, y, angle); }

// A GJK/EPA query of two proxies at two transforms.
inline DistanceInput pair(const ShapeProxy& a, const Transform& xfA, const ShapeProxy& b,
                          const Transform& xfB, bool useRadii = true) {
    DistanceInput input;
    input.proxyA = a;
    input.proxyB = b;
    input.transformA = xfA;
    input.transformB = xfB;
    input.useRadii = useRadii;
    return input;
}

// Fixed-seed random numbers for the property tests, mapped by hand so every standard library
// draws the same values.
class TestRandom {
public:
    explicit TestRandom(unsigned seed) : engine_(seed) {}
    float uniform(float lo, float hi) {
        return lo + (hi - lo) * static_cast<float>(engine_() - engine_.min()) /
                        static_cast<float>(engine_.max() - engine_.min());
    }
    int index(int n) { return static_cast<int>(engine_() % static_cast<unsigned>(n)); }

private:
    std::mt19937 engine_;
};

// Two manifolds equal bit for bit, the unused second point included (the SSE paths against
// their scalar paths); `pair` names the case in the failure message.
inline void expectSameManifoldBits(const Manifold& simd, const Manifold& scalar, int pair) {
    ASSERT_EQ(simd.pointCount, scalar.pointCount) << "pair " << pair;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(simd.normal),
              std::bit_cast<std::uint64_t>(scalar.normal))
        << "pair " << pair;
    for (int i = 0; i < 2; ++i) {
        const ManifoldPoint& p = simd.points[i];
        const ManifoldPoint& q = scalar.points[i];
        EXPECT_EQ(p.id, q.id) << "pair " << pair;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(p.point), std::bit_cast<std::uint64_t>(q.point))
            << "pair " << pair;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(p.anchorA), std::bit_cast<std::uint64_t>(q.anchorA))
            << "pair " << pair;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(p.anchorB), std::bit_cast<std::uint64_t>(q.anchorB))
            << "pair " << pair;
        EXPECT_EQ(std::bit_cast<std::uint32_t>(p.separation),
                  std::bit_cast<std::uint32_t>(q.separation))
            << "pair " << pair;
    }
}

#define E2D_EXPECT_VEC2_NEAR(actual, ex, ey, tol)                                                  \
    do {                                                                                           \
        const ::e2d::physics::Vec2 e2dActual_ = (actual);                                          \
        EXPECT_NEAR(e2dActual_.x, (ex), (tol)) << #actual ".x";                                    \
        EXPECT_NEAR(e2dActual_.y, (ey), (tol)) << #actual ".y";                                    \
    } while (false)

// The anchors of every point must match the point and the two transforms.
inline void expectAnchorsConsistent(const Manifold& m, const Transform& xfA, const Transform& xfB) {
    for (int i = 0; i < m.pointCount; ++i) {
        const ManifoldPoint& mp = m.points[i];
        E2D_EXPECT_VEC2_NEAR(mp.anchorA, mp.point.x - xfA.p.x, mp.point.y - xfA.p.y, 1e-5f);
        E2D_EXPECT_VEC2_NEAR(mp.anchorB, mp.point.x - xfB.p.x, mp.point.y - xfB.p.y, 1e-5f);
    }
}

} // namespace e2d::physics::test
