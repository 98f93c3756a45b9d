// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/component.hpp>
#include <e2d/core/mask.hpp>
#include <e2d/physics/contact_info.hpp>
#include <e2d/physics/geometry.hpp>
#include <e2d/physics/id.hpp>

#include <functional>
#include <glm/mat2x2.hpp>

namespace e2d::physics {

class PhysicsSystem;
class Rigidbody;

/// Decides, during the fixed step, whether a touching contact of a Collider takes part in this
/// step's solver (ColliderDef::preSolve). `contact` is as CollisionEnter carries it (world units,
/// normals pointing away from this collider's object, towards contact.other); return false to
/// let the other shape pass through for this step. Runs inside World::step(): it may read
/// anything but must not create, destroy or move bodies (see World).
using ColliderPreSolve = std::function<bool(const ContactInfo& contact)>;

/// Material, sensor flag, masks and contact rules of a Collider: ShapeDef's fields under
/// ShapeDef's names, in world units.
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
    /// A sensor detects overlaps (TriggerEnter/Exit events) but is not solid. A sensor on an object
    /// without a Rigidbody (or a kinematic one) sees dynamic bodies only, unless
    /// sensorSeesNonDynamic (see ShapeDef). Default false.
    bool isSensor = false;
    /// Sensors only: also see kinematic bodies (and, on a kinematic body, static ones), as
    /// ShapeDef::sensorSeesNonDynamic. Default false.
    bool sensorSeesNonDynamic = false;
    /// What this collider is (a core::Mask). Default: the first mask bit.
    core::Mask category{1};
    /// What it may touch; both sides' masks must match. Default: everything.
    core::Mask mask = core::Mask::all();
    /// A one-way platform: solid only for what comes onto it along the object's world up (+y
    /// turned by the object's orientation) and is not already sunk into it (by more than
    /// 0.05 m, in world units 0.05 * unitsPerMetre). Jump up through it, land on it.
    /// Default false.
    bool oneWay = false;
    /// Called for each of this collider's touching solid contacts before the solver, every
    /// fixed step (see ColliderPreSolve); combined with oneWay and with the other collider's
    /// rule (the contact is solved only if every rule says yes). Default none.
    ColliderPreSolve preSolve{};
};

/// A convex shape attached to its GameObject, in the object's local frame (world units; the
/// PhysicsSystem divides them by its unitsPerMetre() for the World's metres).
///
/// Which body. The collider is a shape of the body of the nearest Rigidbody on its object or
/// on an ancestor (a compound body: a child's collider rides on the parent's body at the
/// child's pose relative to the parent, scale included, and adds to its mass). With no
/// Rigidbody on the way up it is static: a static body of its own, teleported when the object
/// is moved by hand. Several colliders may share an object.
///
/// Following the hierarchy. At every fixed step the collider is checked against its object:
/// reparenting (under or away from a Rigidbody), a new pose relative to its body's object,
/// and a new scale (of the object or of any ancestor) rebuild the shape there (its contacts
/// start again); removing the component removes the shape.
///
/// Scale. The geometry is scaled by the object's scale and its ancestors' (on the body's own
/// object by the magnitude per axis, mirroring ignored; on a child by the full transform
/// relative to the body, mirroring included; a circle's or capsule's radius by the larger
/// factor). A scale that makes the shape degenerate (0, or so small that a side is shorter
/// than the linear slop, 0.005 m) leaves the collider without a shape: it neither collides nor
/// detects, shape() is null, and the shape appears at the first fixed step after the scale
/// grows back ("pop in from scale 0" works as it looks).
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

    /// The shape, null while not attached, while its scale makes it degenerate, or once its
    /// body was destroyed through the World (see PhysicsSystem). A shape destroyed alone
    /// through the World leaves a stale id here.
    [[nodiscard]] ShapeId shape() const noexcept { return shape_; }
    /// The body the shape is on (a Rigidbody's, or the collider's own static one); null when
    /// it has no shape.
    [[nodiscard]] BodyId body() const noexcept { return body_; }
    /// The Rigidbody the collider rides on (on its object or an ancestor), or nullptr (static).
    [[nodiscard]] Rigidbody* rigidbody() const noexcept { return owner_; }
    [[nodiscard]] const ShapeGeometry& geometry() const noexcept { return geometry_; }
    [[nodiscard]] bool isSensor() const noexcept { return def_.isSensor; }
    [[nodiscard]] const ColliderDef& def() const noexcept { return def_; }

    void onInitialize() override;
    void onTerminate() override;

private:
    friend class PhysicsSystem;
    friend class Rigidbody;

    /// Where the geometry sits on its body: body frame = linear * local + offset (world units).
    struct Placement {
        glm::mat2 linear{1.0f};
        glm::vec2 offset{0.0f, 0.0f};
    };

    /// The Rigidbody the collider should ride on now (nearest on the way up, not leaving).
    [[nodiscard]] Rigidbody* findOwner() const;
    [[nodiscard]] Placement placementOn(const Rigidbody* owner) const;
    /// Whether the owner or the placement changed since the shape was made.
    [[nodiscard]] bool isOutOfDate() const;
    /// Detaches (if attached) and attaches to the right body.
    void attach();
    void detach() noexcept;

    PhysicsSystem& sys() const;

    mutable PhysicsSystem* system_ = nullptr; // found through the scene when not given
    ShapeGeometry geometry_;
    ColliderDef def_;
    ShapeId shape_{};
    BodyId body_{};
    BodyId ownBody_{};           // the static body of a collider without a Rigidbody
    Rigidbody* owner_ = nullptr; // cleared by the owner when it goes
    Placement placed_{};
    bool attached_ = false; // between attach() and detach(), shape or not
    glm::vec2 writtenPosition_{0.0f, 0.0f};
    float writtenAngle_ = 0.0f;
};

} // namespace e2d::physics
