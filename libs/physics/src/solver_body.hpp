// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/math.hpp>

#include <cmath>
#include <cstdint>

// The solver's view of the awake moving bodies: two contiguous arrays built once per step.
namespace e2d::physics::detail {

// Per-axis locks and other per-body solver switches.
enum BodyFlag : std::uint8_t {
    kLockX = 1,        // the centre of mass never moves along x
    kLockY = 2,        // ... along y
    kLockRotation = 4, // fixed rotation
    kIsBullet = 8,
    kIsFast = 16,    // moved far enough this step to need time of impact (finalizePositions())
    kNonFinite = 32, // its velocity overflowed this step: held still, disabled afterwards
};

// What the sub-step loops touch, and nothing else, so many fit in a cache line. Static bodies
// have no BodyState: constraints against them use a zero state (index -1).
struct BodyState {
    Vec2 linearVelocity{0.0f, 0.0f};
    float angularVelocity = 0.0f;
    std::uint32_t flags = 0;
    // Motion since the start of the step; the contact solver recomputes separations from it.
    // Starts at the body's position residual (BodyMotion::positionResidual): the motion from
    // the float centre the narrow phase saw, so no sub-step loses what the float centre cannot
    // hold.
    Vec2 deltaPosition{0.0f, 0.0f};
    Rot deltaRotation{};
};

// Everything else the step needs about an awake moving body.
struct BodySim {
    Transform transform{};    // body origin
    Vec2 center{0.0f, 0.0f};  // world centre of mass
    Vec2 center0{0.0f, 0.0f}; // centre of mass at the start of the step
    Rot rotation0{};          // rotation at the start of the step
    Vec2 localCenter{0.0f, 0.0f};
    // What the float centre at the end of the step cannot hold (BodyMotion::positionResidual),
    // set by finalizePositions().
    Vec2 positionResidual{0.0f, 0.0f};
    Vec2 force{0.0f, 0.0f};
    float torque = 0.0f;
    // Per-axis inverse mass: a locked axis has zero.
    Vec2 invMass{0.0f, 0.0f};
    float invInertia = 0.0f;
    float linearDamping = 0.0f;
    float angularDamping = 0.0f;
    float gravityScale = 1.0f;
    // Largest and smallest distance from the centre of mass to a shape's surface, for
    // continuous collision (BodyMotion::maxExtent, minExtent).
    float maxExtent = 0.0f;
    float minExtent = 0.0f;
    int bodyIndex = -1; // the world's body slot
    std::uint32_t flags = 0;
    // One integration step's velocity change from gravity, force and torque, and its damping
    // factors: the same for every sub-step of a step (prepareIntegration()).
    Vec2 velocityStep{0.0f, 0.0f};
    float angularVelocityStep = 0.0f;
    float linearDampingFactor = 1.0f;
    float angularDampingFactor = 1.0f;
};

// What building a contact's constraint reads of an awake moving side (prepareWideGroup(), the
// world's ContactBodyView), one row per body in BodyState order, written with the body's BodySim
// and BodyState: its velocity as the step begins (the BodyState's until the body's block is
// solved), inverse mass and inertia (the BodySim's), and centre offset: rotate(rotation0,
// localCenter), the centre of mass from the origin in world axes at the start of the step. The
// build visits the bodies in colour order, scattered: here it reads one cache line a side, where
// the BodySim's fields (spread over two of its three lines) and the BodyState took two or three.
// Two rows of four floats: {vx, vy, w, invInertia} and {centerOffset, invMass}.
struct alignas(32) ContactBodyRow {
    Vec2 linearVelocity{0.0f, 0.0f};
    float angularVelocity = 0.0f;
    float invInertia = 0.0f;
    Vec2 centerOffset{0.0f, 0.0f};
    Vec2 invMass{0.0f, 0.0f}; // per axis, as BodySim::invMass
};
static_assert(sizeof(ContactBodyRow) == 32, "ContactBodyRow must stay two 16-byte rows");

// q advanced by angle `da` (small): q + da * perp(q), renormalised. Cheaper than sin/cos and
// exact enough for one sub-step.
inline Rot integrateRotation(Rot q, float da) {
    float c = q.c - da * q.s;
    float s = q.s + da * q.c;
    float mag = std::sqrt(c * c + s * s);
    if (!(mag > 0.0f && mag < INFINITY)) [[unlikely]] {
        // A huge angle (a classic position correction pushed by an absurd impulse) overflows
        // the first-order step into a zero rotation, which is finite and so would pass for a
        // valid state: turn by da exactly instead (NaN for a non-finite da, which the world
        // then reports).
        return mulRot(Rot{std::cos(da), std::sin(da)}, q);
    }
    float inv = 1.0f / mag;
    return {c * inv, s * inv};
}

// Soft constraint coefficients for a spring of `hertz` and damping ratio `zeta` stepped by h.
struct Softness {
    float biasRate = 0.0f;
    float massScale = 1.0f;
    float impulseScale = 0.0f;
};

inline Softness makeSoftness(float hertz, float zeta, float h) {
    if (hertz == 0.0f) {
        return {0.0f, 1.0f, 0.0f};
    }
    float omega = 2.0f * 3.14159265359f * hertz;
    float a1 = 2.0f * zeta + h * omega;
    float a2 = h * omega * a1;
    float a3 = 1.0f / (1.0f + a2);
    return {omega / a1, a2 * a3, a3};
}

} // namespace e2d::physics::detail
