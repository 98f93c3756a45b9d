// SPDX-License-Identifier: MIT
#include <e2d/physics/physics_system.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/contact_info.hpp>
#include <e2d/physics/rigidbody.hpp>

#include "object_pose.hpp"

#include "error_format.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace e2d::physics {

namespace {

float checkedScale(float unitsPerMetre) {
    if (!std::isfinite(unitsPerMetre) || unitsPerMetre <= 0.0f) {
        throw core::Error("physics::PhysicsSystem::PhysicsSystem(): unitsPerMetre must be finite "
                          "and > 0, got " + detail::formatFloat(unitsPerMetre));
    }
    return unitsPerMetre;
}

} // namespace

PhysicsSystem::PhysicsSystem(const WorldDef& def, float unitsPerMetre)
    : def_(def), unitsPerMetre_(checkedScale(unitsPerMetre)), world_(def) {}

std::optional<RayResult> PhysicsSystem::castRayClosest(Vec2 origin, Vec2 translation,
                                                       const QueryFilter& filter) const {
    std::optional<RayResult> hit = world_.castRayClosest(toMetres(origin), toMetres(translation), filter);
    if (hit) {
        hit->point = toUnits(hit->point);
    }
    return hit;
}

std::vector<RayResult> PhysicsSystem::castRayAll(Vec2 origin, Vec2 translation,
                                                 const QueryFilter& filter) const {
    std::vector<RayResult> hits = world_.castRayAll(toMetres(origin), toMetres(translation), filter);
    for (RayResult& hit : hits) {
        hit.point = toUnits(hit.point);
    }
    return hits;
}

PhysicsSystem::~PhysicsSystem() = default;

Collider* PhysicsSystem::collider(ShapeId shape) const noexcept {
    if (shape.isNull() || shape.index1 > colliders_.size()) {
        return nullptr;
    }
    const ColliderSlot& slot = colliders_[shape.index1 - 1];
    return slot.shape == shape ? slot.collider : nullptr;
}

void PhysicsSystem::registerCollider(ShapeId shape, Collider& collider) {
    if (colliders_.size() < shape.index1) {
        colliders_.resize(shape.index1);
    }
    colliders_[shape.index1 - 1] = {shape, &collider};
}

void PhysicsSystem::unregisterCollider(ShapeId shape) noexcept {
    if (!shape.isNull() && shape.index1 <= colliders_.size() &&
        colliders_[shape.index1 - 1].shape == shape) {
        colliders_[shape.index1 - 1] = {};
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

void PhysicsSystem::fixedUpdate(double step) {
    if (dispatching_) {
        throw core::Error("physics::PhysicsSystem::fixedUpdate(): called from inside an event "
                          "handler (CollisionEnter/Exit, TriggerEnter/Exit) of the same "
                          "system");
    }
    forgetDestroyedBodies();
    pullMovedObjects();
    world_.step(static_cast<float>(step));
    pushBodyTransforms();
    dispatchEvents();
}

void PhysicsSystem::clear() {
    // The old scene's components were terminated before this; whatever is left goes.
    world_ = World(def_);
    colliders_.clear();
    rigidbodies_.clear();
    staticColliders_.clear();
}

// Game code may destroy a component's body or a static collider's body through the World (in
// an event callback or anywhere else). Its components then have no body and no shapes: the
// object stays where the body last put it, as if it had no Rigidbody or Collider.
void PhysicsSystem::forgetDestroyedBodies() {
    std::erase_if(rigidbodies_, [&](Rigidbody* rb) {
        if (world_.isValid(rb->body_)) {
            return false;
        }
        for (Collider* c : rb->gameObject()->getComponents<Collider>()) {
            if (!c->shape_.isNull() && !world_.isValid(c->shape_)) {
                unregisterCollider(c->shape_);
                c->shape_ = {};
            }
        }
        rb->body_ = {};
        return true;
    });
    std::erase_if(staticColliders_, [&](Collider* c) {
        if (world_.isValid(c->ownBody_)) {
            return false;
        }
        unregisterCollider(c->shape_);
        c->shape_ = {};
        c->ownBody_ = {};
        return true;
    });
}

// Objects moved by game code since the last step are teleported: the object is the authority
// between steps, the body during them.
void PhysicsSystem::pullMovedObjects() {
    for (Rigidbody* rb : rigidbodies_) {
        const detail::Pose pose = detail::worldPose(*rb->gameObject(), unitsPerMetre_);
        if (detail::movedApart(pose, rb->writtenPosition_, rb->writtenAngle_)) {
            world_.setTransform(rb->body_, pose.position, pose.angle);
            rb->writtenPosition_ = pose.position;
            rb->writtenAngle_ = pose.angle;
        }
    }
    for (Collider* c : staticColliders_) {
        const detail::Pose pose = detail::worldPose(*c->gameObject(), unitsPerMetre_);
        if (detail::movedApart(pose, c->writtenPosition_, c->writtenAngle_)) {
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

namespace {

// The contact as the receiving object sees it: normals point away from it.
ContactInfo contactFor(const Manifold* manifold, bool receiverIsA, core::GameObject* other, Collider* otherCollider,
                       float unitsPerMetre) {
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

} // namespace

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
    // What the receiving object is told about `other`: points and separations in world units.
    const auto contact = [this](const Manifold* manifold, bool receiverIsA, Collider* other) {
        return contactFor(manifold, receiverIsA, other != nullptr ? other->gameObject() : nullptr, other,
                          unitsPerMetre_);
    };
    for (const ContactBeginTouchEvent& e : beginEvents_) {
        Collider* a = collider(e.shapeA);
        Collider* b = collider(e.shapeB);
        if (a != nullptr) {
            a->gameObject()->dispatch(CollisionEnter{contact(&e.manifold, true, b)});
        }
        if (b != nullptr) {
            b->gameObject()->dispatch(CollisionEnter{contact(&e.manifold, false, a)});
        }
    }
    for (const ContactEndTouchEvent& e : endEvents_) {
        Collider* a = collider(e.shapeA);
        Collider* b = collider(e.shapeB);
        if (a != nullptr) {
            a->gameObject()->dispatch(CollisionExit{contact(nullptr, true, b)});
        }
        if (b != nullptr) {
            b->gameObject()->dispatch(CollisionExit{contact(nullptr, false, a)});
        }
    }
    for (const SensorBeginTouchEvent& e : sensorBeginEvents_) {
        Collider* sensor = collider(e.sensorShape);
        Collider* visitor = collider(e.visitorShape);
        if (sensor != nullptr) {
            sensor->gameObject()->dispatch(TriggerEnter{contact(nullptr, true, visitor)});
        }
        if (visitor != nullptr) {
            visitor->gameObject()->dispatch(TriggerEnter{contact(nullptr, true, sensor)});
        }
    }
    for (const SensorEndTouchEvent& e : sensorEndEvents_) {
        Collider* sensor = collider(e.sensorShape);
        Collider* visitor = collider(e.visitorShape);
        if (sensor != nullptr) {
            sensor->gameObject()->dispatch(TriggerExit{contact(nullptr, true, visitor)});
        }
        if (visitor != nullptr) {
            visitor->gameObject()->dispatch(TriggerExit{contact(nullptr, true, sensor)});
        }
    }
}

} // namespace e2d::physics
