// SPDX-License-Identifier: MIT
#include <e2d/physics/joint_component.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/physics/physics_system.hpp>
#include <e2d/physics/rigidbody.hpp>

#include "error_format.hpp"
#include "joint_def_check.hpp"

#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

namespace e2d::physics {

namespace {

constexpr std::string_view kCreatePrefix = "physics::World::createJoint(): ";

// The def in metres: lengths, linear speeds and forces divided by the units per metre, torques
// by its square (angles, rates in rad/s, frequencies and ratios need no scale).
JointDef inMetres(JointDef def, float upm) {
    std::visit(
        [upm](auto& d) {
            using D = std::decay_t<decltype(d)>;
            const auto length = [upm](auto& v) { v /= upm; };
            const auto torque = [upm](float& v) { v = v / upm / upm; };
            if constexpr (requires { d.localAnchorA; }) {
                length(d.localAnchorA);
            }
            if constexpr (requires { d.localAnchorB; }) {
                length(d.localAnchorB);
            }
            if constexpr (std::is_same_v<D, DistanceJointDef>) {
                length(d.length);
                length(d.minLength);
                if (d.maxLength < kHuge) { // kHuge: no limit, at any scale
                    length(d.maxLength);
                }
                length(d.maxMotorForce);
                length(d.motorSpeed);
            } else if constexpr (std::is_same_v<D, MotorJointDef>) {
                length(d.linearOffset);
                length(d.maxForce);
                torque(d.maxTorque);
            } else if constexpr (std::is_same_v<D, MouseJointDef>) {
                length(d.target);
                length(d.maxForce);
            } else if constexpr (std::is_same_v<D, PrismaticJointDef>) {
                length(d.lowerTranslation);
                length(d.upperTranslation);
                length(d.maxMotorForce);
                length(d.motorSpeed);
            } else if constexpr (std::is_same_v<D, RevoluteJointDef>) {
                torque(d.maxMotorTorque);
            } else if constexpr (std::is_same_v<D, WheelJointDef>) {
                length(d.lowerTranslation);
                length(d.upperTranslation);
                torque(d.maxMotorTorque);
            }
        },
        def);
    return def;
}

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
    : system_(system), def_(def), metres_(inMetres(def.joint, system.unitsPerMetre())) {
    try {
        detail::validateJointDef(metres_);
    } catch (const core::Error& e) {
        std::string what = e.what();
        if (what.rfind(kCreatePrefix, 0) == 0) {
            what.erase(0, kCreatePrefix.size());
        }
        if (system.unitsPerMetre() != 1.0f) {
            what += " (in metres: the def's world units divided by unitsPerMetre " +
                    detail::formatFloat(system.unitsPerMetre()) + ")";
        }
        fail("JointComponent", "def.joint: " + what);
    }
}

JointComponent::~JointComponent() = default;

bool JointComponent::isConnected() const { return !joint_.isNull() && system_.world().isValid(joint_); }

Vec2 JointComponent::reactionForce() const {
    return isConnected() ? system_.toUnits(system_.world().jointReactionForce(joint_)) : Vec2{0.0f, 0.0f};
}

float JointComponent::reactionTorque() const {
    const float upm = system_.unitsPerMetre();
    return isConnected() ? system_.world().jointReactionTorque(joint_) * upm * upm : 0.0f;
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
        joint_ = system_.world().createJoint(withBodies(metres_, bodyA, bodyB));
    } catch (...) {
        disconnect();
        throw;
    }
}

void JointComponent::onTerminate() { disconnect(); }

} // namespace e2d::physics
