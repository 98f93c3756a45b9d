// SPDX-License-Identifier: MIT
// What a game needs around the step: pre-solve and pair filter callbacks, body move events,
// shape overlap queries, explosions, point helpers and the setters of what has getters.
#include <e2d/physics/world.hpp>

#include <e2d/physics/distance.hpp>

#include "world_check.hpp"
#include "world_impl.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace e2d::physics {

using detail::kNullIndex;
namespace check = detail::world_check;

// --- Impl ---

void World::Impl::collectMoveEvents(float dt) {
    std::vector<BodyMoveEvent>& events = hooks.moveEvents;
    if (dt <= 0.0f) {
        events.clear();
        return;
    }
    // solve() wrote one event per solver body it left enabled, in solver order (the disabled
    // ones are reported in nonFiniteBodies() or outOfRangeBodies()); the bodies updateSleep()
    // put to sleep are marked here. A solver body's event is its index less the disabled
    // bodies before it.
    const std::vector<int>& disabled = sim.disabledSims;
    for (const int k : sim.sleptSims) {
        std::size_t event = static_cast<std::size_t>(k);
        if (!disabled.empty()) {
            const auto at = std::lower_bound(disabled.begin(), disabled.end(), k);
            if (at != disabled.end() && *at == k) {
                continue;
            }
            event -= static_cast<std::size_t>(at - disabled.begin());
        }
        events[event].fellAsleep = true;
    }
}

bool World::Impl::passesChainAndFilter(int movingShape, int otherShape, const Transform& xfMoving,
                                       const Transform& xfOther) const {
    const detail::Shape& other = shape(otherShape);
    if (const auto* chain = std::get_if<ChainSegment>(&other.geometry)) {
        // One-sided for continuous collision too: a shape starting behind passes through.
        const Aabb box = computeAabb(shape(movingShape).geometry, xfMoving);
        const Vec2 center = invTransformPoint(xfOther, 0.5f * (box.lower + box.upper));
        const Segment& s = chain->segment;
        if (dot(center - s.point1, rightPerp(s.point2 - s.point1)) < 0.0f) {
            return false;
        }
    }
    if (!hooks.pairFilter) {
        return true;
    }
    CallbackLock lock(*this, "step", "pair filter");
    return hooks.pairFilter(shapeId(movingShape), shapeId(otherShape));
}

// --- hooks ---

void World::setPreSolveCallback(PreSolveCallback callback) {
    impl_->requireUnlocked("setPreSolveCallback");
    impl_->hooks.preSolve = std::move(callback);
}

void World::setPairFilterCallback(PairFilterCallback callback) {
    impl_->requireUnlocked("setPairFilterCallback");
    impl_->hooks.pairFilter = std::move(callback);
}

std::span<const BodyMoveEvent> World::bodyMoveEvents() const { return impl_->hooks.moveEvents; }

// --- queries ---

std::vector<ShapeId> World::overlapShape(const ShapeGeometry& geometry, const Transform& transform,
                                         const QueryFilter& filter) const {
    constexpr const char* kFn = "overlapShape";
    const ShapeType type = typeOf(geometry);
    if (type == ShapeType::Segment || type == ShapeType::ChainSegment) {
        check::fail(kFn, "geometry must be a circle, capsule or polygon (a segment has no inside)");
    }
    validate(geometry, "physics::World::overlapShape()");
    check::requirePosition(kFn, "transform.p", transform.p);
    if (!isFinite(transform.q.c) || !isFinite(transform.q.s) ||
        std::abs(transform.q.c * transform.q.c + transform.q.s * transform.q.s - 1.0f) > 1e-3f) {
        check::fail(kFn, "transform.q must be a finite unit rotation, got (" +
                             check::text(transform.q.c) + ", " + check::text(transform.q.s) + ")");
    }
    const Impl& w = *impl_;
    const ShapeProxy proxy = makeProxy(geometry);
    const Aabb box = computeAabb(geometry, transform);
    std::vector<ShapeId> result;
    // overlapAabb() applies the filter and returns slot order; the exact test follows.
    for (ShapeId id : overlapAabb(box, filter)) {
        const detail::Shape& s = w.shape(w.find(id));
        DistanceInput input;
        input.proxyA = proxy;
        input.proxyB = makeProxy(s.geometry);
        input.transformA = transform;
        input.transformB = w.body(s.body).transform;
        input.useRadii = true;
        if (shapeDistance(input).distance <= 0.0f) {
            result.push_back(id);
        }
    }
    return result;
}

int World::explode(const ExplosionDef& def) {
    constexpr const char* kFn = "explode";
    check::requirePosition(kFn, "def.position", def.position);
    check::requireNonNegative(kFn, "def.radius", def.radius);
    check::requireNonNegative(kFn, "def.falloff", def.falloff);
    check::requireFinite(kFn, "def.impulsePerLength", def.impulsePerLength);
    Impl& w = *impl_;
    const float reach = def.radius + def.falloff;
    const Aabb box{def.position - Vec2{reach, reach}, def.position + Vec2{reach, reach}};
    QueryFilter filter;
    filter.maskBits = def.maskBits;
    filter.categoryBits = ~std::uint64_t{0};
    int pushed = 0;
    for (ShapeId id : overlapAabb(box, filter)) {
        const int si = w.find(id);
        const detail::Shape& s = w.shape(si);
        const int bi = s.body;
        detail::Body& b = w.body(bi);
        if (b.type != BodyType::Dynamic || !b.enabled) {
            continue;
        }
        // Closest point of the shape to the centre, and the width the shape shows it.
        DistanceInput input;
        input.proxyA = makeProxy(std::span<const Vec2>(&def.position, 1), 0.0f);
        input.proxyB = makeProxy(s.geometry);
        input.transformA = Transform{};
        input.transformB = b.transform;
        input.useRadii = true;
        const DistanceOutput out = shapeDistance(input);
        const float dist = out.distance;
        if (dist > reach) {
            continue;
        }
        const Vec2 closest = out.pointB;
        Vec2 direction = closest - def.position;
        if (lengthSquared(direction) <= 0.0f) {
            // The centre is inside the shape: push from the centre to its centre of mass.
            direction = transformPoint(b.transform, b.motion.localCenter) - def.position;
        }
        if (lengthSquared(direction) <= 0.0f) {
            continue;
        }
        direction = normalize(direction);
        // Width facing the centre: the shape's extent across the push direction.
        const Vec2 across = leftPerp(direction);
        float lo = kHuge;
        float hi = -kHuge;
        for (int k = 0; k < input.proxyB.count; ++k) {
            const float t =
                dot(transformPoint(b.transform, input.proxyB.points[static_cast<std::size_t>(k)]) -
                        def.position,
                    across);
            lo = std::min(lo, t);
            hi = std::max(hi, t);
        }
        const float width = hi - lo + 2.0f * input.proxyB.radius;
        const float strength =
            dist <= def.radius
                ? 1.0f
                : (def.falloff > 0.0f ? 1.0f - (dist - def.radius) / def.falloff : 0.0f);
        const float magnitude = def.impulsePerLength * width * strength;
        if (!(magnitude != 0.0f)) {
            continue;
        }
        applyLinearImpulse(w.bodyId(bi), magnitude * direction, closest, true);
        ++pushed;
    }
    return pushed;
}

// --- points ---

Vec2 World::worldPoint(BodyId id, Vec2 localPoint) const {
    check::requireFinite("worldPoint", "localPoint", localPoint);
    return transformPoint(impl_->body(impl_->require(id, "worldPoint")).transform, localPoint);
}

Vec2 World::localPoint(BodyId id, Vec2 worldPoint) const {
    check::requireFinite("localPoint", "worldPoint", worldPoint);
    return invTransformPoint(impl_->body(impl_->require(id, "localPoint")).transform, worldPoint);
}

Vec2 World::worldVector(BodyId id, Vec2 localVector) const {
    check::requireFinite("worldVector", "localVector", localVector);
    return rotate(impl_->body(impl_->require(id, "worldVector")).transform.q, localVector);
}

Vec2 World::localVector(BodyId id, Vec2 worldVector) const {
    check::requireFinite("localVector", "worldVector", worldVector);
    return invRotate(impl_->body(impl_->require(id, "localVector")).transform.q, worldVector);
}

Vec2 World::linearVelocityAtWorldPoint(BodyId id, Vec2 worldPoint) const {
    check::requireFinite("linearVelocityAtWorldPoint", "worldPoint", worldPoint);
    const detail::Body& b = impl_->body(impl_->require(id, "linearVelocityAtWorldPoint"));
    const Vec2 center = transformPoint(b.transform, b.motion.localCenter);
    return b.linearVelocity + cross(b.angularVelocity, worldPoint - center);
}

Vec2 World::linearVelocityAtLocalPoint(BodyId id, Vec2 localPoint) const {
    check::requireFinite("linearVelocityAtLocalPoint", "localPoint", localPoint);
    const detail::Body& b = impl_->body(impl_->require(id, "linearVelocityAtLocalPoint"));
    return b.linearVelocity +
           cross(b.angularVelocity, rotate(b.transform.q, localPoint - b.motion.localCenter));
}

// --- setters ---

void World::setBodyType(BodyId id, BodyType type) {
    impl_->requireUnlocked("setBodyType");
    Impl& w = *impl_;
    const int index = w.require(id, "setBodyType");
    const int typeIndex = static_cast<int>(type);
    if (typeIndex < 0 || typeIndex >= kBodyTypeCount) {
        check::fail("setBodyType",
                    "type must be Static, Kinematic or Dynamic, got " + std::to_string(typeIndex));
    }
    detail::Body& b = w.body(index);
    if (b.type == type) {
        return;
    }
    // The proxies live in one tree per body type, and the pair rules depend on the type: the
    // shapes leave the broad phase (their contacts end, waking what touched them) and come
    // back under the new type.
    for (int s = b.headShape; s != kNullIndex; s = w.shape(s).nextShape) {
        w.destroyProxy(s);
    }
    b.type = type;
    if (type == BodyType::Static) {
        b.linearVelocity = {0.0f, 0.0f};
        b.angularVelocity = 0.0f;
        b.motion.awake = false;
    }
    b.motion.force = {0.0f, 0.0f};
    b.motion.torque = 0.0f;
    w.updateMass(index);
    if (b.enabled) {
        for (int s = b.headShape; s != kNullIndex; s = w.shape(s).nextShape) {
            w.createProxy(s);
        }
    }
    if (type != BodyType::Static) {
        b.motion.awake = false; // wakeBody() starts from a sleeping body
        w.wakeBody(index);
    }
}

namespace {

void requireMaterial(const char* function, const char* name, float value) {
    check::requireNonNegative(function, name, value);
}

} // namespace

void World::setShapeFriction(ShapeId id, float friction) {
    Impl& w = *impl_;
    const int index = w.require(id, "setShapeFriction");
    requireMaterial("setShapeFriction", "friction", friction);
    w.shape(index).friction = friction;
    w.refreshContactMaterials(index);
}

void World::setShapeRestitution(ShapeId id, float restitution) {
    Impl& w = *impl_;
    const int index = w.require(id, "setShapeRestitution");
    if (!(isFinite(restitution) && restitution >= 0.0f && restitution <= 1.0f)) {
        check::fail("setShapeRestitution",
                    "restitution must be finite and in [0, 1], got " + check::text(restitution));
    }
    w.shape(index).restitution = restitution;
    w.refreshContactMaterials(index);
}

void World::setShapeRollingResistance(ShapeId id, float rollingResistance) {
    Impl& w = *impl_;
    const int index = w.require(id, "setShapeRollingResistance");
    requireMaterial("setShapeRollingResistance", "rollingResistance", rollingResistance);
    w.shape(index).rollingResistance = rollingResistance;
    w.refreshContactMaterials(index);
}

void World::setShapeDensity(ShapeId id, float density) {
    Impl& w = *impl_;
    const int index = w.require(id, "setShapeDensity");
    requireMaterial("setShapeDensity", "density", density);
    w.shape(index).density = density;
    w.updateMass(w.shape(index).body);
}

void World::setShapeSensor(ShapeId id, bool isSensor) {
    impl_->requireUnlocked("setShapeSensor");
    Impl& w = *impl_;
    const int index = w.require(id, "setShapeSensor");
    detail::Shape& s = w.shape(index);
    if (s.isSensor == isSensor) {
        return;
    }
    s.isSensor = isSensor;
    if (s.proxyKey != kNullIndex) {
        w.destroyProxy(index);
        w.createProxy(index);
    }
}

void World::setShapeGeometry(ShapeId id, const ShapeGeometry& geometry) {
    impl_->requireUnlocked("setShapeGeometry");
    Impl& w = *impl_;
    const int index = w.require(id, "setShapeGeometry");
    validate(geometry, "physics::World::setShapeGeometry()");
    detail::Shape& s = w.shape(index);
    const bool inBroadPhase = s.proxyKey != kNullIndex;
    if (inBroadPhase) {
        w.destroyProxy(index);
    }
    s.geometry = geometry;
    s.aabb = computeAabb(s.geometry, w.body(s.body).transform);
    if (inBroadPhase) {
        w.createProxy(index);
    }
    w.updateMass(s.body);
    w.wakeBody(s.body);
}

void World::setShapeEventFlags(ShapeId id, bool contactEvents, bool sensorEvents, bool hitEvents) {
    Impl& w = *impl_;
    const int index = w.require(id, "setShapeEventFlags");
    detail::Shape& s = w.shape(index);
    s.contactEvents = contactEvents;
    s.sensorEvents = sensorEvents;
    s.hitEvents = hitEvents;
    w.refreshContactMaterials(index);
}

void World::Impl::refreshContactMaterials(int shapeIndex) {
    const int bodyIndex = shape(shapeIndex).body;
    for (int ci = body(bodyIndex).motion.contactHead; ci != kNullIndex;) {
        detail::Contact& c = sim.contacts[static_cast<std::size_t>(ci)];
        const detail::ContactLinks& l = sim.contactLinks[static_cast<std::size_t>(ci)];
        const int side = c.bodyA == bodyIndex ? 0 : 1;
        if (l.shapeA == shapeIndex || l.shapeB == shapeIndex) {
            const detail::Shape& a = shape(l.shapeA);
            const detail::Shape& b = shape(l.shapeB);
            c.friction = detail::mixFriction(sim.def, a.friction, b.friction);
            c.restitution = detail::mixRestitution(sim.def, a.restitution, b.restitution);
            c.rollingResistance = std::max(a.rollingResistance, b.rollingResistance);
            c.touchEvents =
                c.sensor ? a.sensorEvents && b.sensorEvents : a.contactEvents && b.contactEvents;
            c.hitEvents = a.hitEvents && b.hitEvents;
        }
        ci = l.next[side];
    }
}

} // namespace e2d::physics
