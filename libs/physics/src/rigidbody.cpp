// SPDX-License-Identifier: MIT
#include <e2d/physics/rigidbody.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/physics_system.hpp>

#include "component_check.hpp"
#include "object_pose.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace e2d::physics {

namespace {
constexpr const char* kConstructor = "Rigidbody::Rigidbody";
} // namespace

Rigidbody::Rigidbody(PhysicsSystem& system, const RigidbodyDef& def) : system_(system), def_(def) {
    if (def.type == BodyType::Static) {
        throw core::Error("physics::Rigidbody::Rigidbody(): def.type must be dynamic or kinematic; "
                          "a Collider without a Rigidbody is static");
    }
    using namespace detail::component_check;
    requireFinite(kConstructor, "gravityScale", def.gravityScale);
    requireNonNegative(kConstructor, "linearDamping", def.linearDamping);
    requireNonNegative(kConstructor, "angularDamping", def.angularDamping);
    requireFinite(kConstructor, "linearVelocity.x", def.linearVelocity.x);
    requireFinite(kConstructor, "linearVelocity.y", def.linearVelocity.y);
    requireFinite(kConstructor, "angularVelocity", def.angularVelocity);
}

Rigidbody::~Rigidbody() = default;

BodyId Rigidbody::ensureBody() {
    if (!body_.isNull()) {
        return body_;
    }
    const detail::Pose pose = detail::worldPose(*gameObject());
    BodyDef def;
    def.type = def_.type;
    def.position = pose.position;
    def.angle = pose.angle;
    def.linearVelocity = def_.linearVelocity;
    def.angularVelocity = def_.angularVelocity;
    def.linearDamping = def_.linearDamping;
    def.angularDamping = def_.angularDamping;
    def.gravityScale = def_.gravityScale;
    def.fixedRotation = def_.freezeRotation;
    def.lockX = def_.freezePositionX;
    def.lockY = def_.freezePositionY;
    def.isBullet = def_.bullet;
    body_ = system_.world().createBody(def);
    writtenPosition_ = pose.position;
    writtenAngle_ = pose.angle;
    system_.registerRigidbody(*this);
    return body_;
}

void Rigidbody::onInitialize() {
    ensureBody();
    // Colliders that attached to a static body before this component existed move onto it.
    for (Collider* c : gameObject()->getComponents<Collider>()) {
        if (!c->shape_.isNull() && (!system_.world().isValid(c->shape_) ||
                                    system_.world().shapeBody(c->shape_) != body_)) {
            c->attach();
        }
    }
    leaving_ = false;
}

void Rigidbody::onTerminate() {
    if (body_.isNull()) {
        return;
    }
    if (!system_.world().isValid(body_)) {
        // Destroyed through the World since the last fixed step: its shapes went with it.
        system_.forgetDestroyedBodies();
        return;
    }
    // While it goes, colliders looking for a Rigidbody must not find this one.
    leaving_ = true;
    std::vector<Collider*> riders;
    for (Collider* c : gameObject()->getComponents<Collider>()) {
        if (!c->shape_.isNull() && system_.world().isValid(c->shape_) &&
            system_.world().shapeBody(c->shape_) == body_) {
            c->detach();
            riders.push_back(c);
        }
    }
    system_.unregisterRigidbody(*this);
    system_.world().destroyBody(body_);
    body_ = {};
    // Colliders that stay on a living object become static again.
    if (!gameObject()->isPendingDestroy()) {
        for (Collider* c : riders) {
            c->attach();
        }
    }
    leaving_ = false;
}

BodyId Rigidbody::requireBody(const char* function) const {
    if (body_.isNull()) {
        throw core::Error(std::string("physics::Rigidbody::") + function +
                          "(): the Rigidbody has no body (its object is not in a scene yet, or "
                          "its body was destroyed through the World)");
    }
    return body_;
}

Vec2 Rigidbody::linearVelocity() const {
    return system_.world().linearVelocity(requireBody("linearVelocity"));
}
void Rigidbody::setLinearVelocity(Vec2 velocity) {
    system_.world().setLinearVelocity(requireBody("setLinearVelocity"), velocity);
}
float Rigidbody::angularVelocity() const {
    return system_.world().angularVelocity(requireBody("angularVelocity"));
}
void Rigidbody::setAngularVelocity(float velocity) {
    system_.world().setAngularVelocity(requireBody("setAngularVelocity"), velocity);
}
float Rigidbody::mass() const { return system_.world().massData(requireBody("mass")).mass; }
float Rigidbody::gravityScale() const {
    return system_.world().gravityScale(requireBody("gravityScale"));
}
void Rigidbody::setGravityScale(float scale) {
    system_.world().setGravityScale(requireBody("setGravityScale"), scale);
}
void Rigidbody::setFreezeRotation(bool freeze) {
    system_.world().setFixedRotation(requireBody("setFreezeRotation"), freeze);
}
void Rigidbody::setFreezePosition(bool x, bool y) {
    system_.world().setPositionLocks(requireBody("setFreezePosition"), x, y);
}
void Rigidbody::applyForce(Vec2 force) {
    system_.world().applyForceToCenter(requireBody("applyForce"), force);
}
void Rigidbody::applyForceAtPoint(Vec2 force, Vec2 point) {
    system_.world().applyForce(requireBody("applyForceAtPoint"), force, point);
}
void Rigidbody::applyTorque(float torque) {
    system_.world().applyTorque(requireBody("applyTorque"), torque);
}
void Rigidbody::applyLinearImpulse(Vec2 impulse) {
    system_.world().applyLinearImpulseToCenter(requireBody("applyLinearImpulse"), impulse);
}
void Rigidbody::applyImpulseAtPoint(Vec2 impulse, Vec2 point) {
    system_.world().applyLinearImpulse(requireBody("applyImpulseAtPoint"), impulse, point);
}
void Rigidbody::applyAngularImpulse(float impulse) {
    system_.world().applyAngularImpulse(requireBody("applyAngularImpulse"), impulse);
}

} // namespace e2d::physics
