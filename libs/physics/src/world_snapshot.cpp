// SPDX-License-Identifier: MIT
// World::saveSnapshot() and World::restoreSnapshot(): the whole simulation state as bytes.
//
// Format (every value little-endian, fixed width; floats as their IEEE-754 bits):
//   header, 32 bytes:
//     magic "E2DSNAP\0" (8), format version u32 (kSnapshotFormatVersion), layout u32
//     (kLayout: the polygon vertex capacity and the widths the payload assumes), payload
//     length u64, FNV-1a 64 of the payload u64;
//   payload: sections, each opened by a four-letter tag, in this order:
//     WRLD  tag, gravity, narrow phase, speculative distance, SolverDef
//     BODY  body slots (live and dead: generations), the body id pool (free list, next)
//     SHAP  shape slots, the shape id pool
//     JOIN  joint slots, the joint id pool
//     CONT  contact slots (manifolds with impulses and feature ids, and the manifold origins
//           recycling moves them from), free list, live count
//     BRPH  the three dynamic trees (nodes, free list, root, deferred leaves), proxy infos,
//           move buffer, pair table (capacity, then each entry with its slot)
//     EVNT  end events waiting for the next step
//     END.
// Every slot is written whole except the per-step solver indices (BodyMotion::solverIndex,
// Joint::indexA/indexB), which the step sets before reading. The restore reads into a new
// World::Impl, checks that every index names what it must (lists, trees, pairs, pools) so
// that stepping the result is safe, and only then replaces the world's state.
#include <e2d/physics/world.hpp>

#include "snapshot_io.hpp"
#include "world_check.hpp"
#include "world_impl.hpp"

#include <algorithm>
#include <cstring>
#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace e2d::physics {

// Bounds of the enums a snapshot holds (SnapshotReader::primitive() refuses the others).
static constexpr int enumCount(BodyType) { return kBodyTypeCount; }
static constexpr int enumCount(JointType) { return kJointTypeCount; }
static constexpr int enumCount(ShapeType) {
    return static_cast<int>(std::variant_size_v<ShapeGeometry>);
}
static constexpr int enumCount(CollisionAlgorithm) { return 2; }
static constexpr int enumCount(SolverMode) { return 2; }
static constexpr int enumCount(MixingRule) { return 5; }
static constexpr int enumCount(JointSolver) { return 3; }

namespace detail {

// --- the structures' fields, one function each, for writing and reading alike ---

template <class Io>
void transfer(Io& io, Vec2& v) {
    field(io, "x", v.x);
    field(io, "y", v.y);
}
template <class Io>
void transfer(Io& io, Rot& q) {
    field(io, "c", q.c);
    field(io, "s", q.s);
}
template <class Io>
void transfer(Io& io, Transform& xf) {
    field(io, "p", xf.p);
    field(io, "q", xf.q);
}
template <class Io>
void transfer(Io& io, Aabb& box) {
    field(io, "lower", box.lower);
    field(io, "upper", box.upper);
}
template <class Io>
void transfer(Io& io, Filter& f) {
    field(io, "categoryBits", f.categoryBits);
    field(io, "maskBits", f.maskBits);
    field(io, "group", f.group);
}
template <class Io>
void transfer(Io& io, ShapeId& id) {
    field(io, "index1", id.index1);
    field(io, "generation", id.generation);
    field(io, "world", id.owner);
}
template <class Io>
void transfer(Io& io, Circle& c) {
    field(io, "center", c.center);
    field(io, "radius", c.radius);
}
template <class Io>
void transfer(Io& io, Capsule& c) {
    field(io, "center1", c.center1);
    field(io, "center2", c.center2);
    field(io, "radius", c.radius);
}
template <class Io>
void transfer(Io& io, Segment& s) {
    field(io, "point1", s.point1);
    field(io, "point2", s.point2);
}
template <class Io>
void transfer(Io& io, ChainSegment& s) {
    field(io, "segment", s.segment);
    field(io, "ghost1", s.ghost1);
    field(io, "ghost2", s.ghost2);
    field(io, "hasGhost1", s.hasGhost1);
    field(io, "hasGhost2", s.hasGhost2);
}
template <class Io>
void transfer(Io& io, Polygon& p) {
    for (std::size_t i = 0; i < p.vertices.size(); ++i) {
        auto scope = io.scope("vertices", i);
        transfer(io, p.vertices[i]);
    }
    for (std::size_t i = 0; i < p.normals.size(); ++i) {
        auto scope = io.scope("normals", i);
        transfer(io, p.normals[i]);
    }
    field(io, "centroid", p.centroid);
    field(io, "radius", p.radius);
    field(io, "count", p.count);
}
template <class Io>
void transfer(Io& io, ShapeGeometry& g) {
    ShapeType type = typeOf(g);
    field(io, "type", type);
    if constexpr (Io::kReading) {
        switch (type) {
        case ShapeType::Circle:
            g = Circle{};
            break;
        case ShapeType::Capsule:
            g = Capsule{};
            break;
        case ShapeType::Segment:
            g = Segment{};
            break;
        case ShapeType::Polygon:
            g = Polygon{};
            break;
        case ShapeType::ChainSegment:
            g = ChainSegment{};
            break;
        }
    }
    std::visit([&](auto& shape) { transfer(io, shape); }, g);
}
template <class Io>
void transfer(Io& io, ManifoldPoint& p) {
    field(io, "point", p.point);
    field(io, "anchorA", p.anchorA);
    field(io, "anchorB", p.anchorB);
    field(io, "separation", p.separation);
    field(io, "normalImpulse", p.normalImpulse);
    field(io, "tangentImpulse", p.tangentImpulse);
    field(io, "id", p.id);
    field(io, "persisted", p.persisted);
}
template <class Io>
void transfer(Io& io, Manifold& m) {
    field(io, "normal", m.normal);
    field(io, "points", m.points);
    field(io, "pointCount", m.pointCount);
}
// A contact's origin with whether it has one (Contact::originValid), as one structure.
template <class Io>
void transfer(Io& io, ManifoldOrigin& o, bool& valid) {
    Transform bInA = o.bInA();
    Vec2 aInB = o.aInB();
    field(io, "bInA", bInA);
    field(io, "aInB", aInB);
    o.setFrames(aInB, bInA);
    field(io, "extentA", o.extentA);
    field(io, "extentB", o.extentB);
    field(io, "normalInA", o.normalInA);
    field(io, "surfaceA", o.surfaceA);
    field(io, "surfaceB", o.surfaceB);
    field(io, "valid", valid);
}
template <class Io>
void transfer(Io& io, Softness& s) {
    field(io, "biasRate", s.biasRate);
    field(io, "massScale", s.massScale);
    field(io, "impulseScale", s.impulseScale);
}
template <class Io>
void transfer(Io& io, SolverDef& d) {
    field(io, "mode", d.mode);
    field(io, "subSteps", d.subSteps);
    field(io, "relaxIterations", d.relaxIterations);
    field(io, "velocityIterations", d.velocityIterations);
    field(io, "positionIterations", d.positionIterations);
    field(io, "classicAllowedPenetration", d.classicAllowedPenetration);
    field(io, "classicPositionBias", d.classicPositionBias);
    field(io, "contactHertz", d.contactHertz);
    field(io, "contactDampingRatio", d.contactDampingRatio);
    field(io, "jointHertz", d.jointHertz);
    field(io, "jointDampingRatio", d.jointDampingRatio);
    field(io, "jointSolver", d.jointSolver);
    field(io, "jointPositionIterations", d.jointPositionIterations);
    field(io, "contactPushMaxSpeed", d.contactPushMaxSpeed);
    field(io, "restitutionThreshold", d.restitutionThreshold);
    field(io, "maxLinearSpeed", d.maxLinearSpeed);
    field(io, "hitEventThreshold", d.hitEventThreshold);
    field(io, "linearSleepTolerance", d.linearSleepTolerance);
    field(io, "angularSleepTolerance", d.angularSleepTolerance);
    field(io, "timeToSleep", d.timeToSleep);
    field(io, "enableSleep", d.enableSleep);
    field(io, "enableContinuous", d.enableContinuous);
    field(io, "frictionMixing", d.frictionMixing);
    field(io, "restitutionMixing", d.restitutionMixing);
    field(io, "contactRecycleDistance", d.contactRecycleDistance);
}
template <class Io>
void transfer(Io& io, BodyMotion& m) {
    field(io, "localCenter", m.localCenter);
    field(io, "mass", m.mass);
    field(io, "inertia", m.inertia);
    field(io, "invMass", m.invMass);
    field(io, "invInertia", m.invInertia);
    field(io, "force", m.force);
    field(io, "torque", m.torque);
    field(io, "linearDamping", m.linearDamping);
    field(io, "angularDamping", m.angularDamping);
    field(io, "gravityScale", m.gravityScale);
    field(io, "positionResidual", m.positionResidual);
    field(io, "sleepTime", m.sleepTime);
    field(io, "minExtent", m.minExtent);
    field(io, "maxExtent", m.maxExtent);
    field(io, "contactHead", m.contactHead);
    // solverIndex: the step's (set before it is read), not state.
    field(io, "fixedRotation", m.fixedRotation);
    field(io, "lockX", m.lockX);
    field(io, "lockY", m.lockY);
    field(io, "isBullet", m.isBullet);
    field(io, "enableSleep", m.enableSleep);
    field(io, "awake", m.awake);
}
template <class Io>
void transfer(Io& io, Body& b) {
    field(io, "transform", b.transform);
    field(io, "linearVelocity", b.linearVelocity);
    field(io, "angularVelocity", b.angularVelocity);
    field(io, "userData", b.userData);
    field(io, "headShape", b.headShape);
    field(io, "shapeCount", b.shapeCount);
    field(io, "jointHead", b.jointHead);
    field(io, "generation", b.generation);
    field(io, "type", b.type);
    field(io, "enabled", b.enabled);
    field(io, "alive", b.alive);
    field(io, "motion", b.motion);
}
template <class Io>
void transfer(Io& io, Shape& s) {
    field(io, "geometry", s.geometry);
    field(io, "aabb", s.aabb);
    field(io, "filter", s.filter);
    field(io, "userData", s.userData);
    field(io, "density", s.density);
    field(io, "friction", s.friction);
    field(io, "restitution", s.restitution);
    field(io, "rollingResistance", s.rollingResistance);
    field(io, "body", s.body);
    field(io, "prevShape", s.prevShape);
    field(io, "nextShape", s.nextShape);
    field(io, "proxyKey", s.proxyKey);
    field(io, "generation", s.generation);
    field(io, "isSensor", s.isSensor);
    field(io, "alive", s.alive);
    field(io, "contactEvents", s.contactEvents);
    field(io, "sensorEvents", s.sensorEvents);
    field(io, "hitEvents", s.hitEvents);
    field(io, "sensorSeesNonDynamic", s.sensorSeesNonDynamic);
}
template <class Io>
void transfer(Io& io, Joint& j) {
    field(io, "type", j.type);
    field(io, "enableSpring", j.enableSpring);
    field(io, "enableLimit", j.enableLimit);
    field(io, "enableMotor", j.enableMotor);
    // indexA, indexB: the step's (prepareJoint() sets them), not state.
    field(io, "invInertiaA", j.invInertiaA);
    field(io, "invInertiaB", j.invInertiaB);
    field(io, "angle0", j.angle0);
    field(io, "invMassA", j.invMassA);
    field(io, "invMassB", j.invMassB);
    field(io, "anchorA", j.anchorA);
    field(io, "anchorB", j.anchorB);
    field(io, "deltaCenter", j.deltaCenter);
    field(io, "axisA", j.axisA);
    field(io, "linearImpulse", j.linearImpulse);
    field(io, "angularImpulse", j.angularImpulse);
    field(io, "springImpulse", j.springImpulse);
    field(io, "motorImpulse", j.motorImpulse);
    field(io, "lowerImpulse", j.lowerImpulse);
    field(io, "upperImpulse", j.upperImpulse);
    field(io, "perpImpulse", j.perpImpulse);
    field(io, "axialMass", j.axialMass);
    field(io, "angularMass", j.angularMass);
    field(io, "lower", j.lower);
    field(io, "upper", j.upper);
    field(io, "motorSpeed", j.motorSpeed);
    field(io, "maxMotorForce", j.maxMotorForce);
    field(io, "hertz", j.hertz);
    field(io, "angularHertz", j.angularHertz);
    field(io, "length", j.length);
    field(io, "minLength", j.minLength);
    field(io, "maxLength", j.maxLength);
    field(io, "maxTorque", j.maxTorque);
    field(io, "correctionFactor", j.correctionFactor);
    field(io, "springSoftness", j.springSoftness);
    field(io, "angularSoftness", j.angularSoftness);
    field(io, "bodyA", j.bodyA);
    field(io, "bodyB", j.bodyB);
    field(io, "prev", j.prev);
    field(io, "next", j.next);
    field(io, "userData", j.userData);
    field(io, "generation", j.generation);
    field(io, "alive", j.alive);
    field(io, "collideConnected", j.collideConnected);
    field(io, "localAnchorA", j.localAnchorA);
    field(io, "localAnchorB", j.localAnchorB);
    field(io, "localAxisA", j.localAxisA);
    field(io, "target", j.target);
    field(io, "referenceAngle", j.referenceAngle);
    field(io, "dampingRatio", j.dampingRatio);
    field(io, "angularDampingRatio", j.angularDampingRatio);
    field(io, "angle", j.angle);
    field(io, "angleRotation", j.angleRotation);
    field(io, "reactionForce", j.reactionForce);
    field(io, "reactionTorque", j.reactionTorque);
}
// A contact slot: its two parts (Simulation::contacts and contactLinks) as one structure.
template <class Io>
void transfer(Io& io, Contact& c, ContactLinks& l) {
    field(io, "manifold", c.manifold);
    {
        auto scope = io.scope("origin");
        transfer(io, c.origin, c.originValid);
    }
    field(io, "friction", c.friction);
    field(io, "restitution", c.restitution);
    field(io, "rollingResistance", c.rollingResistance);
    field(io, "shapeA", l.shapeA);
    field(io, "shapeB", l.shapeB);
    field(io, "bodyA", c.bodyA);
    field(io, "bodyB", c.bodyB);
    field(io, "prev", l.prev);
    field(io, "next", l.next);
    field(io, "idA", l.idA);
    field(io, "idB", l.idB);
    field(io, "touching", c.touching);
    field(io, "sensor", c.sensor);
    field(io, "alive", c.alive);
    field(io, "enabled", c.enabled);
    field(io, "touchEvents", c.touchEvents);
    field(io, "hitEvents", c.hitEvents);
}
template <class Io>
void transfer(Io& io, ContactEndTouchEvent& e) {
    field(io, "shapeA", e.shapeA);
    field(io, "shapeB", e.shapeB);
}
template <class Io>
void transfer(Io& io, SensorEndTouchEvent& e) {
    field(io, "sensorShape", e.sensorShape);
    field(io, "visitorShape", e.visitorShape);
}
template <class Io>
void transfer(Io& io, PairEntry& e) {
    field(io, "key", e.key);
    field(io, "proxyKeyA", e.proxyKeyA);
    field(io, "proxyKeyB", e.proxyKeyB);
}

// The private parts of the pools, trees and pair table (a friend of each).
struct SnapshotAccess {
    template <class Io>
    static void transfer(Io& io, IdPool& pool) {
        sequence(io, "free", pool.free_, 4);
        field(io, "next", pool.next_);
    }

    template <class Io>
    static void transfer(Io& io, DynamicTree& tree) {
        std::size_t n = tree.nodes_.size();
        io.count("nodes", n, kNodeBytes);
        if constexpr (Io::kReading) {
            tree.nodes_.assign(n, DynamicTree::Node{});
        }
        for (std::size_t i = 0; i < n; ++i) {
            auto scope = io.scope("nodes", i);
            DynamicTree::Node& node = tree.nodes_[i];
            field(io, "aabb", node.aabb);
            field(io, "categoryBits", node.categoryBits);
            field(io, "userData", node.userData);
            field(io, "parent", node.parent);
            field(io, "child1", node.child1);
            field(io, "child2", node.child2);
            field(io, "height", node.height);
        }
        sequence(io, "deferred", tree.deferred_, 4);
        field(io, "deferredCount", tree.deferredCount_);
        field(io, "root", tree.root_);
        field(io, "freeList", tree.freeList_);
        field(io, "proxyCount", tree.proxyCount_);
    }

    // `shapeSlots`: the shapes the pairs are made of, which bound the table's size.
    template <class Io>
    static void transfer(Io& io, PairSet& pairs, std::size_t shapeSlots) {
        // The table's capacity and each entry with its slot: the probe order (and so the pairs'
        // iteration order) comes back as it was.
        auto capacity = static_cast<std::uint32_t>(pairs.slots_.size());
        field(io, "capacity", capacity);
        std::size_t entries = static_cast<std::size_t>(pairs.size_);
        io.count("entries", entries, 4 + encodedSize<PairEntry>());
        if constexpr (Io::kReading) {
            // The table starts at 32 slots and doubles when it would be more than half full, so
            // it never holds more than 4 slots per pair that n shapes can make (n (n - 1) / 2):
            // a few bytes of snapshot cannot ask for a gigabyte.
            const std::uint64_t n = shapeSlots;
            const std::uint64_t most = std::min<std::uint64_t>(
                std::max<std::uint64_t>(32, 2 * n * (n > 0 ? n - 1 : 0)), std::uint64_t{1} << 30);
            if (capacity > most || (capacity & (capacity - 1)) != 0 || 2 * entries > capacity) {
                io.fail("capacity",
                        "must be a power of two of at least twice the " + std::to_string(entries) +
                            " entries and at most " + std::to_string(most) + " (for " +
                            std::to_string(n) + " shapes), got " + std::to_string(capacity),
                        0);
            }
            pairs.slots_.assign(capacity, PairEntry{});
            pairs.size_ = static_cast<int>(entries);
            std::size_t last = 0;
            for (std::size_t k = 0; k < entries; ++k) {
                auto scope = io.scope("entries", k);
                std::uint32_t slot = 0;
                field(io, "slot", slot);
                if (slot >= capacity || (k > 0 && slot <= last)) {
                    io.fail("slot",
                            "must be ascending and below the capacity " + std::to_string(capacity) +
                                ", got " + std::to_string(slot),
                            4);
                }
                last = slot;
                PairEntry& entry = pairs.slots_[slot];
                detail::transfer(io, entry);
                if (entry.key == 0) {
                    io.fail("key", "must not be 0 (the empty marker)", 16);
                }
            }
        } else {
            std::size_t k = 0;
            for (std::size_t slot = 0; slot < capacity; ++slot) {
                PairEntry& entry = pairs.slots_[slot];
                if (entry.key != 0) {
                    auto scope = io.scope("entries", k++);
                    auto index = static_cast<std::uint32_t>(slot);
                    field(io, "slot", index);
                    detail::transfer(io, entry);
                }
            }
        }
    }

    template <class Io>
    static void transfer(Io& io, BroadPhase& bp, std::size_t shapeSlots) {
        for (std::size_t t = 0; t < bp.trees_.size(); ++t) {
            auto scope = io.scope("trees", t);
            transfer(io, bp.trees_[t]);
        }
        std::size_t n = bp.infos_.size();
        io.count("infos", n, 8);
        if constexpr (Io::kReading) {
            bp.infos_.assign(n, BroadPhase::ProxyInfo{});
        }
        for (std::size_t i = 0; i < n; ++i) {
            auto scope = io.scope("infos", i);
            field(io, "pairCount", bp.infos_[i].pairCount);
            field(io, "moveIndex", bp.infos_[i].moveIndex);
        }
        sequence(io, "moveBuffer", bp.moveBuffer_, 4);
        auto scope = io.scope("pairs");
        transfer(io, bp.pairs_, shapeSlots);
    }

    // Bytes of one encoded tree node.
    static constexpr std::size_t kNodeBytes = 16 + 8 + 8 + 4 * 4;

    // --- what the checks below read ---
    static const DynamicTree& tree(const BroadPhase& bp, std::size_t t) { return bp.trees_[t]; }
    static const auto& nodes(const DynamicTree& tree) { return tree.nodes_; }
    static const auto& deferred(const DynamicTree& tree) { return tree.deferred_; }
    static int root(const DynamicTree& tree) { return tree.root_; }
    static int freeList(const DynamicTree& tree) { return tree.freeList_; }
    static int deferredCount(const DynamicTree& tree) { return tree.deferredCount_; }
    static int proxyCount(const DynamicTree& tree) { return tree.proxyCount_; }
    static const auto& infos(const BroadPhase& bp) { return bp.infos_; }
    static const std::vector<int>& moveBuffer(const BroadPhase& bp) { return bp.moveBuffer_; }
    static const std::vector<PairEntry>& pairSlots(const BroadPhase& bp) {
        return bp.pairs_.slots_;
    }
    static const PairSet& pairSet(const BroadPhase& bp) { return bp.pairs_; }
    static const std::vector<int>& freeSlots(const IdPool& pool) { return pool.free_; }
};

template <class Io>
void transfer(Io& io, IdPool& pool) {
    SnapshotAccess::transfer(io, pool);
}

// The contact slots as one sequence (sequence()'s format): the two arrays, element by element.
template <class Io>
void contactSequence(Io& io, Simulation& s) {
    const std::size_t elementBytes = [] {
        SnapshotWriter writer;
        Contact c{};
        ContactLinks l{};
        transfer(writer, c, l);
        return writer.size();
    }();
    std::size_t n = s.contacts.size();
    io.count("contacts", n, elementBytes);
    if constexpr (Io::kReading) {
        s.contacts.resize(n);
        s.contactLinks.resize(n);
    }
    for (std::size_t i = 0; i < n; ++i) {
        auto scope = io.scope("contacts", i);
        transfer(io, s.contacts[i], s.contactLinks[i]);
    }
}

// The payload: every section in order (see the top of the file).
// (W: World::Impl, a template parameter as World's private type cannot be named here.)
template <class Io, class W>
void transferWorld(Io& io, W& w) {
    io.tag("WRLD");
    {
        auto scope = io.scope("world");
        field(io, "tag", w.tag);
        field(io, "gravity", w.gravity);
        field(io, "collisionAlgorithm", w.collisionAlgorithm);
        field(io, "speculativeDistance", w.speculativeDistance);
        field(io, "solver", w.sim.def);
    }
    io.tag("BODY");
    sequence(io, "bodies", w.bodies, encodedSize<Body>());
    field(io, "bodyIds", w.bodyIds);
    io.tag("SHAP");
    sequence(io, "shapes", w.shapes, encodedSize<Shape>());
    field(io, "shapeIds", w.shapeIds);
    io.tag("JOIN");
    sequence(io, "joints", w.joints, encodedSize<Joint>());
    field(io, "jointIds", w.jointIds);
    io.tag("CONT");
    contactSequence(io, w.sim);
    sequence(io, "freeContacts", w.sim.freeContacts, 4);
    field(io, "contactCount", w.sim.contactCount);
    io.tag("BRPH");
    {
        auto scope = io.scope("broadPhase");
        SnapshotAccess::transfer(io, w.broadPhase, w.shapes.size());
    }
    io.tag("EVNT");
    sequence(io, "pendingEndEvents", w.sim.pendingEndEvents, encodedSize<ContactEndTouchEvent>());
    sequence(io, "pendingSensorEndEvents", w.sim.pendingSensorEndEvents,
             encodedSize<SensorEndTouchEvent>());
    io.tag("END.");
}

} // namespace detail

namespace {

using detail::kNullIndex;
using detail::SnapshotAccess;

constexpr const char* kRestore = "physics::World::restoreSnapshot()";
constexpr char kMagic[8] = {'E', '2', 'D', 'S', 'N', 'A', 'P', '\0'};
constexpr std::size_t kHeaderBytes = kSnapshotHeaderBytes;
// What the payload's layout depends on beyond the version: the polygon vertex capacity (every
// polygon is written with that many vertices and normals) and the widths of an index (4) and a
// float (4). A build with another kMaxPolygonVertices reads none of these snapshots.
constexpr std::uint32_t kLayout =
    static_cast<std::uint32_t>(kMaxPolygonVertices) | (4u << 8) | (4u << 16);

std::uint64_t fnv1a(std::span<const std::uint8_t> bytes) {
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint8_t b : bytes) {
        h = (h ^ b) * 1099511628211ull;
    }
    return h;
}

// The header's fields as read.
struct Header {
    std::uint32_t version = 0;
    std::uint32_t layout = 0;
    std::uint64_t payloadBytes = 0;
    std::uint64_t checksum = 0;
};

// Refuses what the header says is not this build's snapshot, cut short or damaged.
std::span<const std::uint8_t> readHeader(std::span<const std::uint8_t> bytes) {
    detail::SnapshotReader reader(bytes.first(std::min(bytes.size(), kHeaderBytes)), 0, kRestore);
    auto scope = reader.scope("header");
    for (int i = 0; i < 8; ++i) {
        std::uint8_t c = 0;
        reader.primitive("magic", c);
        if (c != static_cast<std::uint8_t>(kMagic[i])) {
            reader.fail("magic", "not a physics::World snapshot (expected \"E2DSNAP\")", 1);
        }
    }
    Header h;
    reader.primitive("version", h.version);
    if (h.version != kSnapshotFormatVersion) {
        reader.fail("version",
                    "format version " + std::to_string(h.version) + ", this build reads version " +
                        std::to_string(kSnapshotFormatVersion),
                    4);
    }
    reader.primitive("layout", h.layout);
    if (h.layout != kLayout) {
        reader.fail("layout",
                    "layout " + std::to_string(h.layout) +
                        " (polygon vertices, index and float "
                        "widths), this build's is " +
                        std::to_string(kLayout),
                    4);
    }
    reader.primitive("payloadBytes", h.payloadBytes);
    reader.primitive("checksum", h.checksum);
    const std::size_t available = bytes.size() - kHeaderBytes;
    if (h.payloadBytes != available) {
        reader.fail("payloadBytes",
                    "the header announces " + std::to_string(h.payloadBytes) +
                        " bytes of payload, " + std::to_string(available) + " follow (" +
                        (h.payloadBytes > available ? "truncated" : "trailing bytes") + ")",
                    12);
    }
    std::span<const std::uint8_t> payload = bytes.subspan(kHeaderBytes);
    if (fnv1a(payload) != h.checksum) {
        reader.fail("checksum", "the payload does not match its checksum (damaged)", 8);
    }
    return payload;
}

// The checks of a state just read: every index names what it must, every list and tree is
// well formed, so that stepping the world is safe. Messages name the section, its offset and
// the field's path.
// (W: World::Impl, see transferWorld().)
template <class W>
class Checker {
public:
    explicit Checker(const W& w) : w_(w) {}

    void section(const char* name, std::size_t offset) {
        section_ = name;
        offset_ = offset;
    }
    [[noreturn]] void fail(const std::string& path, const std::string& what) const {
        throw core::Error(std::string(kRestore) + ": section '" + section_ + "' (offset " +
                          std::to_string(offset_) + "), " + path + ": " + what);
    }
    void require(bool condition, const std::string& path, const std::string& what) const {
        if (!condition) {
            fail(path, what);
        }
    }
    static std::string at(const char* name, std::size_t index, const char* leaf = nullptr) {
        std::string text(name);
        text.append("[").append(std::to_string(index)).append("]");
        if (leaf != nullptr) {
            text.append(".").append(leaf);
        }
        return text;
    }

    bool liveBody(int i) const {
        return i >= 0 && static_cast<std::size_t>(i) < w_.bodies.size() && w_.body(i).alive;
    }
    bool liveShape(int i) const {
        return i >= 0 && static_cast<std::size_t>(i) < w_.shapes.size() && w_.shape(i).alive;
    }
    bool liveJoint(int i) const {
        return i >= 0 && static_cast<std::size_t>(i) < w_.joints.size() && w_.joint(i).alive;
    }
    bool liveContact(int i) const {
        return i >= 0 && static_cast<std::size_t>(i) < w_.sim.contacts.size() &&
               w_.sim.contacts[static_cast<std::size_t>(i)].alive;
    }

    void world() const {
        require(w_.tag != 0, "world.tag", "must not be 0");
        require(isFinite(w_.gravity), "world.gravity", "must be finite");
        require(isFinite(w_.speculativeDistance) && w_.speculativeDistance >= 0.0f &&
                    w_.speculativeDistance <= kAabbMargin,
                "world.speculativeDistance",
                "must be in [0, kAabbMargin], got " + core::formatNumber(w_.speculativeDistance));
        try {
            validate(w_.sim.def);
        } catch (const core::Error& e) {
            fail("world.solver", e.what());
        }
    }

    // A pool hands out exactly the dead slots, each once, and one past the last slot next.
    template <class IsLive>
    void pool(const detail::IdPool& p, std::size_t slots, const char* name, IsLive isLive) const {
        const std::string path = std::string(name) + "Ids";
        require(static_cast<std::size_t>(p.capacity()) == slots, path + ".next",
                "must equal the " + std::to_string(slots) + " slots, got " +
                    std::to_string(p.capacity()));
        std::vector<unsigned char> seen(slots, 0);
        std::size_t dead = 0;
        for (std::size_t i = 0; i < slots; ++i) {
            dead += isLive(static_cast<int>(i)) ? 0 : 1;
        }
        const std::vector<int>& free = SnapshotAccess::freeSlots(p);
        for (std::size_t k = 0; k < free.size(); ++k) {
            const int slot = free[k];
            require(slot >= 0 && static_cast<std::size_t>(slot) < slots && !isLive(slot) &&
                        seen[static_cast<std::size_t>(slot)] == 0,
                    at((path + ".free").c_str(), k),
                    "must name a dead slot once, got " + std::to_string(slot));
            seen[static_cast<std::size_t>(slot)] = 1;
        }
        require(free.size() == dead, path + ".free",
                "must list the " + std::to_string(dead) + " dead slots, lists " +
                    std::to_string(free.size()));
    }

    void bodies() {
        std::size_t shapesListed = 0;
        for (std::size_t i = 0; i < w_.bodies.size(); ++i) {
            const detail::Body& b = w_.bodies[i];
            if (!b.alive) {
                require(b.headShape == kNullIndex && b.shapeCount == 0 &&
                            b.jointHead == kNullIndex && b.motion.contactHead == kNullIndex,
                        at("bodies", i), "a dead body must have no shapes, joints or contacts");
                continue;
            }
            require(b.generation != 0, at("bodies", i, "generation"), "must not be 0 when live");
            require(isFinite(b.transform.p) && std::abs(b.transform.p.x) <= kHuge &&
                        std::abs(b.transform.p.y) <= kHuge && isFinite(b.transform.q.c) &&
                        isFinite(b.transform.q.s),
                    at("bodies", i, "transform"), "must be finite and within kHuge");
            require(isFinite(b.linearVelocity) && isFinite(b.angularVelocity),
                    at("bodies", i, "linearVelocity"), "must be finite");
            const detail::BodyMotion& m = b.motion;
            const float values[] = {m.localCenter.x,
                                    m.localCenter.y,
                                    m.mass,
                                    m.inertia,
                                    m.invMass,
                                    m.invInertia,
                                    m.force.x,
                                    m.force.y,
                                    m.torque,
                                    m.linearDamping,
                                    m.angularDamping,
                                    m.gravityScale,
                                    m.positionResidual.x,
                                    m.positionResidual.y,
                                    m.sleepTime,
                                    m.minExtent,
                                    m.maxExtent};
            for (float v : values) {
                require(isFinite(v), at("bodies", i, "motion"), "every number must be finite");
            }
            // The body's shape list: its shapes, linked both ways, shapeCount long.
            int prev = kNullIndex;
            int count = 0;
            for (int s = b.headShape; s != kNullIndex; s = w_.shape(s).nextShape) {
                require(liveShape(s) && w_.shape(s).body == static_cast<int>(i) &&
                            w_.shape(s).prevShape == prev && count < b.shapeCount,
                        at("bodies", i, "headShape"),
                        "the shape list must link shapeCount live shapes of this body both ways");
                prev = s;
                ++count;
            }
            require(count == b.shapeCount, at("bodies", i, "shapeCount"),
                    "the list holds " + std::to_string(count) + " shapes, shapeCount says " +
                        std::to_string(b.shapeCount));
            shapesListed += static_cast<std::size_t>(count);
            jointsListed_ +=
                listLength(b.jointHead, static_cast<int>(i), w_.joints.size(),
                           at("bodies", i, "jointHead"), [&](int j) -> std::optional<ListNode> {
                               if (!liveJoint(j)) {
                                   return std::nullopt;
                               }
                               const detail::Joint& e = w_.joint(j);
                               return ListNode{e.bodyA, e.bodyB, e.prev, e.next};
                           });
            contactsListed_ += listLength(
                m.contactHead, static_cast<int>(i), w_.sim.contacts.size(),
                at("bodies", i, "motion.contactHead"), [&](int c) -> std::optional<ListNode> {
                    if (!liveContact(c)) {
                        return std::nullopt;
                    }
                    const auto k = static_cast<std::size_t>(c);
                    const detail::Contact& e = w_.sim.contacts[k];
                    const detail::ContactLinks& l = w_.sim.contactLinks[k];
                    return ListNode{e.bodyA, e.bodyB, l.prev, l.next};
                });
        }
        std::size_t liveShapes = 0;
        for (std::size_t i = 0; i < w_.shapes.size(); ++i) {
            liveShapes += w_.shapes[i].alive ? 1 : 0;
        }
        require(shapesListed == liveShapes, "bodies",
                "the bodies' shape lists hold " + std::to_string(shapesListed) + " shapes, " +
                    std::to_string(liveShapes) + " are live");
    }

    void shapes() const {
        for (std::size_t i = 0; i < w_.shapes.size(); ++i) {
            const detail::Shape& s = w_.shapes[i];
            if (!s.alive) {
                require(s.body == kNullIndex && s.proxyKey == kNullIndex, at("shapes", i),
                        "a dead shape must have no body and no proxy");
                continue;
            }
            require(liveBody(s.body), at("shapes", i, "body"),
                    "must name a live body, got " + std::to_string(s.body));
            require(s.generation != 0, at("shapes", i, "generation"), "must not be 0 when live");
            try {
                validate(s.geometry, kRestore);
            } catch (const core::Error& e) {
                fail(at("shapes", i, "geometry"), e.what());
            }
            require(isFinite(s.aabb.lower) && isFinite(s.aabb.upper) &&
                        s.aabb.lower.x <= s.aabb.upper.x && s.aabb.lower.y <= s.aabb.upper.y,
                    at("shapes", i, "aabb"), "must be finite with lower <= upper");
            require(isFinite(s.density) && isFinite(s.friction) && isFinite(s.restitution) &&
                        isFinite(s.rollingResistance),
                    at("shapes", i, "density"), "the materials must be finite");
            const detail::Body& b = w_.body(s.body);
            if (!b.enabled) {
                require(s.proxyKey == kNullIndex, at("shapes", i, "proxyKey"),
                        "a disabled body's shape has no proxy, got " + std::to_string(s.proxyKey));
                continue;
            }
            const BodyType treeType =
                s.isSensor && s.sensorSeesNonDynamic ? BodyType::Dynamic : b.type;
            const int key = s.proxyKey;
            bool ok = key >= 0 && detail::proxyTypeOf(key) == treeType;
            if (ok) {
                const DynamicTree& tree =
                    SnapshotAccess::tree(w_.broadPhase, static_cast<std::size_t>(key & 3));
                ok = tree.isProxy(detail::proxyIdOf(key)) &&
                     tree.userData(detail::proxyIdOf(key)) == i;
            }
            require(ok, at("shapes", i, "proxyKey"),
                    "must name a proxy of this shape in its body type's tree, got " +
                        std::to_string(key));
        }
    }

    void joints() const {
        std::size_t live = 0;
        for (std::size_t i = 0; i < w_.joints.size(); ++i) {
            const detail::Joint& j = w_.joints[i];
            if (!j.alive) {
                continue;
            }
            ++live;
            require(liveBody(j.bodyA) && liveBody(j.bodyB) && j.bodyA != j.bodyB,
                    at("joints", i, "bodyA"),
                    "bodyA and bodyB must name two live bodies, got " + std::to_string(j.bodyA) +
                        " and " + std::to_string(j.bodyB));
            require(j.generation != 0, at("joints", i, "generation"), "must not be 0 when live");
        }
        require(jointsListed_ == 2 * live, "joints",
                "the bodies' joint lists hold " + std::to_string(jointsListed_) + " entries, the " +
                    std::to_string(live) + " live joints need twice that");
    }

    void contacts() const {
        const detail::Simulation& s = w_.sim;
        std::size_t live = 0;
        for (std::size_t i = 0; i < s.contacts.size(); ++i) {
            const detail::Contact& c = s.contacts[i];
            const detail::ContactLinks& l = s.contactLinks[i];
            if (!c.alive) {
                continue;
            }
            ++live;
            require(liveShape(l.shapeA) && liveShape(l.shapeB) && l.shapeA != l.shapeB,
                    at("contacts", i, "shapeA"), "shapeA and shapeB must name two live shapes");
            const detail::Shape& a = w_.shape(l.shapeA);
            const detail::Shape& b = w_.shape(l.shapeB);
            require(a.proxyKey != kNullIndex && b.proxyKey != kNullIndex, at("contacts", i),
                    "both shapes must be in the broad phase");
            require(c.bodyA == a.body && c.bodyB == b.body && c.bodyA != c.bodyB,
                    at("contacts", i, "bodyA"), "must be the shapes' (different) bodies");
            require(l.idA == w_.shapeId(l.shapeA) && l.idB == w_.shapeId(l.shapeB),
                    at("contacts", i, "idA"), "must be the shapes' ids");
            require(c.manifold.pointCount >= 0 && c.manifold.pointCount <= 2,
                    at("contacts", i, "manifold.pointCount"),
                    "must be in [0, 2], got " + std::to_string(c.manifold.pointCount));
        }
        require(static_cast<std::size_t>(s.contactCount) == live && s.contactCount >= 0,
                "contactCount",
                "must count the " + std::to_string(live) + " live contacts, got " +
                    std::to_string(s.contactCount));
        std::vector<unsigned char> seen(s.contacts.size(), 0);
        for (std::size_t k = 0; k < s.freeContacts.size(); ++k) {
            const int c = s.freeContacts[k];
            require(c >= 0 && static_cast<std::size_t>(c) < s.contacts.size() && !liveContact(c) &&
                        seen[static_cast<std::size_t>(c)] == 0,
                    at("freeContacts", k),
                    "must name a dead contact once, got " + std::to_string(c));
            seen[static_cast<std::size_t>(c)] = 1;
        }
        require(s.freeContacts.size() + live == s.contacts.size(), "freeContacts",
                "must list every dead contact");
        require(contactsListed_ == 2 * live, "contacts",
                "the bodies' contact lists hold " + std::to_string(contactsListed_) +
                    " entries, the " + std::to_string(live) + " live contacts need twice that");
    }

    // Each tree: every node is reached once from the root, or is on the free list, or is a
    // deferred leaf; then DynamicTree::validate() for boxes, heights and categories.
    void trees() const {
        for (std::size_t t = 0; t < kBodyTypeCount; ++t) {
            const DynamicTree& tree = SnapshotAccess::tree(w_.broadPhase, t);
            const auto& nodes = SnapshotAccess::nodes(tree);
            const std::string path = at("broadPhase.trees", t);
            const std::size_t n = nodes.size();
            auto inRange = [&](int i) { return i >= 0 && static_cast<std::size_t>(i) < n; };
            require(n < (std::size_t{1} << 28), path, "too many nodes");
            std::vector<unsigned char> seen(n, 0);
            int leaves = 0;
            const int root = SnapshotAccess::root(tree);
            if (root != DynamicTree::kNullProxy) {
                require(inRange(root) &&
                            nodes[static_cast<std::size_t>(root)].parent == DynamicTree::kNullProxy,
                        path + ".root",
                        "must name a node without parent, got " + std::to_string(root));
                std::vector<int> stack{root};
                seen[static_cast<std::size_t>(root)] = 1;
                while (!stack.empty()) {
                    const int index = stack.back();
                    stack.pop_back();
                    const auto& node = nodes[static_cast<std::size_t>(index)];
                    const std::string where = path + ".nodes[" + std::to_string(index) + "]";
                    if (node.child1 == DynamicTree::kNullProxy) {
                        require(node.child2 == DynamicTree::kNullProxy && node.height == 0, where,
                                "a leaf must have height 0 and no children");
                        ++leaves;
                        continue;
                    }
                    require(node.height > 0, where + ".height", "an inner node's must be > 0");
                    for (int child : {node.child1, node.child2}) {
                        require(inRange(child) && seen[static_cast<std::size_t>(child)] == 0 &&
                                    nodes[static_cast<std::size_t>(child)].parent == index,
                                where + ".child1",
                                "children must be distinct nodes reached once, whose parent is "
                                "this node");
                        seen[static_cast<std::size_t>(child)] = 1;
                        stack.push_back(child);
                    }
                }
            }
            for (int i = SnapshotAccess::freeList(tree); i != DynamicTree::kNullProxy;
                 i = nodes[static_cast<std::size_t>(i)].parent) {
                require(inRange(i) && seen[static_cast<std::size_t>(i)] == 0 &&
                            nodes[static_cast<std::size_t>(i)].height == -1,
                        path + ".freeList", "must link free nodes (height -1), each once");
                seen[static_cast<std::size_t>(i)] = 1;
            }
            int deferred = 0;
            for (std::size_t i = 0; i < n; ++i) {
                if (seen[i] != 0) {
                    continue;
                }
                const auto& node = nodes[i];
                // A deferred leaf: height 0, parent kDeferredParent (-2).
                require(node.height == 0 && node.parent == -2 &&
                            node.child1 == DynamicTree::kNullProxy,
                        path + ".nodes[" + std::to_string(i) + "]",
                        "neither in the tree, nor free, nor a deferred leaf");
                require(isFinite(node.aabb.lower) && isFinite(node.aabb.upper) &&
                            node.aabb.lower.x <= node.aabb.upper.x &&
                            node.aabb.lower.y <= node.aabb.upper.y,
                        path + ".nodes[" + std::to_string(i) + "].aabb",
                        "must be finite with lower <= upper");
                ++deferred;
            }
            require(deferred == SnapshotAccess::deferredCount(tree), path + ".deferredCount",
                    "must count the " + std::to_string(deferred) + " deferred leaves");
            require(leaves + deferred == SnapshotAccess::proxyCount(tree), path + ".proxyCount",
                    "must count the " + std::to_string(leaves + deferred) + " leaves");
            const auto& list = SnapshotAccess::deferred(tree);
            for (std::size_t k = 0; k < list.size(); ++k) {
                require(inRange(list[k]), at((path + ".deferred").c_str(), k),
                        "must name a node, got " + std::to_string(list[k]));
            }
            require(tree.validate(), path,
                    "boxes, heights or categories of the hierarchy are inconsistent");
        }
    }

    // Proxies, move buffer and pairs against the shapes.
    void broadPhase() const {
        const detail::BroadPhase& bp = w_.broadPhase;
        const auto& infos = SnapshotAccess::infos(bp);
        const std::vector<int>& moves = SnapshotAccess::moveBuffer(bp);
        std::vector<unsigned char> live(infos.size(), 0);
        std::size_t liveCount = 0;
        for (std::size_t i = 0; i < w_.shapes.size(); ++i) {
            const int key = w_.shapes[i].proxyKey;
            if (key != kNullIndex) {
                require(static_cast<std::size_t>(key) < infos.size(), at("shapes", i, "proxyKey"),
                        "has no proxy info (" + std::to_string(infos.size()) + " infos)");
                live[static_cast<std::size_t>(key)] = 1;
                ++liveCount;
            }
        }
        int proxies = 0;
        for (std::size_t t = 0; t < kBodyTypeCount; ++t) {
            proxies += SnapshotAccess::proxyCount(SnapshotAccess::tree(bp, t));
        }
        require(static_cast<std::size_t>(proxies) == liveCount, "broadPhase.trees",
                "hold " + std::to_string(proxies) + " proxies, the shapes " +
                    std::to_string(liveCount));
        for (std::size_t k = 0; k < moves.size(); ++k) {
            const int key = moves[k];
            require(key == detail::kNullProxyKey ||
                        (key >= 0 && static_cast<std::size_t>(key) < infos.size() &&
                         live[static_cast<std::size_t>(key)] != 0 &&
                         infos[static_cast<std::size_t>(key)].moveIndex == static_cast<int>(k)),
                    at("broadPhase.moveBuffer", k),
                    "must be -1 or a live proxy whose moveIndex is here, got " +
                        std::to_string(key));
        }
        std::vector<int> pairCounts(infos.size(), 0);
        const std::vector<detail::PairEntry>& slots = SnapshotAccess::pairSlots(bp);
        const detail::PairSet& set = SnapshotAccess::pairSet(bp);
        for (std::size_t k = 0; k < slots.size(); ++k) {
            const detail::PairEntry& e = slots[k];
            if (e.key == 0) {
                continue;
            }
            const std::string path = at("broadPhase.pairs.slots", k);
            const std::uint64_t a = detail::pairKeyLow(e.key);
            const std::uint64_t b = detail::pairKeyHigh(e.key);
            require(a < b && b < w_.shapes.size() && liveShape(static_cast<int>(a)) &&
                        liveShape(static_cast<int>(b)),
                    path + ".key", "must pair two live shapes");
            require(e.proxyKeyA == w_.shape(static_cast<int>(a)).proxyKey &&
                        e.proxyKeyB == w_.shape(static_cast<int>(b)).proxyKey &&
                        e.proxyKeyA != kNullIndex && e.proxyKeyB != kNullIndex,
                    path + ".proxyKeyA", "must be the shapes' proxies");
            require(set.find(e.key) == &e, path, "is not where the table's probing finds it");
            ++pairCounts[static_cast<std::size_t>(e.proxyKeyA)];
            ++pairCounts[static_cast<std::size_t>(e.proxyKeyB)];
        }
        for (std::size_t key = 0; key < infos.size(); ++key) {
            const auto& info = infos[key];
            const std::string path = at("broadPhase.infos", key);
            require(info.pairCount == pairCounts[key], path + ".pairCount",
                    "must count the proxy's " + std::to_string(pairCounts[key]) + " pairs, got " +
                        std::to_string(info.pairCount));
            if (live[key] == 0) {
                require(info.moveIndex == -1, path + ".moveIndex",
                        "must be -1 for a key without proxy");
                continue;
            }
            require(info.moveIndex == -1 ||
                        (info.moveIndex >= 0 &&
                         static_cast<std::size_t>(info.moveIndex) < moves.size() &&
                         moves[static_cast<std::size_t>(info.moveIndex)] == static_cast<int>(key)),
                    path + ".moveIndex", "must be -1 or where the move buffer lists the proxy");
        }
    }

private:
    // An element of a body's intrusive list (a joint or a contact): its bodies and its links,
    // prev[2] and next[2] (side 0 through bodyA).
    struct ListNode {
        int bodyA;
        int bodyB;
        const int* prev;
        const int* next;
    };
    // Length of a body's intrusive list, checking each link; `get` gives the live element's
    // ListNode or nullopt.
    template <class Get>
    std::size_t listLength(int head, int bodyIndex, std::size_t slots, const std::string& path,
                           Get get) const {
        std::size_t count = 0;
        int prev = kNullIndex;
        for (int k = head; k != kNullIndex;) {
            const std::optional<ListNode> e = get(k);
            require(
                e.has_value() && (e->bodyA == bodyIndex || e->bodyB == bodyIndex) && count < slots,
                path, "the list must link live elements of this body, got " + std::to_string(k));
            const int side = e->bodyA == bodyIndex ? 0 : 1;
            require(e->prev[side] == prev, path,
                    "element " + std::to_string(k) + " is not linked back to " +
                        std::to_string(prev));
            ++count;
            prev = k;
            k = e->next[side];
        }
        return count;
    }

    const W& w_;
    const char* section_ = "";
    std::size_t offset_ = 0;
    std::size_t jointsListed_ = 0;
    std::size_t contactsListed_ = 0;
};

} // namespace

std::vector<std::uint8_t> World::saveSnapshot() const {
    impl_->requireUnlocked("saveSnapshot");
    detail::SnapshotWriter writer;
    writer.tag("E2DS");
    writer.tag("NAP\0");
    writer.primitive("version", kSnapshotFormatVersion);
    writer.primitive("layout", kLayout);
    writer.primitive("payloadBytes", std::uint64_t{0});
    writer.primitive("checksum", std::uint64_t{0});
    // The writer only reads the state (impl_ is not const behind a const World).
    detail::transferWorld(writer, *impl_);
    std::vector<std::uint8_t>& bytes = writer.bytes();
    const std::span<const std::uint8_t> payload(bytes.data() + kHeaderBytes,
                                                bytes.size() - kHeaderBytes);
    writer.patch(16, payload.size(), 8);
    writer.patch(24, fnv1a(payload), 8);
    return std::move(bytes);
}

void World::restoreSnapshot(std::span<const std::uint8_t> snapshot) {
    impl_->requireUnlocked("restoreSnapshot");
    const std::span<const std::uint8_t> payload = readHeader(snapshot);
    auto fresh = std::make_unique<Impl>();
    detail::SnapshotReader reader(payload, kHeaderBytes, kRestore);
    detail::transferWorld(reader, *fresh);
    if (reader.remaining() != 0) {
        reader.fail("END.", std::to_string(reader.remaining()) + " bytes after the last section",
                    0);
    }
    Checker check(*fresh);
    auto section = [&](const char* name) { check.section(name, reader.sectionOffset(name)); };
    section("WRLD");
    check.world();
    section("BODY");
    check.pool(fresh->bodyIds, fresh->bodies.size(), "body",
               [&](int i) { return check.liveBody(i); });
    section("SHAP");
    check.pool(fresh->shapeIds, fresh->shapes.size(), "shape",
               [&](int i) { return check.liveShape(i); });
    section("BRPH");
    check.trees();
    section("SHAP");
    check.shapes();
    section("BODY");
    check.bodies();
    section("JOIN");
    check.pool(fresh->jointIds, fresh->joints.size(), "joint",
               [&](int i) { return check.liveJoint(i); });
    check.joints();
    section("CONT");
    check.contacts();
    section("BRPH");
    check.broadPhase();
    fresh->copyContactShapes();
    // Not state: how this world runs (its callbacks, its workers, its SIMD width) stays.
    fresh->hooks.preSolve = std::move(impl_->hooks.preSolve);
    fresh->hooks.pairFilter = std::move(impl_->hooks.pairFilter);
    fresh->tasks = std::move(impl_->tasks);
    fresh->sim.simdLanes = impl_->sim.simdLanes;
    impl_ = std::move(fresh);
}

} // namespace e2d::physics
