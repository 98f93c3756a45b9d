// SPDX-License-Identifier: MIT
// World::step(): pairs -> contacts -> narrow phase -> solver arrays -> solve -> continuous ->
// write back and broad-phase moves -> stored impulses, hit events -> sleep.
#include <e2d/physics/world.hpp>

#include "body_solver.hpp"
#include "world_check.hpp"
#include "world_impl.hpp"

#include <algorithm>
#include <cmath>

namespace e2d::physics {

using detail::kNullIndex;
namespace check = detail::world_check;

namespace {

bool isFiniteState(const detail::BodySim& s, const detail::BodyState& st) {
    return (st.flags & detail::kNonFinite) == 0 && isFinite(s.center) && isFinite(s.transform.p) && isFinite(s.transform.q.c) &&
           isFinite(s.transform.q.s) && isFinite(st.linearVelocity) &&
           isFinite(st.angularVelocity);
}

} // namespace

void World::step(float timeStep) {
    if (!(isFinite(timeStep) && timeStep >= 0.0f)) {
        check::fail("step", "timeStep must be finite and >= 0, got " + check::text(timeStep));
    }
    Impl& w = *impl_;
    detail::Simulation& s = w.sim;
    s.beginEvents.clear();
    s.endEvents.clear();
    s.sensorBeginEvents.clear();
    s.sensorEndEvents.clear();
    s.hitEvents.clear();
    s.nonFiniteBodies.clear();
    s.counters = {};
    s.endEvents.swap(s.pendingEndEvents);
    s.sensorEndEvents.swap(s.pendingSensorEndEvents);
    s.inStep = true;
    w.updateContacts(timeStep);
    if (timeStep > 0.0f) {
        w.solve(timeStep);
        s.counters.solverBodies = static_cast<int>(s.sims.size());
        s.counters.contactConstraints = static_cast<int>(s.constraints.size());
        w.updateSleep(timeStep);
    }
    s.inStep = false;
}

void World::Impl::solve(float dt) {
    detail::Simulation& s = sim;
    const SolverDef& def = s.def;

    // The awake moving bodies, in slot order.
    s.sims.clear();
    s.states.clear();
    for (std::size_t bi = 0; bi < bodies.size(); ++bi) {
        detail::Body& b = bodies[bi];
        detail::BodyMotion& m = b.motion;
        if (!b.alive || !b.enabled || b.type == BodyType::Static || !m.awake) {
            m.solverIndex = kNullIndex;
            continue;
        }
        m.solverIndex = static_cast<int>(s.sims.size());
        detail::BodySim& bs = s.sims.emplace_back();
        bs.transform = b.transform;
        bs.localCenter = m.localCenter;
        bs.center = transformPoint(b.transform, m.localCenter);
        bs.center0 = bs.center;
        bs.rotation0 = b.transform.q;
        bs.force = m.force;
        bs.torque = m.torque;
        bs.invMass = {m.lockX ? 0.0f : m.invMass, m.lockY ? 0.0f : m.invMass};
        bs.invInertia = m.invInertia;
        bs.linearDamping = m.linearDamping;
        bs.angularDamping = m.angularDamping;
        bs.gravityScale = m.gravityScale;
        bs.maxExtent = m.maxExtent;
        bs.bodyIndex = static_cast<int>(bi);
        detail::BodyState& st = s.states.emplace_back();
        // A kinematic body keeps its velocity; a locked axis has none.
        st.linearVelocity = {m.lockX && b.type == BodyType::Dynamic ? 0.0f : b.linearVelocity.x,
                             m.lockY && b.type == BodyType::Dynamic ? 0.0f : b.linearVelocity.y};
        st.angularVelocity = m.invInertia == 0.0f && b.type == BodyType::Dynamic
                                 ? 0.0f
                                 : b.angularVelocity;
    }

    detail::ContactSoftness softness = detail::makeContactSoftness(def, dt);
    auto viewOf = [&](int bodyIndex) {
        const detail::Body& b = body(bodyIndex);
        const detail::BodyMotion& m = b.motion;
        detail::ContactBodyView v;
        v.centerOffset = rotate(b.transform.q, m.localCenter);
        if (m.solverIndex != kNullIndex) {
            const detail::BodySim& bs = s.sims[static_cast<std::size_t>(m.solverIndex)];
            const detail::BodyState& st = s.states[static_cast<std::size_t>(m.solverIndex)];
            v.linearVelocity = st.linearVelocity;
            v.angularVelocity = st.angularVelocity;
            v.invMass = bs.invMass;
            v.invInertia = bs.invInertia;
            v.stateIndex = m.solverIndex;
        }
        return v;
    };
    // One constraint per touching solid contact with a moving side, in contact order. Each
    // also gets a level (see ConstraintLevels): solving level by level is the same sweep as
    // solving in contact order, but the constraints of a level share no moving body, so the
    // wide solver takes four at a time.
    s.constraintLevel.clear();
    s.levels.reset(static_cast<int>(s.sims.size()));
    auto movingState = [&](int bodyIndex) {
        int k = body(bodyIndex).motion.solverIndex;
        if (k == kNullIndex) {
            return kNullIndex;
        }
        const detail::BodySim& bs = s.sims[static_cast<std::size_t>(k)];
        bool rigid = bs.invMass.x == 0.0f && bs.invMass.y == 0.0f && bs.invInertia == 0.0f;
        return rigid ? kNullIndex : k;
    };
    bool rolling = false;
    int constraintCount = 0;
    for (std::size_t ci = 0; ci < s.contacts.size(); ++ci) {
        detail::Contact& c = s.contacts[ci];
        c.constraintIndex = kNullIndex;
        if (!c.alive || !c.touching || c.sensor) {
            continue;
        }
        if (body(c.bodyA).motion.solverIndex == kNullIndex &&
            body(c.bodyB).motion.solverIndex == kNullIndex) {
            continue;
        }
        rolling = rolling || c.rollingResistance > 0.0f;
        s.constraintLevel.push_back(s.levels.assign(movingState(c.bodyA), movingState(c.bodyB)));
        c.constraintIndex = constraintCount++;
    }

    // Rolling resistance is scalar only (and solved in contact order, the same sweep).
    const bool wide = def.mode == SolverMode::SoftStep && !rolling;
    if (wide) {
        // The constraints by level (a counting sort, so contact order within a level).
        const int levelCount = s.levels.levelCount();
        s.levelStart.assign(static_cast<std::size_t>(levelCount) + 1, 0);
        for (int k = 0; k < levelCount; ++k) {
            s.levelStart[static_cast<std::size_t>(k) + 1] =
                s.levelStart[static_cast<std::size_t>(k)] +
                s.levels.counts()[static_cast<std::size_t>(k)];
        }
        s.levelNext.assign(s.levelStart.begin(), s.levelStart.end() - 1);
        s.levelOrder.resize(static_cast<std::size_t>(constraintCount));
        s.constraintSlot.resize(static_cast<std::size_t>(constraintCount));
        for (std::size_t k = 0; k < s.constraintLevel.size(); ++k) {
            int slot = s.levelNext[static_cast<std::size_t>(s.constraintLevel[k])]++;
            s.levelOrder[static_cast<std::size_t>(slot)] = static_cast<int>(k);
            s.constraintSlot[k] = slot;
        }
        detail::layoutWide(s.wideContacts, s.levelStart, detail::bestWideLanes());
    }

    s.constraints.resize(static_cast<std::size_t>(constraintCount));
    for (std::size_t ci = 0; ci < s.contacts.size(); ++ci) {
        detail::Contact& c = s.contacts[ci];
        if (c.constraintIndex == kNullIndex) {
            continue;
        }
        const auto k = static_cast<std::size_t>(c.constraintIndex);
        detail::ContactConstraint& cc = s.constraints[k];
        detail::ContactBodyView a = viewOf(c.bodyA);
        detail::ContactBodyView b = viewOf(c.bodyB);
        bool rigidSide = (a.invMass.x == 0.0f && a.invMass.y == 0.0f && a.invInertia == 0.0f) ||
                         (b.invMass.x == 0.0f && b.invMass.y == 0.0f && b.invInertia == 0.0f);
        detail::prepareContact(cc, c.manifold, a, b,
                               {c.friction, c.restitution, c.rollingResistance},
                               rigidSide ? softness.vsStatic : softness.dynamic);
        cc.contactIndex = static_cast<int>(ci);
        auto gravityOf = [&](const detail::ContactBodyView& v, int bodyIndex) {
            float scale = body(bodyIndex).motion.gravityScale;
            return Vec2{v.invMass.x > 0.0f ? scale * gravity.x : 0.0f,
                        v.invMass.y > 0.0f ? scale * gravity.y : 0.0f};
        };
        cc.pressAcceleration = -dot(gravityOf(b, c.bodyB) - gravityOf(a, c.bodyA), cc.normal);
        if (wide) {
            // Packed while it is in cache (gathering it later by level is a random read).
            const int level = s.constraintLevel[k];
            detail::packWideLane(s.wideContacts, level,
                                 s.constraintSlot[k] - s.levelStart[static_cast<std::size_t>(level)], cc);
        }
    }

    detail::SolverStep step{s.sims, s.states, s.constraints, gravity, dt, &def};
    if (wide) {
        step.wide = &s.wideContacts;
        step.levelOrder = s.levelOrder;
        step.levelStart = s.levelStart;
    }
    if (def.mode == SolverMode::SoftStep) {
        detail::solveSoftStep(step);
    } else {
        detail::solveClassic(step);
    }
    detail::finalizePositions(s.sims, s.states);

    if (def.enableContinuous) {
        for (std::size_t k = 0; k < s.sims.size(); ++k) {
            solveContinuous(static_cast<int>(k));
        }
    }

    // Write back, move the proxies; a body whose state went non-finite is disabled instead.
    for (std::size_t k = 0; k < s.sims.size(); ++k) {
        const detail::BodySim& bs = s.sims[k];
        const detail::BodyState& st = s.states[k];
        detail::Body& b = body(bs.bodyIndex);
        b.motion.force = {0.0f, 0.0f};
        b.motion.torque = 0.0f;
        if (!isFiniteState(bs, st)) {
            s.nonFiniteBodies.push_back(bodyId(bs.bodyIndex));
            b.linearVelocity = {0.0f, 0.0f};
            b.angularVelocity = 0.0f;
            b.enabled = false;
            b.motion.solverIndex = kNullIndex;
            for (int si = b.headShape; si != kNullIndex; si = shape(si).nextShape) {
                destroyProxy(si);
            }
            continue;
        }
        b.transform = bs.transform;
        b.linearVelocity = st.linearVelocity;
        b.angularVelocity = st.angularVelocity;
        // The broad-phase box also covers where the body will be next step, so the pairs
        // (and speculative contacts) exist before a fast body arrives.
        Vec2 ahead = dt * b.linearVelocity;
        for (int si = b.headShape; si != kNullIndex; si = shape(si).nextShape) {
            detail::Shape& sh = shape(si);
            sh.aabb = computeAabb(sh.geometry, b.transform);
            if (sh.proxyKey != kNullIndex) {
                Aabb swept = sh.aabb;
                swept.lower += Vec2{std::min(ahead.x, 0.0f), std::min(ahead.y, 0.0f)};
                swept.upper += Vec2{std::max(ahead.x, 0.0f), std::max(ahead.y, 0.0f)};
                broadPhase.moveProxy(sh.proxyKey, swept);
            }
        }
    }

    // Impulses back to the manifolds for next step's warm start; hit events.
    for (const detail::ContactConstraint& cc : s.constraints) {
        detail::Contact& c = s.contacts[static_cast<std::size_t>(cc.contactIndex)];
        if (!c.alive) {
            continue; // ended with a non-finite body
        }
        float fastest = def.hitEventThreshold;
        int fastestPoint = -1;
        for (int j = 0; j < cc.pointCount; ++j) {
            const detail::ContactConstraintPoint& cp = cc.points[j];
            c.manifold.points[j].normalImpulse = cp.normalImpulse;
            c.manifold.points[j].tangentImpulse = cp.tangentImpulse;
            float approach = -cp.relativeVelocity;
            if (cp.maxNormalImpulse > 0.0f && approach > fastest) {
                fastest = approach;
                fastestPoint = j;
            }
        }
        if (fastestPoint >= 0) {
            // A speculative point sits midway across the gap; the hit is on A's surface.
            const ManifoldPoint& mp = c.manifold.points[fastestPoint];
            s.hitEvents.push_back({c.idA, c.idB, mp.point - 0.5f * mp.separation * c.manifold.normal,
                                   c.manifold.normal, fastest});
        }
    }
}

} // namespace e2d::physics
