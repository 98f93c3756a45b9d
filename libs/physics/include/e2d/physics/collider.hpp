// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/component.hpp>
#include <e2d/core/mask.hpp>
#include <e2d/physics/geometry.hpp>
#include <e2d/physics/id.hpp>

namespace e2d::physics {

class PhysicsSystem;

/// Material, trigger flag and masks of a Collider.
struct ColliderDef {
    /// kg per square metre, >= 0 (metres whatever the system's unitsPerMetre(), so a scene
    /// drawn at any scale weighs the same). Default 1.
    float density = 1.0f;
    /// Coulomb coefficient, >= 0. Default 0.6.
    float friction = 0.6f;
    /// 0 (no bounce) .. 1 (elastic). Default 0.
    float restitution = 0.0f;
    /// Rolling resistance, world units, >= 0. Default 0.
    float rollingResistance = 0.0f;
    /// A trigger detects overlaps (TriggerEnter/Exit events) but is not solid. Default false.
    bool isTrigger = false;
    /// What this collider is (a core::Mask). Default: the first mask bit.
    core::Mask category{1};
    /// What it may touch; both sides' masks must match. Default: everything.
    core::Mask mask = core::Mask::all();
};

/// A convex shape attached to its GameObject, in the object's local frame (world units; the
/// PhysicsSystem divides them by its unitsPerMetre() for the World's metres), scaled by the
/// object's world scale (its magnitude per axis; mirroring is ignored) when it is attached;
/// later scale changes are not followed. It rides on
/// the object's Rigidbody; an object without one is static, and moving it by hand moves the
/// collider at the next fixed step. Several colliders may share an object.
class Collider : public core::Component {
public:
    /// The PhysicsSystem is found through the scene when the object enters it
    /// (`scene()->system<PhysicsSystem>()`, core::Error naming the type when there is none).
    /// Throws core::Error for an invalid geometry (see physics::validate) or an invalid field
    /// of `def`.
    explicit Collider(const ShapeGeometry& geometry, const ColliderDef& def = {});
    /// With an explicit system, which must outlive the component.
    Collider(PhysicsSystem& system, const ShapeGeometry& geometry, const ColliderDef& def = {});
    ~Collider() override;

    /// The shape, null while not attached or once its body was destroyed through the World
    /// (see PhysicsSystem). A shape destroyed alone through the World leaves a stale id here.
    [[nodiscard]] ShapeId shape() const noexcept { return shape_; }
    [[nodiscard]] const ShapeGeometry& geometry() const noexcept { return geometry_; }
    [[nodiscard]] bool isTrigger() const noexcept { return def_.isTrigger; }
    [[nodiscard]] const ColliderDef& def() const noexcept { return def_; }

    void onInitialize() override;
    void onTerminate() override;

private:
    friend class PhysicsSystem;
    friend class Rigidbody;

    /// Detaches (if attached) and attaches to the object's Rigidbody, or to a static body.
    void attach();
    void detach() noexcept;

    PhysicsSystem& sys() const;

    mutable PhysicsSystem* system_ = nullptr; // found through the scene when not given
    ShapeGeometry geometry_;
    ColliderDef def_;
    ShapeId shape_{};
    BodyId ownBody_{}; // the static body of a collider without a Rigidbody
    glm::vec2 writtenPosition_{0.0f, 0.0f};
    float writtenAngle_ = 0.0f;
};

} // namespace e2d::physics
