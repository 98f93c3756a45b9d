// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/world.hpp>
#include <e2d/scenes/scene.hpp>

#include <vector>

namespace e2d::scenes {

/// An e2d world built from a SceneDesc: shapes as the scene gives them (boxes are 4-vertex
/// polygons, capsules and segments native, no skin). `bodies` lists the body ids in SceneDesc
/// order.
struct E2dScene {
    physics::World world;
    std::vector<physics::BodyId> bodies;
    float timeStep = 1.0f / 60.0f;

    void step() { world.step(timeStep); }
};

/// Builds the scene into a world made from `def` (its gravity is replaced by the scene's, and
/// bodyCapacity by the scene's body count).
E2dScene buildE2d(const SceneDesc& scene, physics::WorldDef def = {});

/// The shape a ShapeDesc describes, as e2d geometry.
physics::ShapeGeometry toE2dGeometry(const ShapeDesc& shape);

} // namespace e2d::scenes
