// SPDX-License-Identifier: MIT
// detail::localToWorld(), which every polygon and capsule routine ends with: its SSE2 path must
// give, bit for bit, what the field-by-field definition gives (world point, anchors, separation,
// zero impulses, id, flag; a one-point manifold's second point all zero), signed zeros included.
#include <e2d/physics/manifold.hpp>

#include "geometry_test_util.hpp"
#include "manifold_detail.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>

namespace e2d::physics {
namespace {

using Rng = test::TestRandom;

// The definition: rotate the local point by A's rotation (the anchor from A's origin), then
// add A's position (the world point) or A's minus B's position (the anchor from B's origin).
ManifoldPoint expectedPoint(Vec2 local, float separation, std::uint16_t id, const Transform& xfA,
                            const Transform& xfB) {
    ManifoldPoint p;
    p.anchorA = rotate(xfA.q, local);
    p.point = p.anchorA + xfA.p;
    p.anchorB = p.anchorA + (xfA.p - xfB.p);
    p.separation = separation;
    p.id = id;
    return p;
}

std::uint32_t bits(float f) { return std::bit_cast<std::uint32_t>(f); }

void expectSame(const ManifoldPoint& got, const ManifoldPoint& want, int index) {
    SCOPED_TRACE(index);
    EXPECT_EQ(bits(got.point.x), bits(want.point.x));
    EXPECT_EQ(bits(got.point.y), bits(want.point.y));
    EXPECT_EQ(bits(got.anchorA.x), bits(want.anchorA.x));
    EXPECT_EQ(bits(got.anchorA.y), bits(want.anchorA.y));
    EXPECT_EQ(bits(got.anchorB.x), bits(want.anchorB.x));
    EXPECT_EQ(bits(got.anchorB.y), bits(want.anchorB.y));
    EXPECT_EQ(bits(got.separation), bits(want.separation));
    EXPECT_EQ(bits(got.normalImpulse), bits(0.0f));
    EXPECT_EQ(bits(got.tangentImpulse), bits(0.0f));
    EXPECT_EQ(got.id, want.id);
    EXPECT_FALSE(got.persisted);
}

TEST(ManifoldDetail, LocalToWorldMatchesItsDefinitionBitForBit) {
    Rng rng(20261127u);
    for (int trial = 0; trial < 2000; ++trial) {
        SCOPED_TRACE(trial);
        // Far origins and zero coordinates (signed zeros) among ordinary ones.
        auto coordinate = [&](float range) {
            const int kind = rng.index(8);
            return kind == 0 ? 0.0f : kind == 1 ? -0.0f : rng.uniform(-range, range);
        };
        const Transform xfA{{coordinate(500.0f), coordinate(500.0f)},
                            Rot::fromAngle(rng.uniform(-3.2f, 3.2f))};
        const Transform xfB{{coordinate(500.0f), coordinate(500.0f)},
                            Rot::fromAngle(rng.uniform(-3.2f, 3.2f))};
        detail::LocalManifold local;
        local.count = 1 + rng.index(2);
        local.normal = Vec2{coordinate(1.0f), coordinate(1.0f)};
        for (int i = 0; i < local.count; ++i) {
            local.points[i] = {coordinate(3.0f), coordinate(3.0f)};
            local.separations[i] = coordinate(0.1f);
            local.ids[i] = static_cast<std::uint16_t>(rng.index(0x10000));
        }
        const Manifold m = detail::localToWorld(local, xfA, xfB);
        ASSERT_EQ(m.pointCount, local.count);
        const Vec2 normal = rotate(xfA.q, local.normal);
        EXPECT_EQ(bits(m.normal.x), bits(normal.x));
        EXPECT_EQ(bits(m.normal.y), bits(normal.y));
        for (int i = 0; i < local.count; ++i) {
            expectSame(m.points[i],
                       expectedPoint(local.points[i], local.separations[i], local.ids[i], xfA, xfB),
                       i);
        }
        if (local.count == 1) {
            expectSame(m.points[1], ManifoldPoint{}, 1);
        }
    }
}

TEST(ManifoldDetail, LocalToWorldOfNoPointsIsEmpty) {
    detail::LocalManifold local;
    local.count = 0;
    const Manifold m = detail::localToWorld(local, test::at(1.0f, 2.0f, 0.3f), test::at(-4, 5));
    EXPECT_EQ(m.pointCount, 0);
    EXPECT_EQ(m.normal.x, 0.0f);
    EXPECT_EQ(m.points[0].separation, 0.0f);
}

} // namespace
} // namespace e2d::physics
