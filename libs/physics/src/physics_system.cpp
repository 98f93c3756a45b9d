// SPDX-License-Identifier: MIT
#include <e2d/physics/physics_system.hpp>

#include <e2d/core/contact_info.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/rigidbody.hpp>

#include "object_pose.hpp"

#include <algorithm>

namespace e2d::physics {

PhysicsSystem::PhysicsSystem(const WorldDef& def) : def_(def), world_(def) {}

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

// Objects moved by game code since the last step are teleported: the object is the authority
// between steps, the body during them.
void PhysicsSystem::pullMovedObjects() {
    for (Rigidbody* rb : rigidbodies_) {
        const detail::Pose pose = detail::worldPose(*rb->gameObject());
        if (detail::movedApart(pose, rb->writtenPosition_, rb->writtenAngle_)) {
            world_.setTransform(rb->body_, pose.position, pose.angle);
            rb->writtenPosition_ = pose.position;
            rb->writtenAngle_ = pose.angle;
        }
    }
    for (Collider* c : staticColliders_) {
        const detail::Pose pose = detail::worldPose(*c->gameObject());
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
        detail::setWorldPose(*rb->gameObject(), pose);
        // Remember what the object now reports, after its own matrix round trip.
        const detail::Pose seen = detail::worldPose(*rb->gameObject());
        rb->writtenPosition_ = seen.position;
        rb->writtenAngle_ = seen.angle;
    }
}

namespace {

// The contact as the receiving object sees it: normals point away from it.
core::ContactInfo contactFor(const Manifold* manifold, bool receiverIsA, core::GameObject* other,
                             core::Component* otherCollider) {
    core::ContactInfo info;
    info.other = other;
    info.otherCollider = otherCollider;
    if (manifold != nullptr) {
        const Vec2 normal = receiverIsA ? manifold->normal : -manifold->normal;
        info.pointCount = std::min(manifold->pointCount, core::ContactInfo::kMaxPoints);
        for (int i = 0; i < info.pointCount; ++i) {
            const ManifoldPoint& mp = manifold->points[i];
            info.points[static_cast<std::size_t>(i)] = {mp.point, normal, mp.separation};
        }
    }
    return info;
}

} // namespace

void PhysicsSystem::dispatchEvents() {
    // Components may destroy objects or components while handling an event; core defers both,
    // so the pointers looked up here stay valid until the next frame.
    const auto objectOf = [](Collider* c) { return c != nullptr ? c->gameObject() : nullptr; };
    for (const ContactBeginTouchEvent& e : world_.contactBeginEvents()) {
        Collider* a = collider(e.shapeA);
        Collider* b = collider(e.shapeB);
        if (a != nullptr) {
            a->gameObject()->dispatchCollisionEnter(contactFor(&e.manifold, true, objectOf(b), b));
        }
        if (b != nullptr) {
            b->gameObject()->dispatchCollisionEnter(contactFor(&e.manifold, false, objectOf(a), a));
        }
    }
    for (const ContactEndTouchEvent& e : world_.contactEndEvents()) {
        Collider* a = collider(e.shapeA);
        Collider* b = collider(e.shapeB);
        if (a != nullptr) {
            a->gameObject()->dispatchCollisionExit(contactFor(nullptr, true, objectOf(b), b));
        }
        if (b != nullptr) {
            b->gameObject()->dispatchCollisionExit(contactFor(nullptr, false, objectOf(a), a));
        }
    }
    for (const SensorBeginTouchEvent& e : world_.sensorBeginEvents()) {
        Collider* sensor = collider(e.sensorShape);
        Collider* visitor = collider(e.visitorShape);
        if (sensor != nullptr) {
            sensor->gameObject()->dispatchTriggerEnter(contactFor(nullptr, true, objectOf(visitor), visitor));
        }
        if (visitor != nullptr) {
            visitor->gameObject()->dispatchTriggerEnter(contactFor(nullptr, true, objectOf(sensor), sensor));
        }
    }
    for (const SensorEndTouchEvent& e : world_.sensorEndEvents()) {
        Collider* sensor = collider(e.sensorShape);
        Collider* visitor = collider(e.visitorShape);
        if (sensor != nullptr) {
            sensor->gameObject()->dispatchTriggerExit(contactFor(nullptr, true, objectOf(visitor), visitor));
        }
        if (visitor != nullptr) {
            visitor->gameObject()->dispatchTriggerExit(contactFor(nullptr, true, objectOf(sensor), sensor));
        }
    }
}

} // namespace e2d::physics
