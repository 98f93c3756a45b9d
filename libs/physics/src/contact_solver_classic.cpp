// SPDX-License-Identifier: MIT
// The classic contact solver (the Box2D 2.4 recipe): restitution targets, velocity iterations
// with friction before the normal impulse, and non-linear Gauss-Seidel position iterations.
#include "contact_solver.hpp"
#include "contact_solver_common.hpp"

#include <algorithm>
#include <cmath>

namespace e2d::physics::detail {

void prepareClassic(std::span<ContactConstraint> constraints, std::span<BodyState> states,
                    float restitutionThreshold) {
    BodyState dummyA;
    BodyState dummyB;
    for (ContactConstraint& c : constraints) {
        auto [sa, sb] = statesOf(c, states, dummyA, dummyB);
        for (int i = 0; i < c.pointCount; ++i) {
            ContactConstraintPoint& cp = c.points[i];
            float s = currentSeparation(c, cp, *sa, *sb);
            if (s > 0.0f) {
                // Speculative: velocityBias is set per solve from the gap; a bounce, if the gap
                // closes this step, comes from applyRestitution() afterwards.
                continue;
            }
            // Touching points bounce through velocityBias; applyRestitution() skips them.
            if (cp.relativeVelocity < -restitutionThreshold) {
                cp.velocityBias = -c.restitution * cp.relativeVelocity;
            }
        }
        if (c.pointCount == 2 && !c.blockSolve) {
            // The two rows are (nearly) the same constraint, e.g. a body that cannot rotate
            // (see prepareBlock()): one point carries the load. Its warm start takes the
            // dropped point's impulse so the total stays.
            c.points[0].normalImpulse += c.points[1].normalImpulse;
            c.points[0].tangentImpulse += c.points[1].tangentImpulse;
            c.points[1].normalImpulse = 0.0f;
            c.points[1].tangentImpulse = 0.0f;
            c.pointCount = 1;
        }
    }
}

namespace {

// Target normal velocity of a point: close a speculative gap within the step, otherwise the
// restitution bias. The velocity iterations move no body: the separation is the one at the
// start of the step (from the states' position residuals, see BodyState::deltaPosition).
inline float normalTarget(const ContactConstraint& c, const ContactConstraintPoint& cp,
                          const BodyState& a, const BodyState& b, float invDt) {
    float s = currentSeparation(c, cp, a, b);
    return s > 0.0f ? -s * invDt : cp.velocityBias;
}

} // namespace

void solveVelocitiesClassic(std::span<ContactConstraint> constraints, std::span<BodyState> states,
                            float invDt) {
    BodyState dummyA;
    BodyState dummyB;
    for (ContactConstraint& c : constraints) {
        auto [sa, sb] = statesOf(c, states, dummyA, dummyB);
        Vec2 vA = sa->linearVelocity;
        float wA = sa->angularVelocity;
        Vec2 vB = sb->linearVelocity;
        float wB = sb->angularVelocity;
        Vec2 normal = c.normal;
        Vec2 tangent = rightPerp(normal);
        Vec2 mA = c.invMassA;
        Vec2 mB = c.invMassB;
        float iA = c.invInertiaA;
        float iB = c.invInertiaB;

        // Friction first, as Box2D 2.4 does: the normal impulse then has the last word.
        solveFriction(c, tangent, vA, wA, vB, wB);

        if (c.blockSolve) {
            ContactConstraintPoint& cp1 = c.points[0];
            ContactConstraintPoint& cp2 = c.points[1];
            Vec2 dv1 = (vB + cross(wB, cp1.anchorB)) - (vA + cross(wA, cp1.anchorA));
            Vec2 dv2 = (vB + cross(wB, cp2.anchorB)) - (vA + cross(wA, cp2.anchorA));
            Vec2 vn{dot(dv1, normal) - normalTarget(c, cp1, *sa, *sb, invDt),
                    dot(dv2, normal) - normalTarget(c, cp2, *sa, *sb, invDt)};
            Vec2 old{cp1.normalImpulse, cp2.normalImpulse};
            Vec2 x = old;
            solveBlock(c, old, vn, x);
            applyBlock(c, old, x, vA, wA, vB, wB);
        } else {
            for (int i = 0; i < c.pointCount; ++i) {
                ContactConstraintPoint& cp = c.points[i];
                Vec2 rA = cp.anchorA;
                Vec2 rB = cp.anchorB;
                Vec2 dv = (vB + cross(wB, rB)) - (vA + cross(wA, rA));
                float vn = dot(dv, normal);
                float impulse = -cp.normalMass * (vn - normalTarget(c, cp, *sa, *sb, invDt));
                float newImpulse = std::max(cp.normalImpulse + impulse, 0.0f);
                impulse = newImpulse - cp.normalImpulse;
                cp.normalImpulse = newImpulse;
                cp.maxNormalImpulse = std::max(cp.maxNormalImpulse, impulse);
                Vec2 p = impulse * normal;
                vA -= scale(mA, p);
                wA -= iA * cross(rA, p);
                vB += scale(mB, p);
                wB += iB * cross(rB, p);
            }
        }

        sa->linearVelocity = vA;
        sa->angularVelocity = wA;
        sb->linearVelocity = vB;
        sb->angularVelocity = wB;
    }
}

float solvePositionsClassic(std::span<ContactConstraint> constraints, std::span<BodyState> states,
                            float allowedPenetration, float bias) {
    constexpr float kMaxCorrection = 0.2f;
    float minSeparation = 0.0f;
    BodyState dummyA;
    BodyState dummyB;
    for (ContactConstraint& c : constraints) {
        auto [sa, sb] = statesOf(c, states, dummyA, dummyB);
        Vec2 normal = c.normal;
        for (int i = 0; i < c.pointCount; ++i) {
            const ContactConstraintPoint& cp = c.points[i];
            Vec2 prA = rotate(sa->deltaRotation, cp.anchorA);
            Vec2 prB = rotate(sb->deltaRotation, cp.anchorB);
            float s = dot((sb->deltaPosition - sa->deltaPosition) + (prB - prA), normal) +
                      cp.baseSeparation;
            minSeparation = std::min(minSeparation, s);
            float correction = std::clamp(bias * (s + allowedPenetration), -kMaxCorrection, 0.0f);
            float k = effectiveMass(normal, prA, prB, c);
            float impulse = -correction * k;
            Vec2 p = impulse * normal;
            // No body moves more than kMaxCorrection for one point. With an axis locked and no
            // rotation, k can be huge while the free axis takes the whole shift: a normal a
            // millionth of a radian off the locked axis asked for a slide of the overlap times
            // a million (8 000 km in one step, a fuzz finding).
            const float shift =
                std::max(length(scale(c.invMassA, p)), length(scale(c.invMassB, p)));
            if (shift > kMaxCorrection) {
                p *= kMaxCorrection / shift;
            }
            sa->deltaPosition -= scale(c.invMassA, p);
            sa->deltaRotation =
                integrateRotation(sa->deltaRotation, -c.invInertiaA * cross(prA, p));
            sb->deltaPosition += scale(c.invMassB, p);
            sb->deltaRotation = integrateRotation(sb->deltaRotation, c.invInertiaB * cross(prB, p));
        }
    }
    return minSeparation;
}

} // namespace e2d::physics::detail
