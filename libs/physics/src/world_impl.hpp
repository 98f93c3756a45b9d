// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/world.hpp>

#include "broad_phase.hpp"
#include "id_pool.hpp"
#include "joint_solver.hpp"
#include "simulation.hpp"
#include "slot_array.hpp"
#include "task_pool.hpp"
#include "world_hooks.hpp"

#include <cstdint>
#include <vector>

namespace e2d::physics::detail {

inline constexpr int kNullIndex = -1;

// A body slot. Slots of destroyed bodies stay in the array (alive == false) and keep their
// generation, so a stale BodyId is recognised; the id pool reuses them.
struct Body {
    // What the narrow phase reads of both bodies of every contact comes first, so that it is
    // in one cache line or two (contact.cpp prefetches just these): the pose, the velocities,
    // the type and (BodyMotion's first fields) the extent and whether the body is awake.
    Transform transform{};
    Vec2 linearVelocity{0.0f, 0.0f};
    float angularVelocity = 0.0f;
    BodyType type = BodyType::Static;
    bool enabled = true;
    bool alive = false;
    // Dynamics (mass, damping, forces, sleep, contact list): owned by the step code.
    BodyMotion motion{};
    std::uint16_t generation = 1;
    // Shapes of a body form an intrusive doubly linked list through the shape array, so a body
    // owns no heap memory of its own.
    int headShape = kNullIndex;
    int shapeCount = 0;
    // Intrusive list of the body's joints (detail::Joint::next[side]).
    int jointHead = kNullIndex;
    std::uint64_t userData = 0;
};

struct Shape {
    ShapeGeometry geometry{};
    // Tight world box at the body's current transform.
    Aabb aabb{};
    Filter filter{};
    std::uint64_t userData = 0;
    float density = 1.0f;
    float friction = 0.6f;
    float restitution = 0.0f;
    float rollingResistance = 0.0f;
    int body = kNullIndex;
    int prevShape = kNullIndex;
    int nextShape = kNullIndex;
    // Broad-phase proxy key; kNullIndex while the body is disabled.
    int proxyKey = kNullIndex;
    std::uint16_t generation = 1;
    bool isSensor = false;
    bool alive = false;
    // Event switches (ShapeDef::enable*Events).
    bool contactEvents = true;
    bool sensorEvents = true;
    bool hitEvents = true;
    // ShapeDef::sensorSeesNonDynamic (only acts while isSensor).
    bool sensorSeesNonDynamic = false;
};

} // namespace e2d::physics::detail

namespace e2d::physics {

struct World::Impl {
    Vec2 gravity{0.0f, -10.0f};
    CollisionAlgorithm collisionAlgorithm = CollisionAlgorithm::Sat;
    float speculativeDistance = kSpeculativeDistance;
    // Written into every id handed out and checked on every use (WorldDef::tag); never 0.
    std::uint16_t tag = 1;

    // Grown without copies (see SlotArray).
    detail::SlotArray<detail::Body> bodies;
    detail::SlotArray<detail::Shape> shapes;
    detail::IdPool bodyIds;
    detail::IdPool shapeIds;
    detail::BroadPhase broadPhase;

    // Index of a live body (shape, joint) named by `id`, or kNullIndex.
    [[nodiscard]] int find(BodyId id) const { return findIn(bodies, id); }
    [[nodiscard]] int find(ShapeId id) const { return findIn(shapes, id); }
    [[nodiscard]] int find(JointId id) const { return findIn(joints, id); }
    template <class Slots, class Id>
    [[nodiscard]] int findIn(const Slots& slots, Id id) const {
        const auto index = core::findSlot(
            id, slots.size(),
            [&slots](std::uint32_t i) {
                return slots[i].alive ? slots[i].generation : std::uint16_t{0};
            },
            tag);
        return index ? static_cast<int>(*index) : detail::kNullIndex;
    }
    // The function whose callback is running (overlapAabb, forEachCandidatePair,
    // forEachTouchingContact, or step/updatePairs for the hooks), or nullptr, and for a hook
    // its name ("pre-solve", "pair filter"). Meanwhile, functions that would change what the
    // callback walks (the broad phase, the contacts, the object arrays) refuse to run.
    mutable const char* lockedBy = nullptr;
    mutable const char* lockedHook = nullptr;
    // Throws core::Error naming `function` and the running callback's function, if any.
    void requireUnlocked(const char* function) const;
    // Locks the world while a query's callback runs; nests.
    class CallbackLock {
    public:
        CallbackLock(const Impl& world, const char* function, const char* hook = nullptr)
            : world_(world), previous_(world.lockedBy), previousHook_(world.lockedHook) {
            world_.lockedBy = function;
            world_.lockedHook = hook;
        }
        ~CallbackLock() {
            world_.lockedBy = previous_;
            world_.lockedHook = previousHook_;
        }
        CallbackLock(const CallbackLock&) = delete;
        CallbackLock& operator=(const CallbackLock&) = delete;

    private:
        const Impl& world_;
        const char* previous_;
        const char* previousHook_;
    };

    // Like find(), but throws core::Error naming `function` for a stale or null handle.
    int require(BodyId id, const char* function) const;
    int require(ShapeId id, const char* function) const;

    [[nodiscard]] BodyId bodyId(int index) const {
        return BodyId::forSlot(static_cast<std::uint32_t>(index), body(index).generation, tag);
    }
    [[nodiscard]] ShapeId shapeId(int index) const {
        return ShapeId::forSlot(static_cast<std::uint32_t>(index), shape(index).generation, tag);
    }
    detail::Body& body(int index) { return bodies[static_cast<std::size_t>(index)]; }
    const detail::Body& body(int index) const { return bodies[static_cast<std::size_t>(index)]; }
    detail::Shape& shape(int index) { return shapes[static_cast<std::size_t>(index)]; }
    const detail::Shape& shape(int index) const { return shapes[static_cast<std::size_t>(index)]; }

    void createProxy(int shapeIndex);
    void destroyProxy(int shapeIndex);
    void destroyShapeAt(int shapeIndex);
    // Whether two shapes may become a candidate pair (the broad phase's filter).
    [[nodiscard]] bool shouldPair(int shapeA, int shapeB) const;
    // The categories a moved shape's broad-phase query looks at: every partner shouldPair()
    // could accept (BroadPhase::updatePairs()).
    [[nodiscard]] std::uint64_t pairQueryMask(int shapeIndex) const;

    // --- dynamics (world_step.cpp, contact.cpp, island.cpp, world_dynamics.cpp) ---

    detail::Simulation sim;
    // The step's parallel stages (WorldDef::workerCount, enqueueTask, finishTask).
    detail::Tasks tasks;
    // Pre-solve and pair filter callbacks, move events (world_hooks.cpp).
    detail::Hooks hooks;

    // Sets the body's motion fields from the def (createBody()).
    void initMotion(int bodyIndex, const BodyDef& def);
    // Mass, centre and extents from the shapes' densities (after a shape is added or removed).
    void updateMass(int bodyIndex);
    // Ends the shape's contacts (end events, wakes the other bodies): before its proxy goes.
    void destroyContacts(int shapeIndex);
    // Wakes the body and every sleeping body touching it, transitively.
    void wakeBody(int bodyIndex);
    // Pairs -> contacts; narrow phase; begin/end/sensor events.
    void updateContacts(float dt);
    // One contact's narrow phase (contact.cpp): its new manifold and whether it touches.
    [[nodiscard]] bool updateManifold(detail::Contact& c, const detail::ContactLinks& links,
                                      float dt) const;
    void createContact(int shapeA, int shapeB);
    // Sets what the live contacts copy from their shapes (ContactLinks::proxyKeyA, proxyKeyB,
    // Contact::circles): after restoreSnapshot(), whose contacts do not carry it.
    void copyContactShapes();
    void destroyContact(int contactIndex, bool reportEnd);
    void solve(float dt);
    void scheduleWide(int constraintCount);
    // The solved bodies' final poses (detail::finalizePositions()) and, if `continuous`, time of
    // impact for this step's fast bodies and bullets (continuous.cpp), on the workers:
    // finalizeAndSweep() picks them from the solver arrays (kIsFast, kIsBullet), sweepBody()
    // sweeps one (index in sims).
    void finalizeAndSweep(bool continuous);
    void sweepBody(int simIndex);
    // The solved states back to the bodies, the broad-phase moves and the move events
    // (world_write_back.cpp).
    void writeBack(float dt);
    // Puts resting islands to sleep; lists them in sim.sleptSims (island.cpp).
    void updateSleep(float dt);
    // Completes hooks.moveEvents, which solve()'s write-back filled: marks the bodies
    // updateSleep() put to sleep; clears them after a step of zero (world_hooks.cpp).
    void collectMoveEvents(float dt);
    // Re-mixes the materials and event switches of the shape's contacts after a setter.
    void refreshContactMaterials(int shapeIndex);
    // Continuous collision's extra rules: a chain segment is one-sided, and the pair filter
    // callback may refuse the pair (world_hooks.cpp).
    [[nodiscard]] bool passesChainAndFilter(int movingShape, int otherShape,
                                            const Transform& xfMoving,
                                            const Transform& xfOther) const;

    // --- joints (joint.cpp, joint_step.cpp) ---

    std::vector<detail::Joint> joints;
    detail::IdPool jointIds;

    int require(JointId id, const char* function) const;
    [[nodiscard]] JointId jointId(int index) const {
        return JointId::forSlot(static_cast<std::uint32_t>(index), joint(index).generation, tag);
    }
    detail::Joint& joint(int index) { return joints[static_cast<std::size_t>(index)]; }
    const detail::Joint& joint(int index) const { return joints[static_cast<std::size_t>(index)]; }
    void destroyJointAt(int jointIndex);
    // Whether a joint between the two bodies turns their collisions off.
    [[nodiscard]] bool jointBlocksCollision(int bodyA, int bodyB) const;
    // Wakes the sleeping dynamic side of every joint whose other side is awake (before solve()).
    void wakeJointedBodies();
    // The step's joints: s.activeJoints (joints with a moving side, in pass order) and
    // s.activeJointLevels, prepared, and s.jointBodies (their BodyState indices).
    void prepareJoints(float dt, float h);
    // Puts the prepared joints in pass order (levels, see there; prepareJoints()).
    void orderJoints();
    // The scalar solvers' pass entries (s.jointOrder, s.pointJoints; packJointPasses()).
    void packJoints();
    // The wide solver's pass entries by block (s.blockJointStart, s.blockJoints, s.pointJoints),
    // after scheduleWide(); scheduleKept: scheduleWide() kept last step's blocks.
    void assignJointBlocks(bool scheduleKept);
    // The quads' impulses back to their joints, then the reactions of the active joints from
    // their impulses (invH: 1 / the sub-step).
    // wide: the step's entries are the wide solver's (s.blockJoints), else s.jointOrder.
    void storeJointReactions(float invH, bool wide);
    // Soft step, after the sub-steps: the joints' position errors removed from the states'
    // motion (SolverDef::jointPositionIterations).
    void projectJoints();
    // After the continuous pass: if it moved a body back to its time of impact (a limb landing
    // fast), the joints' position passes again from where the bodies are, so the joints do
    // not come apart by the distance the pass took back.
    void reprojectJointsAfterContinuous();
};

} // namespace e2d::physics
