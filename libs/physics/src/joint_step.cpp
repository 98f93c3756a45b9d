// SPDX-License-Identifier: MIT
// The joints' part of World::step(): waking the sleeping side of a joint, preparing the
// step's joints, sorting them into the wide solver's blocks and reading their reactions.
#include "world_impl.hpp"

namespace e2d::physics {

using detail::kNullIndex;

void World::Impl::wakeJointedBodies() {
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
    s.activeJoints.clear();
    s.jointBodies.clear();
    if (joints.empty()) {
        return;
    }
    const detail::JointStep step{h, 1.0f / h, detail::makeSoftness(detail::kJointHertz, detail::kJointDampingRatio, h)};
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
        const bool moving = j.type == JointType::Mouse
                                ? b.motion.solverIndex != kNullIndex
                                : a.motion.solverIndex != kNullIndex || b.motion.solverIndex != kNullIndex;
        if (!a.enabled || !b.enabled) {
            j.reactionForce = {0.0f, 0.0f};
            j.reactionTorque = 0.0f;
            continue;
        }
        if (!moving) {
            continue; // asleep: keeps the reaction it fell asleep with
        }
        detail::prepareJoint(j, viewOf(a), viewOf(b), step);
        s.activeJoints.push_back(static_cast<int>(ji));
        s.jointBodies.push_back({j.indexA, j.indexB});
    }
}

void World::Impl::assignJointBlocks() {
    detail::Simulation& s = sim;
    const std::size_t blocks = s.blockBodyStart.size() - 1;
    s.blockJointStart.assign(blocks + 1, 0);
    s.blockJoints.resize(s.activeJoints.size());
    auto blockOf = [&](std::size_t k) {
        const detail::Simulation::ConstraintBodies& jb = s.jointBodies[k];
        return s.bodyBlock[static_cast<std::size_t>(jb.indexA >= 0 ? jb.indexA : jb.indexB)];
    };
    for (std::size_t k = 0; k < s.activeJoints.size(); ++k) {
        ++s.blockJointStart[static_cast<std::size_t>(blockOf(k)) + 1];
    }
    for (std::size_t b = 0; b < blocks; ++b) {
        s.blockJointStart[b + 1] += s.blockJointStart[b];
    }
    s.levelNext.assign(s.blockJointStart.begin(), s.blockJointStart.end() - 1);
    for (std::size_t k = 0; k < s.activeJoints.size(); ++k) {
        s.blockJoints[static_cast<std::size_t>(s.levelNext[static_cast<std::size_t>(blockOf(k))]++)] =
            s.activeJoints[k];
    }
}

void World::Impl::storeJointReactions(float invH) {
    for (int ji : sim.activeJoints) {
        detail::storeJointReaction(joint(ji), sim.states, invH);
    }
}

} // namespace e2d::physics
