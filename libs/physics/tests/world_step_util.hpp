// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/world.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

// Scenes and measurements shared by the world_step / solver accuracy tests.
namespace e2d::physics::test {

inline constexpr float kStep = 1.0f / 60.0f;

/// A static ground box whose top surface is y = 0, 200 m wide.
inline BodyId addGround(World& world, float friction = 0.6f, float restitution = 0.0f) {
    BodyId ground = world.createBody({});
    ShapeDef sd;
    sd.friction = friction;
    sd.restitution = restitution;
    world.createShape(ground, sd, makeOffsetBox(100.0f, 1.0f, {0.0f, -1.0f}, 0.0f));
    return ground;
}

inline BodyId addBox(World& world, Vec2 position, float halfSize, float friction = 0.6f,
                     float density = 1.0f, float angle = 0.0f) {
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = position;
    bd.angle = angle;
    BodyId body = world.createBody(bd);
    ShapeDef sd;
    sd.friction = friction;
    sd.density = density;
    world.createShape(body, sd, makeBox(halfSize, halfSize));
    return body;
}

inline BodyId addBall(World& world, Vec2 position, float radius, float restitution = 0.0f,
                      float friction = 0.6f) {
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = position;
    BodyId body = world.createBody(bd);
    ShapeDef sd;
    sd.restitution = restitution;
    sd.friction = friction;
    world.createShape(body, sd, Circle{{0.0f, 0.0f}, radius});
    return body;
}

/// The deepest overlap among the touching contacts, metres (>= 0).
inline float maxPenetration(const World& world) {
    float deepest = 0.0f;
    world.forEachTouchingContact([&](const ContactData& c) {
        for (int i = 0; i < c.manifold->pointCount; ++i) {
            deepest = std::max(deepest, -c.manifold->points[i].separation);
        }
    });
    return deepest;
}

} // namespace e2d::physics::test
