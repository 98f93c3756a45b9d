// SPDX-License-Identifier: MIT
#include "gjk.hpp"

#include <algorithm>

namespace e2d::physics {

CastOutput shapeCast(const ShapeCastPairInput& input) {
    // In A's frame only B moves, by a pure translation.
    Transform relative = invMulTransforms(input.transformA, input.transformB);
    Vec2 translation = invRotate(input.transformA.q, input.translationB);
    std::array<Vec2, kMaxPolygonVertices> startB;
    std::array<Vec2, kMaxPolygonVertices> pointsB;
    for (int i = 0; i < input.proxyB.count; ++i) {
        startB[i] = transformPoint(relative, input.proxyB.points[i]);
    }
    detail::PointSet setA{input.proxyA.points.data(), input.proxyA.count};
    detail::PointSet setB{pointsB.data(), input.proxyB.count};
    float rA = input.proxyA.radius;
    float radius = rA + input.proxyB.radius;
    float maxFraction = std::clamp(input.maxFraction, 0.0f, 1.0f);

    CastOutput output;
    SimplexCache cache;
    float t = 0.0f;
    // Landing exactly on the contact leaves no distance to take a direction from; the normal of
    // the step that got there is the contact normal.
    Vec2 lastNormal{0.0f, 0.0f};
    for (int iteration = 0; iteration < kMaxShapeCastIterations; ++iteration) {
        for (int i = 0; i < input.proxyB.count; ++i) {
            pointsB[i] = startB[i] + t * translation;
        }
        detail::GjkResult gjk = detail::runGjk(setA, setB, &cache);
        output.iterations = iteration + 1;
        float gap = gjk.distance - radius;
        bool coresApart = gjk.simplex.count < 3 && gjk.distance > detail::kGjkTouching;
        Vec2 normal = coresApart ? (gjk.pointB - gjk.pointA) * (1.0f / gjk.distance) : lastNormal;
        lastNormal = normal;
        if (gap < kShapeCastTolerance) {
            output.hit = true;
            output.fraction = t;
            output.normal = rotate(input.transformA.q, normal);
            output.point = transformPoint(input.transformA, gjk.pointA + rA * normal);
            return output;
        }
        // Closing speed along the normal, per unit fraction; B never passes A when it moves by
        // the gap divided by this.
        float closing = -dot(translation, normal);
        if (closing <= 0.0f) {
            return output;
        }
        t += gap / closing;
        if (t > maxFraction) {
            return output;
        }
    }
    output.fraction = t; // no convergence: how far B is known to move freely
    return output;
}

} // namespace e2d::physics
