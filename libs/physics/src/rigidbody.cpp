// SPDX-License-Identifier: MIT
#include <e2d/physics/rigidbody.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
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

Rigidbody::Rigidbody(PhysicsSystem& system, const RigidbodyDef& def) : Rigidbody(def) { system_ = &system; }

Rigidbody::Rigidbody(const RigidbodyDef& def) : def_(def) {
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

PhysicsSystem& Rigidbody::sys() const {
    if (system_ == nullptr) {
        if (scene() == nullptr) {
            throw core::Error("physics::Rigidbody::system(): the Rigidbody has no PhysicsSystem (it was made "
                              "without one and its object is not in a scene)");
        }
        system_ = &scene()->system<PhysicsSystem>();
    }
    return *system_;
}

BodyId Rigidbody::ensureBody() {
    if (!body_.isNull()) {
        return body_;
    }
    const float upm = sys().unitsPerMetre();
    const detail::Pose pose = detail::worldPose(*gameObject(), upm);
    BodyDef def;
    def.type = def_.type;
    def.position = pose.position;
    def.angle = pose.angle;
    def.linearVelocity = def_.linearVelocity / upm;
    def.angularVelocity = def_.angularVelocity;
    def.linearDamping = def_.linearDamping;
    def.angularDamping = def_.angularDamping;
    def.gravityScale = def_.gravityScale;
    def.fixedRotation = def_.freezeRotation;
    def.lockX = def_.freezePositionX;
    def.lockY = def_.freezePositionY;
    def.isBullet = def_.bullet;
    body_ = sys().world().createBody(def);
    writtenPosition_ = pose.position;
    writtenAngle_ = pose.angle;
    sys().registerRigidbody(*this);
    return body_;
}

void Rigidbody::onInitialize() {
    ensureBody();
    // Colliders that attached to a static body before this component existed move onto it.
    for (Collider* c : gameObject()->getComponents<Collider>()) {
        if (!c->shape_.isNull() && (!sys().world().isValid(c->shape_) ||
                                    sys().world().shapeBody(c->shape_) != body_)) {
            c->attach();
        }
    }
    leaving_ = false;
}

void Rigidbody::onTerminate() {
    if (body_.isNull()) {
        return;
    }
    if (!sys().world().isValid(body_)) {
        // Destroyed through the World since the last fixed step: its shapes went with it.
        sys().forgetDestroyedBodies();
        return;
    }
    // While it goes, colliders looking for a Rigidbody must not find this one.
    leaving_ = true;
    std::vector<Collider*> riders;
    for (Collider* c : gameObject()->getComponents<Collider>()) {
        if (!c->shape_.isNull() && sys().world().isValid(c->shape_) &&
            sys().world().shapeBody(c->shape_) == body_) {
            c->detach();
            riders.push_back(c);
        }
    }
    sys().unregisterRigidbody(*this);
    sys().world().destroyBody(body_);
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

// The world speaks metres; the component speaks world units (see PhysicsSystem): lengths scale
// by 1/upm, torques and angular impulses (a force times a length) by 1/upm^2.
Vec2 Rigidbody::linearVelocity() const {
    return sys().toUnits(sys().world().linearVelocity(requireBody("linearVelocity")));
}
void Rigidbody::setLinearVelocity(Vec2 velocity) {
    sys().world().setLinearVelocity(requireBody("setLinearVelocity"), sys().toMetres(velocity));
}
float Rigidbody::angularVelocity() const {
    return sys().world().angularVelocity(requireBody("angularVelocity"));
}
void Rigidbody::setAngularVelocity(float velocity) {
    sys().world().setAngularVelocity(requireBody("setAngularVelocity"), velocity);
}
float Rigidbody::mass() const { return sys().world().massData(requireBody("mass")).mass; }
float Rigidbody::gravityScale() const {
    return sys().world().gravityScale(requireBody("gravityScale"));
}
void Rigidbody::setGravityScale(float scale) {
    sys().world().setGravityScale(requireBody("setGravityScale"), scale);
}
void Rigidbody::setFreezeRotation(bool freeze) {
    sys().world().setFixedRotation(requireBody("setFreezeRotation"), freeze);
}
void Rigidbody::setFreezePosition(bool x, bool y) {
    sys().world().setPositionLocks(requireBody("setFreezePosition"), x, y);
}
void Rigidbody::applyForce(Vec2 force) {
    sys().world().applyForceToCenter(requireBody("applyForce"), sys().toMetres(force));
}
void Rigidbody::applyForceAtPoint(Vec2 force, Vec2 point) {
    sys().world().applyForce(requireBody("applyForceAtPoint"), sys().toMetres(force), sys().toMetres(point));
}
void Rigidbody::applyTorque(float torque) {
    sys().world().applyTorque(requireBody("applyTorque"), sys().toMetres(sys().toMetres(torque)));
}
void Rigidbody::applyLinearImpulse(Vec2 impulse) {
    sys().world().applyLinearImpulseToCenter(requireBody("applyLinearImpulse"), sys().toMetres(impulse));
}
void Rigidbody::applyImpulseAtPoint(Vec2 impulse, Vec2 point) {
    sys().world().applyLinearImpulse(requireBody("applyImpulseAtPoint"), sys().toMetres(impulse),
                                     sys().toMetres(point));
}
void Rigidbody::applyAngularImpulse(float impulse) {
    sys().world().applyAngularImpulse(requireBody("applyAngularImpulse"), sys().toMetres(sys().toMetres(impulse)));
}

} // namespace e2d::physics
