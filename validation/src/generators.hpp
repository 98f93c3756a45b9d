// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/scenes/scene.hpp>

#include <glm/vec2.hpp>

#include <string>

namespace e2d::validation {

/// Layout parameters shared by the scenario generators (see validation/README.md). Positions
/// are metres; `origin` is the point on the ground top where the layout starts.
struct LayoutParams {
    glm::vec2 origin{0.0f, 0.0f};
    float half = 0.5f; ///< box half-size, metres
    float friction = 0.6f;
    float density = 1.0f;
    float restitution = 0.0f;
    bool ground = true;      ///< add a static ground box under the layout
    std::string tag = "top"; ///< tag of the body the metrics follow
};

/// `count` boxes stacked touching, bottom one resting on y = origin.y. Last box tagged.
void addVerticalStack(scenes::SceneDesc& scene, int count, const LayoutParams& p);
/// A pyramid of `base` rows centred on origin.x (Box2D's benchmark layout). Apex tagged.
void addPyramid(scenes::SceneDesc& scene, int base, const LayoutParams& p);
/// `count` upright dominoes of half-size (p.half / 4, p.half) every `spacing` metres along +x;
/// the first one starts with angular velocity `push` (rad/s, negative tips it towards +x).
/// Last domino tagged.
void addDominoes(scenes::SceneDesc& scene, int count, float spacing, float push,
                 const LayoutParams& p);
/// A `columns` x `rows` grid of copies of `shape`, lower-left centre at origin, `spacing`
/// apart. No ground; the last body is tagged.
void addGrid(scenes::SceneDesc& scene, int columns, int rows, glm::vec2 spacing,
             const scenes::ShapeDesc& shape, const LayoutParams& p);

} // namespace e2d::validation
