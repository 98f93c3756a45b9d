// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec2.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

/// Engine-neutral scene descriptions, shared by the benchmarks and the validation harness so a
/// benchmark scene is the same scene the harness checks. Builders turn a SceneDesc into an e2d
/// world or a Box2D 2.4 world; they translate, they do not tune.
namespace e2d::scenes {

enum class BodyKind : std::uint8_t { Static, Kinematic, Dynamic };
enum class ShapeKind : std::uint8_t { Box, Polygon, Circle, Capsule, Segment, Chain };

/// Friction and restitution of one chain segment (ShapeDesc::materials).
struct ChainMaterial {
    float friction = 0.6f;    ///< Coulomb coefficient
    float restitution = 0.0f; ///< 0 inelastic .. 1 elastic
};

struct ShapeDesc {
    ShapeKind kind = ShapeKind::Box;
    glm::vec2 halfExtents{0.5f, 0.5f}; ///< Box: half-width, half-height, metres
    glm::vec2 center{0.0f, 0.0f};      ///< Box/Circle: local centre, metres
    float angle = 0.0f;                ///< Box: local rotation, radians
    std::vector<glm::vec2> points;     ///< Polygon: local points (hull taken); metres
    float radius = 0.0f;               ///< Circle/Capsule radius; Polygon rounding, metres
    glm::vec2 point1{0.0f, 0.0f};      ///< Capsule/Segment: first end, local, metres
    glm::vec2 point2{0.0f, 0.0f};      ///< Capsule/Segment: second end, local, metres
    /// Chain: one-sided segments through `points` (local, metres), hit from the right-hand side
    /// walking from one point to the next; a loop joins the last point to the first. An open
    /// chain may give the point before the first and after the last (ghosts, never collided).
    bool loop = false;
    std::optional<glm::vec2> ghostBefore;
    std::optional<glm::vec2> ghostAfter;
    /// Chain: empty (every segment takes friction and restitution), one, or one per segment.
    std::vector<ChainMaterial> materials;
    float density = 1.0f;     ///< kg/m^2
    float friction = 0.6f;    ///< Coulomb coefficient
    float restitution = 0.0f; ///< 0 inelastic .. 1 elastic
};

struct BodyDesc {
    BodyKind kind = BodyKind::Dynamic;
    glm::vec2 position{0.0f, 0.0f}; ///< metres
    float angle = 0.0f;             ///< radians, counter-clockwise
    glm::vec2 linearVelocity{0.0f, 0.0f};
    float angularVelocity = 0.0f;
    bool bullet = false;
    bool fixedRotation = false;
    float gravityScale = 1.0f;   ///< multiplies the scene's gravity for this body
    glm::vec2 force{0.0f, 0.0f}; ///< N, applied at the centre of mass before every step
    /// Impulses at the centre of mass: each (time in s, impulse in N s) is applied before the
    /// first step that starts at or after its time.
    std::vector<std::pair<float, glm::vec2>> impulses;
    std::vector<ShapeDesc> shapes;
    std::string tag; ///< names bodies the metrics look at, e.g. "top"; several may share one
};

enum class JointKind { Revolute, Distance, Prismatic, Weld, Wheel, Motor, Mouse };

/// A joint between two bodies of the scene, given in world coordinates at creation (as Box2D's
/// Initialize() functions take it); each builder turns the anchors and axis into its bodies'
/// local frames from their starting poses. The reference angle is angle B - angle A at creation.
struct JointDesc {
    JointKind kind = JointKind::Revolute;
    int bodyA = 0; ///< index in SceneDesc::bodies
    int bodyB = 0;
    /// World, m. Revolute, prismatic, weld, wheel: the one anchor; mouse: the point of body B
    /// pulled (its local point at the start).
    glm::vec2 anchorA{0.0f, 0.0f};
    glm::vec2 anchorB{0.0f, 0.0f}; ///< world, m; distance only
    glm::vec2 axis{1.0f, 0.0f};    ///< prismatic, wheel: unit axis, world (fixed in body A)
    bool collideConnected = false;
    /// Revolute: angles (rad); prismatic: translations along the axis (m); distance: the least
    /// and largest length (m, a rope when there is no spring).
    bool enableLimit = false;
    float lower = 0.0f;
    float upper = 0.0f;
    /// Revolute, wheel: rad/s and N m; prismatic: m/s and N.
    bool enableMotor = false;
    float motorSpeed = 0.0f;
    float maxMotor = 0.0f;
    /// A spring of `hertz` and `dampingRatio`: distance (instead of a rigid rod), wheel (the
    /// suspension along the axis), revolute (angular, to the reference angle), prismatic (to
    /// translation 0), mouse (always on: hertz > 0).
    bool enableSpring = false;
    float hertz = 0.0f;
    float dampingRatio = 0.0f;
    float length = 0.0f; ///< distance: rest length, m (the anchors' distance if 0)
    /// Motor joint: body B's origin in A's frame (m) and B's angle minus A's (rad) it drives to.
    glm::vec2 linearOffset{0.0f, 0.0f};
    float angularOffset = 0.0f;
    /// Motor joint: largest force (N) and torque (N m); mouse: largest force (N).
    float maxForce = 0.0f;
    float maxTorque = 0.0f;
    float correctionFactor = 0.3f; ///< motor joint: in [0, 1]
    glm::vec2 target{0.0f, 0.0f};  ///< mouse: the world target, m (fixed for the run)
};

/// The name of a joint kind as in scenario files ("revolute", ...).
const char* jointKindName(JointKind kind);

struct SceneDesc {
    std::string name;
    glm::vec2 gravity{0.0f, -10.0f}; ///< m/s^2
    float timeStep = 1.0f / 60.0f;   ///< seconds
    std::vector<BodyDesc> bodies;
    std::vector<JointDesc> joints;
};

/// A static box: the ground of most scenes.
BodyDesc staticBox(glm::vec2 position, glm::vec2 halfExtents, float friction = 0.6f);
/// A dynamic box of half-size `half`, density 1.
BodyDesc dynamicBox(glm::vec2 position, float half, float friction = 0.6f);

/// Box2D v3's "large pyramid" benchmark layout: a static ground box of half-extents 100 x 1 at
/// (0, -1) and a pyramid of `base` rows of boxes of half-size 0.5, density 1, friction 0.6; row i
/// (0 = bottom) holds base - i boxes at x = (i+1)*0.5 + (j-i) - base/2, y = i + 0.5.
/// The last box created (tag "top") is the apex.
SceneDesc pyramid(int base);

/// Box2D v3's "many pyramids" layout: rows x columns pyramids of `base` rows on two-sided static
/// segments from x = -110 to 110 at y = 0, 11, 22, ...
SceneDesc manyPyramids(int rows = 20, int columns = 20, int base = 10);

/// `count` boxes of half-size 0.5 stacked touching on a ground box; the last one has tag "top".
SceneDesc verticalStack(int count, float friction = 0.6f);

/// `count` circles of radius 0.25 falling into a static box open at the top.
SceneDesc fallingCircles(int count);

} // namespace e2d::scenes
