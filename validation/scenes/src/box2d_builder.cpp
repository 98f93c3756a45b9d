// SPDX-License-Identifier: MIT
#include <e2d/scenes/box2d_builder.hpp>

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace e2d::scenes {

Box2DScene::Box2DScene() = default;
Box2DScene::Box2DScene(Box2DScene&&) noexcept = default;
Box2DScene& Box2DScene::operator=(Box2DScene&&) noexcept = default;
Box2DScene::~Box2DScene() = default;

void Box2DScene::step(float timeStep) {
    world->Step(timeStep, settings.velocityIterations, settings.positionIterations);
}

namespace {

b2Vec2 toB2(glm::vec2 v) { return {v.x, v.y}; }

void addFixture(b2Body* body, const ShapeDesc& desc, const b2Shape& shape) {
    b2FixtureDef fixture;
    fixture.shape = &shape;
    fixture.density = desc.density;
    fixture.friction = desc.friction;
    fixture.restitution = desc.restitution;
    body->CreateFixture(&fixture);
}

// A chain end without a ghost point is free in e2d (round like a segment's); Box2D 2.4's
// CreateChain() needs one, so it gets the end segment continued straight on.
b2Vec2 ghostOrExtension(const std::optional<glm::vec2>& ghost, glm::vec2 end, glm::vec2 inner) {
    return toB2(ghost ? *ghost : end + (end - inner));
}

// One material for the whole chain: a b2ChainShape. A material per segment: the chain's own
// child edges (one-sided b2EdgeShapes with the same ghost vertices), each its own fixture, since
// a Box2D fixture has one friction.
void addChain(b2Body* body, const ShapeDesc& desc) {
    std::vector<b2Vec2> points;
    for (glm::vec2 p : desc.points) {
        points.push_back(toB2(p));
    }
    const auto n = static_cast<int32>(points.size());
    b2ChainShape chain;
    if (desc.loop) {
        chain.CreateLoop(points.data(), n);
    } else {
        chain.CreateChain(points.data(), n,
                          ghostOrExtension(desc.ghostBefore, desc.points[0], desc.points[1]),
                          ghostOrExtension(desc.ghostAfter, desc.points[std::size_t(n) - 1],
                                           desc.points[std::size_t(n) - 2]));
    }
    if (desc.materials.size() <= 1) {
        ShapeDesc material = desc;
        if (desc.materials.size() == 1) {
            material.friction = desc.materials[0].friction;
            material.restitution = desc.materials[0].restitution;
        }
        addFixture(body, material, chain);
        return;
    }
    for (int32 i = 0; i < chain.GetChildCount(); ++i) {
        b2EdgeShape edge;
        chain.GetChildEdge(&edge, i);
        ShapeDesc material = desc;
        material.friction = desc.materials[std::size_t(i)].friction;
        material.restitution = desc.materials[std::size_t(i)].restitution;
        addFixture(body, material, edge);
    }
}

void addShape(b2Body* body, const ShapeDesc& desc) {
    switch (desc.kind) {
    case ShapeKind::Box: {
        b2PolygonShape box;
        box.SetAsBox(desc.halfExtents.x, desc.halfExtents.y, toB2(desc.center), desc.angle);
        addFixture(body, desc, box);
        break;
    }
    case ShapeKind::Polygon: {
        std::vector<b2Vec2> points;
        for (glm::vec2 p : desc.points) {
            points.push_back(toB2(p));
        }
        b2PolygonShape polygon;
        polygon.Set(points.data(), static_cast<int32>(points.size()));
        polygon.m_radius += desc.radius;
        addFixture(body, desc, polygon);
        break;
    }
    case ShapeKind::Circle: {
        b2CircleShape circle;
        circle.m_p = toB2(desc.center);
        circle.m_radius = desc.radius;
        addFixture(body, desc, circle);
        break;
    }
    case ShapeKind::Capsule: {
        // Two discs and the box between them: the same solid, in shapes Box2D 2.4 has.
        const glm::vec2 axis = desc.point2 - desc.point1;
        const float length = std::sqrt(axis.x * axis.x + axis.y * axis.y);
        for (glm::vec2 c : {desc.point1, desc.point2}) {
            b2CircleShape cap;
            cap.m_p = toB2(c);
            cap.m_radius = desc.radius;
            ShapeDesc part = desc;
            addFixture(body, part, cap);
        }
        if (length > 0.0f) {
            b2PolygonShape middle;
            middle.SetAsBox(0.5f * length, std::max(desc.radius - b2_polygonRadius, 0.001f),
                            toB2(0.5f * (desc.point1 + desc.point2)), std::atan2(axis.y, axis.x));
            addFixture(body, desc, middle);
        }
        break;
    }
    case ShapeKind::Segment: {
        b2EdgeShape edge;
        edge.SetTwoSided(toB2(desc.point1), toB2(desc.point2));
        addFixture(body, desc, edge);
        break;
    }
    case ShapeKind::Chain:
        addChain(body, desc);
        break;
    }
}

// Twice the signed area of a polygon given in order.
float twiceArea(const std::vector<glm::vec2>& points) {
    float area2 = 0.0f;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::vec2 a = points[i];
        const glm::vec2 b = points[(i + 1) % points.size()];
        area2 += a.x * b.y - a.y * b.x;
    }
    return area2;
}

// Box2D 2.4's own weld of b2PolygonShape::Set: a point within 0.5 b2_linearSlop of a kept one
// is dropped.
std::vector<glm::vec2> welded(const std::vector<glm::vec2>& points) {
    constexpr float kWeld = 0.5f * b2_linearSlop;
    std::vector<glm::vec2> kept;
    for (glm::vec2 p : points) {
        const bool unique = std::none_of(kept.begin(), kept.end(), [&](glm::vec2 q) {
            const glm::vec2 d = p - q;
            return d.x * d.x + d.y * d.y < kWeld * kWeld;
        });
        if (unique) {
            kept.push_back(p);
        }
    }
    return kept;
}

std::string shapeUnsupported(const ShapeDesc& shape, bool massive) {
    const auto number = [](float v) {
        std::ostringstream out;
        out << v;
        return out.str();
    };
    switch (shape.kind) {
    case ShapeKind::Polygon: {
        const std::vector<glm::vec2> kept = welded(shape.points);
        if (kept.size() < 3) {
            return "Box2D 2.4 welds polygon vertices closer than 0.5 b2_linearSlop (0.0025 m) "
                   "and " +
                   std::to_string(kept.size()) + " of " + std::to_string(shape.points.size()) +
                   " stay (b2PolygonShape::Set asserts)";
        }
        if (massive && !(0.5f * std::abs(twiceArea(kept)) > b2_epsilon)) {
            return "polygon area " + number(0.5f * std::abs(twiceArea(kept))) +
                   " m^2 is not above b2_epsilon (Box2D 2.4's ComputeMass asserts)";
        }
        return {};
    }
    case ShapeKind::Box:
        if (massive && !(4.0f * shape.halfExtents.x * shape.halfExtents.y > b2_epsilon)) {
            return "box area " + number(4.0f * shape.halfExtents.x * shape.halfExtents.y) +
                   " m^2 is not above b2_epsilon (Box2D 2.4's ComputeMass asserts)";
        }
        return {};
    case ShapeKind::Capsule: {
        const glm::vec2 axis = shape.point2 - shape.point1;
        const float length = std::sqrt(axis.x * axis.x + axis.y * axis.y);
        const float area = length * 2.0f * std::max(shape.radius - b2_polygonRadius, 0.001f);
        if (massive && length > 0.0f && !(area > b2_epsilon)) {
            return "the box between the capsule's discs has area " + number(area) +
                   " m^2, not above b2_epsilon (Box2D 2.4's ComputeMass asserts)";
        }
        return {};
    }
    case ShapeKind::Chain: {
        // b2ChainShape::CreateChain/CreateLoop assert that consecutive vertices are farther
        // apart than b2_linearSlop (the loop's closing pair is not checked).
        for (std::size_t i = 0; i + 1 < shape.points.size(); ++i) {
            const glm::vec2 d = shape.points[i + 1] - shape.points[i];
            if (!(d.x * d.x + d.y * d.y > b2_linearSlop * b2_linearSlop)) {
                return "chain points " + std::to_string(i) + " and " + std::to_string(i + 1) +
                       " are not farther apart than b2_linearSlop (0.005 m; b2ChainShape asserts)";
            }
        }
        return {};
    }
    case ShapeKind::Circle:
    case ShapeKind::Segment:
        return {};
    }
    return {};
}

} // namespace

namespace {

// Box2D 2.4's Initialize() functions take world anchors and set the reference angle, as
// JointDesc does.
b2Joint* createJoint(b2World& world, const JointDesc& j, b2Body* a, b2Body* b) {
    switch (j.kind) {
    case JointKind::Revolute: {
        b2RevoluteJointDef def;
        def.Initialize(a, b, toB2(j.anchorA));
        def.collideConnected = j.collideConnected;
        def.enableLimit = j.enableLimit;
        def.lowerAngle = j.lower;
        def.upperAngle = j.upper;
        def.enableMotor = j.enableMotor;
        def.motorSpeed = j.motorSpeed;
        def.maxMotorTorque = j.maxMotor;
        return world.CreateJoint(&def);
    }
    case JointKind::Prismatic: {
        b2PrismaticJointDef def;
        def.Initialize(a, b, toB2(j.anchorA), toB2(j.axis));
        def.collideConnected = j.collideConnected;
        def.enableLimit = j.enableLimit;
        def.lowerTranslation = j.lower;
        def.upperTranslation = j.upper;
        def.enableMotor = j.enableMotor;
        def.motorSpeed = j.motorSpeed;
        def.maxMotorForce = j.maxMotor;
        return world.CreateJoint(&def);
    }
    case JointKind::Weld: {
        b2WeldJointDef def;
        def.Initialize(a, b, toB2(j.anchorA));
        def.collideConnected = j.collideConnected;
        return world.CreateJoint(&def);
    }
    case JointKind::Wheel: {
        b2WheelJointDef def;
        def.Initialize(a, b, toB2(j.anchorA), toB2(j.axis));
        def.collideConnected = j.collideConnected;
        def.enableLimit = j.enableLimit;
        def.lowerTranslation = j.lower;
        def.upperTranslation = j.upper;
        def.enableMotor = j.enableMotor;
        def.motorSpeed = j.motorSpeed;
        def.maxMotorTorque = j.maxMotor;
        if (j.enableSpring) {
            b2LinearStiffness(def.stiffness, def.damping, j.hertz, j.dampingRatio, a, b);
        }
        return world.CreateJoint(&def);
    }
    case JointKind::Motor: {
        b2MotorJointDef def;
        def.bodyA = a;
        def.bodyB = b;
        def.collideConnected = j.collideConnected;
        def.linearOffset = toB2(j.linearOffset);
        def.angularOffset = j.angularOffset;
        def.maxForce = j.maxForce;
        def.maxTorque = j.maxTorque;
        def.correctionFactor = j.correctionFactor;
        return world.CreateJoint(&def);
    }
    case JointKind::Mouse: {
        // Box2D 2.4 pulls the point of B that is at the target when the joint is made: make it
        // at the anchor, then move the target.
        b2MouseJointDef def;
        def.bodyA = a;
        def.bodyB = b;
        def.collideConnected = j.collideConnected;
        def.target = toB2(j.anchorA);
        def.maxForce = j.maxForce;
        b2LinearStiffness(def.stiffness, def.damping, j.hertz, j.dampingRatio, a, b);
        auto* mouse = static_cast<b2MouseJoint*>(world.CreateJoint(&def));
        mouse->SetTarget(toB2(j.target));
        return mouse;
    }
    case JointKind::Distance: {
        b2DistanceJointDef def;
        // Rigid: minLength = maxLength = length (Initialize's default).
        def.Initialize(a, b, toB2(j.anchorA), toB2(j.anchorB));
        def.collideConnected = j.collideConnected;
        if (j.length > 0.0f) {
            def.length = def.minLength = def.maxLength = j.length;
        }
        if (j.enableSpring || j.enableLimit) {
            // Box2D 2.4 solves a distance joint with minLength < maxLength as a spring (stiffness
            // > 0) or a rope (stiffness 0) between the two.
            def.minLength = j.enableLimit ? j.lower : 0.0f;
            def.maxLength = j.enableLimit ? j.upper : FLT_MAX;
        }
        if (j.enableSpring) {
            b2LinearStiffness(def.stiffness, def.damping, j.hertz, j.dampingRatio, a, b);
        }
        return world.CreateJoint(&def);
    }
    }
    return nullptr;
}

} // namespace

std::string box2DUnsupported(const SceneDesc& scene) {
    for (std::size_t i = 0; i < scene.joints.size(); ++i) {
        const JointDesc& j = scene.joints[i];
        if (j.enableSpring && (j.kind == JointKind::Revolute || j.kind == JointKind::Prismatic)) {
            return "joint " + std::to_string(i) + ": Box2D 2.4.1's " + jointKindName(j.kind) +
                   " joint has no spring (b2" +
                   (j.kind == JointKind::Revolute ? "Revolute" : "Prismatic") +
                   "JointDef has no stiffness; Box2D v3's has one)";
        }
    }
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const BodyDesc& body = scene.bodies[i];
        for (std::size_t j = 0; j < body.shapes.size(); ++j) {
            // Box2D computes mass (and asserts on it) only for dynamic bodies with density.
            const bool massive = body.kind == BodyKind::Dynamic && body.shapes[j].density > 0.0f;
            if (std::string why = shapeUnsupported(body.shapes[j], massive); !why.empty()) {
                return "body " + std::to_string(i) +
                       (body.tag.empty() ? "" : " (\"" + body.tag + "\")") + ", shape " +
                       std::to_string(j) + ": " + why;
            }
        }
    }
    return {};
}

Box2DScene buildBox2D(const SceneDesc& scene, const Box2DSettings& settings) {
    if (std::string why = box2DUnsupported(scene); !why.empty()) {
        throw std::invalid_argument("Box2D 2.4 cannot build this scene: " + why);
    }
    Box2DScene out;
    out.settings = settings;
    out.world = std::make_unique<b2World>(toB2(scene.gravity));
    out.world->SetAllowSleeping(settings.allowSleeping);
    out.world->SetContinuousPhysics(settings.continuous);
    out.world->SetWarmStarting(settings.warmStarting);
    out.bodies.reserve(scene.bodies.size());
    for (const BodyDesc& desc : scene.bodies) {
        b2BodyDef def;
        def.type = desc.kind == BodyKind::Static      ? b2_staticBody
                   : desc.kind == BodyKind::Kinematic ? b2_kinematicBody
                                                      : b2_dynamicBody;
        def.position = toB2(desc.position);
        def.angle = desc.angle;
        def.linearVelocity = toB2(desc.linearVelocity);
        def.angularVelocity = desc.angularVelocity;
        def.bullet = desc.bullet;
        def.fixedRotation = desc.fixedRotation;
        def.gravityScale = desc.gravityScale;
        b2Body* body = out.world->CreateBody(&def);
        for (const ShapeDesc& shape : desc.shapes) {
            addShape(body, shape);
        }
        out.bodies.push_back(body);
    }
    out.joints.reserve(scene.joints.size());
    for (const JointDesc& j : scene.joints) {
        out.joints.push_back(createJoint(*out.world, j, out.bodies[std::size_t(j.bodyA)],
                                         out.bodies[std::size_t(j.bodyB)]));
    }
    return out;
}

} // namespace e2d::scenes
