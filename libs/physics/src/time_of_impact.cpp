// SPDX-License-Identifier: MIT
#include <e2d/physics/time_of_impact.hpp>

#include "gjk.hpp"

#include <algorithm>
#include <cmath>

namespace e2d::physics {

namespace {

// The rotation from q1 to q2 is the shortest one; Rot::angle() returns it in [-pi, pi].
float sweepAngle(const Sweep& sweep) { return invMulRot(sweep.q1, sweep.q2).angle(); }

Transform sweepTransformAt(const Sweep& sweep, float angle, float t) {
    Transform xf;
    xf.q = mulRot(sweep.q1, Rot::fromAngle(t * angle));
    Vec2 center = sweep.c1 + t * (sweep.c2 - sweep.c1);
    xf.p = center - rotate(xf.q, sweep.localCenter);
    return xf;
}

float farthestPoint(const ShapeProxy& proxy, Vec2 center) {
    float result = 0.0f;
    for (int i = 0; i < proxy.count; ++i) {
        result = std::fmax(result, distanceSquared(proxy.points[i], center));
    }
    return std::sqrt(result);
}

} // namespace

Transform sweepTransform(const Sweep& sweep, float t) {
    return sweepTransformAt(sweep, sweepAngle(sweep), t);
}

TOIOutput timeOfImpact(const TOIInput& input) {
    TOIOutput output;
    float tMax = std::clamp(input.maxFraction, 0.0f, 1.0f);
    float totalRadius = input.proxyA.radius + input.proxyB.radius;
    float target = std::fmax(kLinearSlop, totalRadius - kLinearSlop);
    float tolerance = 0.25f * kLinearSlop;

    float angleA = sweepAngle(input.sweepA);
    float angleB = sweepAngle(input.sweepB);
    // Largest speed any core point gets from rotation, per unit t.
    float spin = std::fabs(angleA) * farthestPoint(input.proxyA, input.sweepA.localCenter) +
                 std::fabs(angleB) * farthestPoint(input.proxyB, input.sweepB.localCenter);
    Vec2 relativeMove = (input.sweepA.c2 - input.sweepA.c1) - (input.sweepB.c2 - input.sweepB.c1);

    DistanceInput distanceInput;
    distanceInput.proxyA = input.proxyA;
    distanceInput.proxyB = input.proxyB;
    distanceInput.useRadii = false;
    SimplexCache cache;

    float t = 0.0f;
    for (int iteration = 0; iteration < kMaxToiIterations; ++iteration) {
        distanceInput.transformA = sweepTransformAt(input.sweepA, angleA, t);
        distanceInput.transformB = sweepTransformAt(input.sweepB, angleB, t);
        DistanceOutput d = shapeDistance(distanceInput, &cache);
        output.iterations = iteration + 1;

        if (iteration == 0 && d.distance <= detail::kGjkTouching) {
            output.state = TOIState::Overlapped;
            output.fraction = 0.0f;
            return output;
        }
        if (d.distance < target + tolerance) {
            output.state = TOIState::Hit;
            output.fraction = t;
            return output;
        }
        // Along the fixed axis n, the gap between the shapes' projections shrinks no faster
        // than this; the distance is at least that gap, so stepping by (d - target) / closing
        // cannot reach closer than the target.
        float closing = dot(relativeMove, d.normal) + spin;
        if (closing <= 0.0f) {
            output.state = TOIState::Separated;
            output.fraction = tMax;
            return output;
        }
        t += (d.distance - target) / closing;
        if (t >= tMax) {
            output.state = TOIState::Separated;
            output.fraction = tMax;
            return output;
        }
    }
    output.state = TOIState::Failed;
    output.fraction = t;
    return output;
}

} // namespace e2d::physics
