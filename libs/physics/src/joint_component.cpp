// SPDX-License-Identifier: MIT
#include <e2d/physics/joint_component.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/physics/physics_system.hpp>
#include <e2d/physics/rigidbody.hpp>

#include "joint_def_check.hpp"

#include <string>
#include <string_view>

namespace e2d::physics {

namespace {

constexpr std::string_view kCreatePrefix = "physics::World::createJoint(): ";

// The def with its bodies set.
JointDef withBodies(JointDef def, BodyId a, BodyId b) {
    std::visit(
        [&](auto& d) {
            d.bodyA = a;
            d.bodyB = b;
        },
        def);
    return def;
}

[[noreturn]] void fail(const char* function, const std::string& what) {
    throw core::Error(std::string("physics::JointComponent::") + function + "(): " + what);
}

} // namespace

JointComponent::JointComponent(PhysicsSystem& system, const JointComponentDef& def)
    : system_(system), def_(def) {
    try {
        detail::validateJointDef(def.joint);
    } catch (const core::Error& e) {
        std::string what = e.what();
        if (what.rfind(kCreatePrefix, 0) == 0) {
            what.erase(0, kCreatePrefix.size());
        }
        fail("JointComponent", "def.joint: " + what);
    }
}

JointComponent::~JointComponent() = default;

bool JointComponent::isConnected() const { return !joint_.isNull() && system_.world().isValid(joint_); }

Vec2 JointComponent::reactionForce() const {
    return isConnected() ? system_.world().jointReactionForce(joint_) : Vec2{0.0f, 0.0f};
}

float JointComponent::reactionTorque() const {
    return isConnected() ? system_.world().jointReactionTorque(joint_) : 0.0f;
}

void JointComponent::disconnect() {
    if (isConnected()) {
        system_.world().destroyJoint(joint_);
    }
    joint_ = {};
    if (!anchor_.isNull() && system_.world().isValid(anchor_)) {
        system_.world().destroyBody(anchor_);
    }
    anchor_ = {};
}

void JointComponent::onInitialize() {
    if (isConnected()) {
        return;
    }
    core::GameObject& self = *gameObject();
    Rigidbody* own = self.getComponent<Rigidbody>();
    if (own == nullptr) {
        fail("onInitialize", "the object has no Rigidbody to connect");
    }
    BodyId bodyA;
    if (def_.connectedObject == core::GameObjectId{}) {
        anchor_ = system_.world().createBody(BodyDef{});
        bodyA = anchor_;
    } else {
        core::GameObject* other = self.scene().find(def_.connectedObject);
        if (other == nullptr) {
            fail("onInitialize", "def.connectedObject names no object of the scene");
        }
        Rigidbody* theirs = other->getComponent<Rigidbody>();
        if (theirs == nullptr) {
            fail("onInitialize", "def.connectedObject has no Rigidbody");
        }
        bodyA = theirs->ensureBody();
    }
    const BodyId bodyB = own->ensureBody();
    try {
        joint_ = system_.world().createJoint(withBodies(def_.joint, bodyA, bodyB));
    } catch (...) {
        disconnect();
        throw;
    }
}

void JointComponent::onTerminate() { disconnect(); }

} // namespace e2d::physics
