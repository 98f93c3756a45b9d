// SPDX-License-Identifier: MIT
// PhysicsSystem::saveSnapshot() and restoreSnapshot(): the World's snapshot plus what the
// components keep beside it, and the objects put back where their bodies are.
#include <e2d/physics/physics_system.hpp>

#include <e2d/core/game_object.hpp>
#include <e2d/physics/character_controller.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/rigidbody.hpp>

#include "object_pose.hpp"

#include <algorithm>

namespace e2d::physics {

PhysicsSnapshot PhysicsSystem::saveSnapshot() const {
    requireNotDispatching("saveSnapshot");
    PhysicsSnapshot snapshot;
    snapshot.world_ = world_.saveSnapshot();
    for (const CharacterController* c : characters_) {
        snapshot.characters_.push_back({c, *c->mover_, c->last_, c->touching_, c->sensors_});
    }
    return snapshot;
}

void PhysicsSystem::restoreSnapshot(const PhysicsSnapshot& snapshot) {
    requireNotDispatching("restoreSnapshot");
    world_.restoreSnapshot(snapshot.world_); // throws before anything changed
    // Components whose bodies the snapshot does not have (made after the save).
    forgetDestroyedBodies();
    pushBodyTransforms();
    for (Rigidbody* rb : rigidbodies_) {
        rb->gameObject()->snapRenderPose();
    }
    for (Collider* c : staticColliders_) {
        const Transform xf = world_.transform(c->ownBody_);
        core::GameObject& object = *c->gameObject();
        detail::setWorldPose(object, {xf.p, xf.q.angle()}, unitsPerMetre_);
        const detail::Pose seen = detail::worldPose(object, unitsPerMetre_);
        c->writtenPosition_ = seen.position;
        c->writtenAngle_ = seen.angle;
        object.snapRenderPose();
    }
    for (CharacterController* c : characters_) {
        const auto saved =
            std::find_if(snapshot.characters_.begin(), snapshot.characters_.end(),
                         [c](const PhysicsSnapshot::Character& s) { return s.component == c; });
        if (saved == snapshot.characters_.end()) {
            continue; // made after the save: it goes on from where it is
        }
        c->mover_ = saved->mover;
        c->last_ = saved->last;
        c->touching_ = saved->touching;
        c->sensors_ = saved->sensors;
        core::GameObject& object = *c->gameObject();
        const detail::Pose pose = detail::worldPose(object, unitsPerMetre_);
        detail::setWorldPose(object, {c->mover_->position(), pose.angle}, unitsPerMetre_);
        c->writtenPosition_ = detail::worldPose(object, unitsPerMetre_).position;
        object.snapRenderPose();
    }
}

} // namespace e2d::physics
