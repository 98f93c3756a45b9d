// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/scenes/scene.hpp>

#include <memory>
#include <string>
#include <vector>

class b2World;
class b2Body;
class b2Joint;

namespace e2d::scenes {

/// Box2D 2.4 settings the harness and benchmarks use (Box2D's own defaults).
struct Box2DSettings {
    int velocityIterations = 8;
    int positionIterations = 3;
    bool allowSleeping = true;
    bool continuous = true;
    bool warmStarting = true;
};

/// A Box2D 2.4 world built from a SceneDesc. Translation notes: Box2D gives every polygon a
/// 0.01 m skin (b2_polygonRadius), so boxes placed exactly touching start 0.02 m overlapped and
/// are pushed apart; segments become two-sided b2EdgeShapes; capsules become a box plus two
/// circles on one body (Box2D 2.4 has no capsule); a chain is a b2ChainShape (an open end without
/// a ghost point gets its end segment continued straight on as the ghost), or with a material per
/// segment its one-sided child edges as separate fixtures; wheel and mouse springs take
/// b2LinearStiffness of the same frequency; restitution threshold stays Box2D's 1 m/s.
struct Box2DScene {
    std::unique_ptr<b2World> world;
    std::vector<b2Body*> bodies;  ///< in SceneDesc order
    std::vector<b2Joint*> joints; ///< in SceneDesc::joints order
    Box2DSettings settings;

    Box2DScene();
    Box2DScene(Box2DScene&&) noexcept;
    Box2DScene& operator=(Box2DScene&&) noexcept;
    ~Box2DScene();

    void step(float timeStep);
};

/// Why Box2D 2.4 cannot build `scene` (empty when it can). Box2D checks its input with
/// assertions that abort the process: a polygon whose vertices weld (closer than
/// 0.5 b2_linearSlop = 0.0025 m) to fewer than three, or a dynamic polygon whose area is not above
/// b2_epsilon (b2PolygonShape::Set, ComputeMass), chain points not farther apart than
/// b2_linearSlop (b2ChainShape asserts); and what 2.4.1 lacks: a spring on a revolute or
/// prismatic joint. The reason names the body and shape (`body 3, shape 0: ...`) or the joint.
[[nodiscard]] std::string box2DUnsupported(const SceneDesc& scene);

/// Builds `scene` in a new Box2D world. Throws std::invalid_argument with box2DUnsupported()'s
/// reason instead of building a scene Box2D would abort on.
Box2DScene buildBox2D(const SceneDesc& scene, const Box2DSettings& settings = {});

} // namespace e2d::scenes
