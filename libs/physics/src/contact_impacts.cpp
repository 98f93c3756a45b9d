// SPDX-License-Identifier: MIT
#include "contact_impacts.hpp"

#include "contact_solver_common.hpp"
#include "simulation.hpp"

#include <e2d/physics/constants.hpp>

#include <algorithm>

namespace e2d::physics::detail {

namespace {

// Approaches slower than this, m/s, end the sweeps: what is left is the next step's contact
// solve's (a plastic row converges only geometrically, see kMaxImpactSweeps).
constexpr float kImpactRestSpeed = 1e-3f;
// The smallest normal float: a contact's inverse effective mass below it (two bodies of over
// 1e38 kg) is taken as nothing that moves.
constexpr float kMinImpactInvMass = 0x1p-126f;
// How much kinetic energy a row may gain from rounding before its sequence is refused: a
// relative part and an absolute floor, J (a resting row's energy is 0).
constexpr double kImpactEnergyTolerance = 1.0e-4;
constexpr double kImpactEnergyFloor = 1.0e-9;

bool moves(const BodySim& sim) {
    return sim.invMass.x != 0.0f || sim.invMass.y != 0.0f || sim.invInertia != 0.0f;
}

// Inverse mass a unit impulse along n meets at lever arm r.
float invMassAlong(Vec2 invMass, float invInertia, Vec2 r, Vec2 n) {
    const float rn = cross(r, n);
    return invMass.x * n.x * n.x + invMass.y * n.y * n.y + invInertia * rn * rn;
}

} // namespace

bool ContactImpacts::plan(const Simulation& s, std::span<const ContactConstraint> constraints,
                          float dt) {
    candidates_.clear();
    for (std::size_t k = 0; k < constraints.size(); ++k) {
        const ContactConstraint& c = constraints[k];
        if (c.restitution != 0.0f) {
            candidates_.push_back(
                {c.contactIndex, static_cast<int>(k), c.restitution, c.indexA, c.indexB});
        }
    }
    return planCandidates(s, dt);
}

bool ContactImpacts::plan(const Simulation& s, std::span<const WideRestitution> list, float dt) {
    candidates_.clear();
    for (const WideRestitution& r : list) {
        const auto k = static_cast<std::size_t>(r.constraint);
        const Simulation::ConstraintBodies& cb = s.constraintBodies[k];
        candidates_.push_back({s.constraintContacts[k], -1, r.restitution, cb.indexA, cb.indexB});
    }
    return planCandidates(s, dt);
}

bool ContactImpacts::planCandidates(const Simulation& s, float dt) {
    bodies_.clear();
    rowParent_.clear();
    const float threshold = s.def.restitutionThreshold;
    threshold_ = threshold;
    // A side's centre offset and velocity at the step's start (zero for a static or sleeping
    // side, index -1).
    auto centerOffset = [&](int index) {
        if (index < 0) {
            return Vec2{0.0f, 0.0f};
        }
        const BodySim& sim = s.sims[static_cast<std::size_t>(index)];
        return rotate(sim.transform.q, sim.localCenter);
    };
    auto pointVelocity = [&](int index, Vec2 r) {
        if (index < 0) {
            return Vec2{0.0f, 0.0f};
        }
        const BodyState& st = s.states[static_cast<std::size_t>(index)];
        return st.linearVelocity + cross(st.angularVelocity, r);
    };
    // Struck: a point approaching faster than the threshold that closes its gap within the
    // step (the step in which the solve's restitution would bounce it).
    auto isStruck = [&](const Candidate& c) {
        const Manifold& m = s.contacts[static_cast<std::size_t>(c.contact)].manifold;
        const Vec2 offsetA = centerOffset(c.indexA);
        const Vec2 offsetB = centerOffset(c.indexB);
        for (int i = 0; i < m.pointCount; ++i) {
            const ManifoldPoint& mp = m.points[i];
            const float approach =
                -dot(m.normal, pointVelocity(c.indexB, mp.anchorB - offsetB) -
                                   pointVelocity(c.indexA, mp.anchorA - offsetA));
            if (approach > threshold && mp.separation <= approach * dt + kLinearSlop) {
                return true;
            }
        }
        return false;
    };
    bool anyStruck = false;
    for (const Candidate& c : candidates_) {
        if (isStruck(c)) {
            anyStruck = true;
            break;
        }
    }
    if (!anyStruck) {
        return false; // most steps of most scenes
    }

    // The row contacts: struck, or touching at the step's start.
    edges_.clear();
    if (localOf_.size() < s.states.size()) {
        localOf_.resize(s.states.size(), -1);
    }
    for (std::size_t ci = 0; ci < candidates_.size(); ++ci) {
        const Candidate& c = candidates_[ci];
        const Manifold& m = s.contacts[static_cast<std::size_t>(c.contact)].manifold;
        if (m.pointCount == 0) {
            continue;
        }
        Edge e;
        e.candidate = static_cast<int>(ci);
        e.struck = isStruck(c);
        float separation = m.points[0].separation;
        Vec2 anchorA = m.points[0].anchorA;
        Vec2 anchorB = m.points[0].anchorB;
        if (m.pointCount == 2) {
            separation = std::min(separation, m.points[1].separation);
            anchorA = 0.5f * (anchorA + m.points[1].anchorA);
            anchorB = 0.5f * (anchorB + m.points[1].anchorB);
        }
        if (!e.struck && separation > kTouchingSeparation) {
            continue;
        }
        e.normal = m.normal;
        e.rA = anchorA - centerOffset(c.indexA);
        e.rB = anchorB - centerOffset(c.indexB);
        e.restitution = c.restitution;
        float k = 0.0f;
        auto side = [&](int index, Vec2 r, Vec2& fixedVelocity) {
            if (index >= 0 && moves(s.sims[static_cast<std::size_t>(index)])) {
                const BodySim& sim = s.sims[static_cast<std::size_t>(index)];
                k += invMassAlong(sim.invMass, sim.invInertia, r, e.normal);
                return localBody(index, s);
            }
            fixedVelocity = pointVelocity(index, r); // kinematic, static or asleep
            return -1;
        };
        e.bodyA = side(c.indexA, e.rA, e.fixedA);
        e.bodyB = side(c.indexB, e.rB, e.fixedB);
        if (!(k >= kMinImpactInvMass)) {
            continue; // nothing to move (neither side takes an impulse), or 1 / k overflows
        }
        e.invK = 1.0f / k;
        edges_.push_back(e);
    }
    for (RowBody& b : bodies_) {
        localOf_[static_cast<std::size_t>(b.state)] = -1;
    }

    // Rows: bodies joined by contacts between two moving bodies. A row with one such contact
    // is a pair impact (against the ground or a wall, maybe), which the solve gets right.
    for (const Edge& e : edges_) {
        if (e.bodyA >= 0 && e.bodyB >= 0) {
            const int ra = findRoot(rowParent_, e.bodyA);
            const int rb = findRoot(rowParent_, e.bodyB);
            if (ra != rb) {
                rowParent_[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
            }
        }
    }
    for (const Edge& e : edges_) {
        if (e.bodyA >= 0 && e.bodyB >= 0) {
            ++bodies_[static_cast<std::size_t>(findRoot(rowParent_, e.bodyA))].pairs;
        }
    }

    // The order the impulse travels: breadth first from the struck contacts of rows.
    order_.clear();
    for (std::size_t i = 0; i < edges_.size(); ++i) {
        Edge& e = edges_[i];
        const int body = e.bodyA >= 0 ? e.bodyA : e.bodyB;
        if (e.struck && bodies_[static_cast<std::size_t>(findRoot(rowParent_, body))].pairs >= 2) {
            e.visited = true;
            order_.push_back(static_cast<int>(i));
        }
    }
    if (order_.empty()) {
        return false;
    }
    // Each body's contacts (compressed rows over edges_).
    edgeStart_.assign(bodies_.size() + 1, 0);
    for (const Edge& e : edges_) {
        for (int b : {e.bodyA, e.bodyB}) {
            if (b >= 0) {
                ++edgeStart_[static_cast<std::size_t>(b) + 1];
            }
        }
    }
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        edgeStart_[b + 1] += edgeStart_[b];
    }
    bodyEdges_.resize(static_cast<std::size_t>(edgeStart_.back()));
    fill_.assign(edgeStart_.begin(), edgeStart_.end() - 1);
    for (std::size_t i = 0; i < edges_.size(); ++i) {
        for (int b : {edges_[i].bodyA, edges_[i].bodyB}) {
            if (b >= 0) {
                bodyEdges_[static_cast<std::size_t>(fill_[static_cast<std::size_t>(b)]++)] =
                    static_cast<int>(i);
            }
        }
    }
    for (std::size_t next = 0; next < order_.size(); ++next) {
        const Edge& e = edges_[static_cast<std::size_t>(order_[next])];
        for (int b : {e.bodyA, e.bodyB}) {
            if (b < 0 || bodies_[static_cast<std::size_t>(b)].reached) {
                continue;
            }
            bodies_[static_cast<std::size_t>(b)].reached = true;
            for (int k = edgeStart_[static_cast<std::size_t>(b)];
                 k < edgeStart_[static_cast<std::size_t>(b) + 1]; ++k) {
                Edge& other =
                    edges_[static_cast<std::size_t>(bodyEdges_[static_cast<std::size_t>(k)])];
                if (!other.visited) {
                    other.visited = true;
                    order_.push_back(bodyEdges_[static_cast<std::size_t>(k)]);
                }
            }
        }
    }

    int sweeps = 0;
    while (sweeps < kMaxImpactSweeps && sweep()) {
        ++sweeps;
    }
    // Each collision of the sequence keeps or loses kinetic energy, in exact arithmetic. In
    // floats, with extreme ratios of mass and inertia between the row's bodies (seed
    // impacts-extreme-ratios of fuzz_world: a 1e-13 kg m² rotor between 1e10 kg bodies, lever
    // arms of 400 m), rounding in the sweeps can add energy without bound; a kinematic side can
    // add it too. Then, or if anything is not finite, the row keeps the solve's answer.
    double before = 0.0;
    double after = 0.0;
    for (const RowBody& b : bodies_) {
        const BodyState& st = s.states[static_cast<std::size_t>(b.state)];
        before += kineticEnergy(b, st.linearVelocity, st.angularVelocity);
        after += kineticEnergy(b, b.linearVelocity, b.angularVelocity);
    }
    return after <= before * (1.0 + kImpactEnergyTolerance) + kImpactEnergyFloor;
}

double ContactImpacts::kineticEnergy(const RowBody& b, Vec2 v, float w) {
    auto term = [](float inverse, float speed) {
        return inverse > 0.0f ? static_cast<double>(speed) * speed / inverse : 0.0;
    };
    return 0.5 * (term(b.invMass.x, v.x) + term(b.invMass.y, v.y) + term(b.invInertia, w));
}

int ContactImpacts::localBody(int state, const Simulation& s) {
    int& local = localOf_[static_cast<std::size_t>(state)];
    if (local < 0) {
        local = static_cast<int>(bodies_.size());
        const BodySim& sim = s.sims[static_cast<std::size_t>(state)];
        const BodyState& st = s.states[static_cast<std::size_t>(state)];
        bodies_.push_back(
            {state, sim.invMass, sim.invInertia, st.linearVelocity, st.angularVelocity, 0, false});
        rowParent_.push_back(local);
    }
    return local;
}

// One pass over the row contacts in order_, each approaching pair colliding on its own: the
// impulse that reverses its normal approach times its restitution (none below the threshold).
// Returns whether any pair collided.
bool ContactImpacts::sweep() {
    bool collided = false;
    for (int i : order_) {
        const Edge& e = edges_[static_cast<std::size_t>(i)];
        RowBody* a = e.bodyA >= 0 ? &bodies_[static_cast<std::size_t>(e.bodyA)] : nullptr;
        RowBody* b = e.bodyB >= 0 ? &bodies_[static_cast<std::size_t>(e.bodyB)] : nullptr;
        const Vec2 vA = a ? a->linearVelocity + cross(a->angularVelocity, e.rA) : e.fixedA;
        const Vec2 vB = b ? b->linearVelocity + cross(b->angularVelocity, e.rB) : e.fixedB;
        const float vn = dot(e.normal, vB - vA);
        if (vn >= -kImpactRestSpeed) {
            continue;
        }
        const float restitution = -vn > threshold_ ? e.restitution : 0.0f;
        const Vec2 p = (-(1.0f + restitution) * vn * e.invK) * e.normal;
        if (a) {
            a->linearVelocity -= scale(a->invMass, p);
            a->angularVelocity -= a->invInertia * cross(e.rA, p);
        }
        if (b) {
            b->linearVelocity += scale(b->invMass, p);
            b->angularVelocity += b->invInertia * cross(e.rB, p);
        }
        collided = true;
    }
    return collided;
}

void ContactImpacts::apply(Simulation& s) const {
    for (const RowBody& b : bodies_) {
        if (b.reached) {
            BodyState& st = s.states[static_cast<std::size_t>(b.state)];
            st.linearVelocity = b.linearVelocity;
            st.angularVelocity = b.angularVelocity;
        }
    }
    for (int i : order_) {
        const Candidate& c =
            candidates_[static_cast<std::size_t>(edges_[static_cast<std::size_t>(i)].candidate)];
        Manifold& m = s.contacts[static_cast<std::size_t>(c.contact)].manifold;
        for (int j = 0; j < m.pointCount; ++j) {
            m.points[j].normalImpulse = 0.0f;
            m.points[j].tangentImpulse = 0.0f;
        }
        if (c.constraint >= 0) {
            ContactConstraint& cc = s.constraints[static_cast<std::size_t>(c.constraint)];
            for (ContactConstraintPoint& cp : cc.points) {
                cp.normalImpulse = 0.0f;
                cp.tangentImpulse = 0.0f;
            }
        }
    }
}

} // namespace e2d::physics::detail
