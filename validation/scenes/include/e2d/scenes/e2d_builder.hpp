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
    std::vector<physics::JointId> joints; ///< in SceneDesc::joints order
    float timeStep = 1.0f / 60.0f;

    void step() { world.step(timeStep); }
};

/// Builds the scene into a world made from `def` (its gravity is replaced by the scene's, and
/// bodyCapacity by the scene's body count).
E2dScene buildE2d(const SceneDesc& scene, physics::WorldDef def = {});

/// The joint a JointDesc describes between `world`'s bodies `bodies` (in SceneDesc order, at
/// their starting poses): world anchors and axis become local ones.
physics::JointDef toE2dJoint(const JointDesc& joint, const SceneDesc& scene,
                             const physics::World& world,
                             const std::vector<physics::BodyId>& bodies);

/// The shape a ShapeDesc describes, as e2d geometry. A chain is many shapes: this gives its first
/// segment alone, without neighbours (buildE2d() makes the whole chain with World::createChain()).
physics::ShapeGeometry toE2dGeometry(const ShapeDesc& shape);

} // namespace e2d::scenes
