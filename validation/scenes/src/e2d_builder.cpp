// SPDX-License-Identifier: MIT
#include <e2d/scenes/e2d_builder.hpp>

#include <cmath>
#include <span>

namespace e2d::scenes {

namespace ph = e2d::physics;

ph::ShapeGeometry toE2dGeometry(const ShapeDesc& s) {
    switch (s.kind) {
    case ShapeKind::Box:
        if (s.center == glm::vec2{0.0f} && s.angle == 0.0f) {
            return ph::makeBox(s.halfExtents.x, s.halfExtents.y);
        }
        return ph::makeOffsetBox(s.halfExtents.x, s.halfExtents.y, s.center, s.angle);
    case ShapeKind::Polygon:
        return ph::makePolygon(std::span<const ph::Vec2>(s.points.data(), s.points.size()),
                               s.radius);
    case ShapeKind::Circle:
        return ph::Circle{s.center, s.radius};
    case ShapeKind::Capsule:
        return ph::Capsule{s.point1, s.point2, s.radius};
    case ShapeKind::Segment:
        return ph::Segment{s.point1, s.point2};
    case ShapeKind::Chain: {
        // One segment of the chain standing alone; buildE2d() makes chains with createChain().
        ph::ChainSegment g;
        g.segment = {s.points.front(), s.points.size() > 1 ? s.points[1] : s.points.front()};
        return g;
    }
    }
    return ph::Circle{s.center, s.radius};
}

namespace {

ph::BodyType toType(BodyKind kind) {
    switch (kind) {
    case BodyKind::Static:
        return ph::BodyType::Static;
    case BodyKind::Kinematic:
        return ph::BodyType::Kinematic;
    case BodyKind::Dynamic:
        return ph::BodyType::Dynamic;
    }
    return ph::BodyType::Static;
}

} // namespace

ph::JointDef toE2dJoint(const JointDesc& j, const SceneDesc& scene, const ph::World& world,
                        const std::vector<ph::BodyId>& bodies) {
    const ph::BodyId a = bodies[std::size_t(j.bodyA)];
    const ph::BodyId b = bodies[std::size_t(j.bodyB)];
    const float referenceAngle =
        scene.bodies[std::size_t(j.bodyB)].angle - scene.bodies[std::size_t(j.bodyA)].angle;
    switch (j.kind) {
    case JointKind::Revolute: {
        ph::RevoluteJointDef d;
        d.bodyA = a;
        d.bodyB = b;
        d.localAnchorA = world.localPoint(a, j.anchorA);
        d.localAnchorB = world.localPoint(b, j.anchorA);
        d.referenceAngle = referenceAngle;
        d.enableLimit = j.enableLimit;
        d.lowerAngle = j.lower;
        d.upperAngle = j.upper;
        d.enableMotor = j.enableMotor;
        d.motorSpeed = j.motorSpeed;
        d.maxMotorTorque = j.maxMotor;
        d.enableSpring = j.enableSpring;
        d.hertz = j.hertz;
        d.dampingRatio = j.dampingRatio;
        d.collideConnected = j.collideConnected;
        return d;
    }
    case JointKind::Prismatic: {
        ph::PrismaticJointDef d;
        d.bodyA = a;
        d.bodyB = b;
        d.localAnchorA = world.localPoint(a, j.anchorA);
        d.localAnchorB = world.localPoint(b, j.anchorA);
        d.localAxisA = world.localVector(a, j.axis);
        d.referenceAngle = referenceAngle;
        d.enableLimit = j.enableLimit;
        d.lowerTranslation = j.lower;
        d.upperTranslation = j.upper;
        d.enableMotor = j.enableMotor;
        d.motorSpeed = j.motorSpeed;
        d.maxMotorForce = j.maxMotor;
        d.enableSpring = j.enableSpring;
        d.hertz = j.hertz;
        d.dampingRatio = j.dampingRatio;
        d.collideConnected = j.collideConnected;
        return d;
    }
    case JointKind::Wheel: {
        ph::WheelJointDef d;
        d.bodyA = a;
        d.bodyB = b;
        d.localAnchorA = world.localPoint(a, j.anchorA);
        d.localAnchorB = world.localPoint(b, j.anchorA);
        d.localAxisA = world.localVector(a, j.axis);
        // e2d's def has the spring on by default; the scene says whether there is one.
        d.enableSpring = j.enableSpring;
        d.hertz = j.hertz;
        d.dampingRatio = j.dampingRatio;
        d.enableLimit = j.enableLimit;
        d.lowerTranslation = j.lower;
        d.upperTranslation = j.upper;
        d.enableMotor = j.enableMotor;
        d.motorSpeed = j.motorSpeed;
        d.maxMotorTorque = j.maxMotor;
        d.collideConnected = j.collideConnected;
        return d;
    }
    case JointKind::Motor: {
        ph::MotorJointDef d;
        d.bodyA = a;
        d.bodyB = b;
        d.linearOffset = j.linearOffset;
        d.angularOffset = j.angularOffset;
        d.maxForce = j.maxForce;
        d.maxTorque = j.maxTorque;
        d.correctionFactor = j.correctionFactor;
        d.collideConnected = j.collideConnected;
        return d;
    }
    case JointKind::Mouse: {
        ph::MouseJointDef d;
        d.bodyA = a;
        d.bodyB = b;
        d.target = j.target;
        d.localAnchorB = world.localPoint(b, j.anchorA);
        d.hertz = j.hertz;
        d.dampingRatio = j.dampingRatio;
        d.maxForce = j.maxForce;
        d.collideConnected = j.collideConnected;
        return d;
    }
    case JointKind::Weld: {
        ph::WeldJointDef d;
        d.bodyA = a;
        d.bodyB = b;
        d.localAnchorA = world.localPoint(a, j.anchorA);
        d.localAnchorB = world.localPoint(b, j.anchorA);
        d.referenceAngle = referenceAngle;
        d.collideConnected = j.collideConnected;
        return d;
    }
    case JointKind::Distance:
        break;
    }
    ph::DistanceJointDef d;
    d.bodyA = a;
    d.bodyB = b;
    d.localAnchorA = world.localPoint(a, j.anchorA);
    d.localAnchorB = world.localPoint(b, j.anchorB);
    const glm::vec2 gap = j.anchorB - j.anchorA;
    d.length = j.length > 0.0f ? j.length : std::sqrt(gap.x * gap.x + gap.y * gap.y);
    d.enableSpring = j.enableSpring;
    d.hertz = j.hertz;
    d.dampingRatio = j.dampingRatio;
    d.enableLimit = j.enableLimit;
    d.minLength = j.lower;
    d.maxLength = j.enableLimit ? j.upper : ph::kHuge;
    d.collideConnected = j.collideConnected;
    return d;
}

E2dScene buildE2d(const SceneDesc& scene, ph::WorldDef def) {
    def.gravity = scene.gravity;
    def.bodyCapacity = static_cast<int>(scene.bodies.size());
    E2dScene out{ph::World(def), {}, {}, scene.timeStep};
    out.bodies.reserve(scene.bodies.size());
    for (const BodyDesc& desc : scene.bodies) {
        ph::BodyDef bd;
        bd.type = toType(desc.kind);
        bd.position = desc.position;
        bd.angle = desc.angle;
        bd.linearVelocity = desc.linearVelocity;
        bd.angularVelocity = desc.angularVelocity;
        bd.fixedRotation = desc.fixedRotation;
        bd.isBullet = desc.bullet;
        bd.gravityScale = desc.gravityScale;
        const ph::BodyId body = out.world.createBody(bd);
        for (const ShapeDesc& shape : desc.shapes) {
            ph::ShapeDef sd;
            sd.density = shape.density;
            sd.friction = shape.friction;
            sd.restitution = shape.restitution;
            if (shape.kind == ShapeKind::Chain) {
                ph::ChainDef cd;
                cd.points.assign(shape.points.begin(), shape.points.end());
                cd.isLoop = shape.loop;
                cd.ghostBefore = shape.ghostBefore;
                cd.ghostAfter = shape.ghostAfter;
                for (const ChainMaterial& m : shape.materials) {
                    ph::SurfaceMaterial material;
                    material.friction = m.friction;
                    material.restitution = m.restitution;
                    cd.materials.push_back(material);
                }
                cd.shape = sd;
                out.world.createChain(body, cd);
                continue;
            }
            out.world.createShape(body, sd, toE2dGeometry(shape));
        }
        out.bodies.push_back(body);
    }
    out.joints.reserve(scene.joints.size());
    for (const JointDesc& j : scene.joints) {
        out.joints.push_back(out.world.createJoint(toE2dJoint(j, scene, out.world, out.bodies)));
    }
    return out;
}

} // namespace e2d::scenes
