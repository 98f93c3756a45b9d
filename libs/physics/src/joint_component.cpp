// SPDX-License-Identifier: MIT
#include <e2d/physics/joint_component.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/physics/physics_system.hpp>
#include <e2d/physics/rigidbody.hpp>

#include "component_check.hpp"
#include "joint_def_check.hpp"
#include "object_pose.hpp"

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

// World::createJoint()'s message about `def` ("physics::World::createJoint(): revolute
// def.lowerAngle must be <= def.upperAngle, got 1 > -1") in the component's words, which name
// the fields it takes: "def.joint.lowerAngle must be <= def.joint.upperAngle, got 1 > -1".
std::string inComponentTerms(std::string what) {
    if (what.rfind(kCreatePrefix, 0) == 0) {
        what.erase(0, kCreatePrefix.size());
    }
    // The joint type's name before the first field ("revolute def.").
    if (const auto first = what.find(" def.");
        first != std::string::npos && what.find(' ') == first) {
        what.erase(0, first + 1);
    }
    std::string out;
    for (std::size_t at = 0;;) {
        const std::size_t next = what.find("def.", at);
        if (next == std::string::npos) {
            out.append(what, at, std::string::npos);
            break;
        }
        out.append(what, at, next - at).append("def.joint.");
        at = next + 4;
    }
    return out;
}

// Validates the joint def, reporting in the component's terms; `note` follows the message.
void validate(const JointDef& def, const char* function, const std::string& note) {
    try {
        detail::validateJointDef(def);
    } catch (const core::Error& e) {
        fail(function, inComponentTerms(e.what()) + note);
    }
}

} // namespace

JointComponent::JointComponent(PhysicsSystem& system, const JointComponentDef& def)
    : JointComponent(def) {
    system_ = &system;
    static_cast<void>(validateInMetres("JointComponent"));
}

// Checked as given (world units taken for metres: every sign, order and finiteness rule
// holds at any scale); the scale-dependent rules are checked again in metres on attach.
JointComponent::JointComponent(const JointComponentDef& def) : def_(def) {
    validate(def.joint, "JointComponent", "");
}

JointComponent::~JointComponent() = default;

JointDef JointComponent::validateInMetres(const char* function) const {
    const float upm = system().unitsPerMetre();
    JointDef metres = inMetres(def_.joint, upm);
    validate(metres, function,
             upm != 1.0f ? " (in metres: the def's world units divided by unitsPerMetre " +
                               core::formatNumber(upm) + ")"
                         : std::string());
    return metres;
}

PhysicsSystem& JointComponent::system() const {
    if (system_ == nullptr) {
        if (scene() == nullptr) {
            throw core::Error(
                "physics::JointComponent::system(): the JointComponent has no PhysicsSystem "
                "(it was made without one and its object is not in a scene)");
        }
        system_ = &scene()->system<PhysicsSystem>();
    }
    return *system_;
}

bool JointComponent::isConnected() const {
    return !joint_.isNull() && system().world().isValid(joint_);
}

Vec2 JointComponent::reactionForce() const {
    return isConnected() ? system().toUnits(system().world().jointReactionForce(joint_))
                         : Vec2{0.0f, 0.0f};
}

float JointComponent::reactionTorque() const {
    const float upm = system().unitsPerMetre();
    return isConnected() ? system().world().jointReactionTorque(joint_) * upm * upm : 0.0f;
}

void JointComponent::disconnect() {
    World& world = system().world();
    if (isConnected()) {
        world.destroyJoint(joint_);
    }
    joint_ = {};
    if (!anchor_.isNull() && world.isValid(anchor_)) {
        world.destroyBody(anchor_);
    }
    anchor_ = {};
}

void JointComponent::onInitialize() {
    if (isConnected()) {
        return;
    }
    PhysicsSystem& sys = system();
    const float upm = sys.unitsPerMetre();
    const JointDef metres = validateInMetres("onInitialize");
    core::GameObject& self = *gameObject();
    Rigidbody* own = self.getComponent<Rigidbody>();
    if (own == nullptr) {
        fail("onInitialize", "the " + self.describe() + " has no Rigidbody to connect");
    }
    // Body A: the connected object's Rigidbody, or a static anchor where it is (or at the origin).
    Rigidbody* theirs = nullptr;
    detail::Pose anchorPose;
    if (def_.connectedObject != core::GameObjectId{}) {
        core::GameObject* other = self.scene().find(def_.connectedObject);
        if (other == nullptr) {
            fail("onInitialize", "def.connectedObject names no object of the scene");
        }
        if (other == &self) {
            fail("onInitialize", "def.connectedObject is the " + self.describe() + " itself");
        }
        theirs = other->getComponent<Rigidbody>();
        anchorPose = detail::worldPose(*other, upm);
    }
    const bool ownMoves = own->type() == BodyType::Dynamic;
    if (!ownMoves && (theirs == nullptr || theirs->type() != BodyType::Dynamic)) {
        fail("onInitialize",
             "neither the Rigidbody of the " + self.describe() +
                 " nor def.connectedObject's is dynamic: no force would move the joint");
    }
    BodyId bodyA;
    if (theirs != nullptr) {
        bodyA = theirs->ensureBody();
    } else {
        BodyDef anchor;
        anchor.position = anchorPose.position;
        anchor.angle = anchorPose.angle;
        anchor_ = sys.world().createBody(anchor);
        bodyA = anchor_;
    }
    const BodyId bodyB = own->ensureBody();
    try {
        joint_ = sys.world().createJoint(withBodies(metres, bodyA, bodyB));
    } catch (...) {
        disconnect();
        throw;
    }
}

void JointComponent::onTerminate() { disconnect(); }

} // namespace e2d::physics
