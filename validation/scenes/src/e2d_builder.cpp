// SPDX-License-Identifier: MIT
#include <e2d/scenes/e2d_builder.hpp>

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
        return ph::makePolygon(std::span<const ph::Vec2>(s.points.data(), s.points.size()), s.radius);
    case ShapeKind::Circle:
        return ph::Circle{s.center, s.radius};
    case ShapeKind::Capsule:
        return ph::Capsule{s.point1, s.point2, s.radius};
    case ShapeKind::Segment:
        return ph::Segment{s.point1, s.point2};
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

E2dScene buildE2d(const SceneDesc& scene, ph::WorldDef def) {
    def.gravity = scene.gravity;
    def.bodyCapacity = static_cast<int>(scene.bodies.size());
    E2dScene out{ph::World(def), {}, scene.timeStep};
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
            out.world.createShape(body, sd, toE2dGeometry(shape));
        }
        out.bodies.push_back(body);
    }
    return out;
}

} // namespace e2d::scenes
