// SPDX-License-Identifier: MIT
// computeAabb() of a polygon takes two vertices a register on SSE2 targets: it must give what
// transforming each vertex with transformPoint() and folding them in order gives, bit for bit
// (the broad phase's boxes, and through them the pairs, depend on it).
#include <e2d/physics/geometry.hpp>

#include <glm/common.hpp>
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

namespace e2d::physics {
namespace {

// The plain loop: every vertex through transformPoint(), glm::min/max in vertex order.
Aabb referenceAabb(const Polygon& shape, const Transform& xf) {
    Vec2 lower = transformPoint(xf, shape.vertices[0]);
    Vec2 upper = lower;
    for (int i = 1; i < shape.count; ++i) {
        const Vec2 v = transformPoint(xf, shape.vertices[i]);
        lower = glm::min(lower, v);
        upper = glm::max(upper, v);
    }
    const Vec2 r{shape.radius, shape.radius};
    return {lower - r, upper + r};
}

void expectSameBits(const Aabb& got, const Aabb& want, int count) {
    EXPECT_EQ(std::memcmp(&got, &want, sizeof(Aabb)), 0)
        << count << " vertices: got (" << got.lower.x << ", " << got.lower.y << ") - ("
        << got.upper.x << ", " << got.upper.y << "), want (" << want.lower.x << ", " << want.lower.y
        << ") - (" << want.upper.x << ", " << want.upper.y << ")";
}

TEST(ComputeAabb, PolygonMatchesPerVertexTransformBitForBit) {
    std::mt19937 random(24);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (int trial = 0; trial < 2000; ++trial) {
        const int want = 3 + trial % 6; // 3..8 points on a circle: every vertex count, odd and even
        std::vector<Vec2> points;
        for (int i = 0; i < want; ++i) {
            const float angle = 6.2831853f * (static_cast<float>(i) + 0.3f * unit(random)) /
                                static_cast<float>(want);
            const float r = 1.0f + 0.2f * unit(random);
            points.push_back({r * std::cos(angle), r * std::sin(angle)});
        }
        const Polygon shape = makePolygon(points, trial % 3 == 0 ? 0.1f : 0.0f);
        const float angle = 3.14159265f * unit(random);
        const Transform xf{{100.0f * unit(random), 100.0f * unit(random)},
                           {std::cos(angle), std::sin(angle)}};
        expectSameBits(computeAabb(shape, xf), referenceAabb(shape, xf), shape.count);
        expectSameBits(computeAabb(ShapeGeometry{shape}, xf), referenceAabb(shape, xf),
                       shape.count);
    }
}

TEST(ComputeAabb, PolygonKeepsTheFirstOfEqualBounds) {
    // Bounds of +0 and -0 compare equal; the loop keeps the one it met first, and so must the
    // vector path (a translation of -0 keeps the vertices' zero signs).
    for (int count = 3; count <= 8; ++count) {
        for (int signFirst = 0; signFirst < 2; ++signFirst) {
            Polygon shape;
            shape.count = count;
            for (int i = 0; i < count; ++i) {
                const bool negative = (i % 2 == 0) == (signFirst == 0);
                const float zero = negative ? -0.0f : 0.0f;
                shape.vertices[static_cast<std::size_t>(i)] = {zero, zero};
            }
            const Transform xf{{-0.0f, -0.0f}, {1.0f, 0.0f}};
            expectSameBits(computeAabb(shape, xf), referenceAabb(shape, xf), count);
        }
    }
}

} // namespace
} // namespace e2d::physics
