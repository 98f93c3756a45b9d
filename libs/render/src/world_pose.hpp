// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/game_object.hpp>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <cmath>

namespace e2d::render::detail {

// Position, z, rotation and scale at which the object is drawn this frame: its render
// transform (parent chain included, interpolated between fixed steps, see
// core::GameObject::renderTransform()). Every render component reads the pose here, so a
// sprite, a label and a camera on one object or its children agree.
struct WorldPose {
    glm::vec2 position;
    float z;
    float rotation;
    glm::vec2 scale;
};

inline WorldPose worldPose(const core::GameObject& object) {
    const glm::mat4 m = object.renderTransform();
    glm::vec2 xAxis(m[0][0], m[0][1]);
    glm::vec2 yAxis(m[1][0], m[1][1]);
    float sx = glm::length(xAxis);
    float sy = glm::length(yAxis);
    // A mirrored transform keeps its x axis' direction (worldOrientation()) and flips y.
    if (xAxis.x * yAxis.y - xAxis.y * yAxis.x < 0.0f) {
        sy = -sy;
    }
    return {glm::vec2(m[3][0], m[3][1]), m[3][2], std::atan2(xAxis.y, xAxis.x), {sx, sy}};
}

} // namespace e2d::render::detail
