// SPDX-License-Identifier: MIT
// World::step(): pairs -> contacts -> narrow phase -> solver arrays -> solve -> continuous ->
// write back and broad-phase moves -> stored impulses, hit events -> sleep.
#include <e2d/physics/world.hpp>

#include "body_solver.hpp"
#include "prefetch.hpp"
#include "soft_step_stages.hpp"
#include "world_check.hpp"
#include "world_impl.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>

namespace e2d::physics {

using detail::kNullIndex;
namespace check = detail::world_check;

void World::step(float timeStep) {
    impl_->requireUnlocked("step");
    if (!(isFinite(timeStep) && timeStep >= 0.0f)) {
        check::fail("step", "timeStep must be finite and >= 0, got " + check::text(timeStep));
    }
    if (timeStep > kMaxTimeStep) {
        check::fail("step", "timeStep must be <= kMaxTimeStep (" + check::text(kMaxTimeStep) +
                                " s), got " + check::text(timeStep) +
                                ": longer steps sink bodies into what they rest on; call step() "
                                "several times");
    }
    Impl& w = *impl_;
    detail::Simulation& s = w.sim;
    s.beginEvents.clear();
    s.endEvents.clear();
    s.sensorBeginEvents.clear();
    s.sensorEndEvents.clear();
    s.hitEvents.clear();
    s.nonFiniteBodies.clear();
    s.outOfRangeBodies.clear();
    s.counters = {};
    s.endEvents.swap(s.pendingEndEvents);
    s.sensorEndEvents.swap(s.pendingSensorEndEvents);
    s.inStep = true;
    // A callback (pre-solve, pair filter) that throws leaves the step where it was, and the
    // world out of it.
    struct InStep {
        detail::Simulation& sim;
        ~InStep() { sim.inStep = false; }
    } inStep{s};
    w.updateContacts(timeStep);
    if (timeStep > 0.0f) {
        w.solve(timeStep);
        s.counters.solverBodies = static_cast<int>(s.sims.size());
        s.counters.contactConstraints = static_cast<int>(s.constraintContacts.size());
        if (s.def.mode == SolverMode::SoftStep) {
            s.counters.relaxIterations = 1 + s.def.relaxIterations + s.extraRelaxIterations;
        }
        w.updateSleep(timeStep);
    }
    w.collectMoveEvents(timeStep);
}

namespace {

// Constraints per block of islands the wide solver runs through all sub-steps at once: about
// 0.7 MB of packed constraints, well inside a core's L2 cache with its bodies.
constexpr int kBlockConstraints = 4096;
// The fewest constraints of a block solved by several workers at once (World::Impl::solve()):
// each of its passes then waits for the slowest worker about once per level, which a smaller
// block does not make up for.
constexpr int kStagedBlockConstraints = 1024;
// Touching contacts per chunk of the constraint list's parallel walk (World::Impl::solve()).
constexpr int kConstraintChunk = 1024;

} // namespace

// The wide solver's schedule. Islands (bodies joined through constraints, any body with a
// state joins) go whole into blocks of about kBlockConstraints constraints, in order of first
// appearance; each block's constraints are sorted by level (a counting sort, so contact order
// within a level), and the blocks' levels follow one another in one list. Streaming every
// constraint from memory for each of the twelve passes of a step cost more than solving
// them; a block stays in cache through its sub-steps.
void World::Impl::scheduleWide(int constraintCount) {
    detail::Simulation& s = sim;
    const std::size_t n = s.sims.size();
    const auto count = static_cast<std::size_t>(constraintCount);
    std::vector<int>& parent = s.blockParent;
    parent.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        parent[i] = static_cast<int>(i);
    }
    auto join = [&](const detail::Simulation::ConstraintBodies& cb) {
        if (cb.indexA >= 0 && cb.indexB >= 0) {
            int ra = detail::findRoot(parent, cb.indexA);
            int rb = detail::findRoot(parent, cb.indexB);
            if (ra != rb) {
                parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
            }
        }
    };
    for (const detail::Simulation::ConstraintBodies& cb : s.constraintBodies) {
        join(cb);
    }
    // Jointed bodies share a block: a block runs all its sub-steps before the next one, so
    // none of its bodies may be moved by another block's joints.
    for (const detail::Simulation::ConstraintBodies& jb : s.jointBodies) {
        join(jb);
    }
    s.islandConstraints.assign(n, 0);
    s.constraintIsland.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
        const detail::Simulation::ConstraintBodies& cb = s.constraintBodies[k];
        int root = detail::findRoot(parent, cb.indexA >= 0 ? cb.indexA : cb.indexB);
        s.constraintIsland[k] = root;
        ++s.islandConstraints[static_cast<std::size_t>(root)];
    }
    s.islandBlock.assign(n, -1);
    s.blockLevelStart.assign(1, 0); // level counts first, made starts below
    // Per block, whether a constraint has a rigid side with a state (a kinematic body): one
    // level may then hold several constraints writing that state.
    s.blockRigid.clear();
    int blockCount = 0;
    int blockSize = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const auto root = static_cast<std::size_t>(s.constraintIsland[k]);
        if (s.islandBlock[root] < 0) {
            if (blockCount == 0 || blockSize + s.islandConstraints[root] > kBlockConstraints) {
                ++blockCount;
                blockSize = 0;
                s.blockLevelStart.push_back(0);
                s.blockRigid.push_back(0);
            }
            s.islandBlock[root] = blockCount - 1;
            blockSize += s.islandConstraints[root];
        }
        const auto block = static_cast<std::size_t>(s.islandBlock[root]);
        int& levels = s.blockLevelStart[block + 1];
        levels = std::max(levels, s.constraintLevel[k] + 1);
        const detail::Simulation::ConstraintBodies& cb = s.constraintBodies[k];
        s.blockRigid[block] |= static_cast<unsigned char>(
            (cb.indexA >= 0 && s.stateRigid[static_cast<std::size_t>(cb.indexA)] != 0) ||
            (cb.indexB >= 0 && s.stateRigid[static_cast<std::size_t>(cb.indexB)] != 0));
    }
    // Block `blockCount` holds the bodies no constraint touches: no levels.
    for (int b = 0; b < blockCount; ++b) {
        s.blockLevelStart[static_cast<std::size_t>(b) + 1] +=
            s.blockLevelStart[static_cast<std::size_t>(b)];
    }
    s.blockLevelStart.push_back(s.blockLevelStart.back());
    const int levelCount = s.blockLevelStart[static_cast<std::size_t>(blockCount)];

    // Each constraint's level becomes its place in the list of all blocks' levels.
    s.levelStart.assign(static_cast<std::size_t>(levelCount) + 1, 0);
    for (std::size_t k = 0; k < count; ++k) {
        const int block = s.islandBlock[static_cast<std::size_t>(s.constraintIsland[k])];
        int& level = s.constraintLevel[k];
        level += s.blockLevelStart[static_cast<std::size_t>(block)];
        ++s.levelStart[static_cast<std::size_t>(level) + 1];
    }
    for (int k = 0; k < levelCount; ++k) {
        s.levelStart[static_cast<std::size_t>(k) + 1] += s.levelStart[static_cast<std::size_t>(k)];
    }
    s.levelNext.assign(s.levelStart.begin(), s.levelStart.end() - 1);
    // Each constraint's slot (level k holds slots [levelStart[k], levelStart[k + 1]), contact
    // order within a level). Slot order is the order the solver builds and stores in: the
    // constraint, contact and bodies of each slot, so those passes read them in order.
    s.slotConstraint.resize(count);
    s.slotContact.resize(count);
    s.slotBodies.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
        const auto slot =
            static_cast<std::size_t>(s.levelNext[static_cast<std::size_t>(s.constraintLevel[k])]++);
        s.slotConstraint[slot] = static_cast<int>(k);
        s.slotContact[slot] = s.constraintContacts[k];
        s.slotBodies[slot] = s.constraintBodies[k];
    }
    // Eight lanes only pay when levels are wide enough to fill them: a small pile's levels
    // hold a few constraints each, and half-empty groups of eight cost more than full fours.
    // Only levels that hold constraints count (a block skips the colours it does not use, and
    // overflow levels start after all colours).
    int filledLevels = 0;
    for (int k = 0; k < levelCount; ++k) {
        const auto at = static_cast<std::size_t>(k);
        filledLevels += s.levelStart[at + 1] > s.levelStart[at] ? 1 : 0;
    }
    int lanes = std::min(detail::bestWideLanes(), s.simdLanes);
    if (lanes > 4 && 2 * count < static_cast<std::size_t>(lanes * filledLevels)) {
        lanes = 4;
    }
    detail::layoutWide(s.wideContacts, s.levelStart, lanes);

    // The bodies by block, in state order within a block.
    s.blockBodyStart.assign(static_cast<std::size_t>(blockCount) + 2, 0);
    s.bodyBlock.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        int block =
            s.islandBlock[static_cast<std::size_t>(detail::findRoot(parent, static_cast<int>(i)))];
        block = block < 0 ? blockCount : block;
        s.bodyBlock[i] = block;
        ++s.blockBodyStart[static_cast<std::size_t>(block) + 1];
    }
    for (int b = 0; b <= blockCount; ++b) {
        s.blockBodyStart[static_cast<std::size_t>(b) + 1] +=
            s.blockBodyStart[static_cast<std::size_t>(b)];
    }
    s.levelNext.assign(s.blockBodyStart.begin(), s.blockBodyStart.end() - 1);
    s.blockBodies.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        s.blockBodies[static_cast<std::size_t>(
            s.levelNext[static_cast<std::size_t>(s.bodyBlock[i])]++)] = static_cast<int>(i);
    }
}

void World::Impl::solve(float dt) {
    detail::Simulation& s = sim;
    const SolverDef& def = s.def;

    // The awake moving bodies, in slot order.
    const float integrationStep =
        def.mode == SolverMode::SoftStep ? dt / static_cast<float>(def.subSteps) : dt;
    // Last solve's constraints and rigid states: the wide schedule is kept while they stay the
    // same (see below).
    s.lastConstraintContacts.swap(s.constraintContacts);
    s.lastConstraintBodies.swap(s.constraintBodies);
    s.lastStateRigid.swap(s.stateRigid);
    s.lastJointBodies.swap(s.jointBodies);
    if (!joints.empty()) {
        wakeJointedBodies();
    }
    // Two passes: the solver indices first, so the arrays are sized once and each body written
    // whole in its place (growing them body by body, each element default-built and then
    // overwritten, was about 80 instructions a body).
    detail::Body* const bodySlots = bodies.data();
    const std::size_t bodyCount = bodies.size();
    int simCount = 0;
    s.bodySolverIndex.resize(bodyCount);
    for (std::size_t bi = 0; bi < bodyCount; ++bi) {
        detail::Body& b = bodySlots[bi];
        const bool moving = b.alive & b.enabled & (b.type != BodyType::Static) & b.motion.awake;
        b.motion.solverIndex = moving ? simCount++ : kNullIndex;
        s.bodySolverIndex[bi] = b.motion.solverIndex;
    }
    s.sims.resize(static_cast<std::size_t>(simCount));
    s.states.resize(static_cast<std::size_t>(simCount));
    s.contactRows.resize(static_cast<std::size_t>(simCount));
    s.stateRigid.resize(static_cast<std::size_t>(simCount));
    // Each body writes its own slots: on the workers (about 50 ns a body).
    auto copyIn = [&](int firstBody, int endBody, int /*worker*/) {
        // The arrays in locals: the byte stores to stateRigid may alias them for the compiler, which
        // then loaded them from the world again for every body.
        detail::BodySim* const sims = s.sims.data();
        detail::BodyState* const states = s.states.data();
        detail::ContactBodyRow* const contactRows = s.contactRows.data();
        unsigned char* const stateRigid = s.stateRigid.data();
        const Vec2 bodyGravity = gravity;
        const detail::SpeedCaps caps = detail::speedCaps(def.maxLinearSpeed, integrationStep);
        for (auto bi = static_cast<std::size_t>(firstBody); bi < static_cast<std::size_t>(endBody);
             ++bi) {
            // The walk reads each body's transform and motion, stalling on them even in a
            // base-40 pyramid (perf: a third of solve()'s own time in falling circles); a few
            // bodies ahead hides it (pyramid_40 and falling circles about -4 %, measured).
            if (bi + 4 < static_cast<std::size_t>(endBody)) {
                detail::prefetchObject(bodySlots + bi + 4);
            }
            const detail::Body& b = bodySlots[bi];
            const detail::BodyMotion& m = b.motion;
            if (m.solverIndex == kNullIndex) {
                continue;
            }
            const auto k = static_cast<std::size_t>(m.solverIndex);
            // transformPoint(), its rotation kept for the contacts (viewOf()).
            const Vec2 centerOffset = rotate(b.transform.q, m.localCenter);
            const Vec2 center = centerOffset + b.transform.p;
            const Vec2 invMass{m.lockX ? 0.0f : m.invMass, m.lockY ? 0.0f : m.invMass};
            detail::BodySim& entry = sims[k];
            entry = detail::BodySim{
                .transform = b.transform,
                .center = center,
                .center0 = center,
                .rotation0 = b.transform.q,
                .localCenter = m.localCenter,
                .force = m.force,
                .torque = m.torque,
                .invMass = invMass,
                .invInertia = m.invInertia,
                .linearDamping = m.linearDamping,
                .angularDamping = m.angularDamping,
                .gravityScale = m.gravityScale,
                .maxExtent = m.maxExtent,
                .minExtent = m.minExtent,
                .bodyIndex = static_cast<int>(bi),
                .flags = m.isBullet ? std::uint32_t{detail::kIsBullet} : 0u,
            };
            // The integration steps' gravity, forces and damping, here while the body is at hand
            // rather than in a pass of its own (the soft step's sub-steps; the classic solver and
            // solveSoftStep() prepare their own).
            detail::prepareIntegration(entry, bodyGravity, integrationStep);
            // Whether invMass.x, invMass.y and invInertia are all zero (+0 or -0): their bits past
            // the sign are. One test for the three float comparisons (== 0.0f each), which cost
            // about fifteen instructions a body without branches.
            stateRigid[k] =
                static_cast<unsigned char>(((std::bit_cast<std::uint32_t>(invMass.x) |
                                             std::bit_cast<std::uint32_t>(invMass.y) |
                                             std::bit_cast<std::uint32_t>(m.invInertia)) &
                                            0x7FFFFFFFu) == 0u);
            // A kinematic body keeps its velocity; a locked axis has none.
            Vec2 v{m.lockX && b.type == BodyType::Dynamic ? 0.0f : b.linearVelocity.x,
                   m.lockY && b.type == BodyType::Dynamic ? 0.0f : b.linearVelocity.y};
            float w =
                m.invInertia == 0.0f && b.type == BodyType::Dynamic ? 0.0f : b.angularVelocity;
            // Velocities set beyond the caps (a finite 1e38 spin) are capped before the contacts
            // read them: integration would cap them anyway, and a contact's approach speed taken
            // from the raw value could overflow its restitution and hit event.
            detail::clampVelocity(v, w, caps);
            states[k] = detail::BodyState{
                .linearVelocity = v, .angularVelocity = w, .deltaPosition = m.positionResidual};
            contactRows[k] = detail::ContactBodyRow{.linearVelocity = v,
                                                    .angularVelocity = w,
                                                    .invInertia = m.invInertia,
                                                    .centerOffset = centerOffset,
                                                    .invMass = invMass};
        }
    };
    tasks.parallelFor(static_cast<int>(bodyCount), tasks.minRange(50), copyIn);

    prepareJoints(dt, integrationStep);
    detail::ContactSoftness softness = detail::makeContactSoftness(def, dt);
    // A contact's side as prepareContact() sees it: body `bodyIndex`, `solverIndex` its place
    // in this step's arrays (kNullIndex: static or asleep, read from the body itself).
    auto viewOf = [&](int bodyIndex, int solverIndex) {
        if (solverIndex == kNullIndex) {
            const detail::Body& b = body(bodyIndex);
            return detail::ContactBodyView{.centerOffset =
                                               rotate(b.transform.q, b.motion.localCenter)};
        }
        // The step's copy of the body (its centre offset rotated once for all its contacts), as
        // the step begins: contacts are prepared before any solve moves their bodies.
        const detail::ContactBodyRow& row = s.contactRows[static_cast<std::size_t>(solverIndex)];
        return detail::ContactBodyView{.centerOffset = row.centerOffset,
                                       .linearVelocity = row.linearVelocity,
                                       .angularVelocity = row.angularVelocity,
                                       .invMass = row.invMass,
                                       .invInertia = row.invInertia,
                                       .stateIndex = solverIndex};
    };
    auto isRigid = [](const detail::ContactBodyView& v) {
        return detail::isRigidSide(v.invMass, v.invInertia);
    };
    auto softnessOf = [&](const detail::ContactBodyView& a, const detail::ContactBodyView& b) {
        return isRigid(a) || isRigid(b) ? softness.vsStatic : softness.dynamic;
    };
    // Relative acceleration from gravity pressing B onto A along the normal (restitution).
    auto pressOf = [&](const detail::Contact& c, const detail::ContactBodyView& a,
                       const detail::ContactBodyView& b) {
        auto gravityOf = [&](const detail::ContactBodyView& v, int bodyIndex) {
            float scale = body(bodyIndex).motion.gravityScale;
            return Vec2{v.invMass.x > 0.0f ? scale * gravity.x : 0.0f,
                        v.invMass.y > 0.0f ? scale * gravity.y : 0.0f};
        };
        return -dot(gravityOf(b, c.bodyB) - gravityOf(a, c.bodyA), c.manifold.normal);
    };
    // Whether a contact overlaps deeper than its load explains (shapes spawned or moved into
    // each other): the soft step then sweeps more, so that pushing them apart leaves no velocity
    // behind (detail::kPushOutRelaxIterations).
    auto pushedApart = [&](const detail::Contact& c, const detail::ContactBodyView& a,
                           const detail::ContactBodyView& b) {
        if (def.mode != SolverMode::SoftStep) {
            return false;
        }
        return detail::isPushedApart(c.manifold, a, b, softnessOf(a, b));
    };
    bool pushOut = false; // the scalar solvers': any contact in the world
    // One constraint per touching solid contact with a moving side, in contact order.
    // Sized for every touching contact and cut to the ones kept: a push_back per constraint
    // checked the capacity of both arrays each time.
    bool rolling = false;
    int constraintCount = 0;
    s.constraintContacts.resize(s.touchingContacts.size());
    s.constraintBodies.resize(s.touchingContacts.size());
    {
        // On the workers, in chunks of kConstraintChunk touching contacts (one chunk with one
        // worker), each cut to its kept ones in place; the chunks are closed up here, in order.
        const auto touching = static_cast<int>(s.touchingContacts.size());
        const int chunk = tasks.workerCount() > 1 ? kConstraintChunk : std::max(touching, 1);
        const int chunkCount = (touching + chunk - 1) / chunk;
        s.constraintChunkKept.resize(static_cast<std::size_t>(chunkCount));
        std::atomic<bool> anyRolling{false};
        auto listChunks = [&](int firstChunk, int endChunk, int /*worker*/) {
            // The arrays and the count in locals, as in the copy above (the lambdas below take
            // constraintCount by reference, which kept it in memory through the loop).
            int* const contactsOut = s.constraintContacts.data();
            detail::Simulation::ConstraintBodies* const bodiesOut = s.constraintBodies.data();
            const detail::Simulation::TouchingContact* const touchingIn = s.touchingContacts.data();
            const int* const solverIndexOf = s.bodySolverIndex.data();
            bool rollingHere = false;
            for (int ch = firstChunk; ch < endChunk; ++ch) {
                const int begin = ch * chunk;
                const int end = std::min(begin + chunk, touching);
                int kept = begin;
                for (int i = begin; i < end; ++i) {
                    const detail::Simulation::TouchingContact& c = touchingIn[i];
                    const int indexA = solverIndexOf[c.bodyA];
                    const int indexB = solverIndexOf[c.bodyB];
                    if (indexA == kNullIndex && indexB == kNullIndex) {
                        continue;
                    }
                    rollingHere |= c.rollingResistance > 0.0f;
                    contactsOut[kept] = c.contact;
                    bodiesOut[kept] = {indexA, indexB};
                    ++kept;
                }
                s.constraintChunkKept[static_cast<std::size_t>(ch)] = kept - begin;
            }
            if (rollingHere) {
                anyRolling.store(true, std::memory_order_relaxed);
            }
        };
        // About 6 ns a contact.
        tasks.parallelFor(chunkCount, tasks.minRange(6 * chunk), listChunks);
        rolling = anyRolling.load(std::memory_order_relaxed);
        for (int ch = 0; ch < chunkCount; ++ch) {
            const int begin = ch * chunk;
            const int kept = s.constraintChunkKept[static_cast<std::size_t>(ch)];
            if (constraintCount != begin) {
                std::memmove(&s.constraintContacts[static_cast<std::size_t>(constraintCount)],
                             &s.constraintContacts[static_cast<std::size_t>(begin)],
                             static_cast<std::size_t>(kept) * sizeof(int));
                std::memmove(&s.constraintBodies[static_cast<std::size_t>(constraintCount)],
                             &s.constraintBodies[static_cast<std::size_t>(begin)],
                             static_cast<std::size_t>(kept) *
                                 sizeof(detail::Simulation::ConstraintBodies));
            }
            constraintCount += kept;
        }
    }
    s.constraintContacts.resize(static_cast<std::size_t>(constraintCount));
    s.constraintBodies.resize(static_cast<std::size_t>(constraintCount));

    // Rolling resistance is scalar only (and solved in contact order).
    const bool wide = def.mode == SolverMode::SoftStep && !rolling;
    if (wide) {
        // A settled pile has the same constraints step after step: its schedule is last step's.
        // (The build below rewrites every lane of every group, padding included.)
        auto sameAsLast = [](const auto& now, const auto& last) {
            return now.size() == last.size() &&
                   (now.empty() ||
                    std::memcmp(now.data(), last.data(), now.size() * sizeof(now[0])) == 0);
        };
        static_assert(sizeof(detail::Simulation::ConstraintBodies) == 2 * sizeof(int));
        const bool same = s.wideScheduleValid && s.stateRigid == s.lastStateRigid &&
                          sameAsLast(s.constraintBodies, s.lastConstraintBodies) &&
                          sameAsLast(s.constraintContacts, s.lastConstraintContacts) &&
                          sameAsLast(s.jointBodies, s.lastJointBodies);
        if (!same) {
            // Each constraint's level: its colour (see ConstraintColors), taken in contact
            // order. The constraints of a level share no moving body, so the wide solver takes
            // several at a time, and there are few levels: a stack or a pyramid is a handful of
            // full ones, not one per row. A rigid side is not moving: the constraint never
            // changes its velocity.
            auto moving = [&](int k) {
                return k == kNullIndex || s.stateRigid[static_cast<std::size_t>(k)] != 0
                           ? kNullIndex
                           : k;
            };
            s.colors.reset(static_cast<int>(s.sims.size()));
            s.constraintLevel.clear();
            for (const detail::Simulation::ConstraintBodies& cb : s.constraintBodies) {
                s.constraintLevel.push_back(s.colors.assign(moving(cb.indexA), moving(cb.indexB)));
            }
            scheduleWide(constraintCount);
        }
        if (!s.activeJoints.empty()) {
            assignJointBlocks(same);
        }
    }
    s.wideScheduleValid = wide;
    if (!wide && !s.activeJoints.empty()) {
        packJoints();
    }

    if (wide) {
        // Built block by block right before each block is solved (below).
        s.constraints.clear();
    } else {
        s.constraints.resize(static_cast<std::size_t>(constraintCount));
        for (std::size_t k = 0; k < s.constraintContacts.size(); ++k) {
            const int ci = s.constraintContacts[k];
            const detail::Contact& c = s.contacts[static_cast<std::size_t>(ci)];
            const detail::ContactBodyView a = viewOf(c.bodyA, s.constraintBodies[k].indexA);
            const detail::ContactBodyView b = viewOf(c.bodyB, s.constraintBodies[k].indexB);
            detail::ContactConstraint& cc = s.constraints[k];
            detail::prepareContact(cc, c.manifold, a, b,
                                   {c.friction, c.restitution, c.rollingResistance},
                                   softnessOf(a, b));
            cc.pressAcceleration = pressOf(c, a, b);
            cc.contactIndex = ci;
            pushOut = pushOut || pushedApart(c, a, b);
        }
    }

    // Impulses go back to the manifolds for next step's warm start; a hit event for the
    // fastest approaching point of each, emitted in contact order at the end.
    s.hitCandidates.clear();
    // A hit candidate for the fastest approaching point of contact `contactIndex` that was
    // pushed on, if one approached faster than the threshold.
    auto noteHit = [&](std::vector<detail::Simulation::HitCandidate>& hits, int contactIndex,
                       int pointCount, const float* relativeVelocity,
                       const float* maxNormalImpulse) {
        float fastest = def.hitEventThreshold;
        int fastestPoint = -1;
        for (int j = 0; j < pointCount; ++j) {
            float approach = -relativeVelocity[j];
            if (maxNormalImpulse[j] > 0.0f && approach > fastest) {
                fastest = approach;
                fastestPoint = j;
            }
        }
        if (fastestPoint >= 0) {
            hits.push_back({contactIndex, fastestPoint, fastest});
        }
    };

    const detail::JointStep jointStep = detail::makeJointStep(def, integrationStep, &s.jointDirect);
    detail::SolverStep step{s.sims, s.states, s.constraints, gravity,   dt,
                            &def,   joints,   s.jointOrder,  jointStep, &s.pointJoints};
    auto pushOutSweeps = [](detail::SolverStep& st, bool on) {
        st.extraSolveIterations = on ? detail::kPushOutSolveIterations : 0;
        st.extraRelaxIterations = on ? detail::kPushOutRelaxIterations : 0;
    };
    pushOutSweeps(step, pushOut);
    s.extraRelaxIterations = step.extraRelaxIterations;
    if (wide) {
        // The lanes pick their softness from these (prepareWideGroup()).
        s.wideContacts.dynamic = softness.dynamic;
        s.wideContacts.vsStatic = softness.vsStatic;
        // Contacts are visited in slot order, twice a block: gathered before it is solved and
        // their impulses stored right after, while its lanes are in cache. A level's contacts
        // lie one island apart in the array, too far for the hardware prefetcher: where they
        // do not fit in the cache, fetch the ones a few slots ahead: the lines the solver reads
        // (Contact::kSolverBytes), not the whole contact: the slots before prefetchEnd do (none
        // where the contacts fit). (Always inlined: GCC deletes a call to a function that only
        // prefetches, see prefetch.hpp.)
        constexpr int kPrefetchAhead = 16;
        const int prefetchEnd = s.contacts.size() * sizeof(detail::Contact) > detail::kPrefetchBytes
                                    ? constraintCount - kPrefetchAhead
                                    : 0;
        auto prefetchContact = [](const detail::Contact* contacts, const int* slotContact, int slot)
            __attribute__((always_inline)) {
            detail::prefetchFirst<detail::Contact::kSolverBytes>(
                contacts + slotContact[static_cast<std::size_t>(slot + kPrefetchAhead)]);
        };
        // Group `group` of level `level`: where its constraints' manifolds and bodies are,
        // gathered lane by lane, then prepared all at once (prepareWideGroup()), right before
        // its block is solved: no constraint array in between, and the block's contacts, lanes
        // and bodies stay in cache through build, sub-steps and store. Appends its restitution
        // entries; returns whether it holds shapes pushed apart.
        auto buildGroup = [&](auto& in, int level, int group,
                              std::vector<detail::WideRestitution>& restitution) {
            constexpr int N = static_cast<int>(sizeof(in.indexA) / sizeof(in.indexA[0]));
            const int levelFirst = s.levelStart[static_cast<std::size_t>(level)];
            const int levelEnd = s.levelStart[static_cast<std::size_t>(level) + 1];
            const int first =
                levelFirst +
                (group - s.wideContacts.levelStart[static_cast<std::size_t>(level)]) * N;
            // The arrays in locals: the lanes' pointer stores below may alias them for the
            // compiler, which then loaded them from the world again for every lane.
            const detail::ContactBodyRow* const rows = s.contactRows.data();
            const detail::Contact* const contacts = s.contacts.data();
            const int* const slotContact = s.slotContact.data();
            const detail::Simulation::ConstraintBodies* const slotBodies = s.slotBodies.data();
            const int prefetchBefore = prefetchEnd;
            // The lanes' common case first, in a loop without calls: a moving side's row, and
            // which lanes have a static (or asleep) side or restitution, handled after it.
            const int used = std::min(N, levelEnd - first);
            int staticLanes = 0;
            int restitutionLanes = 0;
            for (int lane = 0; lane < used; ++lane) {
                const int slot = first + lane;
                if (slot < prefetchBefore) {
                    prefetchContact(contacts, slotContact, slot);
                }
                const auto at = static_cast<std::size_t>(slot);
                const detail::Contact& c = contacts[slotContact[at]];
                const detail::Simulation::ConstraintBodies sides = slotBodies[at];
                in.manifold[lane] = &c.manifold;
                in.indexA[lane] = sides.indexA;
                in.indexB[lane] = sides.indexB;
                in.friction[lane] = c.friction;
                in.sideA[lane] = rows + std::max(sides.indexA, 0);
                in.sideB[lane] = rows + std::max(sides.indexB, 0);
                staticLanes |= (sides.indexA < 0 || sides.indexB < 0 ? 1 : 0) << lane;
                restitutionLanes |= (c.restitution != 0.0f ? 1 : 0) << lane;
            }
            // A static side's row: viewOf()'s centre offset, no velocity, no mass.
            for (int bits = staticLanes; bits != 0; bits &= bits - 1) {
                const int lane = std::countr_zero(static_cast<unsigned>(bits));
                const detail::Contact& c =
                    contacts[slotContact[static_cast<std::size_t>(first + lane)]];
                if (in.indexA[lane] < 0) {
                    detail::ContactBodyRow& row = in.staticSides[2 * lane];
                    row = {.centerOffset = viewOf(c.bodyA, kNullIndex).centerOffset};
                    in.sideA[lane] = &row;
                }
                if (in.indexB[lane] < 0) {
                    detail::ContactBodyRow& row = in.staticSides[2 * lane + 1];
                    row = {.centerOffset = viewOf(c.bodyB, kNullIndex).centerOffset};
                    in.sideB[lane] = &row;
                }
            }
            for (int bits = restitutionLanes; bits != 0; bits &= bits - 1) {
                const int lane = std::countr_zero(static_cast<unsigned>(bits));
                const int slot = first + lane;
                const auto at = static_cast<std::size_t>(slot);
                const detail::Contact& c = contacts[slotContact[at]];
                restitution.push_back(
                    {level, slot - levelFirst, c.manifold.pointCount, c.restitution,
                     pressOf(c, viewOf(c.bodyA, in.indexA[lane]), viewOf(c.bodyB, in.indexB[lane])),
                     s.slotConstraint[at]});
            }
            for (int lane = used; lane < N; ++lane) {
                in.clearLane(lane);
            }
            // pushedApart() on every lane (the wide path is soft-step).
            return detail::prepareWideGroup(s.wideContacts, group, in, s.states) != 0;
        };
        // The level holding group `group` among levels [firstLevel, endLevel) (a group past
        // the last of a level is in the next non-empty one).
        const std::span<const int> groupStart = s.wideContacts.levelStart;
        auto levelOfGroup = [&](int firstLevel, int endLevel, int group) {
            const auto begin = groupStart.begin() + firstLevel;
            return static_cast<int>(std::upper_bound(begin, groupStart.begin() + endLevel, group) -
                                    groupStart.begin()) -
                   1;
        };
        // Builds the groups [groupBegin, groupEnd) of levels [firstLevel, endLevel).
        auto buildGroups = [&](int firstLevel, int endLevel, int groupBegin, int groupEnd,
                               std::vector<detail::WideRestitution>& restitution) {
            auto build = [&](auto& in) {
                bool pushOutHere = false;
                int level = levelOfGroup(firstLevel, endLevel, groupBegin);
                for (int g = groupBegin; g < groupEnd; ++g) {
                    while (groupStart[static_cast<std::size_t>(level) + 1] <= g) {
                        ++level;
                    }
                    pushOutHere = buildGroup(in, level, g, restitution) || pushOutHere;
                }
                return pushOutHere;
            };
            if (s.wideContacts.lanes == 8) {
                detail::WideGatherT<8> lanes8;
                return build(lanes8);
            }
            detail::WideGatherT<4> lanes4;
            return build(lanes4);
        };
        // applyRestitution() goes in constraint order.
        auto sortRestitution = [](std::vector<detail::WideRestitution>& restitution) {
            std::sort(restitution.begin(), restitution.end(),
                      [](const detail::WideRestitution& x, const detail::WideRestitution& y) {
                          return x.constraint < y.constraint;
                      });
        };
        // Where a slot's impulses go (detail::storeWideImpulses()): its contact's manifold.
        // (The arrays by value: through the world the compiler loaded them again for each lane.)
        auto manifoldOfSlot = [contacts = s.contacts.data(), slotContact = s.slotContact.data(),
                               prefetchEnd, prefetchContact](int slot) -> Manifold& {
            if (slot < prefetchEnd) {
                prefetchContact(contacts, slotContact, slot);
            }
            return contacts[slotContact[static_cast<std::size_t>(slot)]].manifold;
        };
        // A slot's hit, noted in `hits`.
        auto hitOfSlot = [&](std::vector<detail::Simulation::HitCandidate>& hits) {
            return [&, out = &hits](int slot, const Manifold& m, const detail::WideLaneHit& h) {
                noteHit(*out, s.slotContact[static_cast<std::size_t>(slot)], m.pointCount,
                        h.relativeVelocity, h.maxNormalImpulse);
            };
        };
        const std::span<const int> blockBodies = s.blockBodies;
        auto bodiesOf = [&](std::size_t b) {
            return blockBodies.subspan(
                static_cast<std::size_t>(s.blockBodyStart[b]),
                static_cast<std::size_t>(s.blockBodyStart[b + 1] - s.blockBodyStart[b]));
        };
        const int blockCount = static_cast<int>(s.blockLevelStart.size()) - 1;
        const int workerCount = tasks.workerCount();
        s.blockWorkers.resize(static_cast<std::size_t>(workerCount));
        for (detail::Simulation::BlockWorker& w : s.blockWorkers) {
            w.hits.clear();
            w.extraRelaxIterations = 0;
            w.jointDirect.resetDense();
        }
        // A block holding more than a worker's share of the constraints (a single large pile)
        // is solved by all workers at once, stage by stage (solveSoftStepStaged()), when it is
        // large enough for that to pay, has no joints (their passes are not split) and no
        // rigid side (a kinematic body's state may be in several constraints of one level).
        auto isStaged = [&](std::size_t b) {
            const int constraints =
                s.levelStart[static_cast<std::size_t>(s.blockLevelStart[b + 1])] -
                s.levelStart[static_cast<std::size_t>(s.blockLevelStart[b])];
            const bool jointed =
                !s.activeJoints.empty() && s.blockJointStart[b + 1] > s.blockJointStart[b];
            return workerCount > 1 && constraints >= kStagedBlockConstraints &&
                   constraints * workerCount > constraintCount && !jointed && s.blockRigid[b] == 0;
        };
        // Build and store are per group, in pieces over the workers; what the pieces gather
        // (restitution lists, hits) is put in constraint or contact order afterwards.
        constexpr int kGroupsPerPiece = 16;
        auto solveStaged = [&](std::size_t b) {
            const int firstLevel = s.blockLevelStart[b];
            const int endLevel = s.blockLevelStart[b + 1];
            s.counters.stagedConstraints += s.levelStart[static_cast<std::size_t>(endLevel)] -
                                            s.levelStart[static_cast<std::size_t>(firstLevel)];
            const int groupBegin = groupStart[static_cast<std::size_t>(firstLevel)];
            const int groupEnd = groupStart[static_cast<std::size_t>(endLevel)];
            for (detail::Simulation::BlockWorker& w : s.blockWorkers) {
                w.restitution.clear();
                w.pushOut = false;
            }
            tasks.parallelFor(groupEnd - groupBegin, kGroupsPerPiece,
                              [&](int begin, int end, int worker) {
                                  detail::Simulation::BlockWorker& w =
                                      s.blockWorkers[static_cast<std::size_t>(worker)];
                                  w.pushOut = buildGroups(firstLevel, endLevel, groupBegin + begin,
                                                          groupBegin + end, w.restitution) ||
                                              w.pushOut;
                              });
            std::vector<detail::WideRestitution>& restitution = s.stagedRestitution;
            restitution.clear();
            bool blockPushOut = false;
            for (const detail::Simulation::BlockWorker& w : s.blockWorkers) {
                restitution.insert(restitution.end(), w.restitution.begin(), w.restitution.end());
                blockPushOut = blockPushOut || w.pushOut;
            }
            sortRestitution(restitution);
            detail::SolverStep blockStep = step;
            pushOutSweeps(blockStep, blockPushOut);
            s.extraRelaxIterations =
                std::max(s.extraRelaxIterations, blockStep.extraRelaxIterations);
            const bool impacts = !restitution.empty() && s.impacts.plan(s, restitution, dt);
            detail::solveSoftStepStaged(blockStep, s.wideContacts, firstLevel, endLevel,
                                        bodiesOf(b), restitution, tasks, s.softStepStages);
            tasks.parallelFor(
                groupEnd - groupBegin, kGroupsPerPiece, [&](int begin, int end, int worker) {
                    auto hit = hitOfSlot(s.blockWorkers[static_cast<std::size_t>(worker)].hits);
                    int level = levelOfGroup(firstLevel, endLevel, groupBegin + begin);
                    for (int g = groupBegin + begin; g < groupBegin + end;) {
                        const int levelEnd = std::min(
                            groupStart[static_cast<std::size_t>(level) + 1], groupBegin + end);
                        detail::storeWideImpulsesOfGroups(s.wideContacts, s.levelStart, level, g,
                                                          levelEnd, def.hitEventThreshold,
                                                          manifoldOfSlot, hit);
                        g = levelEnd;
                        ++level;
                    }
                });
            if (impacts) {
                s.impacts.apply(s);
            }
        };
        // Blocks share no body (see scheduleWide()), so the others are solved on several
        // workers at once, each block whole on one, with what the others also write kept per
        // worker.
        auto solveBlock = [&](std::size_t b, detail::Simulation::BlockWorker& worker) {
            const int firstLevel = s.blockLevelStart[b];
            const int endLevel = s.blockLevelStart[b + 1];
            if ((firstLevel == endLevel && s.blockBodyStart[b] == s.blockBodyStart[b + 1]) ||
                isStaged(b)) {
                return; // the block of bodies no constraint touches and there are none, or done
            }
            // Only the block holding shapes pushed apart sweeps more.
            detail::SolverStep blockStep = step;
            if (blockStep.jointStep.direct != nullptr) {
                blockStep.jointStep.direct = &worker.jointDirect;
            }
            worker.restitution.clear();
            const bool blockPushOut =
                buildGroups(firstLevel, endLevel, groupStart[static_cast<std::size_t>(firstLevel)],
                            groupStart[static_cast<std::size_t>(endLevel)], worker.restitution);
            sortRestitution(worker.restitution);
            pushOutSweeps(blockStep, blockPushOut);
            worker.extraRelaxIterations =
                std::max(worker.extraRelaxIterations, blockStep.extraRelaxIterations);
            // Struck rows of elastic bodies pass their impacts on (contact_impacts.hpp).
            const bool impacts =
                !worker.restitution.empty() && worker.impacts.plan(s, worker.restitution, dt);
            detail::solveSoftStepBlock(
                blockStep, s.wideContacts, firstLevel, endLevel, bodiesOf(b), worker.restitution,
                s.activeJoints.empty()
                    ? std::span<const int>{}
                    : std::span<const int>(s.blockJoints)
                          .subspan(static_cast<std::size_t>(s.blockJointStart[b]),
                                   static_cast<std::size_t>(s.blockJointStart[b + 1] -
                                                            s.blockJointStart[b])));
            detail::storeWideImpulses(s.wideContacts, s.levelStart, firstLevel, endLevel,
                                      def.hitEventThreshold, manifoldOfSlot,
                                      hitOfSlot(worker.hits));
            if (impacts) {
                worker.impacts.apply(s);
            }
        };
        for (int b = 0; b < blockCount; ++b) {
            if (isStaged(static_cast<std::size_t>(b))) {
                solveStaged(static_cast<std::size_t>(b));
            }
        }
        auto solveBlocks = [&](int begin, int end, int worker) {
            for (int b = begin; b < end; ++b) {
                solveBlock(static_cast<std::size_t>(b),
                           s.blockWorkers[static_cast<std::size_t>(worker)]);
            }
        };
        // Blocks go whole to one worker: the others can take only what lies outside the
        // largest one, about 40 ns a constraint; too little, and the caller does them all.
        int blockedConstraints = 0;
        int largestBlock = 0;
        for (std::size_t b = 0; b < static_cast<std::size_t>(blockCount); ++b) {
            if (!isStaged(b)) {
                const int constraints =
                    s.levelStart[static_cast<std::size_t>(s.blockLevelStart[b + 1])] -
                    s.levelStart[static_cast<std::size_t>(s.blockLevelStart[b])];
                blockedConstraints += constraints;
                largestBlock = std::max(largestBlock, constraints);
            }
        }
        const bool spread = blockedConstraints - largestBlock >= tasks.minRange(40);
        tasks.parallelFor(blockCount, spread ? 1 : blockCount, solveBlocks);
        std::vector<int>& dense = s.jointDirect.denseComponents; // a set: order does not matter
        for (detail::Simulation::BlockWorker& w : s.blockWorkers) {
            s.hitCandidates.insert(s.hitCandidates.end(), w.hits.begin(), w.hits.end());
            s.extraRelaxIterations = std::max(s.extraRelaxIterations, w.extraRelaxIterations);
            dense.insert(dense.end(), w.jointDirect.denseComponents.begin(),
                         w.jointDirect.denseComponents.end());
        }
    } else {
        const bool impacts = s.impacts.plan(s, s.constraints, dt);
        if (def.mode == SolverMode::SoftStep) {
            detail::solveSoftStep(step);
        } else {
            detail::solveClassic(step);
        }
        if (impacts) {
            s.impacts.apply(s);
        }
    }
    if (!s.activeJoints.empty()) {
        storeJointReactions(1.0f / integrationStep, wide);
        if (def.mode == SolverMode::SoftStep) {
            projectJoints();
        }
    }
    finalizeAndSweep(def.enableContinuous);
    if (def.enableContinuous && !s.activeJoints.empty() && def.mode == SolverMode::SoftStep) {
        reprojectJointsAfterContinuous();
    }

    // Write back, move the proxies, the move events (collectMoveEvents() marks the ones
    // updateSleep() puts to sleep).
    writeBack(dt);

    if (!wide) {
        for (const detail::ContactConstraint& cc : s.constraints) {
            if (!s.contacts[static_cast<std::size_t>(cc.contactIndex)].alive) {
                continue; // ended with a non-finite body
            }
            // Impulses back to the manifold for next step's warm start.
            Manifold& m = s.contacts[static_cast<std::size_t>(cc.contactIndex)].manifold;
            float relativeVelocity[2];
            float maxNormalImpulse[2];
            for (int j = 0; j < cc.pointCount; ++j) {
                m.points[j].normalImpulse = cc.points[j].normalImpulse;
                m.points[j].tangentImpulse = cc.points[j].tangentImpulse;
                relativeVelocity[j] = cc.points[j].relativeVelocity;
                maxNormalImpulse[j] = cc.points[j].maxNormalImpulse;
            }
            noteHit(s.hitCandidates, cc.contactIndex, cc.pointCount, relativeVelocity,
                    maxNormalImpulse);
        }
    } else {
        std::sort(s.hitCandidates.begin(), s.hitCandidates.end(),
                  [](const detail::Simulation::HitCandidate& x,
                     const detail::Simulation::HitCandidate& y) { return x.contact < y.contact; });
    }
    for (const detail::Simulation::HitCandidate& h : s.hitCandidates) {
        const detail::Contact& c = s.contacts[static_cast<std::size_t>(h.contact)];
        if (!c.alive || !c.hitEvents) {
            continue; // ended with a non-finite body, or a shape's hit events are off
        }
        // A speculative point sits midway across the gap; the hit is on A's surface.
        const ManifoldPoint& mp = c.manifold.points[h.point];
        const detail::ContactLinks& l = s.contactLinks[static_cast<std::size_t>(h.contact)];
        s.hitEvents.push_back({l.idA, l.idB, mp.point - 0.5f * mp.separation * c.manifold.normal,
                               c.manifold.normal, h.speed});
    }
}

} // namespace e2d::physics
