// SPDX-License-Identifier: MIT
#include <e2d/scenes/scene.hpp>

#include <string>

namespace e2d::scenes {

const char* jointKindName(JointKind kind) {
    switch (kind) {
    case JointKind::Revolute:
        return "revolute";
    case JointKind::Distance:
        return "distance";
    case JointKind::Prismatic:
        return "prismatic";
    case JointKind::Weld:
        return "weld";
    case JointKind::Wheel:
        return "wheel";
    case JointKind::Motor:
        return "motor";
    case JointKind::Mouse:
        return "mouse";
    }
    return "?";
}

BodyDesc staticBox(glm::vec2 position, glm::vec2 halfExtents, float friction) {
    BodyDesc body;
    body.kind = BodyKind::Static;
    body.position = position;
    ShapeDesc box;
    box.halfExtents = halfExtents;
    box.friction = friction;
    body.shapes.push_back(box);
    return body;
}

BodyDesc dynamicBox(glm::vec2 position, float half, float friction) {
    BodyDesc body;
    body.position = position;
    ShapeDesc box;
    box.halfExtents = {half, half};
    box.friction = friction;
    body.shapes.push_back(box);
    return body;
}

SceneDesc pyramid(int base) {
    SceneDesc scene;
    scene.name = "pyramid_" + std::to_string(base);
    scene.bodies.push_back(staticBox({0.0f, -1.0f}, {100.0f, 1.0f}));
    const float half = 0.5f;
    const float shift = static_cast<float>(base) * 0.5f;
    for (int i = 0; i < base; ++i) {
        for (int j = i; j < base; ++j) {
            const float x = static_cast<float>(i + 1) * half + static_cast<float>(j - i) - shift;
            const float y = static_cast<float>(i) + half;
            scene.bodies.push_back(dynamicBox({x, y}, half));
        }
    }
    scene.bodies.back().tag = "top";
    return scene;
}

SceneDesc manyPyramids(int rows, int columns, int base) {
    SceneDesc scene;
    scene.name = "many_pyramids_" + std::to_string(rows) + "x" + std::to_string(columns) + "_" +
                 std::to_string(base);
    const float half = 0.5f;
    for (int r = 0; r < rows; ++r) {
        BodyDesc ground;
        ground.kind = BodyKind::Static;
        ShapeDesc segment;
        segment.kind = ShapeKind::Segment;
        const float y = 11.0f * static_cast<float>(r);
        segment.point1 = {-110.0f, y};
        segment.point2 = {110.0f, y};
        ground.shapes.push_back(segment);
        scene.bodies.push_back(ground);
    }
    for (int c = 0; c < columns; ++c) {
        const float left = -110.0f + 11.0f * static_cast<float>(c) + 1.0f - half;
        for (int r = 0; r < rows; ++r) {
            const float bottom = 11.0f * static_cast<float>(r);
            for (int i = 0; i < base; ++i) {
                for (int j = i; j < base; ++j) {
                    const float x =
                        static_cast<float>(i + 1) * half + static_cast<float>(j - i) + left;
                    const float y = static_cast<float>(i) + half + bottom;
                    scene.bodies.push_back(dynamicBox({x, y}, half));
                }
            }
        }
    }
    return scene;
}

SceneDesc verticalStack(int count, float friction) {
    SceneDesc scene;
    scene.name = "stack_" + std::to_string(count);
    scene.bodies.push_back(staticBox({0.0f, -1.0f}, {20.0f, 1.0f}, friction));
    for (int i = 0; i < count; ++i) {
        scene.bodies.push_back(dynamicBox({0.0f, 0.5f + static_cast<float>(i)}, 0.5f, friction));
    }
    scene.bodies.back().tag = "top";
    return scene;
}

SceneDesc fallingCircles(int count) {
    SceneDesc scene;
    scene.name = "falling_circles_" + std::to_string(count);
    // A container 20 m wide: floor and two walls.
    scene.bodies.push_back(staticBox({0.0f, -1.0f}, {11.0f, 1.0f}));
    scene.bodies.push_back(staticBox({-11.0f, 20.0f}, {1.0f, 21.0f}));
    scene.bodies.push_back(staticBox({11.0f, 20.0f}, {1.0f, 21.0f}));
    const int perRow = 32;
    for (int i = 0; i < count; ++i) {
        BodyDesc body;
        body.position = {-9.3f + 0.6f * static_cast<float>(i % perRow),
                         1.0f + 0.6f * static_cast<float>(i / perRow)};
        ShapeDesc circle;
        circle.kind = ShapeKind::Circle;
        circle.radius = 0.25f;
        body.shapes.push_back(circle);
        scene.bodies.push_back(body);
    }
    return scene;
}

} // namespace e2d::scenes
