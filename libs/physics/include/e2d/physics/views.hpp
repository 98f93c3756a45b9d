// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/world.hpp>

#include <cstdint>
#include <optional>
#include <vector>

/// Handle views: a World and an id in one small value, with the world's functions for that
/// body, shape or joint as members, so that an editor's completion lists what a body can do.
///
///     physics::Body ball = world.body(ballId);
///     ball.applyLinearImpulseToCenter({0.0f, 5.0f});
///     physics::Shape skin = ball.createShape(def, physics::Circle{{0, 0}, 0.5f});
///     skin.setFriction(0.2f);
///
/// A view holds a reference to its world and costs nothing beyond the call it forwards (every
/// member is inline). It checks its id on every call like the World function it forwards to
/// (a stale id throws core::Error); isValid() tells beforehand. A view must not outlive its
/// world. The World functions stay: views add a way in, not a second implementation.
namespace e2d::physics {

/// A body of a World (World::body()).
class Body {
public:
    Body(World& world, BodyId id) : world_(&world), id_(id) {}

    [[nodiscard]] BodyId id() const { return id_; }
    [[nodiscard]] World& world() const { return *world_; }
    [[nodiscard]] bool isValid() const { return world_->isValid(id_); }
    /// Destroys the body and its shapes; the view becomes stale.
    void destroy() { world_->destroyBody(id_); }

    [[nodiscard]] BodyType type() const { return world_->bodyType(id_); }
    void setType(BodyType type) { world_->setBodyType(id_, type); }
    [[nodiscard]] Transform transform() const { return world_->transform(id_); }
    /// The body origin's world position, metres.
    [[nodiscard]] Vec2 position() const { return world_->transform(id_).p; }
    /// Radians counter-clockwise, in [-pi, pi].
    [[nodiscard]] float angle() const { return world_->transform(id_).q.angle(); }
    void setTransform(Vec2 position, float angle) { world_->setTransform(id_, position, angle); }
    [[nodiscard]] Vec2 linearVelocity() const { return world_->linearVelocity(id_); }
    void setLinearVelocity(Vec2 velocity) { world_->setLinearVelocity(id_, velocity); }
    [[nodiscard]] float angularVelocity() const { return world_->angularVelocity(id_); }
    void setAngularVelocity(float velocity) { world_->setAngularVelocity(id_, velocity); }

    [[nodiscard]] MassData massData() const { return world_->massData(id_); }
    void setMassData(const MassData& massData) { world_->setMassData(id_, massData); }
    /// kg.
    [[nodiscard]] float mass() const { return world_->massData(id_).mass; }
    [[nodiscard]] Vec2 worldCenterOfMass() const { return world_->worldCenterOfMass(id_); }

    [[nodiscard]] Vec2 worldPoint(Vec2 localPoint) const {
        return world_->worldPoint(id_, localPoint);
    }
    [[nodiscard]] Vec2 localPoint(Vec2 worldPoint) const {
        return world_->localPoint(id_, worldPoint);
    }
    [[nodiscard]] Vec2 worldVector(Vec2 localVector) const {
        return world_->worldVector(id_, localVector);
    }
    [[nodiscard]] Vec2 localVector(Vec2 worldVector) const {
        return world_->localVector(id_, worldVector);
    }
    [[nodiscard]] Vec2 linearVelocityAtWorldPoint(Vec2 worldPoint) const {
        return world_->linearVelocityAtWorldPoint(id_, worldPoint);
    }
    [[nodiscard]] Vec2 linearVelocityAtLocalPoint(Vec2 localPoint) const {
        return world_->linearVelocityAtLocalPoint(id_, localPoint);
    }

    void applyForce(Vec2 force, Vec2 point, bool wake = true) {
        world_->applyForce(id_, force, point, wake);
    }
    void applyForceToCenter(Vec2 force, bool wake = true) {
        world_->applyForceToCenter(id_, force, wake);
    }
    void applyTorque(float torque, bool wake = true) { world_->applyTorque(id_, torque, wake); }
    void applyLinearImpulse(Vec2 impulse, Vec2 point, bool wake = true) {
        world_->applyLinearImpulse(id_, impulse, point, wake);
    }
    void applyLinearImpulseToCenter(Vec2 impulse, bool wake = true) {
        world_->applyLinearImpulseToCenter(id_, impulse, wake);
    }
    void applyAngularImpulse(float impulse, bool wake = true) {
        world_->applyAngularImpulse(id_, impulse, wake);
    }

    [[nodiscard]] float linearDamping() const { return world_->linearDamping(id_); }
    void setLinearDamping(float damping) { world_->setLinearDamping(id_, damping); }
    [[nodiscard]] float angularDamping() const { return world_->angularDamping(id_); }
    void setAngularDamping(float damping) { world_->setAngularDamping(id_, damping); }
    [[nodiscard]] float gravityScale() const { return world_->gravityScale(id_); }
    void setGravityScale(float scale) { world_->setGravityScale(id_, scale); }
    [[nodiscard]] bool isFixedRotation() const { return world_->isFixedRotation(id_); }
    void setFixedRotation(bool fixed) { world_->setFixedRotation(id_, fixed); }
    [[nodiscard]] bool isBullet() const { return world_->isBullet(id_); }
    void setBullet(bool bullet) { world_->setBullet(id_, bullet); }

    [[nodiscard]] bool isAwake() const { return world_->isAwake(id_); }
    void setAwake(bool awake) { world_->setAwake(id_, awake); }
    [[nodiscard]] bool isSleepEnabled() const { return world_->isSleepEnabled(id_); }
    void setSleepEnabled(bool enabled) { world_->setSleepEnabled(id_, enabled); }
    [[nodiscard]] bool isEnabled() const { return world_->isBodyEnabled(id_); }
    void setEnabled(bool enabled) { world_->setBodyEnabled(id_, enabled); }
    [[nodiscard]] std::uint64_t userData() const { return world_->bodyUserData(id_); }
    void setUserData(std::uint64_t userData) { world_->setBodyUserData(id_, userData); }

    /// World::createShape() on this body.
    inline Shape createShape(const ShapeDef& def, const ShapeGeometry& geometry);
    /// World::createChain() on this body.
    std::vector<ShapeId> createChain(const ChainDef& def) { return world_->createChain(id_, def); }
    /// The body's shapes, most recently created first.
    [[nodiscard]] std::vector<ShapeId> shapes() const { return world_->bodyShapes(id_); }
    /// World::createJoint(); the def names its bodies (this one among them, or not).
    inline Joint createJoint(const JointDef& def);
    /// The body's joints, most recently created first.
    [[nodiscard]] std::vector<JointId> joints() const { return world_->bodyJoints(id_); }

    friend bool operator==(const Body& a, const Body& b) {
        return a.world_ == b.world_ && a.id_ == b.id_;
    }

private:
    World* world_;
    BodyId id_;
};

/// A shape of a World (World::shape()).
class Shape {
public:
    Shape(World& world, ShapeId id) : world_(&world), id_(id) {}

    [[nodiscard]] ShapeId id() const { return id_; }
    [[nodiscard]] World& world() const { return *world_; }
    [[nodiscard]] bool isValid() const { return world_->isValid(id_); }
    /// Destroys the shape; the view becomes stale.
    void destroy() { world_->destroyShape(id_); }

    /// The body the shape is attached to.
    [[nodiscard]] Body body() const { return Body(*world_, world_->shapeBody(id_)); }
    [[nodiscard]] ShapeType type() const { return world_->shapeType(id_); }
    [[nodiscard]] const ShapeGeometry& geometry() const { return world_->shapeGeometry(id_); }
    void setGeometry(const ShapeGeometry& geometry) { world_->setShapeGeometry(id_, geometry); }
    [[nodiscard]] Aabb aabb() const { return world_->shapeAabb(id_); }

    [[nodiscard]] Filter filter() const { return world_->shapeFilter(id_); }
    void setFilter(const Filter& filter) { world_->setShapeFilter(id_, filter); }
    [[nodiscard]] bool isSensor() const { return world_->isSensor(id_); }
    void setSensor(bool isSensor) { world_->setShapeSensor(id_, isSensor); }
    [[nodiscard]] float density() const { return world_->shapeDensity(id_); }
    void setDensity(float density) { world_->setShapeDensity(id_, density); }
    [[nodiscard]] float friction() const { return world_->shapeFriction(id_); }
    void setFriction(float friction) { world_->setShapeFriction(id_, friction); }
    [[nodiscard]] float restitution() const { return world_->shapeRestitution(id_); }
    void setRestitution(float restitution) { world_->setShapeRestitution(id_, restitution); }
    [[nodiscard]] float rollingResistance() const { return world_->shapeRollingResistance(id_); }
    void setRollingResistance(float value) { world_->setShapeRollingResistance(id_, value); }
    [[nodiscard]] std::uint64_t userData() const { return world_->shapeUserData(id_); }
    void setUserData(std::uint64_t userData) { world_->setShapeUserData(id_, userData); }
    void setEventFlags(bool contactEvents, bool sensorEvents, bool hitEvents) {
        world_->setShapeEventFlags(id_, contactEvents, sensorEvents, hitEvents);
    }

    /// World::rayCastShape() on this shape.
    [[nodiscard]] std::optional<RayResult> rayCast(Vec2 origin, Vec2 translation,
                                                   bool ignoreBackFaces = true) const {
        return world_->rayCastShape(id_, origin, translation, ignoreBackFaces);
    }

    friend bool operator==(const Shape& a, const Shape& b) {
        return a.world_ == b.world_ && a.id_ == b.id_;
    }

private:
    World* world_;
    ShapeId id_;
};

/// A joint of a World (World::joint()).
class Joint {
public:
    Joint(World& world, JointId id) : world_(&world), id_(id) {}

    [[nodiscard]] JointId id() const { return id_; }
    [[nodiscard]] World& world() const { return *world_; }
    [[nodiscard]] bool isValid() const { return world_->isValid(id_); }
    /// Destroys the joint (its bodies stay and wake); the view becomes stale.
    void destroy() { world_->destroyJoint(id_); }

    [[nodiscard]] JointType type() const { return world_->jointType(id_); }
    [[nodiscard]] Body bodyA() const { return Body(*world_, world_->jointBodyA(id_)); }
    [[nodiscard]] Body bodyB() const { return Body(*world_, world_->jointBodyB(id_)); }
    /// World metres (see World::jointAnchorA()).
    [[nodiscard]] Vec2 anchorA() const { return world_->jointAnchorA(id_); }
    [[nodiscard]] Vec2 anchorB() const { return world_->jointAnchorB(id_); }
    /// On body B during the last step: N (world axes) and N*m.
    [[nodiscard]] Vec2 reactionForce() const { return world_->jointReactionForce(id_); }
    [[nodiscard]] float reactionTorque() const { return world_->jointReactionTorque(id_); }
    /// Angle (revolute), translation (prismatic, wheel) or length (distance); see
    /// World::jointValue().
    [[nodiscard]] float value() const { return world_->jointValue(id_); }

    void enableMotor(bool enable) { world_->enableJointMotor(id_, enable); }
    void setMotorSpeed(float speed) { world_->setJointMotorSpeed(id_, speed); }
    void setMaxMotorForce(float force) { world_->setJointMaxMotorForce(id_, force); }
    void enableLimit(bool enable) { world_->enableJointLimit(id_, enable); }
    void setLimits(float lower, float upper) { world_->setJointLimits(id_, lower, upper); }
    void setSpring(float hertz, float dampingRatio) {
        world_->setJointSpring(id_, hertz, dampingRatio);
    }
    /// Mouse joints.
    void setTarget(Vec2 target) { world_->setMouseJointTarget(id_, target); }
    /// Motor joints.
    void setOffsets(Vec2 linearOffset, float angularOffset) {
        world_->setMotorJointOffsets(id_, linearOffset, angularOffset);
    }
    [[nodiscard]] std::uint64_t userData() const { return world_->jointUserData(id_); }
    void setUserData(std::uint64_t userData) { world_->setJointUserData(id_, userData); }

    friend bool operator==(const Joint& a, const Joint& b) {
        return a.world_ == b.world_ && a.id_ == b.id_;
    }

private:
    World* world_;
    JointId id_;
};

inline Shape Body::createShape(const ShapeDef& def, const ShapeGeometry& geometry) {
    return Shape(*world_, world_->createShape(id_, def, geometry));
}

inline Joint Body::createJoint(const JointDef& def) {
    return Joint(*world_, world_->createJoint(def));
}

inline Body World::body(BodyId id) { return Body(*this, id); }
inline Shape World::shape(ShapeId id) { return Shape(*this, id); }
inline Joint World::joint(JointId id) { return Joint(*this, id); }

} // namespace e2d::physics
