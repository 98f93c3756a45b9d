// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/joint.hpp>
#include <e2d/physics/solver_def.hpp>

#include "joint_lcp.hpp"
#include "solver_body.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

// Joints as the world stores them (one slot each, every type's fields in one struct) and the
// solver passes over them. The passes mirror the contacts': prepare once per step, then per
// sub-step warm start, solve with a soft position bias, relax without it (soft step), or warm
// start and velocity iterations with the bias (classic). Each type's solve is in its own
// joint_<type>.cpp.
namespace e2d::physics::detail {

// Laid out for the solver: what the per-sub-step passes read and write sits in the first two
// cache lines (128 bytes), the definition and what prepareJoint() alone reads after them. A
// big joint grid is bound by memory traffic, so this halves the lines each pass touches.
struct alignas(64) Joint {
    // --- hot: every pass (first cache line) ---
    JointType type = JointType::Distance;
    bool enableSpring = false;
    bool enableLimit = false;
    bool enableMotor = false;
    int indexA = -1; // BodyState index this step, -1: static or asleep
    int indexB = -1;
    float invInertiaA = 0.0f;
    float invInertiaB = 0.0f;
    float angle0 = 0.0f; // joint angle at the step start
    Vec2 invMassA{0.0f, 0.0f};
    Vec2 invMassB{0.0f, 0.0f};
    Vec2 anchorA{0.0f, 0.0f}; // from A's centre of mass, world axes, at the step start
    Vec2 anchorB{0.0f, 0.0f};
    Vec2 deltaCenter{0.0f, 0.0f}; // B's centre minus A's (mouse: minus the target)
    Vec2 axisA{0.0f, 0.0f};       // world axes at the step start
    // Accumulated impulses of the last (sub-)step: warm start and reaction force.
    Vec2 linearImpulse{0.0f, 0.0f}; // point (revolute, weld, mouse, motor) or (perp, angle)
    // --- hot, second cache line (to maxMotorForce; the rest of the line is read when a
    // spring, a weld or a distance joint needs it) ---
    float angularImpulse = 0.0f; // weld, motor
    float springImpulse = 0.0f;  // distance: its rigid or spring impulse
    float motorImpulse = 0.0f;
    float lowerImpulse = 0.0f;
    float upperImpulse = 0.0f;
    float perpImpulse = 0.0f; // wheel
    float axialMass = 0.0f;
    float angularMass = 0.0f;
    float lower = 0.0f; // limits: translations or angles
    float upper = 0.0f;
    float motorSpeed = 0.0f;
    float maxMotorForce = 0.0f; // force or torque (mouse, motor: maxForce)
    float hertz = 0.0f;         // spring (mouse: its pull; weld: linear)
    float angularHertz = 0.0f;  // weld
    float length = 1.0f;
    float minLength = 0.0f;

    // --- cold: the step's prepare, the definition, the lists ---
    float maxLength = 0.0f;
    float maxTorque = 0.0f; // motor joint
    float correctionFactor = 0.0f;
    Softness springSoftness{};
    Softness angularSoftness{};
    int bodyA = -1;
    int bodyB = -1;
    // Intrusive lists of each body's joints (side 0: through body A, side 1: through body B).
    int prev[2] = {-1, -1};
    int next[2] = {-1, -1};
    std::uint64_t userData = 0;
    std::uint16_t generation = 1;
    bool alive = false;
    bool collideConnected = false;
    // JointSolver::Direct, this step: the joint's connected group has too many closed loops for
    // the direct solve (tooLoopy(), markLoopyJoints()): Gauss-Seidel, its plain hinges in groups.
    bool loopy = false;
    Vec2 localAnchorA{0.0f, 0.0f}; // from body A's origin, A's frame (motor: linearOffset)
    Vec2 localAnchorB{0.0f, 0.0f};
    Vec2 localAxisA{1.0f, 0.0f}; // unit
    Vec2 target{0.0f, 0.0f};     // mouse
    float referenceAngle = 0.0f; // motor: angularOffset
    float dampingRatio = 0.0f;
    float angularDampingRatio = 0.0f;
    // The joint angle, followed through whole turns (revolute), as it was when B's rotation
    // relative to A was `angleRotation` (see prepareJoint(): a plain hinge follows it only
    // when it has turned more than kAngleFollowTurn from there).
    float angle = 0.0f;
    Rot angleRotation{};
    Vec2 reactionForce{0.0f, 0.0f};
    float reactionTorque = 0.0f;
};
static_assert(offsetof(Joint, maxMotorForce) + sizeof(float) <= 128,
              "the solver's fields fit two cache lines");

// Whether a prepared joint is a plain hinge: a revolute joint with nothing but its point (no
// spring, motor or limit: a chain's, a net's, or a ragdoll's hinge without limits). The soft
// step solves those four or eight at a time (PointJointLanes).
inline bool isPointJoint(const Joint& j) {
    return j.type == JointType::Revolute && !j.enableSpring && !j.enableMotor && !j.enableLimit;
}

// N plain hinges (4 or 8) that share no moving body, as the soft step's passes read them:
// their prepared fields lane by lane (a copy of the joints' own, made once a step by
// packJointPasses()), solved together with the revolute joint's arithmetic in each lane, so
// each lane's results are the bits the joint alone would get. Their impulses go back to the
// joints once after the step (storePointJointGroups()). A lane whose slot is -1 is padding:
// no bodies, no mass, no impulse.
template <int N>
struct alignas(64) PointJointLanes {
    int indexA[N] = {}; // BodyState indices this step, -1: static or asleep
    int indexB[N] = {};
    int slot[N] = {}; // the joint slot
    float invInertiaA[N] = {};
    float invInertiaB[N] = {};
    float invMassAx[N] = {};
    float invMassAy[N] = {};
    float invMassBx[N] = {};
    float invMassBy[N] = {};
    float anchorAx[N] = {};
    float anchorAy[N] = {};
    float anchorBx[N] = {};
    float anchorBy[N] = {};
    float deltaCenterX[N] = {};
    float deltaCenterY[N] = {};
    float impulseX[N] = {};
    float impulseY[N] = {};

    PointJointLanes() {
        std::fill(std::begin(indexA), std::end(indexA), -1);
        std::fill(std::begin(indexB), std::end(indexB), -1);
        std::fill(std::begin(slot), std::end(slot), -1);
    }
};
using PointJointQuad = PointJointLanes<4>;
using PointJointOctet = PointJointLanes<8>;

// The step's plain hinges in groups: quads (SSE2, or scalar code where there is no SIMD) and,
// where `lanes` is 8 (bestPointJointLanes(): x86-64 CPUs with AVX2), octets too. A pass entry
// k < 0 names a group: ~k even the quad ~k / 2, odd the octet ~k / 2.
struct PointJointGroups {
    int lanes = 4; // the widest group the packer makes: 4 or 8
    std::vector<PointJointQuad> quads;
    std::vector<PointJointOctet> octets;

    void clear() {
        quads.clear();
        octets.clear();
    }
    std::size_t size() const { return quads.size() + octets.size(); }
    static int quadEntry(std::size_t index) { return ~(2 * static_cast<int>(index)); }
    static int octetEntry(std::size_t index) { return ~(2 * static_cast<int>(index) + 1); }
};

// 8 on x86-64 CPUs with AVX2, 4 elsewhere.
int bestPointJointLanes();

// The passes' order from the prepared joints joints[slots[k]] in order, levels[k] their
// levels (ascending; joints of one level share no moving body): pass entries appended to
// `entries`, k >= 0 the joint slot k, k < 0 a group of `groups` (PointJointGroups). With
// `quadsAllowed` (without it, those of loopy groups alone: Joint::loopy), the plain hinges of each level are packed into groups appended to `groups`
// (eights while five or more are left and groups.lanes is 8, then fours; the last group of a
// level padded; a single hinge left over stays a slot) and go before the level's other
// joints; a level's joints share no body, so this order gives the same results as slot order.
void packJointPasses(std::span<const Joint> joints, std::span<const int> slots,
                     std::span<const int> levels, bool quadsAllowed, PointJointGroups& groups,
                     std::vector<int>& entries);
// Copies every lane's prepared fields again from its joint: the groups' layout kept, the
// joints prepared anew.
void refreshPointJointGroups(PointJointGroups& groups, std::span<const Joint> joints);
// The groups' accumulated impulses back to their joints, and their reactions as
// storeJointReaction() gives a revolute joint's (invH: 1 / the sub-step).
void storePointJointGroups(const PointJointGroups& groups, std::span<Joint> joints, float invH);

struct JointDirectScratch;

// What a pass needs besides the joint and the bodies' states.
struct JointStep {
    float h = 0.0f; // the (sub-)step the velocities act over
    float invH = 0.0f;
    // The rigid parts of every joint (a revolute's point, a limit reached, a prismatic's
    // sideways and angular rows) are soft constraints of SolverDef::jointHertz and
    // jointDampingRatio at the sub-step h, as Box2D v3's.
    Softness jointSoftness{};
    // Rigid rows: a revolute joint's point and limit are solved as one block.
    bool blockLimit = false;
    // JointSolver::Direct: the joints' arrays for solveJointsDirect() after each pass.
    JointDirectScratch* direct = nullptr;
};

// The step's JointStep for sub-step h (direct: the scratch solveJointsDirect() uses, or null).
JointStep makeJointStep(const SolverDef& def, float h, JointDirectScratch* direct);

// One side of a joint at the step start, as prepareJoint() reads it.
struct JointBodyView {
    Rot q{};
    Vec2 center{0.0f, 0.0f};
    Vec2 localCenter{0.0f, 0.0f};
    Vec2 invMass{0.0f, 0.0f};
    float invInertia = 0.0f;
    int stateIndex = -1;
};

// The angle of rotation b relative to a, radians in [-pi, pi].
inline float relativeAngle(Rot a, Rot b) { return invMulRot(a, b).angle(); }

// A plain hinge (no spring, motor or limit reads its angle) follows its angle through whole
// turns only once its bodies' relative rotation has turned more than this from where it was
// last followed (cosine of 45 degrees): an atan2f every few steps instead of every step. The
// angle stays right as long as a joint turns less than 135 degrees in one step (the other
// joints, and jointValue(), assume half a turn).
inline constexpr float kAngleFollowCos = 0.70710678f;

// x wrapped into [-pi, pi]. Within half a turn x is its own remainder, bit for bit, so the
// common case (a joint angle that has not wrapped) skips the library call.
inline float wrapAngle(float x) {
    constexpr float kTurn = 6.28318530718f;
    return std::fabs(x) < 0.5f * kTurn ? x : std::remainder(x, kTurn);
}

// Fills the step's fields (anchors, masses, softness) of an alive joint.
void prepareJoint(Joint& j, const JointBodyView& a, const JointBodyView& b, const JointStep& step);
void warmStartJoint(Joint& j, std::span<BodyState> states);
// useBias: correct the position error of the rigid parts (solve) or not (relax).
void solveJoint(Joint& j, std::span<BodyState> states, const JointStep& step, bool useBias);
// reactionForce and reactionTorque from the accumulated impulses of the last (sub-)step.
void storeJointReaction(Joint& j, std::span<const BodyState> states, float invH);

// The passes over the entries of `order` in order (as packJointPasses() makes them: joint
// slots, or groups of plain hinges).
void warmStartJoints(std::span<Joint> joints, PointJointGroups& groups, std::span<const int> order,
                     std::span<BodyState> states);
void solveJoints(std::span<Joint> joints, PointJointGroups& groups, std::span<const int> order,
                 std::span<BodyState> states, const JointStep& step, bool useBias);
// One group's passes (joint_point.cpp); an octet's only where bestPointJointLanes() is 8.
void warmStartPointQuad(PointJointQuad& q, std::span<BodyState> states);
void solvePointQuad(PointJointQuad& q, std::span<BodyState> states, const Softness& soft);
void warmStartPointOctet(PointJointOctet& q, std::span<BodyState> states);
void solvePointOctet(PointJointOctet& q, std::span<BodyState> states, const Softness& soft);

// Box2D 2.4's caps on one position correction, which keep a large error (a limit or a rod
// violated far) from overshooting: a bounded push-out.
inline constexpr float kMaxLinearCorrection = 0.2f;
inline constexpr float kMaxAngularCorrection = 8.0f / 180.0f * 3.14159265f;
// The angular error the position passes leave (Box2D 2.4's b2_angularSlop, 2 degrees).
inline constexpr float kAngularSlop = 2.0f / 180.0f * 3.14159265f;

// Position error past a limit [lower, upper] (0 inside), capped at +-cap.
inline float pastLimit(float value, float lower, float upper, float cap) {
    if (value < lower) {
        return std::max(value - lower, -cap);
    }
    if (value > upper) {
        return std::min(value - upper, cap);
    }
    return 0.0f;
}

// The largest position errors a pass met.
struct JointErrors {
    float linear = 0.0f;
    float angular = 0.0f;
};

// Classic mode: one non-linear Gauss-Seidel pass over the rigid parts' position errors
// (joint_position.cpp). True when every error was within the slops before the pass. `order`
// holds joint slots only (classic mode solves no point joints).
bool solveJointPositions(std::span<Joint> joints, std::span<const int> order,
                         std::span<BodyState> states);

// The joints of a pass split into the connected components of their graph over the moving
// bodies (two joints sharing a moving body are in one; a static or sleeping side joins
// nothing), each in ascending slot order, the components in the order of their smallest
// slot. A world with the same joints finds the same components in the same order, whatever
// its body states' order, pass order or solver blocks, so a pass that goes component by
// component (the direct solve, the position passes and where they stop) gives the same bits.
struct JointComponents {
    std::vector<int> start; // component c holds slots[start[c] .. start[c + 1])
    std::vector<int> slots;
    std::vector<int> loops; // each component's independent closed loops through moving bodies
    std::size_t size() const { return start.empty() ? 0 : start.size() - 1; }
    std::span<const int> component(std::size_t c) const {
        return std::span<const int>(slots).subspan(
            static_cast<std::size_t>(start[c]), static_cast<std::size_t>(start[c + 1] - start[c]));
    }
    // A union-find over the body states the joints touch: entries are valid where their stamp
    // is this call's, so a call costs the joints', not the world's bodies.
    std::vector<int> parent;
    std::vector<int> componentOfRoot;
    std::vector<std::uint32_t> stamp;
    std::uint32_t generation = 0;
    std::vector<int> componentOf; // per entry of `sorted`: the slots ascending
    std::vector<int> sorted;
    std::vector<int> cursor;
    std::vector<std::uint8_t> closesLoop;
};

// Fills `out` from the pass entries `order` (joint slots; groups of plain hinges, k < 0, are
// skipped, and with `skipLoopy` the joints marked loopy) over `stateCount` body states
// (joint_components.cpp).
void findJointComponents(std::span<const Joint> joints, std::span<const int> order,
                         std::size_t stateCount, JointComponents& out, bool skipLoopy = false);

// A connected group of `joints` joints with `loops` independent closed loops through moving
// bodies is too loopy for the direct solve when it has more than 8 loops and more than one per
// 16 joints (a net: its factor fills in and costs more than it saves); Gauss-Seidel there.
inline bool tooLoopy(std::size_t joints, std::size_t loops) {
    return loops > std::max<std::size_t>(8, joints / 16);
}

// Sets Joint::loopy on the joints `slots` (every prepared joint of the step) by tooLoopy() of
// their connected group: a union-find, no sorting (once per step, JointSolver::Direct).
void markLoopyJoints(std::span<Joint> joints, std::span<const int> slots, std::size_t stateCount,
                     JointComponents& scratch);

// What the direct solve keeps between calls (its arrays' capacity, and the step's verdicts).
struct JointDirectScratch {
    // 3 x 3, row major; a joint's unused rows are padding. Doubles: a long limited arm or a
    // cantilever makes K ill-conditioned enough (1e6 and more) that floats lose the solve.
    using Block = std::array<double, 9>;
    struct Rows { // a joint's rows: the motion of B's side minus A's
        Vec2 linA[3];
        float angA[3];
        Vec2 linB[3];
        float angB[3];
        float* acc[3];    // the joint's accumulated impulse each row adds to (velocity solve)
        bool oneSided[3]; // a limit: its accumulated impulse stays >= 0
    };
    struct Entry {
        int node; // the other joint
        Block block;
    };
    JointComponents components;
    std::vector<Rows> rows;
    std::vector<int> rowCount;
    std::vector<std::array<double, 3>> rhs;
    std::vector<std::array<float, 3>> error;
    std::vector<std::array<double, 3>> solution;
    std::vector<Block> diag;
    std::vector<Block> inverseDiag;
    std::vector<std::vector<Entry>> adjacency;   // the remaining matrix's blocks by row
    std::vector<std::vector<Entry>> factor;      // each joint's blocks when it was eliminated
    std::vector<std::pair<int, int>> bodyJoints; // (body state, joint) of the moving sides
    std::vector<int> bodyJointStart;             // per body in the range: its first in bodyJoints
    std::vector<std::pair<int, int>> unsortedBodyJoints; // bodyJoints before the bucket sort
    std::vector<int> order;
    // A min-heap of (degree, joint) of the joints not eliminated yet; an entry whose degree is
    // no longer its joint's, or whose joint was eliminated, is stale and skipped.
    std::vector<std::pair<int, int>> queue;
    std::vector<std::uint8_t> eliminated; // per joint: taken out of the queue
    // The elimination order of each component (by its first slot) at its last successful
    // factorisation, and the (indexA, indexB) of its joints then, which alone decide it.
    struct KnownOrder {
        std::vector<std::pair<int, int>> bodies;
        std::vector<int> order;
    };
    std::unordered_map<int, KnownOrder> knownOrders;
    int componentKey = -1;                            // the assembled component's first slot
    std::vector<std::pair<int, int>> componentBodies; // its joints' (indexA, indexB)
    std::vector<std::uint8_t> released; // joints whose limit row the velocity solve let go
    // The velocity solve's limits (joint, row) and their Schur complement over the other rows:
    // each limit's column of K over the other rows (n x 3 per limit), that column solved with
    // the factor, the limits' own K and the complement S (m x m), the other rows' impulse with
    // the limits at rest, the limits' velocities then, and their impulses.
    std::vector<std::pair<int, int>> limits;
    std::vector<int> limitOf; // per joint: its limit's index, or -1
    std::vector<double> limitColumns;
    std::vector<double> limitResponse;
    std::vector<double> limitK;
    std::vector<double> schur;
    std::vector<std::array<double, 3>> unlimited;
    std::vector<double> limitVelocity;
    std::vector<double> limitImpulse;
    DenseLcpScratch lcp;
    // The components (by smallest slot) whose factorisation gave up this step (a net that
    // fills in too much): Gauss-Seidel alone for them until the next step's prepare.
    std::vector<int> denseComponents;
    void resetDense() { denseComponents.clear(); }
};

// Soft step with SolverDef::jointSolver Direct: the step's position passes over the joints
// `order` (slots), component by component (JointComponents): at most `iterations` Newton
// passes each, every rigid row of the component at once, K dlambda = -C solved directly
// (joint_direct.cpp), moving the states' deltaPosition and deltaRotation; a component stops
// once its errors are within the slops. A component with too many closed loops gets
// Gauss-Seidel passes (solveJointPositions()) instead; with `gaussSeidel`, every one does.
void projectJointComponents(std::span<Joint> joints, std::span<const int> order,
                            std::span<BodyState> states, int iterations, bool gaussSeidel,
                            JointDirectScratch& scratch);

// Soft step with SolverDef::jointSolver Direct: after a Gauss-Seidel pass, the velocities of
// every rigid row of the joints `order` (slots) and of each revolute limit within reach, solved
// component by component (K dlambda = -(J v + bias)), the impulses added to the joints'
// accumulated ones. The limits are a complementarity problem on the Schur complement of the
// other rows (each limit's impulse >= 0, its row's velocity >= 0, one of them 0: exact, none
// pulling, none let through), solved densely (joint_lcp.hpp) up to 64 limits per component,
// by an active set that releases limits beyond. A component whose graph fills in too much (a
// large net) is left to the Gauss-Seidel pass.
void solveJointsDirect(std::span<Joint> joints, std::span<const int> order,
                       std::span<BodyState> states, const JointStep& step, bool useBias,
                       JointDirectScratch& scratch);

// Per-type passes (joint_<type>.cpp).
void warmStartDistance(Joint& j, BodyState& a, BodyState& b);
void solveDistance(Joint& j, BodyState& a, BodyState& b, const JointStep& step, bool useBias);
void warmStartMotor(Joint& j, BodyState& a, BodyState& b);
void solveMotor(Joint& j, BodyState& a, BodyState& b, const JointStep& step, bool useBias);
void warmStartMouse(Joint& j, BodyState& a, BodyState& b);
void solveMouse(Joint& j, BodyState& a, BodyState& b, const JointStep& step, bool useBias);
void warmStartPrismatic(Joint& j, BodyState& a, BodyState& b);
void solvePrismatic(Joint& j, BodyState& a, BodyState& b, const JointStep& step, bool useBias);
void warmStartRevolute(Joint& j, BodyState& a, BodyState& b);
void solveRevolute(Joint& j, BodyState& a, BodyState& b, const JointStep& step, bool useBias);
void warmStartWeld(Joint& j, BodyState& a, BodyState& b);
void solveWeld(Joint& j, BodyState& a, BodyState& b, const JointStep& step, bool useBias);
void warmStartWheel(Joint& j, BodyState& a, BodyState& b);
void solveWheel(Joint& j, BodyState& a, BodyState& b, const JointStep& step, bool useBias);

// --- shared pieces of the per-type solves ---

// The anchors' current offsets from the centres (rotated by the step's motion so far).
struct JointFrame {
    Vec2 rA;
    Vec2 rB;
    Vec2 d; // anchor B minus anchor A, world
};
inline JointFrame currentFrame(const Joint& j, const BodyState& a, const BodyState& b) {
    Vec2 rA = rotate(a.deltaRotation, j.anchorA);
    Vec2 rB = rotate(b.deltaRotation, j.anchorB);
    return {rA, rB, (b.deltaPosition - a.deltaPosition) + j.deltaCenter + (rB - rA)};
}

// The joint angle now: at the step start plus the relative turn since.
inline float currentAngle(const Joint& j, const BodyState& a, const BodyState& b) {
    return j.angle0 + relativeAngle(a.deltaRotation, b.deltaRotation);
}

// Inverse mass along a unit axis with per-axis inverse masses.
inline float axisMass(Vec2 invMass, Vec2 axis) {
    return invMass.x * axis.x * axis.x + invMass.y * axis.y * axis.y;
}

// The point constraint's effective-mass matrix K (symmetric: k11, k12, k22).
struct Mat22 {
    float k11 = 0.0f;
    float k12 = 0.0f;
    float k22 = 0.0f;
};
inline Mat22 pointMatrix(const Joint& j, Vec2 rA, Vec2 rB) {
    float iA = j.invInertiaA;
    float iB = j.invInertiaB;
    return {j.invMassA.x + j.invMassB.x + iA * rA.y * rA.y + iB * rB.y * rB.y,
            -iA * rA.x * rA.y - iB * rB.x * rB.y,
            j.invMassA.y + j.invMassB.y + iA * rA.x * rA.x + iB * rB.x * rB.x};
}
// K^-1 b (zero where K is singular).
inline Vec2 solve22(const Mat22& k, Vec2 b) {
    float det = k.k11 * k.k22 - k.k12 * k.k12;
    if (det != 0.0f) {
        det = 1.0f / det;
    }
    return {det * (k.k22 * b.x - k.k12 * b.y), det * (k.k11 * b.y - k.k12 * b.x)};
}

// Applies impulse p at the anchors (B gets +p, A gets -p) plus angular impulse l about them.
inline void applyPointImpulse(const Joint& j, BodyState& a, BodyState& b, Vec2 rA, Vec2 rB, Vec2 p,
                              float l = 0.0f) {
    a.linearVelocity -= j.invMassA * p;
    a.angularVelocity -= j.invInertiaA * (cross(rA, p) + l);
    b.linearVelocity += j.invMassB * p;
    b.angularVelocity += j.invInertiaB * (cross(rB, p) + l);
}

// Velocity of anchor B relative to anchor A.
inline Vec2 relativeVelocity(const BodyState& a, const BodyState& b, Vec2 rA, Vec2 rB) {
    return (b.linearVelocity + cross(b.angularVelocity, rB)) -
           (a.linearVelocity + cross(a.angularVelocity, rA));
}

// One side of a one-sided limit along `Cdot`'s direction: C >= 0 is allowed. Returns the
// impulse change applied (accumulated in `impulse`, kept >= 0). A limit not reached yet is
// speculative: it only stops the bodies from passing it within this sub-step.
inline float solveLimitRow(float& impulse, float mass, float C, float Cdot, const JointStep& step,
                           bool useBias) {
    float bias = 0.0f;
    float massScale = 1.0f;
    float impulseScale = 0.0f;
    if (C > 0.0f) {
        bias = C * step.invH;
    } else if (useBias) {
        bias = step.jointSoftness.biasRate * C;
        massScale = step.jointSoftness.massScale;
        impulseScale = step.jointSoftness.impulseScale;
    }
    float delta = -mass * massScale * (Cdot + bias) - impulseScale * impulse;
    float next = std::max(impulse + delta, 0.0f);
    delta = next - impulse;
    impulse = next;
    return delta;
}

// A motor row: drives Cdot to speed with at most maxImpulse accumulated.
inline float solveMotorRow(float& impulse, float mass, float speed, float Cdot, float maxImpulse) {
    float delta = mass * (speed - Cdot);
    float next = std::clamp(impulse + delta, -maxImpulse, maxImpulse);
    delta = next - impulse;
    impulse = next;
    return delta;
}

// A spring or rigid row (soft): impulse towards C = 0 with the given softness.
inline float solveSoftRow(float& impulse, float mass, float C, float Cdot, const Softness& soft) {
    float delta = -mass * soft.massScale * (Cdot + soft.biasRate * C) - soft.impulseScale * impulse;
    impulse += delta;
    return delta;
}

// The rigid parts' softness: with the bias while solving, none while relaxing.
inline Softness rigidSoftness(const JointStep& step, bool useBias) {
    return useBias ? step.jointSoftness : Softness{0.0f, 1.0f, 0.0f};
}

// A prismatic or wheel joint's axis (fixed in A) and its lever arms now: an impulse p along
// the axis turns A by p * a1 and B by p * a2 (perp: s1, s2).
struct SlideFrame {
    JointFrame f;
    Vec2 axis;
    Vec2 perp;
    float a1;
    float a2;
    float s1;
    float s2;
};
inline SlideFrame currentSlide(const Joint& j, const BodyState& a, const BodyState& b) {
    const JointFrame f = currentFrame(j, a, b);
    const Vec2 axis = rotate(a.deltaRotation, j.axisA);
    const Vec2 perp = leftPerp(axis);
    const Vec2 arm = f.d + f.rA;
    return {
        f, axis, perp, cross(arm, axis), cross(f.rB, axis), cross(arm, perp), cross(f.rB, perp)};
}
// Impulse p along `dir` with lever arms (l1, l2), plus angular impulse l on both.
inline void applySlideImpulse(const Joint& j, BodyState& a, BodyState& b, Vec2 dir, float p,
                              float l1, float l2, float l = 0.0f) {
    a.linearVelocity -= j.invMassA * (p * dir);
    a.angularVelocity -= j.invInertiaA * (p * l1 + l);
    b.linearVelocity += j.invMassB * (p * dir);
    b.angularVelocity += j.invInertiaB * (p * l2 + l);
}
inline float slideVelocity(const BodyState& a, const BodyState& b, Vec2 dir, float l1, float l2) {
    return dot(dir, b.linearVelocity - a.linearVelocity) + l2 * b.angularVelocity -
           l1 * a.angularVelocity;
}

} // namespace e2d::physics::detail
