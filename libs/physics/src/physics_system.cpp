// SPDX-License-Identifier: MIT
#include <e2d/physics/physics_system.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/contact_info.hpp>
#include <e2d/physics/manifold.hpp>
#include <e2d/physics/rigidbody.hpp>

#include "component_check.hpp"
#include "object_pose.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace e2d::physics {

namespace {

float checkedScale(float unitsPerMetre) {
    if (!std::isfinite(unitsPerMetre) || unitsPerMetre <= 0.0f) {
        throw core::Error("physics::PhysicsSystem::PhysicsSystem(): unitsPerMetre must be finite "
                          "and > 0, got " +
                          core::formatNumber(unitsPerMetre));
    }
    return unitsPerMetre;
}

// A one-way platform lets through what is not coming down onto it along its up (in metres,
// deeper than this it is passing through from below).
constexpr float kOneWayDepth = 0.05f;

} // namespace

PhysicsSystem::PhysicsSystem(const WorldDef& def, float unitsPerMetre)
    : def_(def), unitsPerMetre_(checkedScale(unitsPerMetre)), world_(def) {}

PhysicsSystem::~PhysicsSystem() = default;

// --- queries in world units ---

std::optional<RayResult> PhysicsSystem::castRayClosest(Vec2 origin, Vec2 translation,
                                                       const QueryFilter& filter) const {
    std::optional<RayResult> hit =
        world_.castRayClosest(toMetres(origin), toMetres(translation), filter);
    if (hit) {
        hit->point = toUnits(hit->point);
    }
    return hit;
}

std::vector<RayResult> PhysicsSystem::castRayAll(Vec2 origin, Vec2 translation,
                                                 const QueryFilter& filter) const {
    std::vector<RayResult> hits =
        world_.castRayAll(toMetres(origin), toMetres(translation), filter);
    for (RayResult& hit : hits) {
        hit.point = toUnits(hit.point);
    }
    return hits;
}

std::optional<RayResult> PhysicsSystem::castShape(const ShapeGeometry& geometry, Vec2 position,
                                                  float angle, Vec2 translation,
                                                  const QueryFilter& filter) const {
    const ShapeGeometry metres =
        detail::placedGeometry(geometry, glm::mat2(1.0f), {0.0f, 0.0f}, unitsPerMetre_);
    std::optional<RayResult> hit =
        world_.castShape(metres, Transform{toMetres(position), Rot::fromAngle(angle)},
                         toMetres(translation), filter);
    if (hit) {
        hit->point = toUnits(hit->point);
    }
    return hit;
}

std::vector<ShapeId> PhysicsSystem::overlapPoint(Vec2 point, const QueryFilter& filter) const {
    return world_.overlapPoint(toMetres(point), filter);
}

std::vector<ShapeId> PhysicsSystem::overlapAabb(const Aabb& box, const QueryFilter& filter) const {
    return world_.overlapAabb(Aabb{toMetres(box.lower), toMetres(box.upper)}, filter);
}

std::vector<ShapeId> PhysicsSystem::overlapShape(const ShapeGeometry& geometry, Vec2 position,
                                                 float angle, const QueryFilter& filter) const {
    const ShapeGeometry metres =
        detail::placedGeometry(geometry, glm::mat2(1.0f), {0.0f, 0.0f}, unitsPerMetre_);
    return world_.overlapShape(metres, Transform{toMetres(position), Rot::fromAngle(angle)},
                               filter);
}

// --- bookkeeping ---

namespace {

// The slot of `slots` (indexed by shape slot) that holds `shape` itself (same slot, generation
// and world), or null: the one lookup of collider() and unregisterShape().
template <class Slots>
auto* slotHolding(Slots& slots, ShapeId shape) noexcept {
    auto* slot = shape.isNull() || shape.index() >= slots.size() ? nullptr : &slots[shape.index()];
    return slot != nullptr && slot->shape == shape ? slot : nullptr;
}

} // namespace

Collider* PhysicsSystem::collider(ShapeId shape) const noexcept {
    const auto* slot = slotHolding(colliders_, shape);
    return slot != nullptr ? slot->collider : nullptr;
}

void PhysicsSystem::registerCollider(Collider& collider) {
    allColliders_.push_back(&collider);
    if (collider.def_.oneWay || collider.def_.preSolve) {
        ++ruledColliders_;
        updatePreSolve();
    }
}

void PhysicsSystem::unregisterCollider(Collider& collider) noexcept {
    const auto erased = std::erase(allColliders_, &collider);
    if (erased != 0 && (collider.def_.oneWay || collider.def_.preSolve)) {
        --ruledColliders_;
    }
}

void PhysicsSystem::registerShape(ShapeId shape, Collider& collider) {
    if (colliders_.size() < shape.index1) {
        colliders_.resize(shape.index1);
    }
    colliders_[shape.index1 - 1] = {shape, &collider};
}

void PhysicsSystem::unregisterShape(ShapeId shape) noexcept {
    if (auto* slot = slotHolding(colliders_, shape)) {
        *slot = {};
    }
}

void PhysicsSystem::registerRigidbody(Rigidbody& body) { rigidbodies_.push_back(&body); }

void PhysicsSystem::unregisterRigidbody(Rigidbody& body) noexcept {
    std::erase(rigidbodies_, &body);
}

void PhysicsSystem::registerStaticCollider(Collider& collider) {
    staticColliders_.push_back(&collider);
}

void PhysicsSystem::unregisterStaticCollider(Collider& collider) noexcept {
    std::erase(staticColliders_, &collider);
}

void PhysicsSystem::registerCharacter(CharacterController& character) {
    characters_.push_back(&character);
}

void PhysicsSystem::unregisterCharacter(CharacterController& character) noexcept {
    std::erase(characters_, &character);
}

std::vector<Collider*> PhysicsSystem::collidersOn(const Rigidbody* body) const {
    std::vector<Collider*> riders;
    for (Collider* c : allColliders_) {
        if (c->owner_ == body) {
            riders.push_back(c);
        }
    }
    return riders;
}

void PhysicsSystem::reattachColliders(const std::function<bool(const Collider&)>& which) {
    for (Collider* c : allColliders_) {
        if (c->attached_ && which(*c)) {
            c->attach();
        }
    }
}

void PhysicsSystem::updatePreSolve() {
    // Installed lazily (a world without rules pays no callback per contact) and kept once
    // installed: removing it is not allowed from inside a step, where a collider may go.
    if (ruledColliders_ > 0 && !preSolveInstalled_) {
        world_.setPreSolveCallback([this](ShapeId a, ShapeId b, const Manifold& manifold) {
            return preSolve(a, b, manifold);
        });
        preSolveInstalled_ = true;
    }
}

namespace {

// The contact as the receiving collider sees it: normals point away from it; points and
// separations in world units.
ContactInfo contactFor(const Manifold* manifold, bool receiverIsA, core::GameObject* other,
                       core::Component* otherCollider, float unitsPerMetre) {
    ContactInfo info;
    info.other = other;
    info.otherCollider = otherCollider;
    if (manifold != nullptr) {
        const Vec2 normal = receiverIsA ? manifold->normal : -manifold->normal;
        info.pointCount = std::min(manifold->pointCount, ContactInfo::kMaxPoints);
        for (int i = 0; i < info.pointCount; ++i) {
            const ManifoldPoint& mp = manifold->points[i];
            info.points[static_cast<std::size_t>(i)] = {mp.point * unitsPerMetre, normal,
                                                        mp.separation * unitsPerMetre};
        }
    }
    return info;
}

// Whether a one-way collider lets this contact be solved: only what comes onto it along its
// object's up and has not sunk into it (from below).
bool oneWayAccepts(const Collider& platform, const Manifold& manifold, bool platformIsA) {
    const glm::mat4& m = platform.gameObject()->worldTransform();
    glm::vec2 up{m[1][0], m[1][1]};
    const float length = std::hypot(up.x, up.y);
    up = length > 0.0f ? up / length : glm::vec2{0.0f, 1.0f};
    const Vec2 normal = platformIsA ? manifold.normal : -manifold.normal;
    if (normal.x * up.x + normal.y * up.y < 0.7f) {
        return false;
    }
    for (int i = 0; i < manifold.pointCount; ++i) {
        if (manifold.points[i].separation < -kOneWayDepth) {
            return false;
        }
    }
    return true;
}

} // namespace

bool PhysicsSystem::preSolve(ShapeId a, ShapeId b, const Manifold& manifold) const {
    Collider* ca = collider(a);
    Collider* cb = collider(b);
    const auto accepts = [&](const Collider* self, const Collider* other, bool selfIsA) {
        if (self == nullptr) {
            return true;
        }
        if (self->def_.oneWay && !oneWayAccepts(*self, manifold, selfIsA)) {
            return false;
        }
        if (self->def_.preSolve) {
            Collider* o = const_cast<Collider*>(other);
            return self->def_.preSolve(contactFor(
                &manifold, selfIsA, o != nullptr ? o->gameObject() : nullptr, o, unitsPerMetre_));
        }
        return true;
    };
    return accepts(ca, cb, true) && accepts(cb, ca, false);
}

// --- the step ---

void PhysicsSystem::requireNotDispatching(const char* function) const {
    if (dispatching_) {
        throw core::Error(std::string("physics::PhysicsSystem::") + function +
                          "(): called from inside an event handler (CollisionEnter/Exit, "
                          "TriggerEnter/Exit) of the same system");
    }
}

void PhysicsSystem::fixedUpdate(double step) {
    requireNotDispatching("fixedUpdate");
    forgetDestroyedBodies();
    syncColliders();
    pullMovedObjects(static_cast<float>(step));
    world_.step(static_cast<float>(step));
    pushBodyTransforms();
    dispatchEvents();
}

void PhysicsSystem::clear() {
    // The old scene's components were terminated before this; whatever is left goes.
    world_ = World(def_);
    allColliders_.clear();
    colliders_.clear();
    rigidbodies_.clear();
    staticColliders_.clear();
    characters_.clear();
    ruledColliders_ = 0;
    preSolveInstalled_ = false;
}

// Game code may destroy a component's body or a static collider's body through the World (in
// an event callback or anywhere else). Its components then have no body and no shapes: the
// object stays where the body last put it, as if it had no Rigidbody or Collider.
void PhysicsSystem::forgetDestroyedBodies() {
    std::erase_if(rigidbodies_, [&](Rigidbody* rb) {
        if (world_.isValid(rb->body_)) {
            return false;
        }
        for (Collider* c : collidersOn(rb)) {
            if (!c->shape_.isNull() && !world_.isValid(c->shape_)) {
                unregisterShape(c->shape_);
                c->shape_ = {};
                c->body_ = {};
            }
        }
        rb->body_ = {};
        rb->state_ = Rigidbody::State::Gone;
        return true;
    });
    std::erase_if(staticColliders_, [&](Collider* c) {
        if (world_.isValid(c->ownBody_)) {
            return false;
        }
        unregisterShape(c->shape_);
        c->shape_ = {};
        c->body_ = {};
        c->ownBody_ = {};
        return true;
    });
}

// Colliders follow the hierarchy: a new parent, a new pose relative to the body, a new scale.
void PhysicsSystem::syncColliders() {
    for (Collider* c : allColliders_) {
        if (c->attached_ && c->isOutOfDate()) {
            c->attach();
        }
    }
}

// Objects moved by game code since the last step are teleported: the object is the authority
// between steps, the body during them. Kinematic targets set their bodies' velocities.
void PhysicsSystem::pullMovedObjects(float step) {
    for (Rigidbody* rb : rigidbodies_) {
        const detail::Pose pose = detail::worldPose(*rb->gameObject(), unitsPerMetre_);
        if (detail::movedApart(pose, rb->writtenPosition_, rb->writtenAngle_)) {
            detail::component_check::requireInRange(*rb->gameObject(), "Rigidbody", unitsPerMetre_);
            world_.setTransform(rb->body_, pose.position, pose.angle);
            rb->writtenPosition_ = pose.position;
            rb->writtenAngle_ = pose.angle;
        }
        if (step > 0.0f) {
            rb->applyTarget(step);
        }
    }
    for (Collider* c : staticColliders_) {
        const detail::Pose pose = detail::worldPose(*c->gameObject(), unitsPerMetre_);
        if (detail::movedApart(pose, c->writtenPosition_, c->writtenAngle_)) {
            detail::component_check::requireInRange(*c->gameObject(), "Collider", unitsPerMetre_);
            world_.setTransform(c->ownBody_, pose.position, pose.angle);
            c->writtenPosition_ = pose.position;
            c->writtenAngle_ = pose.angle;
        }
    }
}

void PhysicsSystem::pushBodyTransforms() {
    for (Rigidbody* rb : rigidbodies_) {
        const Transform xf = world_.transform(rb->body_);
        const detail::Pose pose{xf.p, xf.q.angle()};
        detail::setWorldPose(*rb->gameObject(), pose, unitsPerMetre_);
        // Remember what the object now reports, after its own matrix round trip.
        const detail::Pose seen = detail::worldPose(*rb->gameObject(), unitsPerMetre_);
        rb->writtenPosition_ = seen.position;
        rb->writtenAngle_ = seen.angle;
    }
}

void PhysicsSystem::dispatchEvents() {
    // Components may destroy objects or components while handling an event; core defers both,
    // so the pointers looked up here stay valid until the next frame. They may also change the
    // world (destroy bodies, create them, even step it): the events are copied first, so the
    // world's own arrays may change under the loops below.
    beginEvents_.assign(world_.contactBeginEvents().begin(), world_.contactBeginEvents().end());
    endEvents_.assign(world_.contactEndEvents().begin(), world_.contactEndEvents().end());
    sensorBeginEvents_.assign(world_.sensorBeginEvents().begin(), world_.sensorBeginEvents().end());
    sensorEndEvents_.assign(world_.sensorEndEvents().begin(), world_.sensorEndEvents().end());
    dispatching_ = true;
    struct Reset {
        bool& flag;
        ~Reset() { flag = false; }
    } reset{dispatching_};
    // Sends the event to the collider's object, and to its Rigidbody's object when that is an
    // ancestor (a compound body hears of its children's contacts).
    const auto send = [this]<class Event>(Collider* receiver, Event, const Manifold* manifold,
                                          bool receiverIsA, Collider* other) {
        if (receiver == nullptr) {
            return;
        }
        const Event event{contactFor(manifold, receiverIsA,
                                     other != nullptr ? other->gameObject() : nullptr, other,
                                     unitsPerMetre_)};
        core::GameObject* object = receiver->gameObject();
        Rigidbody* owner = receiver->owner_;
        object->dispatch(event);
        if (owner != nullptr && owner->gameObject() != object) {
            owner->gameObject()->dispatch(event);
        }
    };
    for (const ContactBeginTouchEvent& e : beginEvents_) {
        Collider* a = collider(e.shapeA);
        Collider* b = collider(e.shapeB);
        // The manifold where the shapes are now, after the step (the event's is from the
        // narrow phase, before the solver moved them).
        Manifold now = e.manifold;
        if (world_.isValid(e.shapeA) && world_.isValid(e.shapeB)) {
            now = collide(
                world_.shapeGeometry(e.shapeA), world_.transform(world_.shapeBody(e.shapeA)),
                world_.shapeGeometry(e.shapeB), world_.transform(world_.shapeBody(e.shapeB)),
                world_.collisionAlgorithm(), world_.speculativeDistance());
            if (now.pointCount == 0) {
                now = e.manifold;
            }
        }
        send(a, CollisionEnter{}, &now, true, b);
        send(b, CollisionEnter{}, &now, false, a);
    }
    for (const ContactEndTouchEvent& e : endEvents_) {
        Collider* a = collider(e.shapeA);
        Collider* b = collider(e.shapeB);
        send(a, CollisionExit{}, nullptr, true, b);
        send(b, CollisionExit{}, nullptr, false, a);
    }
    for (const SensorBeginTouchEvent& e : sensorBeginEvents_) {
        Collider* sensor = collider(e.sensorShape);
        Collider* visitor = collider(e.visitorShape);
        send(sensor, TriggerEnter{}, nullptr, true, visitor);
        send(visitor, TriggerEnter{}, nullptr, true, sensor);
    }
    for (const SensorEndTouchEvent& e : sensorEndEvents_) {
        Collider* sensor = collider(e.sensorShape);
        Collider* visitor = collider(e.visitorShape);
        send(sensor, TriggerExit{}, nullptr, true, visitor);
        send(visitor, TriggerExit{}, nullptr, true, sensor);
    }
}

} // namespace e2d::physics
