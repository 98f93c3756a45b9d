// SPDX-License-Identifier: MIT
#include <e2d/physics/collider.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/physics/physics_system.hpp>
#include <e2d/physics/rigidbody.hpp>

#include "component_check.hpp"
#include "object_pose.hpp"

#include <glm/mat4x4.hpp>

#include <cmath>
#include <string>

namespace e2d::physics {

Collider::Collider(PhysicsSystem& system, const ShapeGeometry& geometry, const ColliderDef& def)
    : Collider(geometry, def) {
    system_ = &system;
}

Collider::Collider(const ShapeGeometry& geometry, const ColliderDef& def) : geometry_(geometry), def_(def) {
    validate(geometry, "physics::Collider::Collider()");
    using detail::component_check::requireNonNegative;
    constexpr const char* kConstructor = "Collider::Collider";
    requireNonNegative(kConstructor, "density", def.density);
    requireNonNegative(kConstructor, "friction", def.friction);
    detail::component_check::requireUnitInterval(kConstructor, "restitution", def.restitution);
    requireNonNegative(kConstructor, "rollingResistance", def.rollingResistance);
}

Collider::~Collider() = default;

PhysicsSystem& Collider::sys() const {
    if (system_ == nullptr) {
        if (scene() == nullptr) {
            throw core::Error("physics::Collider::system(): the Collider has no PhysicsSystem (it was made "
                              "without one and its object is not in a scene)");
        }
        system_ = &scene()->system<PhysicsSystem>();
    }
    return *system_;
}

void Collider::onInitialize() { attach(); }

void Collider::onTerminate() { detach(); }

void Collider::attach() {
    detach();
    core::GameObject& object = *gameObject();
    // The world matrix's basis vectors carry the scale of the object and all its parents.
    const glm::mat4& m = object.worldTransform();
    const glm::vec2 scale{std::hypot(m[0][0], m[0][1]), std::hypot(m[1][0], m[1][1])};
    // The geometry is in world units, the world in metres.
    const float upm = sys().unitsPerMetre();
    const ShapeGeometry scaled = detail::scaledGeometry(geometry_, scale, upm);
    BodyId body{};
    if (Rigidbody* rb = object.getComponent<Rigidbody>(); rb != nullptr && !rb->leaving_) {
        body = rb->ensureBody();
    } else {
        const detail::Pose pose = detail::worldPose(object, upm);
        BodyDef def;
        def.type = BodyType::Static;
        def.position = pose.position;
        def.angle = pose.angle;
        ownBody_ = sys().world().createBody(def);
        writtenPosition_ = pose.position;
        writtenAngle_ = pose.angle;
        body = ownBody_;
        sys().registerStaticCollider(*this);
    }
    ShapeDef def;
    def.density = def_.density;
    def.friction = def_.friction;
    def.restitution = def_.restitution;
    def.rollingResistance = def_.rollingResistance / upm;
    def.isSensor = def_.isTrigger;
    def.filter.categoryBits = def_.category.bits();
    def.filter.maskBits = def_.mask.bits();
    shape_ = sys().world().createShape(body, def, scaled);
    sys().registerCollider(shape_, *this);
}

void Collider::detach() noexcept {
    if (!shape_.isNull()) {
        sys().unregisterCollider(shape_);
        if (sys().world().isValid(shape_)) {
            sys().world().destroyShape(shape_);
        }
        shape_ = {};
    }
    if (!ownBody_.isNull()) {
        sys().unregisterStaticCollider(*this);
        if (sys().world().isValid(ownBody_)) {
            sys().world().destroyBody(ownBody_);
        }
        ownBody_ = {};
    }
}

} // namespace e2d::physics
