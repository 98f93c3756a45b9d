// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/events.hpp>
#include <e2d/physics/geometry.hpp>
#include <e2d/physics/manifold.hpp>
#include <e2d/physics/solver_def.hpp>

#include "constraint_graph.hpp"
#include "contact_impacts.hpp"
#include "contact_solver.hpp"
#include "contact_solver_wide.hpp"
#include "joint_solver.hpp"
#include "soft_step_stages.hpp"
#include "solver_body.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

// The dynamics half of the world: per-body motion data, the persistent contacts and the
// per-step scratch arrays. World::Impl holds one Simulation; every array here is reused from
// step to step, so a warm world allocates nothing per step.
namespace e2d::physics::detail {

// A body's dynamics, kept in its world slot (detail::Body::motion).
struct BodyMotion {
    // Smallest and largest distance from the centre of mass to the shapes' surfaces, metres:
    // a body that moves more than minExtent in a step may tunnel (continuous collision).
    // maxExtent and awake come first: the narrow phase reads them with the body's pose (Body).
    float maxExtent = 0.0f;
    float minExtent = 0.0f;
    bool awake = true;
    bool fixedRotation = false;
    bool lockX = false;
    bool lockY = false;
    bool isBullet = false;
    bool enableSleep = true;
    Vec2 localCenter{0.0f, 0.0f};
    float mass = 0.0f;
    float inertia = 0.0f; // about the centre of mass
    float invMass = 0.0f;
    float invInertia = 0.0f;
    Vec2 force{0.0f, 0.0f};
    float torque = 0.0f;
    float linearDamping = 0.0f;
    float angularDamping = 0.0f;
    float gravityScale = 1.0f;
    // The centre of mass's position below the float resolution at the body's place: the true
    // centre is transformPoint(transform, localCenter) + positionResidual. Far from the origin
    // a float step is coarse (8 mm at 100 km) and the small motions of a resting body round
    // away at every step; kept here, they add up as they do at the origin. Below half a float
    // step of the centre; zero until the solver moves the body, and after setTransform().
    Vec2 positionResidual{0.0f, 0.0f};
    float sleepTime = 0.0f;
    int contactHead = -1; // intrusive list of the body's contacts
    int solverIndex = -1; // index in this step's awake arrays, -1 when not awake
};

// The root of i's set in a union-find forest (parent[root] == root), halving the path on the
// way. Islands (island.cpp) and the wide solver's blocks (world_step.cpp) use it.
inline int findRoot(std::vector<int>& parent, int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
        int grand = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
        parent[static_cast<std::size_t>(i)] = grand;
        i = grand;
    }
    return i;
}

// A contact's manifold as the collision routine last computed it, in the bodies' frames, so
// that later steps can move it with the bodies instead of colliding again
// (SolverDef::contactRecycleDistance; contact.cpp). Whether there is one: Contact::originValid.
struct ManifoldOrigin {
    // The bodies' relative pose, x components in frame[0..2] and y components in frame[3..5]
    // (lanes of contact.cpp's SSE2 code): 0, A's origin in B's frame; 1, B's origin in A's
    // frame; 2, B's rotation in A's frame (cos, sin). Each row is loaded as four floats, the
    // fourth (the next row's first, or extentA) unused.
    float frame[6]{};
    // The farthest any point of the body's shapes was from its origin, metres.
    float extentA = 0.0f;
    float extentB = 0.0f;
    // The normal in A's frame; per point, its surface point on A (A's frame, from A's origin)
    // and on B (B's frame, from B's origin).
    Vec2 normalInA{0.0f, 0.0f};
    Vec2 surfaceA[2]{};
    Vec2 surfaceB[2]{};

    [[nodiscard]] Vec2 aInB() const { return {frame[0], frame[3]}; }
    [[nodiscard]] Transform bInA() const { return {{frame[1], frame[4]}, {frame[2], frame[5]}}; }
    void setFrames(Vec2 aInB, const Transform& bInA) {
        frame[0] = aInB.x;
        frame[3] = aInB.y;
        frame[1] = bInA.p.x;
        frame[4] = bInA.p.y;
        frame[2] = bInA.q.c;
        frame[5] = bInA.q.s;
    }
};
static_assert(offsetof(ManifoldOrigin, extentA) == 6 * sizeof(float),
              "the y row's four-float load ends in extentA");

// A pair of shapes whose fat boxes overlap. Contacts live in one array with a free list; each
// is linked into both bodies' lists. This part is what the narrow phase and the solver use
// every step; the rest (which shapes, the list links, the ids) is its ContactLinks, at the same
// index: three cache lines, not four (the narrow phase streams every contact each step).
//
// What the solver reads and writes of a contact each step (the manifold, the mixed materials and
// the bodies: its first Contact::kSolverBytes) comes first: on a large island the solver visits
// the contacts out of array order (colour by colour), twice a step, and each visit then fetches
// two cache lines (or three, by where the array starts), not the four or five it took when
// these fields were spread over the contact. (Aligning contacts to cache lines as well slowed
// the narrow phase's walk over them by about a third on a base-100 pyramid: measured, not
// understood.)
struct Contact {
    Manifold manifold{};
    float friction = 0.0f;
    float restitution = 0.0f;
    float rollingResistance = 0.0f;
    int bodyA = -1;
    int bodyB = -1;
    // The end of what the solver touches (see above).
    static constexpr std::size_t kSolverBytes = 112;
    ManifoldOrigin origin{};
    // False until the routine has run with recycling on (and for sensors and chain segments).
    bool originValid = false;
    bool touching = false;
    bool sensor = false; // one shape is a sensor: overlap only, no constraint
    bool alive = false;
    // The pre-solve callback's answer this step: false leaves the contact out of the solver.
    bool enabled = true;
    // Both shapes' event switches (contact or sensor begin/end, hits).
    bool touchEvents = true;
    bool hitEvents = true;
    // Both shapes are circles (their own path). Not in snapshots: restoreSnapshot() sets it
    // (World::Impl::copyContactShapes()).
    bool circles = false;
};
static_assert(offsetof(Contact, bodyB) + sizeof(int) == Contact::kSolverBytes &&
                  Contact::kSolverBytes <= 128,
              "the solver's fields of a contact must come first, in two cache lines' bytes");
static_assert(sizeof(Contact) == 192, "a contact is three cache lines' bytes");

// The rest of a contact (Simulation::contactLinks, same index as Simulation::contacts): its
// shapes, its links in both bodies' contact lists (side 0: body A, side 1: body B) and the
// shapes' ids. The narrow phase reads the shapes only when it runs the routine.
struct ContactLinks {
    int shapeA = -1;
    int shapeB = -1;
    // Copies of the shapes' proxy keys (Shape::proxyKey), for the narrow phase's fat-box test;
    // they stay while the contact lives (a shape's contacts end before its proxy goes). Not in
    // snapshots: restoreSnapshot() sets them (World::Impl::copyContactShapes()).
    int proxyKeyA = -1;
    int proxyKeyB = -1;
    int prev[2] = {-1, -1};
    int next[2] = {-1, -1};
    ShapeId idA{};
    ShapeId idB{};
};

struct Simulation {
    SolverDef def{};
    // The widest SIMD the solver may use (WorldDef::simdLanes): 4 or 8.
    int simdLanes = 8;

    std::vector<Contact> contacts;
    std::vector<ContactLinks> contactLinks; // same size as contacts
    std::vector<int> freeContacts;
    int contactCount = 0;

    // The touching non-sensor contacts after this step's narrow phase, in contact order, with
    // what the solver's walk over them reads.
    struct TouchingContact {
        int contact = -1;
        int bodyA = -1;
        int bodyB = -1;
        float rollingResistance = 0.0f;
    };
    std::vector<TouchingContact> touchingContacts;
    // BroadPhase::fatBoxChanges() when the narrow phase last tested the contacts' fat boxes (~0:
    // never, as after restoreSnapshot()). While it is the same, the fat boxes of every live
    // contact still overlap: those that parted ended then, and a pair found since overlaps.
    std::uint64_t fatBoxChangesTested = ~std::uint64_t{0};
    // The narrow phase's parallel pass (World::Impl::updateContacts()) goes through the contact
    // slots in blocks of kNarrowBlock; per block, from slot block * kNarrowBlock on, it lists the
    // touching contacts it settled and the contacts the serial pass must see, with counts here.
    static constexpr int kNarrowBlock = 64;
    struct NarrowBlock {
        int touching = 0;
        int serial = 0;
        int manifoldUpdates = 0;
        int manifoldsRecycled = 0;
    };
    std::vector<NarrowBlock> narrowBlocks;
    // Where each block's settled touching contacts go in touchingContacts when no contact needs
    // the serial pass (narrowBlocks.size() + 1 entries).
    std::vector<int> narrowTouchingStart;
    std::vector<TouchingContact> blockTouching;
    std::vector<int> blockSerial;
    // Per contact slot listed in blockSerial, what the parallel pass found.
    std::vector<unsigned char> contactUpdates;
    // The soft step's relax iterations on top of SolverDef::relaxIterations in the last solve,
    // the most of any block (detail::kPushOutRelaxIterations while shapes were pushed apart).
    int extraRelaxIterations = 0;

    // Per-step scratch, same order: the awake moving bodies and their world slots.
    std::vector<BodySim> sims;
    std::vector<BodyState> states;
    // Per world body slot, its BodyMotion::solverIndex this step: the constraint list's walk
    // reads two a contact, scattered, and the bodies themselves are too large to stay in cache.
    std::vector<int> bodySolverIndex;
    std::vector<ContactBodyRow> contactRows; // what the contacts' constraint builds read of each
    // The solved contacts, in contact order: contact index and the sides' BodyState indices
    // (-1: static or asleep).
    struct ConstraintBodies {
        int indexA = -1;
        int indexB = -1;
    };
    std::vector<int> constraintContacts;
    std::vector<ConstraintBodies> constraintBodies;
    // Per chunk of the touching contacts (World::Impl::solve()), how many it kept.
    std::vector<int> constraintChunkKept;
    // Per BodyState: zero inverse mass and inertia (no constraint changes its velocity).
    std::vector<unsigned char> stateRigid;
    // Classic mode and rolling resistance only: the wide solver packs each constraint as it is
    // built and keeps it nowhere else.
    std::vector<ContactConstraint> constraints; // in contact order
    ContactImpacts impacts; // the scalar solvers' and a staged block's (BlockWorker: the others')
    // A hit found while storing impulses by level: contact, point, approach speed.
    struct HitCandidate {
        int contact = -1;
        int point = -1;
        float speed = 0.0f;
    };
    std::vector<HitCandidate> hitCandidates;
    // What each worker of the wide solve keeps apart from the others while it solves its blocks
    // (World::Impl::solve()): the block's restitution list and impacts, the hits found, the
    // most relax sweeps added, the direct joint solve's arrays (its components whose
    // factorisation gave up are the projection's to know too). Merged in a fixed order
    // afterwards.
    // A block solved by all workers at once is built in pieces: each worker's restitution
    // entries and whether its pieces held shapes pushed apart, merged into stagedRestitution
    // (in constraint order) before the block is solved (solveSoftStepStaged(), its impacts
    // planned in `impacts` above).
    struct BlockWorker {
        std::vector<WideRestitution> restitution;
        ContactImpacts impacts;
        std::vector<HitCandidate> hits;
        int extraRelaxIterations = 0;
        JointDirectScratch jointDirect;
        bool pushOut = false;
    };
    std::vector<BlockWorker> blockWorkers;
    std::vector<WideRestitution> stagedRestitution;
    SoftStepStages softStepStages;
    // The wide soft-step solver's schedule: each constraint's level (its colour,
    // ConstraintColors), the slots in level order (level k holds slots [levelStart[k],
    // levelStart[k + 1]), contact order within a level) with each slot's constraint, contact
    // and bodies, and the packed constraints.
    ConstraintColors colors;
    std::vector<int> constraintLevel;
    std::vector<int> slotConstraint;
    std::vector<int> slotContact;
    std::vector<ConstraintBodies> slotBodies;
    std::vector<int> levelStart;
    std::vector<int> levelNext;
    WideContacts wideContacts;
    // Blocks of islands (World::Impl::scheduleWide()): per body a union-find parent and its
    // block, per island root its constraint count and block, per constraint its island root;
    // block b's levels [blockLevelStart[b], blockLevelStart[b + 1]) and bodies
    // blockBodies[blockBodyStart[b] .. blockBodyStart[b + 1]).
    std::vector<int> blockParent;
    std::vector<int> bodyBlock;
    std::vector<int> islandConstraints;
    std::vector<int> islandBlock;
    std::vector<int> constraintIsland;
    std::vector<int> blockLevelStart;
    std::vector<int> blockBodyStart;
    std::vector<int> blockBodies;
    std::vector<unsigned char> blockRigid; // per block: a constraint with a rigid state
    // The schedule above depends on nothing but the constraints (contacts and sides) and which
    // states are rigid. wideScheduleValid: it was built from the last solve's
    // constraintContacts, constraintBodies and stateRigid, which each solve keeps here
    // (swapped, not copied) to compare with its own.
    bool wideScheduleValid = false;
    std::vector<int> lastConstraintContacts;
    std::vector<ConstraintBodies> lastConstraintBodies;
    std::vector<unsigned char> lastStateRigid;
    // Joints this step (World::Impl::prepareJoints()): the world's joint slots with a moving
    // side, in pass order (World::Impl::orderJoints(): by level, every body meeting its joints
    // in slot order) with their levels, and their sides' BodyState indices (-1: static or
    // asleep); last solve's, for the wide schedule's check; the scalar solvers' pass entries
    // (jointOrder, packJointPasses(): slots, or groups of pointJoints); the wide solver's by
    // block: block b's entries are blockJoints[blockJointStart[b] .. blockJointStart[b + 1]).
    // The rest is scratch.
    std::vector<int> activeJoints;
    std::vector<int> activeJointLevels;
    std::vector<int> jointOrder;
    PointJointGroups pointJoints;
    // The joints' direct solve's arrays (SolverDef::jointSolver Direct) for the scalar solvers
    // and the position pass after the solve; the wide solve's blocks use their worker's
    // (BlockWorker::jointDirect).
    JointDirectScratch jointDirect;
    std::vector<int> jointBodyLevel;
    std::vector<int> jointLevel;
    std::vector<int> jointLevelStart;
    std::vector<int> jointSorted;
    std::vector<int> jointScratch;
    std::vector<ConstraintBodies> jointBodiesScratch;
    std::vector<ConstraintBodies> jointBodies;
    std::vector<ConstraintBodies> lastJointBodies;
    std::vector<int> blockJointStart;
    std::vector<int> blockJoints;
    // What decides the joints' order and groups (World::Impl::prepareJoints()): each prepared
    // joint's slot, its sides' BodyState indices and whether it is a plain hinge, in slot
    // order; this step's and last step's. While they are equal, the levels, the pass order
    // and the groups' layout are last step's (jointsReused; jointLayout: which packing built
    // them) and only the lanes' fields are copied anew.
    struct JointKey {
        int slot = -1;
        int indexA = -1;
        int indexB = -1;
        int point = 0;
    };
    enum class JointLayout { None, Scalar, ScalarNoGroups, Wide };
    std::vector<JointKey> jointKeys;
    std::vector<JointKey> lastJointKeys;
    JointLayout jointLayout = JointLayout::None;
    bool jointsReused = false;
    std::vector<int> islandParent; // union-find over the awake arrays
    std::vector<float> islandSleepTime;
    std::vector<float> simSleepTime; // per solver body this step (World::Impl::updateSleep())
    // This step's solver bodies (indices in sims) that updateSleep() put to sleep, ascending,
    // and those the write-back disabled (non-finite or out of range), ascending: the move
    // events are written during the write-back and marked from these.
    std::vector<int> sleptSims;
    std::vector<int> disabledSims;
    // Per solver body, what World::Impl::writeBack()'s parallel pass left for its ordered one.
    std::vector<unsigned char> writeBackResults;
    std::vector<int> wakeStack;

    std::vector<ContactBeginTouchEvent> beginEvents;
    std::vector<ContactEndTouchEvent> endEvents;
    std::vector<SensorBeginTouchEvent> sensorBeginEvents;
    std::vector<SensorEndTouchEvent> sensorEndEvents;
    std::vector<ContactHitEvent> hitEvents;
    std::vector<BodyId> nonFiniteBodies;
    std::vector<BodyId> outOfRangeBodies;
    StepCounters counters{};
    // End events of contacts destroyed between steps (a shape destroyed, a body disabled):
    // handed out with the next step's events, so the current arrays stay valid meanwhile.
    std::vector<ContactEndTouchEvent> pendingEndEvents;
    std::vector<SensorEndTouchEvent> pendingSensorEndEvents;
    bool inStep = false;
};

// Mixed material of two shapes under the world's rules.
inline float mixFriction(const SolverDef& def, float a, float b) {
    return mix(def.frictionMixing, a, b);
}
inline float mixRestitution(const SolverDef& def, float a, float b) {
    return mix(def.restitutionMixing, a, b);
}

} // namespace e2d::physics::detail
