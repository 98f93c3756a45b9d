// SPDX-License-Identifier: MIT
#include <e2d/scenes/box2d_builder.hpp>

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
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
    }
}

} // namespace

Box2DScene buildBox2D(const SceneDesc& scene, const Box2DSettings& settings) {
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
        b2Body* body = out.world->CreateBody(&def);
        for (const ShapeDesc& shape : desc.shapes) {
            addShape(body, shape);
        }
        out.bodies.push_back(body);
    }
    return out;
}

} // namespace e2d::scenes
