// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

/// How World::step() solves contacts: the solver mode and its tuning. Part of WorldDef.
namespace e2d::physics {

/// Which contact solver World::step() runs.
enum class SolverMode : std::uint8_t {
    /// Sub-stepped soft constraints (default): per sub-step integrate, warm start, solve with a
    /// soft bias, integrate positions, relax without bias sweeping the other way; restitution
    /// after the sub-steps. A 2-point manifold is one two-row soft constraint (no point order).
    SoftStep,
    /// The Box2D 2.4 recipe: velocity iterations with warm starting, restitution bias, then
    /// non-linear Gauss-Seidel position iterations.
    Classic,
};

/// How two shapes' friction or restitution coefficients combine into the contact's.
enum class MixingRule : std::uint8_t {
    GeometricMean, ///< sqrt(a * b)
    Average,       ///< (a + b) / 2
    Min,           ///< min(a, b)
    Max,           ///< max(a, b)
    Multiply,      ///< a * b
};

/// How the soft step solves joints (SolverDef::jointSolver).
enum class JointSolver : std::uint8_t {
    /// Box2D v3's model: the rigid rows are soft constraints of SolverDef::jointHertz, no
    /// position pass. A joint under load stretches like a spring.
    Soft,
    /// Box2D 2.4's model within the sub-steps: rigid rows (a revolute joint's point and limit
    /// as one block, so a limit stops a body dead), then SolverDef::jointPositionIterations
    /// non-linear Gauss-Seidel passes over the position errors at the end of the step. A pass
    /// moves an error about one joint along a chain.
    GaussSeidel,
    /// As GaussSeidel, and every pass also solves all rigid rows and reached limits of each
    /// connected group of joints at once (a sparse LDL^T of the joint graph: linear time for
    /// chains and trees, exact for small closed loops), as do the position passes. A group
    /// with more closed loops than max(8, its joints / 16) (a net, which fills in) is solved
    /// as GaussSeidel. Groups go in the order of their joints' creation slots, so the result
    /// does not depend on which bodies sleep or in what order the world keeps them.
    Direct,
};

/// The largest SolverDef::classicAllowedPenetration, metres: a tenth of the smallest objects
/// e2d is tuned for (see constants.hpp).
inline constexpr float kMaxClassicAllowedPenetration = 0.1f;

/// The largest SolverDef::contactRecycleDistance, metres: the broad phase's margin (kAabbMargin).
inline constexpr float kMaxContactRecycleDistance = 0.1f;

/// The solver's settings. World's constructor validates every field and names the bad one.
struct SolverDef {
    /// Default SolverMode::SoftStep.
    SolverMode mode = SolverMode::SoftStep;
    /// Soft step: sub-steps per step, in [1, 64]. Default 4.
    int subSteps = 4;
    /// Soft step: extra relax iterations per sub-step (after the first), in [0, 64]. Default 0.
    int relaxIterations = 0;
    /// Classic: velocity iterations per step, in [1, 256]. Default 8.
    int velocityIterations = 8;
    /// Classic: position iterations per step, in [0, 256]. Default 3.
    int positionIterations = 3;
    /// Classic: the overlap the position iterations leave between touching shapes, metres,
    /// finite, in [0, kMaxClassicAllowedPenetration]. Default 0.005 (kLinearSlop, Box2D 2.4's).
    /// Shapes overlapping deeper (spawned inside each other, pushed in) are pushed apart until
    /// this much is left; a body landing from above stops at the speculative gap's end and
    /// overlaps less. The iterations of a step stop early once nothing overlaps by more than 3
    /// times this. The soft-step solver does not use it.
    float classicAllowedPenetration = 0.005f;
    /// Classic: the fraction of the overlap beyond classicAllowedPenetration that each
    /// position iteration corrects (Baumgarte factor), finite, in [0, 1]. Default 0.2 (Box2D
    /// 2.4's). Lower corrects overlaps more slowly and more softly; 0 turns contact position
    /// correction off (joints are still corrected). The soft-step solver does not use it.
    float classicPositionBias = 0.2f;
    /// Soft step: stiffness of contacts, hertz, finite, > 0. Capped at a quarter of the
    /// sub-step rate; contacts against static bodies use twice this. Default 38.
    /// A resting contact is a spring: a unit box resting flat on another overlaps its load /
    /// (0.5 (2 pi hertz)^2), 0.5 the pair's reduced mass: 6.7 mm under 19 boxes at 38 Hz (10.7 mm
    /// at Box2D v3's 30 Hz). Stiffer is not free: a column spawned overlapped is pushed apart
    /// faster, and a base-100 pyramid drifts more (0.12 m at 45 Hz).
    float contactHertz = 38.0f;
    /// Soft step: damping ratio of contacts, finite, >= 0 (1 is critical). Default 12.5: with
    /// 38 Hz this pushes overlapping shapes apart at Box2D v3's rate (30 Hz, ratio 10), about
    /// 9 m/s per metre of overlap, which keeps a column spawned 25 % overlapped below 10 m/s.
    float contactDampingRatio = 12.5f;
    /// Soft step with JointSolver::Soft: stiffness of the rigid parts of joints (a revolute
    /// joint's point, a weld, a limit reached, a prismatic or wheel joint's sideways and
    /// angular rows), hertz, finite, > 0. Default 60 (Box2D v3's). The other joint models
    /// keep these rows rigid. Like a contact, such a row is a spring: a joint between
    /// two bodies of reduced mass m under a load F stretches by about F / (m (2 pi hertz)^2)
    /// (a 5 kg ball on 0.05 kg links at 60 Hz: about 4 cm per joint). Stiffer holds heavy
    /// loads on light bodies closer, but needs more sub-steps: at 4 sub-steps, 240 Hz made
    /// the validation's joint scenes worse (a heavy ball on a light chain blew up), at 16 it
    /// held a landing ragdoll's joints within 1.2 cm. Classic mode does not use it.
    float jointHertz = 60.0f;
    /// Soft step with JointSolver::Soft: damping ratio of the rigid parts of joints, finite,
    /// >= 0. Default 2 (Box2D v3's).
    float jointDampingRatio = 2.0f;
    /// Soft step: how joints are solved. Default JointSolver::Direct: rigid joints, limits that
    /// stop a body dead, chains and heavy loads held (validation/README.md, "Joints"). Soft is
    /// Box2D v3's model, cheaper on big joint nets that are allowed to stretch. Contacts are
    /// soft constraints in every joint model. Classic mode does not use it.
    JointSolver jointSolver = JointSolver::Direct;
    /// Soft step, JointSolver GaussSeidel or Direct: position passes over the joints' errors at
    /// the end of each step, in [0, 256]; each connected group of joints stops early once its
    /// errors are within the slops (kLinearSlop, 2 degrees). Each corrects a limit or a rod by at most 0.2 m or 8
    /// degrees (a bounded push-out: a limit violated by 30 degrees is out in 4 passes, with
    /// no speed). Default 4.
    int jointPositionIterations = 4;
    /// Soft step: the fastest overlapping shapes are pushed apart, m/s, finite, > 0. Default 3.
    /// The cap is per contact; in a step where shapes overlap deeper than their load explains
    /// (spawned or moved into each other) their island's solve sweeps more
    /// (StepCounters::relaxIterations), so that the pushes along a column or through a packed
    /// lattice do not add up to more than this: 255 packed discs leave at 0.81 m/s, a 10-box
    /// column spawned half overlapped at 2.8 m/s.
    float contactPushMaxSpeed = 3.0f;
    /// Contacts approaching faster than this bounce (restitution), m/s, finite, >= 0.
    /// Default 1.
    float restitutionThreshold = 1.0f;
    /// Linear speeds are clamped to this, m/s, finite, > 0. Default 400 (4 m/s per metre of
    /// e2d's length unit, times 100: the solver stays stable well past game speeds).
    float maxLinearSpeed = 400.0f;
    /// Contacts whose approach speed is at least this emit a hit event, m/s, finite, >= 0.
    /// Default 1.
    float hitEventThreshold = 1.0f;
    /// A body slower than this (at its centre of mass) may sleep, m/s, finite, >= 0.
    /// Default 0.05.
    float linearSleepTolerance = 0.05f;
    /// A body turning slower than this may sleep, radians/s, finite, >= 0. Default 2 degrees/s
    /// (0.0349).
    float angularSleepTolerance = 0.0349066f;
    /// Seconds a whole island must stay slow before it sleeps, finite, > 0. Default 0.5.
    float timeToSleep = 0.5f;
    /// Whether bodies may sleep at all. Default true.
    bool enableSleep = true;
    /// Whether fast bodies and bullets use time of impact against static shapes. Default true.
    bool enableContinuous = true;
    /// How shape frictions combine. Default MixingRule::GeometricMean.
    MixingRule frictionMixing = MixingRule::GeometricMean;
    /// How shape restitutions combine. Default MixingRule::Max.
    MixingRule restitutionMixing = MixingRule::Max;
    /// Contact recycling, metres, finite, in [0, kMaxContactRecycleDistance]; 0 turns it off.
    /// A solid contact whose two bodies have moved relative to each other by less than this
    /// since its manifold was last computed, counting the motion this step can add at the
    /// bodies' current speeds, keeps that manifold instead of running the collision routine:
    /// its points move with the bodies and their separations follow the motion. Capped at
    /// WorldDef::speculativeDistance: a feature the routine did not report was farther than
    /// that, so it cannot reach the other shape before the routine runs again. The cost is
    /// that, until then, the manifold keeps its points and normal (a box sliding off an edge
    /// keeps its point past the edge for that far) and a contact ends that much later.
    /// Only pairs of polygons and segments are recycled (their routine is the costly one);
    /// sensors, circles, capsules and chain segments are always collided. Soft step only:
    /// SolverMode::Classic collides every contact every step whatever this says, as Box2D 2.4
    /// does (with recycling, its validation scenarios house_of_cards and scissor_lift_3 ended
    /// further from their expected results). Default 0.02
    /// (kSpeculativeDistance): 15 % fewer instructions per step on a pyramid, no validation
    /// scenario lost (bench/README.md, "Contact recycling").
    float contactRecycleDistance = 0.02f;
};

/// Throws core::Error naming the first invalid field, as "physics::World::World(): def.solver.x
/// must be ..., got v".
void validate(const SolverDef& def);

/// Combines two coefficients by `rule`.
float mix(MixingRule rule, float a, float b);

} // namespace e2d::physics
