// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/scenes/scene.hpp>

#include <glm/vec2.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace e2d::validation {

/// Which engine a run uses and how it is set up. One struct for every engine so a sweep point
/// is a value; each adapter reads the fields that apply to it and the report prints exactly
/// those (see describe()).
struct EngineConfig {
    std::string engine = "box2d";  ///< "box2d" or "e2d"
    std::string solver = "soft";   ///< e2d: "soft" (sub-steps + relax) or "classic"
    std::string collision = "sat"; ///< e2d: "sat" or "gjk" (polygon narrow phase)
    int velocityIterations = 8;    ///< Box2D and e2d classic
    int positionIterations = 3;    ///< Box2D and e2d classic
    int subSteps = 4;              ///< e2d soft
    int relaxIterations = 0;       ///< e2d soft: extra relax iterations per sub-step
    /// e2d soft: the joint model, physics::SolverDef::jointSolver: "direct" (the default),
    /// "gauss-seidel" or "soft" (Box2D v3's)
    std::string jointSolver = "direct";
    float speculativeDistance = 0.02f; ///< e2d, metres
    bool continuous = true;            ///< CCD for fast/bullet bodies
    bool sleeping = true;
    bool warmStarting = true;

    /// The engine and solver mode, e.g. "box2d" or "e2d soft sat": one curve in the plots.
    [[nodiscard]] std::string family() const;
    /// The settings that matter for this engine, e.g. "vel 8, pos 3, ccd on, sleep on".
    [[nodiscard]] std::string describe() const;
    friend bool operator==(const EngineConfig&, const EngineConfig&) = default;
};

/// A scenario's own solver settings for one engine: the fields it sets replace the defaults in
/// the baseline run (the sweep still varies them).
struct SettingsOverride {
    std::optional<int> velocityIterations;
    std::optional<int> positionIterations;
    std::optional<int> subSteps;
    std::optional<int> relaxIterations;
    std::optional<bool> continuous;
    std::optional<bool> sleeping;

    void applyTo(EngineConfig& config) const;
};

/// What a check compares. Each kind documents its fields in validation/README.md.
enum class CheckKind {
    Standing,         ///< tagged body ends within `tolerance` of its start x and above minY
    MaxPenetration,   ///< deepest contact over the run <= limit
    MaxSpeed,         ///< fastest body (or the tagged body, if `body` is given) over the
                      ///< run <= limit (explosion detector; a bound on one body's speed)
    BounceHeight,     ///< first apex after the first bounce vs e^2 h
    SlideDistance,    ///< distance along the slope at time t vs 1/2 g (sin - mu cos) t^2
    StoppingDistance, ///< distance slid until rest vs v^2 / (2 mu g)
    RollingDistance,  ///< disc rolling down a slope vs 1/2 (2/3) g sin t^2
    Momentum,         ///< |P_end - P_start| <= tolerance * max(|P_start|, 1)
    KineticEnergy,    ///< KE_end / KE_start vs an expected ratio
    Velocity,         ///< tagged body's final velocity vs an expected vector
    Bounds,           ///< tagged body stays inside an axis-aligned box for the whole run
    Sleep,            ///< every dynamic body asleep by time `time`
    Turn,             ///< tagged body's rotation from its start: at least minTurn at the end,
                      ///< at most maxTurn at every instant (a domino falls, a box stays level)
    Moves,            ///< tagged body ends at least `distance` from its start, along
                      ///< `direction` if given (a body must fall, a pushed box must move)
    JointError,       ///< largest joint error over the run (Recording::jointError) <= limit
    Period,           ///< tagged body's mean period of oscillation in x vs `period`
};

struct Check {
    CheckKind kind = CheckKind::Standing;
    std::string body;             ///< tag of the body the check looks at, if any
    float tolerance = 0.0f;       ///< absolute, in the unit of the quantity
    float limit = 0.0f;           ///< MaxPenetration, MaxSpeed
    float minY = 0.0f;            ///< Standing
    float height = 0.0f;          ///< BounceHeight: drop height of the centre above rest, m
    float restY = 0.0f;           ///< BounceHeight: centre height when resting on the floor
    float restitution = 0.0f;     ///< BounceHeight
    float slopeAngle = 0.0f;      ///< SlideDistance, RollingDistance: radians
    float friction = 0.0f;        ///< SlideDistance, StoppingDistance
    float time = 0.0f;            ///< SlideDistance, RollingDistance, Sleep: seconds
    float speed = 0.0f;           ///< StoppingDistance: initial speed, m/s
    float ratio = 1.0f;           ///< KineticEnergy: expected KE_end / KE_start
    glm::vec2 velocity{0.0f};     ///< Velocity
    glm::vec2 lower{0.0f};        ///< Bounds
    glm::vec2 upper{0.0f};        ///< Bounds
    std::optional<float> minTurn; ///< Turn: radians, |rotation| at the end at least this
    std::optional<float> maxTurn; ///< Turn: radians, |rotation| never above this
    float distance = 0.0f;        ///< Moves: metres
    glm::vec2 direction{0.0f};    ///< Moves: unit vector, or zero for any direction
    float period = 0.0f;          ///< Period: seconds
};

/// One scene, what it measures and how it is judged.
struct Scenario {
    std::string name;
    std::string family; ///< stacking, friction, restitution, conservation, joints, hard
    std::string description;
    std::string measures;  ///< the quantity that matters, in words
    std::string file;      ///< where it was read from
    float duration = 5.0f; ///< seconds simulated
    float settle = 1.0f;   ///< seconds before ms/step is timed
    bool quick = false;    ///< part of --quick
    bool sweep = true;     ///< part of the --all sweep
    bool hardCase = false; ///< listed in the hard-case table at the top of the summary
    std::string scaling;   ///< series name in the scaling plot, empty: not plotted
    std::map<std::string, SettingsOverride> settings; ///< key: engine ("box2d", "e2d")
    scenes::SceneDesc scene;
    std::vector<Check> checks;
};

/// The name of a check kind as written in scenario files, e.g. "bounceHeight".
[[nodiscard]] const char* checkKindName(CheckKind kind);

} // namespace e2d::validation
