// SPDX-License-Identifier: MIT
#include <e2d/physics/rigidbody.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/physics_system.hpp>

#include "component_check.hpp"
#include "object_pose.hpp"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace e2d::physics {

namespace {

constexpr const char* kConstructor = "Rigidbody::Rigidbody";

// A setter's argument must be finite: checked when called, also when it waits for the body.
void requireFiniteArg(const char* function, const char* name, float value) {
    if (!std::isfinite(value)) {
        throw core::Error(std::string("physics::Rigidbody::") + function + "(): " + name +
                          " must be finite, got " + core::formatNumber(value));
    }
}

void requireFiniteArg(const char* function, const char* name, Vec2 value) {
    if (!std::isfinite(value.x) || !std::isfinite(value.y)) {
        throw core::Error(std::string("physics::Rigidbody::") + function + "(): " + name +
                          " must be finite, got " + core::formatVector(value));
    }
}

} // namespace

Rigidbody::Rigidbody(PhysicsSystem& system, const RigidbodyDef& def) : Rigidbody(def) {
    system_ = &system;
}

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
            throw core::Error(
                "physics::Rigidbody::system(): the Rigidbody has no PhysicsSystem (it was made "
                "without one and its object is not in a scene)");
        }
        system_ = &scene()->system<PhysicsSystem>();
    }
    return *system_;
}

BodyId Rigidbody::ensureBody() {
    if (state_ != State::NotYet) {
        return body_;
    }
    const float upm = sys().unitsPerMetre();
    const detail::Pose pose = detail::worldPose(*gameObject(), upm);
    detail::component_check::requireInRange(*gameObject(), "Rigidbody", upm);
    BodyDef def;
    def.type = def_.type;
    def.position = pose.position;
    def.angle = pose.angle;
    def.linearVelocity = def_.linearVelocity / upm;
    def.angularVelocity = def_.angularVelocity;
    def.linearDamping = def_.linearDamping;
    def.angularDamping = def_.angularDamping;
    def.gravityScale = def_.gravityScale;
    def.fixedRotation = def_.fixedRotation;
    def.lockX = def_.lockX;
    def.lockY = def_.lockY;
    def.isBullet = def_.isBullet;
    def.enableSleep = def_.enableSleep;
    body_ = sys().world().createBody(def);
    state_ = State::Live;
    writtenPosition_ = pose.position;
    writtenAngle_ = pose.angle;
    sys().registerRigidbody(*this);
    // What was asked of the component before the body existed.
    std::vector<std::function<void(Rigidbody&)>> pending = std::move(pending_);
    pending_.clear();
    for (auto& action : pending) {
        action(*this);
    }
    return body_;
}

void Rigidbody::onInitialize() {
    leaving_ = false;
    ensureBody();
    // Colliders on this object and below it that should ride on this body (they attached to a
    // static body, or to a Rigidbody further up, before this one existed) move onto it.
    sys().reattachColliders(
        [this](const Collider& c) { return c.findOwner() == this && c.owner_ != this; });
}

void Rigidbody::onTerminate() {
    // While it goes, colliders looking for a Rigidbody must not find this one.
    leaving_ = true;
    const std::vector<Collider*> riders = sys().collidersOn(this);
    for (Collider* c : riders) {
        c->detach();
    }
    if (state_ == State::Live) {
        sys().unregisterRigidbody(*this);
        // Destroyed through the World since the last fixed step: its shapes went with it.
        if (sys().world().isValid(body_)) {
            sys().world().destroyBody(body_);
        }
    }
    body_ = {};
    state_ = State::Gone;
    pending_.clear();
    // Colliders that stay on living objects become static again, or ride on a Rigidbody
    // further up.
    for (Collider* c : riders) {
        if (!c->gameObject()->isPendingDestroy()) {
            c->attach();
        }
    }
}

BodyId Rigidbody::bodyOrQueue(const char* function) const {
    if (state_ == State::Gone) {
        throw core::Error(std::string("physics::Rigidbody::") + function + "(): the Rigidbody on " +
                          gameObject()->describe() +
                          " has no body any more (the component was removed, or its body was "
                          "destroyed through the World)");
    }
    return body_;
}

void Rigidbody::now(const char* function, std::function<void(Rigidbody&)> action) {
    if (bodyOrQueue(function).isNull()) {
        pending_.push_back(std::move(action));
    } else {
        action(*this);
    }
}

void Rigidbody::applyTarget(float timeStep) {
    if (!target_) {
        return;
    }
    const Target target = *target_;
    target_.reset();
    sys().world().setTargetTransform(body_, sys().toMetres(target.position), target.angle,
                                     timeStep);
}

// The world speaks metres; the component speaks world units (see PhysicsSystem): lengths scale
// by 1/upm, torques and angular impulses (a force times a length) by 1/upm^2.

BodyType Rigidbody::type() const {
    const BodyId body = bodyOrQueue("type");
    return body.isNull() ? def_.type : sys().world().bodyType(body);
}

Vec2 Rigidbody::linearVelocity() const {
    const BodyId body = bodyOrQueue("linearVelocity");
    return body.isNull() ? def_.linearVelocity : sys().toUnits(sys().world().linearVelocity(body));
}

void Rigidbody::setLinearVelocity(Vec2 velocity) {
    requireFiniteArg("setLinearVelocity", "velocity", velocity);
    if (const BodyId body = bodyOrQueue("setLinearVelocity"); !body.isNull()) {
        sys().world().setLinearVelocity(body, sys().toMetres(velocity));
    } else {
        def_.linearVelocity = velocity;
    }
}

float Rigidbody::angularVelocity() const {
    const BodyId body = bodyOrQueue("angularVelocity");
    return body.isNull() ? def_.angularVelocity : sys().world().angularVelocity(body);
}

void Rigidbody::setAngularVelocity(float velocity) {
    requireFiniteArg("setAngularVelocity", "velocity", velocity);
    if (const BodyId body = bodyOrQueue("setAngularVelocity"); !body.isNull()) {
        sys().world().setAngularVelocity(body, velocity);
    } else {
        def_.angularVelocity = velocity;
    }
}

float Rigidbody::mass() const {
    const BodyId body = bodyOrQueue("mass");
    return body.isNull() ? 0.0f : sys().world().massData(body).mass;
}

float Rigidbody::gravityScale() const {
    const BodyId body = bodyOrQueue("gravityScale");
    return body.isNull() ? def_.gravityScale : sys().world().gravityScale(body);
}

void Rigidbody::setGravityScale(float scale) {
    requireFiniteArg("setGravityScale", "scale", scale);
    if (const BodyId body = bodyOrQueue("setGravityScale"); !body.isNull()) {
        sys().world().setGravityScale(body, scale);
    } else {
        def_.gravityScale = scale;
    }
}

bool Rigidbody::isFixedRotation() const {
    const BodyId body = bodyOrQueue("isFixedRotation");
    return body.isNull() ? def_.fixedRotation : sys().world().isFixedRotation(body);
}

void Rigidbody::setFixedRotation(bool fixed) {
    if (const BodyId body = bodyOrQueue("setFixedRotation"); !body.isNull()) {
        sys().world().setFixedRotation(body, fixed);
    } else {
        def_.fixedRotation = fixed;
    }
}

void Rigidbody::setPositionLocks(bool lockX, bool lockY) {
    if (const BodyId body = bodyOrQueue("setPositionLocks"); !body.isNull()) {
        sys().world().setPositionLocks(body, lockX, lockY);
    } else {
        def_.lockX = lockX;
        def_.lockY = lockY;
    }
}

void Rigidbody::setBullet(bool bullet) {
    if (const BodyId body = bodyOrQueue("setBullet"); !body.isNull()) {
        sys().world().setBullet(body, bullet);
    } else {
        def_.isBullet = bullet;
    }
}

void Rigidbody::setSleepEnabled(bool enabled) {
    if (const BodyId body = bodyOrQueue("setSleepEnabled"); !body.isNull()) {
        sys().world().setSleepEnabled(body, enabled);
    } else {
        def_.enableSleep = enabled;
    }
}

void Rigidbody::setTargetTransform(Vec2 position, float angle) {
    requireFiniteArg("setTargetTransform", "position", position);
    requireFiniteArg("setTargetTransform", "angle", angle);
    if (type() == BodyType::Static) {
        throw core::Error("physics::Rigidbody::setTargetTransform(): the body is static");
    }
    static_cast<void>(bodyOrQueue("setTargetTransform"));
    target_ = Target{position, angle};
}

void Rigidbody::applyForce(Vec2 force) {
    requireFiniteArg("applyForce", "force", force);
    now("applyForce", [force](Rigidbody& rb) {
        rb.sys().world().applyForceToCenter(rb.body_, rb.sys().toMetres(force));
    });
}

void Rigidbody::applyForceAtPoint(Vec2 force, Vec2 point) {
    requireFiniteArg("applyForceAtPoint", "force", force);
    requireFiniteArg("applyForceAtPoint", "point", point);
    now("applyForceAtPoint", [force, point](Rigidbody& rb) {
        rb.sys().world().applyForce(rb.body_, rb.sys().toMetres(force), rb.sys().toMetres(point));
    });
}

void Rigidbody::applyTorque(float torque) {
    requireFiniteArg("applyTorque", "torque", torque);
    now("applyTorque", [torque](Rigidbody& rb) {
        rb.sys().world().applyTorque(rb.body_, rb.sys().toMetres(rb.sys().toMetres(torque)));
    });
}

void Rigidbody::applyLinearImpulse(Vec2 impulse) {
    requireFiniteArg("applyLinearImpulse", "impulse", impulse);
    now("applyLinearImpulse", [impulse](Rigidbody& rb) {
        rb.sys().world().applyLinearImpulseToCenter(rb.body_, rb.sys().toMetres(impulse));
    });
}

void Rigidbody::applyImpulseAtPoint(Vec2 impulse, Vec2 point) {
    requireFiniteArg("applyImpulseAtPoint", "impulse", impulse);
    requireFiniteArg("applyImpulseAtPoint", "point", point);
    now("applyImpulseAtPoint", [impulse, point](Rigidbody& rb) {
        rb.sys().world().applyLinearImpulse(rb.body_, rb.sys().toMetres(impulse),
                                            rb.sys().toMetres(point));
    });
}

void Rigidbody::applyAngularImpulse(float impulse) {
    requireFiniteArg("applyAngularImpulse", "impulse", impulse);
    now("applyAngularImpulse", [impulse](Rigidbody& rb) {
        rb.sys().world().applyAngularImpulse(rb.body_,
                                             rb.sys().toMetres(rb.sys().toMetres(impulse)));
    });
}

} // namespace e2d::physics
