// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/constants.hpp>
#include <e2d/physics/events.hpp>
#include <e2d/physics/function_ref.hpp>
#include <e2d/physics/geometry.hpp>
#include <e2d/physics/id.hpp>
#include <e2d/physics/joint.hpp>
#include <e2d/physics/manifold.hpp>
#include <e2d/physics/math.hpp>
#include <e2d/physics/query.hpp>
#include <e2d/physics/solver_def.hpp>
#include <e2d/physics/task.hpp>
#include <e2d/physics/types.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

/// The physics world: bodies, the shapes attached to them, the broad phase that pairs them,
/// and the queries (ray casts, overlap tests) over them.
namespace e2d::physics {

/// How a World is set up. World's constructor validates every field.
struct WorldDef {
    /// Acceleration of gravity, m/s^2, finite. Default (0, -10).
    Vec2 gravity{0.0f, -10.0f};
    /// Narrow phase for polygon pairs. Default CollisionAlgorithm::Sat.
    CollisionAlgorithm collisionAlgorithm = CollisionAlgorithm::Sat;
    /// Contact points closer than this are reported before the shapes touch, metres, finite,
    /// in [0, kAabbMargin]. Default kSpeculativeDistance (0.02 m).
    float speculativeDistance = kSpeculativeDistance;
    /// Bodies to reserve room for, >= 0. Default 0 (grow on demand).
    int bodyCapacity = 0;
    /// Joints to reserve room for, >= 0. Default 0 (grow on demand).
    int jointCapacity = 0;
    /// Shapes to reserve room for, >= 0. Default 0 (grow on demand).
    int shapeCapacity = 0;
    /// The tag this world writes into every id it hands out (BodyId::world, ShapeId::world);
    /// an id whose tag is not this world's is rejected like a stale one. 1..65535: used as
    /// given (choose distinct tags to make ids of live worlds never mix up, or the same tag
    /// on every run so id values repeat exactly). Default 0: derived from the address of the
    /// world's internal state, never 0 (no counter or other global state); two live worlds then
    /// share a tag with probability 1/65535, and id values differ from run to run (the
    /// simulation itself does not depend on them).
    std::uint16_t tag = 0;

    // --- dynamics (World::step) ---

    /// Solver mode, sub-steps, contact softness, restitution threshold, speed cap, sleeping,
    /// continuous collision and material mixing. Defaults: see SolverDef.
    SolverDef solver{};

    // --- threads (World::step; see task.hpp) ---

    /// Workers the step splits its parallel work over, in [1, kMaxWorkers]. The results are the
    /// same, bit for bit, for every count: it changes the speed only. With more than one and no
    /// enqueueTask, the world starts workerCount - 1 threads of its own (the thread calling
    /// step() is the first worker) and stops them when it is destroyed. Default 1 (no threads).
    int workerCount = 1;
    /// The least work, in nanoseconds of one worker as estimated from the scene's counts (never
    /// timed, so it changes the speed only), a stage of the step needs before it is split over
    /// the workers: below it, handing work to another thread (and waking it) costs more than it
    /// saves (bench/README.md, "Threads"). >= 0; 0 splits every stage of two items or more.
    /// Default 200 000 (0.2 ms).
    int minSplitWork = 200'000;
    /// The game's job system, instead of the world's own threads: both set or both null.
    /// enqueueTask must give each piece a worker index in [0, workerCount). Default null.
    EnqueueTaskFunction enqueueTask = nullptr;
    FinishTaskFunction finishTask = nullptr;
    /// Passed to enqueueTask and finishTask as their userContext. Default null.
    void* userTaskContext = nullptr;
    /// The widest SIMD the solver uses: 8 lanes (AVX2, on x86-64 CPUs that have it) or 4 (SSE2,
    /// NEON, or plain code). The results are the same either way; 4 measures the narrower path
    /// on a CPU with AVX2. Default 8.
    int simdLanes = 8;
};

/// How a body is created. World::createBody() validates every field.
struct BodyDef {
    /// Static, kinematic or dynamic. Default static.
    BodyType type = BodyType::Static;
    /// World position of the body origin, metres, finite, |x|, |y| <= kHuge. Default (0, 0).
    Vec2 position{0.0f, 0.0f};
    /// Rotation, radians counter-clockwise, finite. Default 0.
    float angle = 0.0f;
    /// Velocity of the centre of mass, m/s, finite. Default (0, 0).
    Vec2 linearVelocity{0.0f, 0.0f};
    /// Angular velocity, radians/s counter-clockwise, finite. Default 0.
    float angularVelocity = 0.0f;
    /// Anything the application wants to find the body's owner by. Default 0.
    std::uint64_t userData = 0;
    /// A disabled body's shapes are not in the broad phase: no pairs, no query hits.
    /// Default true.
    bool enabled = true;

    // --- dynamics (World::step) ---

    /// Linear damping coefficient, 1/s, finite, >= 0. Default 0.
    float linearDamping = 0.0f;
    /// Angular damping coefficient, 1/s, finite, >= 0. Default 0.
    float angularDamping = 0.0f;
    /// Multiplies the world's gravity for this body, finite. Default 1.
    float gravityScale = 1.0f;
    /// The body never rotates (infinite rotational inertia). Default false.
    bool fixedRotation = false;
    /// The centre of mass never moves along world x. Default false.
    bool lockX = false;
    /// The centre of mass never moves along world y. Default false.
    bool lockY = false;
    /// A fast dynamic body: continuous collision every step (not only when it moves far),
    /// against static shapes and also against kinematic and non-bullet dynamic ones.
    /// Default false.
    bool isBullet = false;
    /// Whether the body may sleep. Default true.
    bool enableSleep = true;
    /// Whether the body starts awake. Default true.
    bool isAwake = true;
};

/// How a shape is created. World::createShape() validates every field.
struct ShapeDef {
    /// kg/m^2, finite, >= 0. Default 1. A dynamic body's mass, centre and rotational inertia
    /// come from its shapes' densities and areas. When they give no mass (every shape of
    /// density 0, or only segments, which have no area) the body gets 1 kg at its origin and
    /// no rotational inertia, as in Box2D 2.4: it falls and is pushed but never turns. Give it
    /// a density, a shape with area, or World::setMassData().
    float density = 1.0f;
    /// Coulomb friction coefficient, finite, >= 0. Default 0.6.
    float friction = 0.6f;
    /// Bounciness, finite, in [0, 1] (0 does not bounce, 1 is elastic). Default 0.
    float restitution = 0.0f;
    /// Rolling resistance (torque per normal force), metres, finite, >= 0. Default 0.
    float rollingResistance = 0.0f;
    /// What the shape is and what it may touch. Default: category bit 0, touches everything.
    Filter filter{};
    /// A sensor detects overlap but is not solid. Sensors pair only with non-sensor shapes and
    /// are skipped by queries unless QueryFilter::includeSensors. Default false.
    ///
    /// Which pairs a sensor sees follows the broad phase's rule (World::updatePairs()): one of
    /// the two bodies must be dynamic. So a sensor on a static or kinematic body (a trigger
    /// zone, a moving detector) sees dynamic bodies only, and a sensor on a dynamic body sees
    /// static, kinematic and dynamic shapes alike. `sensorSeesNonDynamic` widens that.
    bool isSensor = false;
    /// Sensors only: a sensor on a static or kinematic body also sees the shapes of kinematic
    /// bodies, and one on a kinematic body also those of static bodies (a trigger zone that
    /// must notice a kinematic platform or character, a kinematic detector sweeping over
    /// static scenery). Two static bodies never pair. Such a sensor costs a little more in the
    /// broad phase (it is looked up by every moving kinematic shape). Fixed at creation
    /// (World::setShapeSensor() keeps it). Default false.
    bool sensorSeesNonDynamic = false;
    /// Anything the application wants to find the shape's owner by. Default 0.
    std::uint64_t userData = 0;
    /// Whether the shape's contacts report ContactBeginTouchEvent and ContactEndTouchEvent. A
    /// pair reports them only when both shapes have this on. Default true.
    bool enableContactEvents = true;
    /// Whether the shape's sensor overlaps report SensorBeginTouchEvent and SensorEndTouchEvent
    /// (as the sensor or as the visitor). A pair reports them only when both shapes have this
    /// on. Default true.
    bool enableSensorEvents = true;
    /// Whether the shape's contacts report ContactHitEvent. A pair reports hits only when both
    /// shapes have this on. Default true.
    bool enableHitEvents = true;
};

/// Friction, restitution and rolling resistance of one chain segment (ChainDef::materials).
struct SurfaceMaterial {
    /// Coulomb friction coefficient, finite, >= 0. Default 0.6.
    float friction = 0.6f;
    /// Bounciness, finite, in [0, 1]. Default 0.
    float restitution = 0.0f;
    /// Rolling resistance, metres, finite, >= 0. Default 0.
    float rollingResistance = 0.0f;
    /// The segment's ShapeDef::userData. Default 0.
    std::uint64_t userData = 0;
};

/// A chain of one-sided segments through `points` (World::createChain()): smooth terrain that
/// shapes slide over without catching on the joints. Each segment is hit from its right-hand
/// side walking from one point to the next (see ChainSegment): list a floor's points from right
/// to left, and a loop counter-clockwise to make it solid inside.
struct ChainDef {
    /// Chain points in the body's frame, metres, finite, within kHuge; at least 2 (3 for a
    /// loop); consecutive points (and for a loop the last and the first) at least kLinearSlop
    /// apart. No default.
    std::vector<Vec2> points{};
    /// Joins the last point back to the first: every segment then has neighbours on both
    /// sides. Default false.
    bool isLoop = false;
    /// Open chains only: the point before points[0] and the point after the last one (ghost
    /// points: never collided, they only smooth the end segments' joints with whatever the
    /// chain continues into). Without one, that end is free and round like a Segment's.
    /// Default none.
    std::optional<Vec2> ghostBefore{};
    std::optional<Vec2> ghostAfter{};
    /// Per-segment materials: empty (every segment takes `shape`'s), one (every segment takes
    /// it) or one per segment (points.size() - 1, or points.size() for a loop). Default empty.
    std::vector<SurfaceMaterial> materials{};
    /// What every segment shape is made with: filter, events, friction, restitution and
    /// userData unless `materials` says otherwise. density is ignored (segments have no mass).
    /// Default ShapeDef{}.
    ShapeDef shape{};
};

/// A body moved by the last step: its transform after the step (World::bodyMoveEvents()).
struct BodyMoveEvent {
    BodyId body;
    Transform transform{};
    /// The body fell asleep at the end of this step (it sends no more move events until
    /// something wakes it).
    bool fellAsleep = false;
};

/// An explosion (World::explode()): an impulse pushing every dynamic body whose shapes come
/// within `radius + falloff` of `position`, nothing in between blocking it.
struct ExplosionDef {
    /// Centre, metres, finite, within kHuge. Default (0, 0).
    Vec2 position{0.0f, 0.0f};
    /// Full strength out to this distance, metres, finite, >= 0. Default 1.
    float radius = 1.0f;
    /// Beyond `radius` the strength falls linearly to zero over this distance, metres,
    /// finite, >= 0. Default 1.
    float falloff = 1.0f;
    /// Impulse per metre of the shape's outline facing the explosion at full strength,
    /// N*s/m, finite. Default 1. (A shape's impulse is impulsePerLength times the width it
    /// presents to the centre times the strength at its closest point, pushing along the line
    /// from the centre to that point, applied at its closest point.)
    float impulsePerLength = 1.0f;
    /// Which shapes it reaches (QueryFilter rules; sensors never). Default everything.
    std::uint64_t maskBits = ~std::uint64_t{0};
};

/// Called during World::step() for each touching solid contact after the narrow phase
/// computed its manifold (see World::setPreSolveCallback()). Returns false to leave the contact
/// out of this step's solver.
using PreSolveCallback =
    std::function<bool(ShapeId shapeA, ShapeId shapeB, const Manifold& manifold)>;
/// Called when two shapes could start a pair (see World::setPairFilterCallback()). Returns
/// false to keep them apart.
using PairFilterCallback = std::function<bool(ShapeId shapeA, ShapeId shapeB)>;

/// The format version World::saveSnapshot() writes and World::restoreSnapshot() reads; a
/// snapshot of another version is refused. Raised whenever the bytes of a World's state change
/// meaning.
inline constexpr std::uint32_t kSnapshotFormatVersion = 2;
/// The size of a snapshot's header, bytes (its layout: World::saveSnapshot()); the payload
/// follows it.
inline constexpr std::size_t kSnapshotHeaderBytes = 32;

class Body;
class Joint;
class Shape;

/// A physics world. Owns its bodies, shapes and joints, hands out BodyId, ShapeId and JointId
/// handles, and checks every handle on use: a stale or null handle throws core::Error
/// (isValid() tells beforehand), and so does a handle from another world (each id carries its world's tag, see
/// WorldDef::tag). Functions that throw leave the world unchanged. Worlds are independent: any
/// number may live in one process, each used from one thread at a time.
///
/// Callbacks run while the world walks its shapes, pairs or contacts: those of the queries
/// (overlapAabb(), forEachCandidatePair(), forEachTouchingContact()) and the hooks called inside
/// step() and updatePairs() (the pre-solve and pair filter callbacks). Inside them, reading
/// anything, queries, velocities, forces, impulses, explode(), sleep, materials, event switches
/// and user data are allowed; createBody(), destroyBody(), createShape(), createChain(),
/// destroyShape(), createJoint(), destroyJoint(), setTransform(), setBodyEnabled(),
/// setBodyType(), setMassData(), setShapeFilter(), setShapeSensor(), setShapeDensity(),
/// setShapeGeometry(),
/// setPreSolveCallback(), setPairFilterCallback(), updatePairs() and step() throw core::Error
/// naming themselves and the running callback (collect the ids, act after it returns). The
/// event arrays are read after step() returns: anything but step() may be called while going
/// through them (events of what is destroyed then are reported by the next step()).
///
/// Finding your way: every function takes the id of what it acts on, grouped below as world
/// settings, bodies, shapes, chains, joints, pairs, queries, dynamics, hooks and events. The same
/// functions are reachable through small handle views that hold the world and an id and cost
/// nothing (see views.hpp): `Body b = world.body(id); b.position(); b.applyLinearImpulse(...);
/// b.shapes();`, `Shape s = world.shape(id); s.setFriction(0.2f);` and `Joint j =
/// world.joint(id); j.setMotorSpeed(2.0f);`. A view checks its id on
/// every call like the world does; it never outlives the world it came from.
class World {
public:
    /// Throws core::Error naming the first invalid field of `def`.
    explicit World(const WorldDef& def = {});
    ~World();
    World(World&&) noexcept;
    /// The moved-from world may only be destroyed or assigned to.
    World& operator=(World&&) noexcept;
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    // --- world settings ---

    [[nodiscard]] Vec2 gravity() const;
    /// m/s^2, finite.
    void setGravity(Vec2 gravity);
    [[nodiscard]] CollisionAlgorithm collisionAlgorithm() const;
    [[nodiscard]] float speculativeDistance() const;
    /// The tag in every id this world hands out (WorldDef::tag, or the one derived), never 0.
    [[nodiscard]] std::uint16_t tag() const;

    // --- bodies ---

    /// A new body. Throws core::Error naming the invalid field of `def`.
    BodyId createBody(const BodyDef& def);
    /// Destroys the body and all its shapes (their pairs go with them).
    void destroyBody(BodyId id);
    /// Whether `id` names a live body of this world.
    [[nodiscard]] bool isValid(BodyId id) const;

    [[nodiscard]] BodyType bodyType(BodyId id) const;
    /// The body's transform: origin position (metres) and rotation.
    [[nodiscard]] Transform transform(BodyId id) const;
    /// Teleports the body: position (metres, finite, within kHuge) and angle (radians, finite).
    /// Its shapes' broad-phase boxes follow (pairs update at the next updatePairs()).
    void setTransform(BodyId id, Vec2 position, float angle);
    /// Velocity of the centre of mass, m/s.
    [[nodiscard]] Vec2 linearVelocity(BodyId id) const;
    /// m/s, finite. Wakes the body when non-zero.
    void setLinearVelocity(BodyId id, Vec2 velocity);
    [[nodiscard]] float angularVelocity(BodyId id) const;
    /// radians/s, finite.
    void setAngularVelocity(BodyId id, float velocity);
    /// Sets the velocities that carry the body's origin to `position` (metres, finite, within
    /// kHuge) and its rotation to `angle` (radians, finite; the short way round) in `timeStep`
    /// seconds (finite, > 0): how a kinematic body follows a path (a moving platform, a door)
    /// while pushing and carrying what touches it, which setTransform() (a teleport) does not.
    /// Call it before each step with that step's time. Kinematic and dynamic bodies; throws
    /// core::Error for a static one.
    void setTargetTransform(BodyId id, Vec2 position, float angle, float timeStep);
    [[nodiscard]] std::uint64_t bodyUserData(BodyId id) const;
    void setBodyUserData(BodyId id, std::uint64_t userData);
    [[nodiscard]] bool isBodyEnabled(BodyId id) const;
    /// Disabling removes the body's shapes from the broad phase (their pairs end, queries skip
    /// them); enabling puts them back.
    void setBodyEnabled(BodyId id, bool enabled);
    /// The body's shapes, most recently created first.
    [[nodiscard]] std::vector<ShapeId> bodyShapes(BodyId id) const;

    // --- shapes ---

    /// Attaches a shape to a body; `geometry` is in the body's local frame. Throws core::Error
    /// naming the invalid field of `def` or of `geometry` (see physics::validate()).
    ShapeId createShape(BodyId body, const ShapeDef& def, const ShapeGeometry& geometry);
    /// Detaches and destroys the shape (its pairs go with it).
    void destroyShape(ShapeId id);
    /// Whether `id` names a live shape of this world.
    [[nodiscard]] bool isValid(ShapeId id) const;

    [[nodiscard]] BodyId shapeBody(ShapeId id) const;
    [[nodiscard]] ShapeType shapeType(ShapeId id) const;
    /// The geometry in the body's local frame, as given to createShape().
    [[nodiscard]] const ShapeGeometry& shapeGeometry(ShapeId id) const;
    /// The tight world box of the shape at its body's current transform.
    [[nodiscard]] Aabb shapeAabb(ShapeId id) const;
    /// The enlarged box the broad phase keeps for the shape (contains shapeAabb(); pairs are
    /// found by overlap of these). The tight box while the body is disabled. For debug drawing
    /// and tests.
    [[nodiscard]] Aabb shapeFatAabb(ShapeId id) const;
    [[nodiscard]] Filter shapeFilter(ShapeId id) const;
    /// Changes what the shape touches. Its pairs are found again at the next updatePairs()
    /// (pairs the new filter rejects end, new ones may begin).
    void setShapeFilter(ShapeId id, const Filter& filter);
    [[nodiscard]] bool isSensor(ShapeId id) const;
    [[nodiscard]] float shapeDensity(ShapeId id) const;
    [[nodiscard]] float shapeFriction(ShapeId id) const;
    [[nodiscard]] float shapeRestitution(ShapeId id) const;
    [[nodiscard]] float shapeRollingResistance(ShapeId id) const;
    [[nodiscard]] std::uint64_t shapeUserData(ShapeId id) const;
    void setShapeUserData(ShapeId id, std::uint64_t userData);

    // --- chains ---

    /// Attaches a chain of ChainSegment shapes to a body, one per pair of consecutive points
    /// (ChainDef). Returns the segments' ids in chain order; each is an ordinary shape
    /// (destroyShape(), setShapeFriction(), queries...). Throws core::Error naming the invalid
    /// field of `def` before creating anything.
    std::vector<ShapeId> createChain(BodyId body, const ChainDef& def);

    // --- joints (joint.hpp; joint.cpp) ---

    /// A new joint between the def's two bodies (live, different, at least one dynamic), which
    /// are woken. Unless def.collideConnected, their shapes stop colliding with each other (a
    /// contact between them ends now). Throws core::Error naming the invalid field of `def`.
    JointId createJoint(const JointDef& def);
    /// Destroys the joint and wakes its bodies. destroyBody() destroys the body's joints.
    void destroyJoint(JointId id);
    /// Whether `id` names a live joint of this world.
    [[nodiscard]] bool isValid(JointId id) const;
    [[nodiscard]] JointType jointType(JointId id) const;
    [[nodiscard]] BodyId jointBodyA(JointId id) const;
    [[nodiscard]] BodyId jointBodyB(JointId id) const;
    /// The body's joints, most recently created first.
    [[nodiscard]] std::vector<JointId> bodyJoints(BodyId id) const;
    [[nodiscard]] std::uint64_t jointUserData(JointId id) const;
    void setJointUserData(JointId id, std::uint64_t userData);
    /// The joint's anchors in world coordinates, metres (a mouse joint's A anchor is its
    /// target; a motor joint's is where it drives B's origin, its B anchor B's origin).
    [[nodiscard]] Vec2 jointAnchorA(JointId id) const;
    [[nodiscard]] Vec2 jointAnchorB(JointId id) const;
    /// The force the joint applied to body B during the last step, newtons, world axes (body A
    /// got the opposite), averaged over the step's last sub-step; zero before the first step
    /// and while a body is disabled; while the bodies sleep, the one they fell asleep with. A
    /// game breaks a joint when this exceeds a threshold.
    [[nodiscard]] Vec2 jointReactionForce(JointId id) const;
    /// The torque the joint applied to body B about its anchor during the last step, N*m.
    [[nodiscard]] float jointReactionTorque(JointId id) const;
    /// Revolute: the joint angle (radians, B relative to A minus the reference angle, counted
    /// through whole turns). Prismatic and wheel: the translation of B's anchor along the axis
    /// from A's anchor, metres. Distance: the current length, metres. Throws for other types.
    [[nodiscard]] float jointValue(JointId id) const;
    /// Turns the motor of a distance, prismatic, revolute or wheel joint on or off. Throws for
    /// other types. Wakes the bodies.
    void enableJointMotor(JointId id, bool enable);
    /// Motor speed (m/s or rad/s, finite) of a distance, prismatic, revolute or wheel joint.
    void setJointMotorSpeed(JointId id, float speed);
    /// Largest motor force (N) or torque (N*m), finite, >= 0, of a distance, prismatic,
    /// revolute or wheel joint; the largest force of a mouse or motor joint.
    void setJointMaxMotorForce(JointId id, float force);
    /// Turns the limits of a distance, prismatic, revolute or wheel joint on or off.
    void enableJointLimit(JointId id, bool enable);
    /// Limits (finite, lower <= upper): lengths of a distance joint (lower >= 0), translations
    /// of a prismatic or wheel joint, angles of a revolute joint.
    void setJointLimits(JointId id, float lower, float upper);
    /// Spring of a distance, prismatic, revolute or wheel joint (enabled when hertz > 0) or
    /// the stiffness of a mouse joint (hertz > 0) or of both parts of a weld joint: hertz and
    /// damping ratio finite, >= 0.
    void setJointSpring(JointId id, float hertz, float dampingRatio);
    /// A mouse joint's target, world metres, finite. Wakes body B.
    void setMouseJointTarget(JointId id, Vec2 target);
    /// A motor joint's target pose of B in A's frame (metres, radians, finite). Wakes the
    /// bodies.
    void setMotorJointOffsets(JointId id, Vec2 linearOffset, float angularOffset);
    [[nodiscard]] int jointCount() const;
    /// Every live joint's debug picture (JointDebugData), in slot order.
    [[nodiscard]] std::vector<JointDebugData> jointDebugData() const;

    // --- counts ---

    [[nodiscard]] int bodyCount() const;
    [[nodiscard]] int shapeCount() const;

    // --- candidate pairs (the broad phase; the solver will turn them into contacts) ---

    /// Brings the candidate pairs up to date: looks for new pairs around the shapes whose boxes
    /// moved since the last call (not around the others), then drops pairs whose fattened
    /// boxes no longer overlap. Two shapes pair when their fat boxes overlap, they belong to
    /// different bodies, at least one body is dynamic (static and kinematic bodies do not
    /// respond to contacts, so static-static, static-kinematic and kinematic-kinematic pairs are
    /// never looked for, sensors included), shouldCollide() accepts their filters and not both
    /// are sensors (a sensor pairs only with non-sensor shapes).
    void updatePairs();
    /// Number of current candidate pairs.
    [[nodiscard]] int candidatePairCount() const;
    /// Calls `callback(a, b)` once per current pair, a's slot before b's, in the broad phase's
    /// table order: not sorted, but the same operations give the same order (determinism).
    /// The world is locked during the callback (see World).
    void forEachCandidatePair(FunctionRef<void(ShapeId, ShapeId)> callback) const;

    // --- queries (world space; they read the broad phase, so updatePairs() is not needed) ---

    /// The first shape the ray from `origin` to `origin + translation` hits (metres; the
    /// translation is finite and non-zero, both ends within kHuge).
    [[nodiscard]] std::optional<RayResult> castRayClosest(Vec2 origin, Vec2 translation,
                                                          const QueryFilter& filter = {}) const;
    /// Every hit along the ray, sorted by fraction (ties by shape slot).
    [[nodiscard]] std::vector<RayResult> castRayAll(Vec2 origin, Vec2 translation,
                                                    const QueryFilter& filter = {}) const;
    /// The ray against one shape, ignoring filters and sensor status. With back faces
    /// (ignoreBackFaces false) the closer of entry and exit is returned.
    [[nodiscard]] std::optional<RayResult> rayCastShape(ShapeId id, Vec2 origin, Vec2 translation,
                                                        bool ignoreBackFaces = true) const;
    /// Calls `callback(shape)` for each shape whose tight world box overlaps `box`; the callback
    /// returns false to stop. `box` must be finite with lower <= upper. The world is locked
    /// during the callback (no creating, destroying or moving; see World): to destroy what it
    /// finds, collect the ids (or use the overload returning them) and destroy them after.
    void overlapAabb(const Aabb& box, const QueryFilter& filter,
                     FunctionRef<bool(ShapeId)> callback) const;
    /// The shapes whose tight world box overlaps `box`, in slot order.
    [[nodiscard]] std::vector<ShapeId> overlapAabb(const Aabb& box,
                                                   const QueryFilter& filter = {}) const;
    /// The shapes containing `point` (metres, finite; see physics::testPoint), in slot order.
    [[nodiscard]] std::vector<ShapeId> overlapPoint(Vec2 point,
                                                    const QueryFilter& filter = {}) const;

    /// The first shape that `geometry`, placed at `transform` (local to world, like a body's)
    /// and moved by `translation` (metres, finite, non-zero), would touch. `point` is on the
    /// surface of the shape hit, `normal` points out of it towards the moving shape and
    /// `fraction` is how far along `translation` they meet. A shape the geometry already
    /// overlaps at the start is hit at fraction 0 with a zero normal. Back faces play no part:
    /// a chain segment is seen only from its front (the moving shape's box centre in front of
    /// it, moving against its normal).
    /// Throws core::Error for an invalid geometry or non-finite input.
    [[nodiscard]] std::optional<RayResult> castShape(const ShapeGeometry& geometry,
                                                     const Transform& transform, Vec2 translation,
                                                     const QueryFilter& filter = {}) const;

    // --- dynamics ---

    /// Advances the world by `timeStep` seconds (finite, in [0, kMaxTimeStep (0.25 s)]; 0
    /// updates contacts and events only): pairs, contacts, narrow phase, solver, continuous collision, sleeping, events.
    /// Call it at a fixed rate (e.g. 1/60 s) for stable results.
    void step(float timeStep);
    [[nodiscard]] const SolverDef& solverDef() const;

    /// Mass (kg), local centre of mass (metres) and rotational inertia about it (kg*m^2).
    [[nodiscard]] MassData massData(BodyId id) const;
    /// Overrides the mass the shapes give (dynamic bodies only; mass finite > 0, inertia
    /// finite >= 0, centre finite). Adding or removing a shape recomputes it from densities.
    void setMassData(BodyId id, const MassData& massData);
    /// The centre of mass in world coordinates, metres.
    [[nodiscard]] Vec2 worldCenterOfMass(BodyId id) const;

    [[nodiscard]] float linearDamping(BodyId id) const;
    /// 1/s, finite, >= 0.
    void setLinearDamping(BodyId id, float damping);
    [[nodiscard]] float angularDamping(BodyId id) const;
    /// 1/s, finite, >= 0.
    void setAngularDamping(BodyId id, float damping);
    [[nodiscard]] float gravityScale(BodyId id) const;
    /// Finite.
    void setGravityScale(BodyId id, float scale);
    [[nodiscard]] bool isFixedRotation(BodyId id) const;
    void setFixedRotation(BodyId id, bool fixed);
    /// Per-axis position locks of the centre of mass (world x and y).
    void setPositionLocks(BodyId id, bool lockX, bool lockY);
    [[nodiscard]] bool isLockedX(BodyId id) const;
    [[nodiscard]] bool isLockedY(BodyId id) const;
    [[nodiscard]] bool isBullet(BodyId id) const;
    void setBullet(BodyId id, bool bullet);

    /// Force (newtons, finite) at a world point (metres, finite), applied during the next step
    /// (forces are cleared after each step). Wakes the body if `wake`. Ignored by non-dynamic
    /// bodies and by sleeping ones not woken.
    void applyForce(BodyId id, Vec2 force, Vec2 point, bool wake = true);
    /// Force at the centre of mass, newtons, finite.
    void applyForceToCenter(BodyId id, Vec2 force, bool wake = true);
    /// Torque, N*m, finite.
    void applyTorque(BodyId id, float torque, bool wake = true);
    /// Impulse (N*s, finite) at a world point: changes the velocity at once.
    void applyLinearImpulse(BodyId id, Vec2 impulse, Vec2 point, bool wake = true);
    /// Impulse at the centre of mass, N*s, finite.
    void applyLinearImpulseToCenter(BodyId id, Vec2 impulse, bool wake = true);
    /// Angular impulse, N*m*s, finite.
    void applyAngularImpulse(BodyId id, float impulse, bool wake = true);

    /// Whether the body is awake. Static bodies are never awake.
    [[nodiscard]] bool isAwake(BodyId id) const;
    /// Wakes the body (and everything it touches), or puts its island to sleep.
    void setAwake(BodyId id, bool awake);
    [[nodiscard]] bool isSleepEnabled(BodyId id) const;
    /// A body that may not sleep keeps its island awake.
    void setSleepEnabled(BodyId id, bool enabled);
    /// Number of awake dynamic and kinematic bodies.
    [[nodiscard]] int awakeBodyCount() const;

    /// Events of the last step (ContactBeginTouchEvent and the others), valid until the next
    /// step.
    [[nodiscard]] std::span<const ContactBeginTouchEvent> contactBeginEvents() const;
    [[nodiscard]] std::span<const ContactEndTouchEvent> contactEndEvents() const;
    [[nodiscard]] std::span<const SensorBeginTouchEvent> sensorBeginEvents() const;
    [[nodiscard]] std::span<const SensorEndTouchEvent> sensorEndEvents() const;
    [[nodiscard]] std::span<const ContactHitEvent> hitEvents() const;
    /// Bodies the last step disabled because their state became non-finite (NaN or infinite
    /// position or velocity); the rest of the world went on.
    [[nodiscard]] std::span<const BodyId> nonFiniteBodies() const;
    /// Bodies the last step disabled because their origin left the coordinate range (|x| or
    /// |y| beyond kHuge); each keeps its last transform inside the range and its velocity is
    /// zeroed, so it can be moved back (setTransform()) and enabled again.
    [[nodiscard]] std::span<const BodyId> outOfRangeBodies() const;

    /// Bodies the last step moved: every awake dynamic and kinematic body the solver
    /// integrated, with its transform after the step, in a fixed order. For syncing game
    /// objects (or render transforms) with only the bodies that moved.
    [[nodiscard]] std::span<const BodyMoveEvent> bodyMoveEvents() const;

    /// What the last step computed (see StepCounters).
    [[nodiscard]] StepCounters stepCounters() const;

    /// Number of contacts (pairs of shapes whose fat boxes overlap), touching or not.
    [[nodiscard]] int contactCount() const;
    /// Calls `callback` for each touching solid contact (manifold with points), in a fixed
    /// order. The world is locked during the callback (see World).
    void forEachTouchingContact(FunctionRef<void(const ContactData&)> callback) const;

    // --- hooks ---
    //
    // Both callbacks run inside step() (the pair filter also inside updatePairs()), on the
    // thread that called it: e2d steps on one thread, so they are never called concurrently.
    // The world is locked while they run (see World): reading, queries, velocities, impulses,
    // sleep, materials and user data are allowed; creating, destroying, moving, re-filtering,
    // changing a body's type or a shape's geometry or sensor flag, replacing a callback and
    // stepping throw core::Error naming the call and the callback. An exception thrown by a
    // callback leaves step() at that point (the world stays valid; the step is partial).

    /// Called in step() after the narrow phase computed a contact's manifold and before the
    /// solver, once per step for each touching solid contact with an awake body (shapes in the
    /// pair's order; the manifold's normal points from shapeA to shapeB). Returning false
    /// leaves the contact out of this step's solver (a one-way platform: return false while
    /// the body comes from below); its begin/end touch events are reported all the same, and
    /// a contact between sleeping bodies keeps the last answer. Continuous collision does not
    /// ask it (a chain segment is one-sided for that too). An empty function removes it.
    void setPreSolveCallback(PreSolveCallback callback);
    /// Called when two shapes whose boxes begin to overlap pass the built-in rules (different
    /// bodies, one dynamic, filters, not both sensors: updatePairs()); returning false keeps
    /// them from pairing (no contact, no events) until their boxes part and meet again.
    /// Continuous collision asks it too. An empty function removes it.
    void setPairFilterCallback(PairFilterCallback callback);

    // --- more queries ---

    /// The shapes that `geometry` (a circle, capsule or polygon) placed at `transform` overlaps
    /// (touching counts; distance <= 0), in slot order. Throws core::Error for a segment or
    /// chain segment, an invalid geometry or a non-finite transform.
    [[nodiscard]] std::vector<ShapeId> overlapShape(const ShapeGeometry& geometry,
                                                    const Transform& transform,
                                                    const QueryFilter& filter = {}) const;
    /// Pushes dynamic bodies away from a point (see ExplosionDef), waking them. Returns how
    /// many shapes it pushed. Throws core::Error naming the invalid field.
    int explode(const ExplosionDef& def);

    // --- points and setters ---

    /// A point in the body's frame (metres) in world coordinates.
    [[nodiscard]] Vec2 worldPoint(BodyId id, Vec2 localPoint) const;
    /// A world point (metres) in the body's frame.
    [[nodiscard]] Vec2 localPoint(BodyId id, Vec2 worldPoint) const;
    /// A direction in the body's frame rotated to world axes.
    [[nodiscard]] Vec2 worldVector(BodyId id, Vec2 localVector) const;
    /// A world direction in the body's frame.
    [[nodiscard]] Vec2 localVector(BodyId id, Vec2 worldVector) const;
    /// Velocity (m/s) of the body's material point at a world point (metres).
    [[nodiscard]] Vec2 linearVelocityAtWorldPoint(BodyId id, Vec2 worldPoint) const;
    /// Velocity (m/s) of the body's material point at a point in its frame (metres).
    [[nodiscard]] Vec2 linearVelocityAtLocalPoint(BodyId id, Vec2 localPoint) const;

    /// Changes the body's type. Its mass is recomputed (static and kinematic bodies have
    /// none), its contacts end (pairs are found again under the new type's rules at the next
    /// step) and it wakes unless it became static; a static body stops.
    void setBodyType(BodyId id, BodyType type);
    /// Finite, >= 0. Contacts take it from the next step.
    void setShapeFriction(ShapeId id, float friction);
    /// Finite, in [0, 1]. Contacts take it from the next step.
    void setShapeRestitution(ShapeId id, float restitution);
    /// Finite, >= 0. Contacts take it from the next step.
    void setShapeRollingResistance(ShapeId id, float rollingResistance);
    /// kg/m^2, finite, >= 0. The body's mass is recomputed from its shapes' densities.
    void setShapeDensity(ShapeId id, float density);
    /// Makes the shape a sensor or a solid one. Its contacts end (touching ones report end
    /// events) and pairs are found again at the next step.
    void setShapeSensor(ShapeId id, bool isSensor);
    /// Replaces the shape's geometry (same rules as createShape()): its contacts end, its box
    /// moves, the body's mass is recomputed.
    void setShapeGeometry(ShapeId id, const ShapeGeometry& geometry);
    /// Per-shape event switches (see ShapeDef). Contacts take them from the next step.
    void setShapeEventFlags(ShapeId id, bool contactEvents, bool sensorEvents, bool hitEvents);

    // --- snapshots (world_snapshot.cpp) ---
    //
    // For rollback netcode, save games and replaying a bug: saveSnapshot() now, restoreSnapshot()
    // later (into this world or another), and stepping goes on bit for bit as it would have
    // from the moment of the save.

    /// The world's whole simulation state as bytes: settings (gravity, narrow phase, SolverDef),
    /// bodies with their motion and sleep timers, shapes, joints with their accumulated
    /// impulses, contacts with their manifolds and warm-start impulses, the broad phase (trees,
    /// move buffer, pairs), the id pools (free slots, generations) and the tag, and the end
    /// events waiting for the next step. Not state, so not saved: the pre-solve and pair filter
    /// callbacks, the last step's event arrays, move events and counters, and the step's
    /// scratch. userData values are saved as the numbers they are (a pointer kept there means
    /// something only in this process, while its object lives).
    ///
    /// Format: a 32-byte header (magic "E2DSNAP", kSnapshotFormatVersion, a layout word,
    /// payload length, FNV-1a 64 checksum of the payload), then the payload in fixed-width
    /// little-endian values: the same bytes on every machine, and the same bytes for the same
    /// state (save, restore, save again gives the bytes of the first save). Cost: linear in the
    /// world's slots; about 150 bytes per body, 180 per polygon shape, 220 per joint, 120 per
    /// contact. Throws core::Error inside a callback (see World): mid-step is not a state.
    [[nodiscard]] std::vector<std::uint8_t> saveSnapshot() const;
    /// Replaces this world's state with the snapshot's. Afterwards the world steps exactly like
    /// the saved one would have. Ids the saved world had handed out name the same objects
    /// (the tag becomes the saved world's); ids of what it had destroyed stay stale, and ids
    /// handed out after the save are stale too, until replaying the same calls hands them out
    /// again. Keeps this world's pre-solve and pair filter callbacks and how it runs (workers,
    /// task callbacks, SIMD width: WorldDef); the event arrays, move events and counters are
    /// empty until the next step. Throws core::Error naming the offset
    /// and the field for a snapshot of another format version, cut short, damaged (checksum) or
    /// inconsistent (an index out of range, a broken list or tree), and inside a callback;
    /// the world is then unchanged: the snapshot is read into a new state that replaces the
    /// old one only once it is complete and checked.
    void restoreSnapshot(std::span<const std::uint8_t> snapshot);

    // --- handle views (views.hpp) ---

    /// A view of the body: World plus id, forwarding to the functions above.
    [[nodiscard]] Body body(BodyId id);
    /// A view of the shape: World plus id, forwarding to the functions above.
    [[nodiscard]] Shape shape(ShapeId id);
    /// A view of the joint: World plus id, forwarding to the functions above.
    [[nodiscard]] Joint joint(JointId id);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace e2d::physics

#include <e2d/physics/views.hpp>
