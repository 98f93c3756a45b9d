// SPDX-License-Identifier: MIT
#include <e2d/physics/collider.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/physics/physics_system.hpp>
#include <e2d/physics/rigidbody.hpp>

#include "component_check.hpp"
#include "object_pose.hpp"

#include <string>

namespace e2d::physics {

Collider::Collider(PhysicsSystem& system, const ShapeGeometry& geometry, const ColliderDef& def)
    : Collider(geometry, def) {
    system_ = &system;
}

Collider::Collider(const ShapeGeometry& geometry, const ColliderDef& def)
    : geometry_(geometry), def_(def) {
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
            throw core::Error(
                "physics::Collider::system(): the Collider has no PhysicsSystem (it was made "
                "without one and its object is not in a scene)");
        }
        system_ = &scene()->system<PhysicsSystem>();
    }
    return *system_;
}

void Collider::onInitialize() {
    sys().registerCollider(*this);
    attach();
}

void Collider::onTerminate() {
    detach();
    sys().unregisterCollider(*this);
}

Rigidbody* Collider::findOwner() const {
    for (const core::GameObject* o = gameObject(); o != nullptr; o = o->parent()) {
        if (Rigidbody* rb = o->getComponent<Rigidbody>(); rb != nullptr && !rb->leaving_) {
            return rb;
        }
    }
    return nullptr;
}

Collider::Placement Collider::placementOn(const Rigidbody* owner) const {
    Placement p;
    if (owner == nullptr || owner->gameObject() == gameObject()) {
        p.linear = detail::worldScale(*gameObject());
    } else {
        detail::relativePlacement(*owner->gameObject(), *gameObject(), p.linear, p.offset);
    }
    return p;
}

bool Collider::isOutOfDate() const {
    Rigidbody* owner = findOwner();
    if (owner != owner_) {
        return true;
    }
    const Placement now = placementOn(owner);
    return detail::placementsDiffer(now.linear, now.offset, placed_.linear, placed_.offset);
}

void Collider::attach() {
    detach();
    attached_ = true;
    core::GameObject& object = *gameObject();
    owner_ = findOwner();
    placed_ = placementOn(owner_);
    const float upm = sys().unitsPerMetre();
    if (owner_ != nullptr && owner_->state_ == Rigidbody::State::Gone) {
        return; // its body was destroyed through the World: no shape (see PhysicsSystem)
    }
    // The geometry is in world units on the object, the world in metres on the body.
    std::optional<ShapeGeometry> placed;
    try {
        placed = detail::placedGeometry(geometry_, placed_.linear, placed_.offset, upm);
    } catch (const core::Error&) {
        // The geometry was valid when the component was made: its scale made it degenerate.
        // No shape until the scale grows (see the class comment).
        detail::component_check::requireFinitePlacement(object, "Collider", placed_.linear,
                                                        placed_.offset);
        return;
    }
    if (owner_ != nullptr) {
        body_ = owner_->ensureBody();
    } else {
        const detail::Pose pose = detail::worldPose(object, upm);
        detail::component_check::requireInRange(object, "Collider", upm);
        BodyDef def;
        def.type = BodyType::Static;
        def.position = pose.position;
        def.angle = pose.angle;
        ownBody_ = sys().world().createBody(def);
        writtenPosition_ = pose.position;
        writtenAngle_ = pose.angle;
        body_ = ownBody_;
        sys().registerStaticCollider(*this);
    }
    ShapeDef def;
    def.density = def_.density;
    def.friction = def_.friction;
    def.restitution = def_.restitution;
    def.rollingResistance = def_.rollingResistance / upm;
    def.isSensor = def_.isSensor;
    def.sensorSeesNonDynamic = def_.sensorSeesNonDynamic;
    def.filter.categoryBits = def_.category.bits();
    def.filter.maskBits = def_.mask.bits();
    shape_ = sys().world().createShape(body_, def, *placed);
    sys().registerShape(shape_, *this);
}

void Collider::detach() noexcept {
    attached_ = false;
    owner_ = nullptr;
    body_ = {};
    if (!shape_.isNull()) {
        sys().unregisterShape(shape_);
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
