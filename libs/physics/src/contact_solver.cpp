// SPDX-License-Identifier: MIT
#include "contact_solver.hpp"
#include "contact_solver_common.hpp"

#include <e2d/physics/constants.hpp>

#include <algorithm>
#include <cmath>

namespace e2d::physics::detail {

void prepareContact(ContactConstraint& c, const Manifold& m, const ContactBodyView& a,
                    const ContactBodyView& b, const ContactMaterial& material, Softness softness) {
    c.indexA = a.stateIndex;
    c.indexB = b.stateIndex;
    c.normal = m.normal;
    c.invMassA = a.invMass;
    c.invMassB = b.invMass;
    c.invInertiaA = a.invInertia;
    c.invInertiaB = b.invInertia;
    c.friction = material.friction;
    c.restitution = material.restitution;
    c.rollingResistance = material.rollingResistance;
    c.rollingImpulse = 0.0f;
    float kRoll = a.invInertia + b.invInertia;
    c.rollingMass = kRoll > 0.0f ? 1.0f / kRoll : 0.0f;
    c.softness = softness;
    c.pointCount = m.pointCount;

    Vec2 normal = m.normal;
    Vec2 tangent = rightPerp(normal);
    for (int i = 0; i < m.pointCount; ++i) {
        const ManifoldPoint& mp = m.points[i];
        ContactConstraintPoint& cp = c.points[i];
        Vec2 rA = mp.anchorA - a.centerOffset;
        Vec2 rB = mp.anchorB - b.centerOffset;
        cp.anchorA = rA;
        cp.anchorB = rB;
        cp.baseSeparation = mp.separation - dot(rB - rA, normal);
        cp.normalImpulse = mp.normalImpulse;
        cp.tangentImpulse = mp.tangentImpulse;
        cp.maxNormalImpulse = 0.0f;
        cp.velocityBias = 0.0f;
        cp.normalMass = effectiveMass(normal, rA, rB, c);
        cp.tangentMass = effectiveMass(tangent, rA, rB, c);
        Vec2 vrA = a.linearVelocity + cross(a.angularVelocity, rA);
        Vec2 vrB = b.linearVelocity + cross(b.angularVelocity, rB);
        cp.relativeVelocity = dot(normal, vrB - vrA);
        // A point already touching has no impact later in the step: its approach speed is the
        // one it has now. Were it taken when the point starts to push, every contact of a
        // resting row struck within the step would bounce at up to e times the striker's speed
        // and a Newton's cradle would gain energy. (This velocity and this gap pair up in
        // restitution's invariant the way an impact's do: both are taken at a sub-step's start.)
        cp.impactSeen = mp.separation <= kTouchingSeparation;
        cp.impactGap = cp.impactSeen ? mp.separation : 0.0f;
    }
    prepareBlock(c);
}

bool isDeepPushedApart(const Manifold& m, const ContactBodyView& a, const ContactBodyView& b,
                       Softness softness) {
    const float stiffness = softness.massScale * softness.biasRate;
    if (!(stiffness > 0.0f)) {
        return false; // not a soft contact
    }
    const Vec2 n = m.normal;
    const float linear = dot(a.invMass + b.invMass, Vec2{n.x * n.x, n.y * n.y});
    float rnA[2] = {0.0f, 0.0f};
    float rnB[2] = {0.0f, 0.0f};
    for (int i = 0; i < m.pointCount; ++i) {
        rnA[i] = cross(m.points[i].anchorA - a.centerOffset, n);
        rnB[i] = cross(m.points[i].anchorB - b.centerOffset, n);
    }
    const float restPerImpulse = kPushOutRestMargin * softness.impulseScale / stiffness;
    for (int i = 0; i < m.pointCount; ++i) {
        float load = 0.0f; // (K lambda)_i
        for (int j = 0; j < m.pointCount; ++j) {
            const float k =
                linear + a.invInertia * rnA[i] * rnA[j] + b.invInertia * rnB[i] * rnB[j];
            load += k * m.points[j].normalImpulse;
        }
        if (-m.points[i].separation > kLinearSlop + restPerImpulse * std::max(load, 0.0f)) {
            return true;
        }
    }
    return false;
}

void warmStartContacts(std::span<ContactConstraint> constraints, std::span<BodyState> states) {
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
        for (int i = 0; i < c.pointCount; ++i) {
            const ContactConstraintPoint& cp = c.points[i];
            Vec2 p = cp.normalImpulse * normal + cp.tangentImpulse * tangent;
            wA -= c.invInertiaA * cross(cp.anchorA, p);
            vA -= scale(c.invMassA, p);
            wB += c.invInertiaB * cross(cp.anchorB, p);
            vB += scale(c.invMassB, p);
        }
        wA -= c.invInertiaA * c.rollingImpulse;
        wB += c.invInertiaB * c.rollingImpulse;
        sa->linearVelocity = vA;
        sa->angularVelocity = wA;
        sb->linearVelocity = vB;
        sb->angularVelocity = wB;
    }
}

namespace {

// Where a point is now and the normal velocity it should have: a speculative point (apart)
// closes its gap within this sub-step and no further; an overlapping one is pushed out softly
// when useBias, not at all when relaxing.
struct PointTarget {
    float separation = 0.0f;
    float bias = 0.0f;
    float massScale = 1.0f;
    float impulseScale = 0.0f;
};

inline PointTarget targetOf(const ContactConstraint& c, const ContactConstraintPoint& cp,
                            const BodyState& a, const BodyState& b, float invH, bool useBias,
                            float pushMaxSpeed) {
    PointTarget t;
    t.separation = currentSeparation(c, cp, a, b);
    if (t.separation > 0.0f) {
        t.bias = t.separation * invH;
    } else if (useBias) {
        t.bias = std::max(c.softness.biasRate * t.separation, -pushMaxSpeed);
        t.massScale = c.softness.massScale;
        t.impulseScale = c.softness.impulseScale;
    }
    return t;
}

// The first time a point approaches (vn: its normal velocity before this pass's impulse), its
// approach speed at impact is this one, not the one at the start of the step (gravity kept
// accelerating meanwhile).
inline void noteImpact(ContactConstraintPoint& cp, float vn, float separation, float invH,
                       bool useBias) {
    if (!cp.impactSeen && vn + std::max(separation, 0.0f) * invH < 0.0f) {
        cp.impactSeen = true;
        cp.relativeVelocity = vn;
        // The gap this velocity leads to at the end of the sub-step (positions move after the
        // biased solve, before the relax), to pair it with its velocity.
        cp.impactGap = useBias ? separation + vn / invH : separation;
    }
}

// The point order is a template parameter: indexing the points through a run-time flag cost
// 5 % more instructions per step (measured with callgrind on a base-40 pyramid).
template <bool kReversePoints>
void solveContactsInOrder(std::span<ContactConstraint> constraints, std::span<BodyState> states,
                          float invH, bool useBias, float pushMaxSpeed, bool backward) {
    BodyState dummyA;
    BodyState dummyB;
    std::size_t n = constraints.size();
    for (std::size_t k = 0; k < n; ++k) {
        ContactConstraint& c = constraints[backward ? n - 1 - k : k];
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
        float totalNormalImpulse = 0.0f;

        if (c.blockSolve) {
            ContactConstraintPoint& cp1 = c.points[0];
            ContactConstraintPoint& cp2 = c.points[1];
            PointTarget t1 = targetOf(c, cp1, *sa, *sb, invH, useBias, pushMaxSpeed);
            PointTarget t2 = targetOf(c, cp2, *sa, *sb, invH, useBias, pushMaxSpeed);
            Vec2 dv1 = (vB + cross(wB, cp1.anchorB)) - (vA + cross(wA, cp1.anchorA));
            Vec2 dv2 = (vB + cross(wB, cp2.anchorB)) - (vA + cross(wA, cp2.anchorA));
            Vec2 vn{dot(dv1, normal), dot(dv2, normal)};
            noteImpact(cp1, vn.x, t1.separation, invH, useBias);
            noteImpact(cp2, vn.y, t2.separation, invH, useBias);
            // One point's soft update, k11 (x - lambda) = -massScale (vn + bias) -
            // impulseScale k11 lambda, written for two: K (x - lambda) = -M (vn + bias) -
            // I K lambda, with each point's own mass and impulse scales in the diagonal M and I
            // (a speculative point's row is rigid). Both overlapping, this is the soft update of
            // one two-row constraint (K^-1 its mass): at rest each point overlaps
            // (K lambda)_i / (h w^2), so a box on a box compresses like a spring on the pair's
            // reduced mass, not on one corner's normal mass (a 50-box column sags 0.42 m, not
            // 0.53 m). The block LCP solves it with vn + bias replaced by this right-hand side.
            Vec2 old{cp1.normalImpulse, cp2.normalImpulse};
            Vec2 rhs{t1.massScale * (vn.x + t1.bias) +
                         t1.impulseScale * (c.blockK.a11 * old.x + c.blockK.a12 * old.y),
                     t2.massScale * (vn.y + t2.bias) +
                         t2.impulseScale * (c.blockK.a12 * old.x + c.blockK.a22 * old.y)};
            Vec2 x = old;
            solveBlock(c, old, rhs, x);
            applyBlock(c, old, x, vA, wA, vB, wB);
            totalNormalImpulse = x.x + x.y;
        }

        for (int j = 0; j < (c.blockSolve ? 0 : c.pointCount); ++j) {
            ContactConstraintPoint& cp = c.points[kReversePoints ? c.pointCount - 1 - j : j];
            PointTarget t = targetOf(c, cp, *sa, *sb, invH, useBias, pushMaxSpeed);
            Vec2 rA = cp.anchorA;
            Vec2 rB = cp.anchorB;
            Vec2 dv = (vB + cross(wB, rB)) - (vA + cross(wA, rA));
            float vn = dot(dv, normal);
            noteImpact(cp, vn, t.separation, invH, useBias);
            float impulse =
                -cp.normalMass * t.massScale * (vn + t.bias) - t.impulseScale * cp.normalImpulse;
            float newImpulse = std::max(cp.normalImpulse + impulse, 0.0f);
            impulse = newImpulse - cp.normalImpulse;
            cp.normalImpulse = newImpulse;
            cp.maxNormalImpulse = std::max(cp.maxNormalImpulse, impulse);
            totalNormalImpulse += newImpulse;
            Vec2 p = impulse * normal;
            vA -= scale(mA, p);
            wA -= iA * cross(rA, p);
            vB += scale(mB, p);
            wB += iB * cross(rB, p);
        }

        solveFriction(c, tangent, vA, wA, vB, wB);

        if (c.rollingResistance > 0.0f) {
            float maxLambda = c.rollingResistance * totalNormalImpulse;
            float deltaLambda = -c.rollingMass * (wB - wA);
            float lambda = c.rollingImpulse;
            c.rollingImpulse = std::clamp(lambda + deltaLambda, -maxLambda, maxLambda);
            deltaLambda = c.rollingImpulse - lambda;
            wA -= iA * deltaLambda;
            wB += iB * deltaLambda;
        }

        sa->linearVelocity = vA;
        sa->angularVelocity = wA;
        sb->linearVelocity = vB;
        sb->angularVelocity = wB;
    }
}

} // namespace

void solveContacts(std::span<ContactConstraint> constraints, std::span<BodyState> states,
                   float invH, bool useBias, float pushMaxSpeed, bool backward,
                   bool reversePoints) {
    if (reversePoints) {
        solveContactsInOrder<true>(constraints, states, invH, useBias, pushMaxSpeed, backward);
    } else {
        solveContactsInOrder<false>(constraints, states, invH, useBias, pushMaxSpeed, backward);
    }
}

void applyRestitution(std::span<ContactConstraint> constraints, std::span<BodyState> states,
                      float threshold, float h) {
    BodyState dummyA;
    BodyState dummyB;
    for (ContactConstraint& c : constraints) {
        if (c.restitution == 0.0f) {
            continue;
        }
        auto [sa, sb] = statesOf(c, states, dummyA, dummyB);
        Vec2 vA = sa->linearVelocity;
        float wA = sa->angularVelocity;
        Vec2 vB = sb->linearVelocity;
        float wB = sb->angularVelocity;
        Vec2 normal = c.normal;
        for (int i = 0; i < c.pointCount; ++i) {
            ContactConstraintPoint& cp = c.points[i];
            // Only points that were approaching fast and actually took load bounce.
            if (cp.relativeVelocity > -threshold || cp.maxNormalImpulse == 0.0f ||
                cp.velocityBias > 0.0f) {
                continue;
            }
            Vec2 rA = cp.anchorA;
            Vec2 rB = cp.anchorB;
            Vec2 dv = (vB + cross(wB, rB)) - (vA + cross(wA, rA));
            float vn = dot(dv, normal);
            // Semi-implicit Euler under a constant acceleration g along the normal keeps
            // Q = v^2 + 2 g s - g h v exactly (v: normal velocity, s: gap). Without care a
            // bounce loses about g h v of it every time; instead the rebound speed is chosen so
            // that Q after the bounce is e^2 times Q at the impact: the ball rises to e^2 times
            // the height it fell from, as in the continuous case. (Sub-step solves with a
            // constant acceleration; contact forces only act while touching.)
            float approach = -cp.relativeVelocity;
            float target = c.restitution * approach;
            float g = c.pressAcceleration;
            if (g > 0.0f) {
                // The rebound starts from wherever the push-out left the point.
                float q = approach * approach + 2.0f * g * cp.impactGap + g * h * approach;
                float gapNow = currentSeparation(c, cp, *sa, *sb);
                float rhs = std::max(c.restitution * c.restitution * q - 2.0f * g * gapNow, 0.0f);
                target = 0.5f * (g * h + std::sqrt(g * g * h * h + 4.0f * rhs));
            }
            float impulse = -cp.normalMass * (vn - target);
            float newImpulse = std::max(cp.normalImpulse + impulse, 0.0f);
            impulse = newImpulse - cp.normalImpulse;
            cp.normalImpulse = newImpulse;
            cp.maxNormalImpulse = std::max(cp.maxNormalImpulse, impulse);
            Vec2 p = impulse * normal;
            vA -= scale(c.invMassA, p);
            wA -= c.invInertiaA * cross(rA, p);
            vB += scale(c.invMassB, p);
            wB += c.invInertiaB * cross(rB, p);
        }
        sa->linearVelocity = vA;
        sa->angularVelocity = wA;
        sb->linearVelocity = vB;
        sb->angularVelocity = wB;
    }
}

} // namespace e2d::physics::detail
