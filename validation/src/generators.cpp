// SPDX-License-Identifier: MIT
#include "generators.hpp"

#include <algorithm>

namespace e2d::validation {
namespace {

scenes::ShapeDesc boxShape(glm::vec2 half, const LayoutParams& p) {
    scenes::ShapeDesc box;
    box.kind = scenes::ShapeKind::Box;
    box.halfExtents = half;
    box.friction = p.friction;
    box.density = p.density;
    box.restitution = p.restitution;
    return box;
}

scenes::BodyDesc dynamicBody(glm::vec2 position, const scenes::ShapeDesc& shape) {
    scenes::BodyDesc body;
    body.kind = scenes::BodyKind::Dynamic;
    body.position = position;
    body.shapes.push_back(shape);
    return body;
}

// A ground box whose top face is y = origin.y, wide enough for the layout.
void addGround(scenes::SceneDesc& scene, const LayoutParams& p, float halfWidth, float centreX) {
    scenes::BodyDesc ground;
    ground.kind = scenes::BodyKind::Static;
    ground.position = {centreX, p.origin.y - 1.0f};
    ground.shapes.push_back(boxShape({halfWidth, 1.0f}, p));
    ground.tag = "ground";
    scene.bodies.push_back(ground);
}

} // namespace

void addVerticalStack(scenes::SceneDesc& scene, int count, const LayoutParams& p) {
    if (p.ground) {
        addGround(scene, p, std::max(20.0f, 4.0f * p.half), p.origin.x);
    }
    const scenes::ShapeDesc box = boxShape({p.half, p.half}, p);
    for (int i = 0; i < count; ++i) {
        const float y = p.origin.y + p.half * static_cast<float>(2 * i + 1);
        scene.bodies.push_back(dynamicBody({p.origin.x, y}, box));
    }
    scene.bodies.back().tag = p.tag;
}

void addPyramid(scenes::SceneDesc& scene, int base, const LayoutParams& p) {
    const float size = 2.0f * p.half;
    if (p.ground) {
        addGround(scene, p, std::max(100.0f, size * static_cast<float>(base)), p.origin.x);
    }
    const scenes::ShapeDesc box = boxShape({p.half, p.half}, p);
    // Row i holds base - i boxes, each row shifted half a box to the right.
    const float left = p.origin.x - 0.5f * size * static_cast<float>(base - 1);
    for (int i = 0; i < base; ++i) {
        for (int j = 0; j < base - i; ++j) {
            const float x = left + size * (0.5f * static_cast<float>(i) + static_cast<float>(j));
            const float y = p.origin.y + p.half + size * static_cast<float>(i);
            scene.bodies.push_back(dynamicBody({x, y}, box));
        }
    }
    scene.bodies.back().tag = p.tag;
}

void addDominoes(scenes::SceneDesc& scene, int count, float spacing, float push,
                 const LayoutParams& p) {
    if (p.ground) {
        addGround(scene, p, 0.5f * spacing * static_cast<float>(count) + 10.0f,
                  p.origin.x + 0.5f * spacing * static_cast<float>(count - 1));
    }
    const scenes::ShapeDesc domino = boxShape({0.25f * p.half, p.half}, p);
    for (int i = 0; i < count; ++i) {
        scenes::BodyDesc body = dynamicBody(
            {p.origin.x + spacing * static_cast<float>(i), p.origin.y + p.half}, domino);
        if (i == 0) {
            body.angularVelocity = push;
        }
        scene.bodies.push_back(body);
    }
    scene.bodies.back().tag = p.tag;
}

void addGrid(scenes::SceneDesc& scene, int columns, int rows, glm::vec2 spacing,
             const scenes::ShapeDesc& shape, const LayoutParams& p) {
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            const glm::vec2 position = p.origin + glm::vec2{spacing.x * static_cast<float>(c),
                                                            spacing.y * static_cast<float>(r)};
            scene.bodies.push_back(dynamicBody(position, shape));
        }
    }
    scene.bodies.back().tag = p.tag;
}

} // namespace e2d::validation
