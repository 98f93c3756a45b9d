// SPDX-License-Identifier: MIT
// The joints' part of World::step(): waking the sleeping side of a joint, preparing the
// step's joints, sorting them into the wide solver's blocks and reading their reactions.
#include "world_impl.hpp"

#include "body_solver.hpp"

#include <algorithm>
#include <cstring>

namespace e2d::physics {

using detail::kNullIndex;

namespace {

// The direct joint solve reads joint slots only: no groups of plain hinges.
bool directJoints(const SolverDef& def) {
    return def.mode == SolverMode::SoftStep && def.jointSolver == JointSolver::Direct;
}

} // namespace

void World::Impl::wakeJointedBodies() {
    // Nothing to wake while every moving body is awake (a scene without sleeping): a pass over
    // the bodies is cheaper than one over the joints and both their bodies.
    bool anyAsleep = false;
    for (std::size_t bi = 0; bi < bodies.size(); ++bi) {
        const detail::Body& b = bodies[bi];
        if (b.alive && b.enabled && b.type != BodyType::Static && !b.motion.awake) {
            anyAsleep = true;
            break;
        }
    }
    if (!anyAsleep) {
        return;
    }
    for (const detail::Joint& j : joints) {
        if (!j.alive || j.type == JointType::Mouse) {
            continue;
        }
        const detail::Body& a = body(j.bodyA);
        const detail::Body& b = body(j.bodyB);
        if (a.type == BodyType::Static || b.type == BodyType::Static || !a.enabled || !b.enabled ||
            a.motion.awake == b.motion.awake) {
            continue;
        }
        wakeBody(a.motion.awake ? j.bodyB : j.bodyA);
    }
}

void World::Impl::prepareJoints(float dt, float h) {
    (void)dt;
    detail::Simulation& s = sim;
    using Key = detail::Simulation::JointKey;
    s.jointKeys.swap(s.lastJointKeys);
    s.jointKeys.clear();
    s.jointsReused = false;
    auto reset = [&] {
        s.activeJoints.clear();
        s.activeJointLevels.clear();
        s.jointOrder.clear();
        s.pointJoints.clear();
        s.jointBodies.clear();
        s.jointLayout = detail::Simulation::JointLayout::None;
    };
    s.jointDirect.resetDense();
    if (joints.empty()) {
        reset();
        return;
    }
    const detail::JointStep step = detail::makeJointStep(s.def, h, nullptr);
    auto viewOf = [&](const detail::Body& b) {
        detail::JointBodyView v;
        const int k = b.motion.solverIndex;
        if (k == kNullIndex) {
            v.q = b.transform.q;
            v.localCenter = b.motion.localCenter;
            v.center = transformPoint(b.transform, b.motion.localCenter);
            return v;
        }
        const detail::BodySim& bs = s.sims[static_cast<std::size_t>(k)];
        v.q = bs.transform.q;
        v.center = bs.center;
        v.localCenter = bs.localCenter;
        v.invMass = bs.invMass;
        v.invInertia = bs.invInertia;
        v.stateIndex = k;
        return v;
    };
    for (std::size_t ji = 0; ji < joints.size(); ++ji) {
        detail::Joint& j = joints[ji];
        if (!j.alive) {
            continue;
        }
        const detail::Body& a = body(j.bodyA);
        const detail::Body& b = body(j.bodyB);
        const bool moving = j.type == JointType::Mouse ? b.motion.solverIndex != kNullIndex
                                                       : a.motion.solverIndex != kNullIndex ||
                                                             b.motion.solverIndex != kNullIndex;
        if (!a.enabled || !b.enabled) {
            j.reactionForce = {0.0f, 0.0f};
            j.reactionTorque = 0.0f;
            continue;
        }
        if (!moving) {
            continue; // asleep: keeps the reaction it fell asleep with
        }
        detail::prepareJoint(j, viewOf(a), viewOf(b), step);
        s.jointKeys.push_back(
            {static_cast<int>(ji), j.indexA, j.indexB, detail::isPointJoint(j) ? 1 : 0});
    }
    if (directJoints(s.def)) {
        // Which groups of joints the direct solve leaves to Gauss-Seidel: a function of the
        // keys below, so a kept layout keeps it too.
        s.jointScratch.clear();
        for (const Key& key : s.jointKeys) {
            s.jointScratch.push_back(key.slot);
        }
        detail::markLoopyJoints(joints, s.jointScratch, s.sims.size(), s.jointDirect.components);
    }
    static_assert(sizeof(Key) == 4 * sizeof(int), "JointKey compares as ints");
    if (!s.jointKeys.empty() && s.jointKeys.size() == s.lastJointKeys.size() &&
        std::memcmp(s.jointKeys.data(), s.lastJointKeys.data(), s.jointKeys.size() * sizeof(Key)) ==
            0) {
        // The same joints, sides and kinds as last step: its levels and pass order hold.
        s.jointBodies = s.lastJointBodies;
        s.jointsReused = true;
        return;
    }
    reset();
    for (const Key& key : s.jointKeys) {
        s.activeJoints.push_back(key.slot);
        s.jointBodies.push_back({key.indexA, key.indexB});
    }
    orderJoints();
}

void World::Impl::orderJoints() {
    detail::Simulation& s = sim;
    const std::size_t n = s.activeJoints.size();
    // Levels as the contacts' (ConstraintLevels): a joint goes one level above the last level
    // of each body it moves, so every body meets its joints in slot order and the passes'
    // results are those of slot order, bit for bit; but the joints of a level share no body,
    // so consecutive ones do not wait for each other's velocity writes (a joint net in slot
    // order is one long chain of them).
    s.jointBodyLevel.assign(s.states.size(), -1);
    s.jointLevelStart.assign(1, 0);
    s.jointLevel.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const detail::Simulation::ConstraintBodies& jb = s.jointBodies[k];
        // A static or sleeping side (-1) is a fixed state of the joint's own.
        const int lastA =
            jb.indexA >= 0 ? s.jointBodyLevel[static_cast<std::size_t>(jb.indexA)] : -1;
        const int lastB =
            jb.indexB >= 0 ? s.jointBodyLevel[static_cast<std::size_t>(jb.indexB)] : -1;
        const int level = std::max(lastA, lastB) + 1;
        if (jb.indexA >= 0) {
            s.jointBodyLevel[static_cast<std::size_t>(jb.indexA)] = level;
        }
        if (jb.indexB >= 0) {
            s.jointBodyLevel[static_cast<std::size_t>(jb.indexB)] = level;
        }
        s.jointLevel[k] = level;
        if (static_cast<std::size_t>(level) + 1 >= s.jointLevelStart.size()) {
            s.jointLevelStart.resize(static_cast<std::size_t>(level) + 2, 0);
        }
        ++s.jointLevelStart[static_cast<std::size_t>(level) + 1];
    }
    for (std::size_t l = 1; l < s.jointLevelStart.size(); ++l) {
        s.jointLevelStart[l] += s.jointLevelStart[l - 1];
    }
    // Stable counting sort by level; activeJoints and jointBodies follow, activeJointLevels
    // says each one's level.
    s.jointSorted.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        s.jointSorted[static_cast<std::size_t>(
            s.jointLevelStart[static_cast<std::size_t>(s.jointLevel[k])]++)] = static_cast<int>(k);
    }
    s.jointScratch.assign(s.activeJoints.begin(), s.activeJoints.end());
    s.jointBodiesScratch.assign(s.jointBodies.begin(), s.jointBodies.end());
    s.activeJointLevels.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t from = static_cast<std::size_t>(s.jointSorted[k]);
        s.activeJoints[k] = s.jointScratch[from];
        s.jointBodies[k] = s.jointBodiesScratch[from];
        s.activeJointLevels[k] = s.jointLevel[from];
    }
}

void World::Impl::packJoints() {
    detail::Simulation& s = sim;
    // Classic mode's position pass reads the joint slots: no groups there.
    const bool groups = s.def.mode == SolverMode::SoftStep && !directJoints(s.def);
    const auto layout = groups ? detail::Simulation::JointLayout::Scalar
                               : detail::Simulation::JointLayout::ScalarNoGroups;
    if (s.jointsReused && s.jointLayout == layout) {
        // Last step's entries and groups, the lanes' fields from the joints prepared anew.
        detail::refreshPointJointGroups(s.pointJoints, joints);
        return;
    }
    ++s.counters.jointRepacks;
    s.jointOrder.clear();
    s.pointJoints.clear();
    s.pointJoints.lanes = std::min(detail::bestPointJointLanes(), s.simdLanes);
    detail::packJointPasses(joints, s.activeJoints, s.activeJointLevels, groups, s.pointJoints,
                            s.jointOrder);
    s.jointLayout = layout;
}

void World::Impl::assignJointBlocks(bool scheduleKept) {
    detail::Simulation& s = sim;
    if (scheduleKept && s.jointsReused && s.jointLayout == detail::Simulation::JointLayout::Wide) {
        // Last step's blocks, entries and groups, the lanes' fields from the joints prepared
        // anew.
        detail::refreshPointJointGroups(s.pointJoints, joints);
        return;
    }
    ++s.counters.jointRepacks;
    const std::size_t blocks = s.blockBodyStart.size() - 1;
    const std::size_t n = s.activeJoints.size();
    s.blockJointStart.assign(blocks + 1, 0);
    auto blockOf = [&](std::size_t k) {
        const detail::Simulation::ConstraintBodies& jb = s.jointBodies[k];
        return s.bodyBlock[static_cast<std::size_t>(jb.indexA >= 0 ? jb.indexA : jb.indexB)];
    };
    for (std::size_t k = 0; k < n; ++k) {
        ++s.blockJointStart[static_cast<std::size_t>(blockOf(k)) + 1];
    }
    for (std::size_t b = 0; b < blocks; ++b) {
        s.blockJointStart[b + 1] += s.blockJointStart[b];
    }
    // Each block's joints in pass order (a stable sort by block keeps the levels ascending),
    // then packed block by block; blockJointStart becomes the entries' bounds.
    s.levelNext.assign(s.blockJointStart.begin(), s.blockJointStart.end() - 1);
    s.jointScratch.resize(n);
    s.jointSorted.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t to =
            static_cast<std::size_t>(s.levelNext[static_cast<std::size_t>(blockOf(k))]++);
        s.jointScratch[to] = s.activeJoints[k];
        s.jointSorted[to] = s.activeJointLevels[k];
    }
    s.blockJoints.clear();
    s.pointJoints.clear();
    s.pointJoints.lanes = std::min(detail::bestPointJointLanes(), s.simdLanes);
    int first = 0;
    for (std::size_t b = 0; b < blocks; ++b) {
        const int end = s.blockJointStart[b + 1];
        const auto count = static_cast<std::size_t>(end - first);
        detail::packJointPasses(
            joints,
            std::span<const int>(s.jointScratch).subspan(static_cast<std::size_t>(first), count),
            std::span<const int>(s.jointSorted).subspan(static_cast<std::size_t>(first), count),
            !directJoints(s.def), s.pointJoints, s.blockJoints);
        first = end;
        s.blockJointStart[b + 1] = static_cast<int>(s.blockJoints.size());
    }
    s.jointLayout = detail::Simulation::JointLayout::Wide;
}

void World::Impl::storeJointReactions(float invH, bool wide) {
    detail::storePointJointGroups(sim.pointJoints, joints, invH);
    for (int entry : wide ? sim.blockJoints : sim.jointOrder) {
        if (entry >= 0) {
            detail::storeJointReaction(joint(entry), sim.states, invH);
        }
    }
}

void World::Impl::projectJoints() {
    detail::Simulation& s = sim;
    const JointSolver model = s.def.jointSolver;
    if (model == JointSolver::Soft) {
        return;
    }
    detail::projectJointComponents(joints, s.activeJoints, s.states, s.def.jointPositionIterations,
                                   model == JointSolver::GaussSeidel, s.jointDirect);
}

void World::Impl::reprojectJointsAfterContinuous() {
    detail::Simulation& s = sim;
    bool moved = false;
    for (std::size_t k = 0; k < s.sims.size(); ++k) {
        const detail::BodySim& bs = s.sims[k];
        detail::BodyState& st = s.states[k];
        const Vec2 unmoved = bs.center0 + st.deltaPosition; // finalizePositions()'s centre
        if (bs.center.x != unmoved.x || bs.center.y != unmoved.y) {
            // The continuous pass's pose, as the state's motion since the step start.
            st.deltaPosition = bs.center - bs.center0;
            const Rot q = bs.transform.q;
            const Rot r0 = bs.rotation0;
            st.deltaRotation = {q.c * r0.c + q.s * r0.s, q.s * r0.c - q.c * r0.s};
            moved = true;
        }
    }
    if (moved) {
        projectJoints();
        detail::finalizePositions(s.sims, s.states);
    }
}

} // namespace e2d::physics
