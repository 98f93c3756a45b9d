// SPDX-License-Identifier: MIT
// Islands and sleeping. Islands are found afresh each step by union-find over the awake bodies
// joined by solved contacts (static and kinematic bodies do not join islands); an island
// whose every body has been slow for timeToSleep sleeps as a whole. Waking floods through
// touching contacts, so a sleeping pile wakes together.
#include <e2d/physics/world.hpp>

#include "world_impl.hpp"

#include <algorithm>

namespace e2d::physics {

using detail::kNullIndex;

void World::Impl::wakeBody(int bodyIndex) {
    detail::Body& start = body(bodyIndex);
    if (!start.alive || start.type == BodyType::Static || start.motion.awake) {
        return;
    }
    std::vector<int>& stack = sim.wakeStack;
    stack.clear();
    start.motion.awake = true;
    start.motion.sleepTime = 0.0f;
    stack.push_back(bodyIndex);
    while (!stack.empty()) {
        int k = stack.back();
        stack.pop_back();
        for (int ci = body(k).motion.contactHead; ci != kNullIndex;) {
            const detail::Contact& c = sim.contacts[static_cast<std::size_t>(ci)];
            int side = c.bodyA == k ? 0 : 1;
            int other = side == 0 ? c.bodyB : c.bodyA;
            detail::Body& o = body(other);
            if (c.touching && !c.sensor && o.type != BodyType::Static && !o.motion.awake) {
                o.motion.awake = true;
                o.motion.sleepTime = 0.0f;
                stack.push_back(other);
            }
            ci = sim.contactLinks[static_cast<std::size_t>(ci)].next[side];
        }
        // Jointed bodies wake together.
        for (int ji = body(k).jointHead; ji != kNullIndex;) {
            const detail::Joint& j = joint(ji);
            int side = j.bodyA == k ? 0 : 1;
            int other = side == 0 ? j.bodyB : j.bodyA;
            detail::Body& o = body(other);
            if (o.type != BodyType::Static && !o.motion.awake && o.enabled) {
                o.motion.awake = true;
                o.motion.sleepTime = 0.0f;
                stack.push_back(other);
            }
            ji = j.next[side];
        }
    }
}

void World::Impl::updateSleep(float dt) {
    detail::Simulation& s = sim;
    const SolverDef& def = s.def;
    s.sleptSims.clear();
    if (!def.enableSleep) {
        return;
    }
    auto n = static_cast<int>(s.sims.size());
    s.islandParent.resize(static_cast<std::size_t>(n));
    s.islandSleepTime.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        s.islandParent[static_cast<std::size_t>(i)] = i;
        s.islandSleepTime[static_cast<std::size_t>(i)] = kHuge;
    }
    auto join = [&](const detail::Simulation::ConstraintBodies& c) {
        if (c.indexA < 0 || c.indexB < 0) {
            return;
        }
        // Kinematic bodies would chain everything they carry into one island.
        if (body(s.sims[static_cast<std::size_t>(c.indexA)].bodyIndex).type != BodyType::Dynamic ||
            body(s.sims[static_cast<std::size_t>(c.indexB)].bodyIndex).type != BodyType::Dynamic) {
            return;
        }
        int ra = detail::findRoot(s.islandParent, c.indexA);
        int rb = detail::findRoot(s.islandParent, c.indexB);
        if (ra != rb) {
            // The lower index becomes the root, so the result does not depend on contact order.
            s.islandParent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
        }
    };
    for (const detail::Simulation::ConstraintBodies& c : s.constraintBodies) {
        join(c);
    }
    // Jointed bodies sleep together (and so wake together).
    for (const detail::Simulation::ConstraintBodies& c : s.jointBodies) {
        join(c);
    }

    // Each body's sleep time on several workers (a body is one worker's), copied next to the
    // others; each island's least after, alone (a minimum: the same in any order).
    float linearTolSq = def.linearSleepTolerance * def.linearSleepTolerance;
    float angularTol = def.angularSleepTolerance;
    s.simSleepTime.resize(static_cast<std::size_t>(n));
    auto sleepTimes = [&](int begin, int end, int /*worker*/) {
        for (int i = begin; i < end; ++i) {
            const detail::BodySim& bs = s.sims[static_cast<std::size_t>(i)];
            detail::Body& b = body(bs.bodyIndex);
            float& time = s.simSleepTime[static_cast<std::size_t>(i)];
            if (!b.enabled) {
                time = kHuge; // disabled this step (non-finite): no say in its island
                continue;
            }
            detail::BodyMotion& m = b.motion;
            float w = std::abs(b.angularVelocity);
            if (!m.enableSleep || dot(b.linearVelocity, b.linearVelocity) > linearTolSq ||
                w > angularTol) {
                m.sleepTime = 0.0f;
            } else {
                m.sleepTime += dt;
            }
            time = m.sleepTime;
        }
    };
    // A body is a few nanoseconds.
    tasks.parallelFor(n, tasks.minRange(5), sleepTimes);
    for (int i = 0; i < n; ++i) {
        int root = detail::findRoot(s.islandParent, i);
        float& islandTime = s.islandSleepTime[static_cast<std::size_t>(root)];
        islandTime = std::min(islandTime, s.simSleepTime[static_cast<std::size_t>(i)]);
    }
    for (int i = 0; i < n; ++i) {
        int root = detail::findRoot(s.islandParent, i);
        if (s.islandSleepTime[static_cast<std::size_t>(root)] < def.timeToSleep) {
            continue;
        }
        detail::Body& b = body(s.sims[static_cast<std::size_t>(i)].bodyIndex);
        b.motion.awake = false;
        b.linearVelocity = {0.0f, 0.0f};
        b.angularVelocity = 0.0f;
        s.sleptSims.push_back(i);
    }
}

void World::setAwake(BodyId id, bool awake) {
    Impl& w = *impl_;
    int index = w.require(id, "setAwake");
    if (awake) {
        w.wakeBody(index);
        return;
    }
    detail::Body& start = w.body(index);
    if (start.type == BodyType::Static || !start.motion.awake) {
        return;
    }
    // Sleep the whole touching group, or the first step would wake it again.
    std::vector<int>& stack = w.sim.wakeStack;
    stack.clear();
    stack.push_back(index);
    start.motion.awake = false;
    while (!stack.empty()) {
        int k = stack.back();
        stack.pop_back();
        detail::Body& b = w.body(k);
        b.linearVelocity = {0.0f, 0.0f};
        b.angularVelocity = 0.0f;
        b.motion.sleepTime = 0.0f;
        b.motion.force = {0.0f, 0.0f};
        b.motion.torque = 0.0f;
        for (int ci = b.motion.contactHead; ci != kNullIndex;) {
            const detail::Contact& c = w.sim.contacts[static_cast<std::size_t>(ci)];
            int side = c.bodyA == k ? 0 : 1;
            int other = side == 0 ? c.bodyB : c.bodyA;
            detail::Body& o = w.body(other);
            if (c.touching && !c.sensor && o.type == BodyType::Dynamic && o.motion.awake) {
                o.motion.awake = false;
                stack.push_back(other);
            }
            ci = w.sim.contactLinks[static_cast<std::size_t>(ci)].next[side];
        }
        for (int ji = b.jointHead; ji != kNullIndex;) {
            const detail::Joint& j = w.joint(ji);
            int side = j.bodyA == k ? 0 : 1;
            int other = side == 0 ? j.bodyB : j.bodyA;
            detail::Body& o = w.body(other);
            if (j.type != JointType::Mouse && o.type == BodyType::Dynamic && o.motion.awake) {
                o.motion.awake = false;
                stack.push_back(other);
            }
            ji = j.next[side];
        }
    }
}

} // namespace e2d::physics
