// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/constants.hpp>
#include <e2d/physics/manifold.hpp>

#include "solver_body.hpp"

#include <span>

// Contact constraints over plain arrays: the soft-step passes (warm start, solve, relax,
// restitution) and the classic ones (velocity and position iterations). No world in sight,
// so they are tested on hand-made manifolds.
namespace e2d::physics::detail {

struct ContactConstraintPoint {
    // From each centre of mass at the start of the step, world axes.
    Vec2 anchorA{0.0f, 0.0f};
    Vec2 anchorB{0.0f, 0.0f};
    // Separation minus dot(anchorB - anchorA, normal): adding the current anchor offset gives
    // the current separation without running the narrow phase again.
    float baseSeparation = 0.0f;
    // Normal velocity before the step; for a point apart at the start of the step (further
    // than the slop), replaced by the one at the sub-step where it starts to push (the moment
    // of impact). What restitution reflects.
    float relativeVelocity = 0.0f;
    float normalImpulse = 0.0f;
    float tangentImpulse = 0.0f;
    // Largest normal impulse any pass applied this step (hit events, touch reporting).
    float maxNormalImpulse = 0.0f;
    float normalMass = 0.0f;
    float tangentMass = 0.0f;
    // Classic mode: target normal velocity from restitution.
    float velocityBias = 0.0f;
    // Gap left when the impact was seen (the point still closes it in that sub-step), or the
    // separation at the start of the step for a point touching then, metres.
    float impactGap = 0.0f;
    bool impactSeen = false;
};

// Points closer than this at the start of the step count as touching (resting rows placed
// touching, soft contacts' steady penetration), metres.
inline constexpr float kTouchingSeparation = kLinearSlop;

// A symmetric 2x2 matrix [a11 a12; a12 a22].
struct BlockMatrix {
    float a11 = 0.0f;
    float a12 = 0.0f;
    float a22 = 0.0f;
};

// A 2-point manifold's normal impulses are solved together only while K's condition number
// (estimated as k11^2 / det K) stays below this (Box2D 2.4's value); above it the classic mode
// keeps one point and the soft step solves the two one after the other.
inline constexpr float kMaxBlockConditionNumber = 1000.0f;
// ... and while det K is a normal float. K of a body that cannot translate, against a static or
// kinematic side, is its inverse inertia times lever arms squared: 1e-21 for a 2.7e15 kg m^2
// body, whose det K then underflows into denormals, which the condition estimate reads as
// garbage and 1 / det overflows to infinity (the fuzzer found it).
inline constexpr float kMinBlockDeterminant = 0x1p-126f; // FLT_MIN

// A lever arm r x n is only known to within a few float roundings of |r|: the solver reads and
// applies it through cross(w, r) . n and cross(r, p), not through the r x n its effective mass
// used, and the three differ by ~2^-23 |r|. An effective mass therefore counts each side's
// rotation with a lever arm of at least 2^-21 |r| (it adds 2^-42 (iA |rA|^2 + iB |rB|^2) to
// K). Otherwise a normal that passes (to the last bit) through a body's centre leaves that
// body's rotation out of K, and when K is tiny for other reasons (a 2 mm circle whose position
// is locked, pressed by a body 1e16 times heavier) the rounding in the applied torque spins it
// by 1e18 rad/s and the state overflows within a sub-step. The term is below half an ulp of K,
// so changes nothing, unless iA |rA|^2 exceeds about 1e5 times the rest of K.
inline constexpr float kLeverRounding2 = 0x1p-42f;

// A side locked along one axis (BodyDef::lockX, lockY) moves along a contact's normal only by
// the normal's component on its free axis. When that component is tiny (a normal a billionth
// of a radian off the locked axis, which is the rounding of a normal along it), K is that
// component squared times the inverse mass, and the impulse that stops the normal velocity
// throws the body along its free axis at the closing speed divided by the component: 1e12 m/s
// in one iteration, impulses of 1e29 N s within a few steps, and then an overflow that reaches
// every body through a zero inverse mass (a fuzz finding). An effective mass therefore never
// lets an impulse move a side along the axis by more than kMaxContactGain times the velocity
// it corrects: K is at least each side's largest inverse mass times the axis' component on
// that side's free axis, over kMaxContactGain. A side free on both axes has K at least its
// inverse mass, so the floor binds only on locked sides (and changes nothing elsewhere).
inline constexpr float kMaxContactGain = 1024.0f;

struct ContactConstraint {
    ContactConstraintPoint points[2];
    Vec2 normal{0.0f, 0.0f};
    Vec2 invMassA{0.0f, 0.0f};
    Vec2 invMassB{0.0f, 0.0f};
    float invInertiaA = 0.0f;
    float invInertiaB = 0.0f;
    float friction = 0.0f;
    float restitution = 0.0f;
    float rollingResistance = 0.0f;
    float rollingImpulse = 0.0f;
    float rollingMass = 0.0f;
    // Relative acceleration from gravity pressing B onto A along the normal, m/s^2 (>= 0 means
    // pressing). Restitution uses it to bounce to the height the integrator would reach.
    float pressAcceleration = 0.0f;
    Softness softness{};
    // The normal effective-mass matrix of a 2-point manifold and its inverse, set by
    // prepareContact() when blockSolve (well-conditioned): both modes then solve the two normal
    // impulses together (solveBlock() in contact_solver_common.hpp).
    BlockMatrix blockK{};
    BlockMatrix blockInvK{};
    float blockInvDet = 0.0f; // 1 / det blockK: blockInvK is its products with blockK's entries
    bool blockSolve = false;
    int indexA = -1; // BodyState index, -1 for a static body
    int indexB = -1;
    int pointCount = 0;
    int contactIndex = -1; // the world's contact, to store impulses back
};

// Whether no impulse changes a side's velocity (no mass on either axis, no inertia: a static
// side too): the world gives a contact with such a side the static softness
// (ContactSoftness::vsStatic).
inline bool isRigidSide(Vec2 invMass, float invInertia) {
    return invMass.x == 0.0f && invMass.y == 0.0f && invInertia == 0.0f;
}

// One side of a contact as prepare() needs it.
struct ContactBodyView {
    Vec2 centerOffset{0.0f, 0.0f}; // centre of mass minus origin, world axes
    Vec2 linearVelocity{0.0f, 0.0f};
    float angularVelocity = 0.0f;
    Vec2 invMass{0.0f, 0.0f};
    float invInertia = 0.0f;
    int stateIndex = -1;
};

struct ContactMaterial {
    float friction = 0.0f;
    float restitution = 0.0f;
    float rollingResistance = 0.0f;
};

// Fills `c` from the manifold (impulses warm-start from the manifold's stored ones), with the
// block matrix of a 2-point manifold (prepareBlock()).
void prepareContact(ContactConstraint& c, const Manifold& m, const ContactBodyView& a,
                    const ContactBodyView& b, const ContactMaterial& material, Softness softness);

// Soft step.

// Sweeps per sub-step added in a step where shapes are being pushed apart (isPushedApart()),
// for the island block (wide solver) or the world (scalar) holding them. The biased solve moves
// overlapping points apart at up to contactPushMaxSpeed each, and relax is what takes that
// velocity back out of the bodies. But Gauss-Seidel undoes a push spread along a chain about
// one link per sweep, so with a single relax the pushes of a chain add up as real velocity: the
// top of a 10-box column spawned half overlapped left at 17 m/s, the corner of a lattice of 255
// discs overlapping by 0.04 m at 3.35 m/s (the cap is 3). Relax alone (no extra biased sweeps)
// then slows the push itself: the column still overlapped 9 cm after 2 s. With 5 more biased
// and 24 more relax sweeps: 2.8 m/s and 0.81 m/s, the column within 1.7 cm after 2 s. Only those
// steps pay (31 sweeps instead of 2); a resting pile, however deep its contacts, never does.
inline constexpr int kPushOutSolveIterations = 5;
inline constexpr int kPushOutRelaxIterations = 24;
// A point counts as pushed apart when it overlaps more than kLinearSlop beyond this many times
// the overlap its stored normal impulses would rest at.
inline constexpr float kPushOutRestMargin = 2.0f;

// Whether a point of manifold `m` between sides `a` and `b` overlaps deeper than the load it
// carries explains: spawned inside another shape, or moved into one, rather than pressed by
// weight. `softness`: the contact's. At rest point i of the manifold's soft constraint carries
// impulses lambda per sub-step with (K lambda)_i = h w^2 s_i (K the normal mass matrix of its
// points, s_i its overlap), which in terms of the softness is
// s_i = (K lambda)_i impulseScale / (massScale biasRate). Most contacts overlap less than the
// slop and need nothing more: that test is inline (the solver asks every contact each step),
// the rest is isDeepPushedApart(). prepareWideGroup() takes both on a group's lanes at once,
// operation for operation: change them together.
bool isDeepPushedApart(const Manifold& m, const ContactBodyView& a, const ContactBodyView& b,
                       Softness softness);
inline bool isPushedApart(const Manifold& m, const ContactBodyView& a, const ContactBodyView& b,
                          Softness softness) {
    const bool deep = (m.pointCount > 0 && m.points[0].separation < -kLinearSlop) ||
                      (m.pointCount > 1 && m.points[1].separation < -kLinearSlop);
    return deep && isDeepPushedApart(m, a, b, softness);
}

void warmStartContacts(std::span<ContactConstraint> constraints, std::span<BodyState> states);
// useBias: push overlapping points apart with the soft bias (solve) or not (relax).
// Speculative points (separation > 0) keep their bias either way. A blockSolve manifold solves
// its two normal impulses together (one point's soft update written for two, see
// solveContactsInOrder()), so neither point is favoured. Other manifolds go point by point, and
// Gauss-Seidel favours whatever it solves last, so the order alternates (see solveSoftStep()):
// backward visits the constraints last to first; reversePoints solves each constraint's normal
// points last to first.
void solveContacts(std::span<ContactConstraint> constraints, std::span<BodyState> states,
                   float invH, bool useBias, float pushMaxSpeed, bool backward = false,
                   bool reversePoints = false);
// h: the sub-step the positions were integrated with.
void applyRestitution(std::span<ContactConstraint> constraints, std::span<BodyState> states,
                      float threshold, float h);

// Classic. prepareClassic() sets the restitution targets from relativeVelocity and drops an
// ill-conditioned 2-point manifold to one point. solveVelocitiesClassic() then solves both normal
// impulses of a 2-point manifold as one 2x2 linear complementarity problem
// (contact_solver_classic.cpp).
void prepareClassic(std::span<ContactConstraint> constraints, std::span<BodyState> states,
                    float restitutionThreshold);
void solveVelocitiesClassic(std::span<ContactConstraint> constraints, std::span<BodyState> states,
                            float invDt);
// One non-linear Gauss-Seidel pass over the separations; moves deltaPosition/deltaRotation,
// pushing each point apart by `bias` times its overlap beyond `allowedPenetration` (metres).
// Returns the smallest separation seen.
float solvePositionsClassic(std::span<ContactConstraint> constraints, std::span<BodyState> states,
                            float allowedPenetration, float bias);

// The current separation of point `p` of `c` from the bodies' motion since the step began.
inline float currentSeparation(const ContactConstraint& c, const ContactConstraintPoint& p,
                               const BodyState& a, const BodyState& b) {
    Vec2 prA = rotate(a.deltaRotation, p.anchorA);
    Vec2 prB = rotate(b.deltaRotation, p.anchorB);
    Vec2 d = (b.deltaPosition - a.deltaPosition) + (prB - prA);
    return dot(d, c.normal) + p.baseSeparation;
}

} // namespace e2d::physics::detail
