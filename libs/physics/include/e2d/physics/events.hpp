// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/id.hpp>
#include <e2d/physics/manifold.hpp>
#include <e2d/physics/math.hpp>

/// What happened during World::step(), read after it as arrays. Each array is valid until the
/// next step() (or until a shape or body it names is destroyed: check with World::isValid()).
namespace e2d::physics {

/// Two solid shapes started touching (their manifold gained points). shapeA < shapeB by slot.
struct ContactBeginTouchEvent {
    ShapeId shapeA;
    ShapeId shapeB;
    Manifold manifold; ///< the first manifold; normal from A to B
};

/// Two solid shapes stopped touching, or one was destroyed, disabled or re-filtered while
/// touching (then its id may already be stale).
struct ContactEndTouchEvent {
    ShapeId shapeA;
    ShapeId shapeB;
};

/// A shape entered a sensor.
struct SensorBeginTouchEvent {
    ShapeId sensorShape;
    ShapeId visitorShape;
};

/// A shape left a sensor (or one of them went away).
struct SensorEndTouchEvent {
    ShapeId sensorShape;
    ShapeId visitorShape;
};

/// Two shapes hit each other faster than SolverDef::hitEventThreshold.
struct ContactHitEvent {
    ShapeId shapeA;
    ShapeId shapeB;
    Vec2 point{0.0f, 0.0f};     ///< where the fastest point hit, on shape A's surface, metres
    Vec2 normal{0.0f, 0.0f};    ///< from A to B
    float approachSpeed = 0.0f; ///< normal closing speed at impact, m/s, > threshold
};

/// The work the last World::step() did: what a profiler or a test counts (a sleeping pile
/// should cost almost nothing). All zero before the first step and after step(0) solves
/// nothing.
struct StepCounters {
    /// Awake dynamic and kinematic bodies the solver integrated.
    int solverBodies = 0;
    /// Touching contacts the solver ran (one per shape pair, any point count).
    int contactConstraints = 0;
    /// Contacts whose manifold the narrow phase recomputed (pairs with an awake body).
    int manifoldUpdates = 0;
    /// Of those, the manifolds moved with their bodies instead of collided again
    /// (SolverDef::contactRecycleDistance).
    int manifoldsRecycled = 0;
    /// Shapes whose broad-phase box the step moved (a shape that leaves its fat box, or whose
    /// box grew much larger than it needs, is reinserted into the tree).
    int proxyMoves = 0;
    /// Times the step sorted its joints into levels and packed them for the solver: 0 while
    /// the joints with a moving side, their bodies and their kinds (a plain hinge or not) are
    /// the last step's, whose order the step then keeps.
    int jointRepacks = 0;
    /// Soft step: relax sweeps per sub-step, 1 + SolverDef::relaxIterations, and 24 more (with 5
    /// more biased sweeps) where a contact overlaps deeper than its load explains (shapes
    /// spawned or moved into each other), so that pushing them apart leaves no velocity behind:
    /// the most of any island block this step (those extra sweeps are the contacts': joints
    /// are solved and relaxed 1 + SolverDef::relaxIterations times per sub-step either way).
    /// 0 in classic mode.
    int relaxIterations = 0;
    /// Soft step: contact constraints of the island blocks that all workers solved together,
    /// level by level (a pile holding more than one worker's share of the step's constraints,
    /// at least about a thousand, with no joint and no kinematic body); the others' blocks each
    /// run whole on one worker. 0 with one worker (WorldDef::workerCount).
    int stagedConstraints = 0;
};

/// A touching contact as World::forEachTouchingContact() shows it.
struct ContactData {
    ShapeId shapeA;
    ShapeId shapeB;
    const Manifold* manifold = nullptr; ///< valid during the callback
};

} // namespace e2d::physics
