// SPDX-License-Identifier: MIT
#pragma once

#include "player_controller.hpp"

#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/physics/physics_system.hpp>

#include <glm/vec2.hpp>

#include <vector>

namespace e2d::physics {
class CharacterController;
class Collider;
class PhysicsSystem;
class Rigidbody;
} // namespace e2d::physics

/// The platformer's one level and its rules, as game objects with physics components
/// (Rigidbody, Collider, CharacterController) in a scene with a physics::PhysicsSystem and
/// nothing else (no window, no sound, no input device), so the whole game can be played by a
/// test at the fixed step.
/// World units (reference pixels), seconds, y up; the level is laid out on a grid of kTile
/// units (a tile is a metre to the physics: the game's unitsPerMetre is kTile). The scenes
/// (scenes.cpp) give its objects sprites, play its sounds and feed it input.
///
/// Layout, left to right: the start ground with a coin, a spike pit to jump over, a lift (a
/// kinematic platform going up and down) in front of a cliff too high to jump, a coin in the
/// lift's shaft, the upper ledge with a one-way platform (jump up through it, land on it) and a
/// coin on it, a shuttle sliding left and right above the end of the ledge to a bonus coin, and
/// the goal flag before the end wall.
namespace platformer {

/// An axis-aligned rectangle, world units.
struct Box {
    glm::vec2 center{0.0f, 0.0f};
    glm::vec2 half{0.0f, 0.0f};
};

struct Coin {
    glm::vec2 position{0.0f, 0.0f};
    bool collected = false;
    /// The coin's sensor object (a sprite goes on a child of it).
    e2d::core::GameObject* object = nullptr;
};

/// A kinematic platform following a timetable: it waits `dwell` seconds at `from`, travels to
/// `to` in `travel` seconds, waits there, travels back; `phase` seconds of that cycle have passed
/// at level time 0.
struct MovingPlatform {
    glm::vec2 half{1.5f * kTile, 0.2f * kTile};
    glm::vec2 from{0.0f, 0.0f};
    glm::vec2 to{0.0f, 0.0f};
    float dwell = 2.0f;
    float travel = 2.5f;
    float phase = 0.0f;
    /// Solid from above only, like the one-way platform. Default false.
    bool oneWay = false;
    /// Its object (Rigidbody, kinematic, and Collider).
    e2d::core::GameObject* object = nullptr;
    /// Where the timetable puts the platform's centre at level time `t`.
    [[nodiscard]] glm::vec2 positionAt(double t) const;
};

/// What happened in the last fixed step, for sounds and effects.
struct StepEvents {
    int coinsCollected = 0;
    bool jumped = false;
    bool landed = false;
    bool died = false;
    bool won = false;
};

class Level;

/// Everything a run of the level is at one moment, its rules' state and its physics (a
/// PhysicsSnapshot of the scene): Level::restore() plays on from there exactly as the run did.
struct LevelCheckpoint {
    e2d::physics::PhysicsSnapshot physics;
    PlayerController controller;
    std::vector<bool> collected; // per coin
    glm::vec2 velocity{0.0f, 0.0f};
    std::vector<const e2d::core::GameObject*> touches;
    double time = 0.0;
    int score = 0;
    int jumps = 0;
    int stepsOnMoving = 0;
    int stepsOnOneWay = 0;
    bool grounded = false;
    bool won = false;
    bool dead = false;
    glm::vec2 groundVelocity{0.0f, 0.0f};
    bool onMoving = false;
    bool onOneWay = false;
};

class Level {
public:
    /// Builds the level's objects into `scene`, whose PhysicsSystem it sets the gravity of.
    /// The objects are the scene's: they go with it.
    explicit Level(e2d::core::Scene& scene, const PlayerTuning& tuning = {});
    Level(const Level&) = delete;
    Level& operator=(const Level&) = delete;

    /// One fixed step, before the PhysicsSystem's: takes the sensor events of the last step
    /// (coins, hazards, goal), moves the platforms along their timetables, and sets the player's
    /// velocity from `input`. Does nothing more once the player won or died.
    void fixedUpdate(const PlayerInput& input, float dt);

    /// The run so far, to come back to (between fixed steps).
    [[nodiscard]] LevelCheckpoint save() const;
    /// Back to `checkpoint`, saved by this level: the rules' state and the scene's physics.
    void restore(const LevelCheckpoint& checkpoint);

    // State --------------------------------------------------------------------------------
    [[nodiscard]] double time() const noexcept { return time_; }
    [[nodiscard]] int score() const noexcept { return score_; }
    [[nodiscard]] int coinCount() const noexcept { return static_cast<int>(coins_.size()); }
    [[nodiscard]] bool won() const noexcept { return won_; }
    [[nodiscard]] bool dead() const noexcept { return dead_; }
    [[nodiscard]] const StepEvents& events() const noexcept { return events_; }
    [[nodiscard]] glm::vec2 playerPosition() const;
    [[nodiscard]] glm::vec2 playerVelocity() const;
    [[nodiscard]] bool grounded() const noexcept { return grounded_; }
    [[nodiscard]] int facing() const noexcept { return controller_.facing(); }
    [[nodiscard]] int jumps() const noexcept { return jumps_; }
    /// Steps the player stood on a moving platform, and on the one-way platform.
    [[nodiscard]] int stepsOnMovingPlatform() const noexcept { return stepsOnMoving_; }
    [[nodiscard]] int stepsOnOneWay() const noexcept { return stepsOnOneWay_; }

    // Layout and objects, for drawing -----------------------------------------------------
    [[nodiscard]] static glm::vec2 playerHalfSize() noexcept {
        return glm::vec2{0.35f, 0.6f} * kTile;
    }
    [[nodiscard]] e2d::core::GameObject& player() const noexcept { return *player_; }
    [[nodiscard]] const std::vector<glm::vec2>& terrain() const noexcept { return terrain_; }
    [[nodiscard]] const std::vector<Coin>& coins() const noexcept { return coins_; }
    [[nodiscard]] const std::vector<Box>& hazards() const noexcept { return hazards_; }
    [[nodiscard]] const std::vector<MovingPlatform>& platforms() const noexcept {
        return platforms_;
    }
    [[nodiscard]] const Box& oneWay() const noexcept { return oneWay_; }
    [[nodiscard]] const Box& goal() const noexcept { return goal_; }
    /// The lowest y the player may reach before falling out of the world counts as death.
    [[nodiscard]] static float killPlaneY() noexcept { return -12.0f * kTile; }

private:
    void touched(const e2d::core::GameObject* other);
    void movePlatforms(float dt);
    void readGround();

    e2d::physics::PhysicsSystem& physics_;
    PlayerController controller_;
    std::vector<glm::vec2> terrain_;
    std::vector<Coin> coins_;
    std::vector<Box> hazards_;
    std::vector<const e2d::core::GameObject*> hazardObjects_;
    std::vector<MovingPlatform> platforms_;
    Box oneWay_;
    Box goal_;
    const e2d::core::GameObject* goalObject_ = nullptr;
    e2d::core::GameObject* player_ = nullptr;
    e2d::physics::CharacterController* character_ = nullptr;
    glm::vec2 velocity_{0.0f, 0.0f};                    // the player's, world units/s
    std::vector<const e2d::core::GameObject*> touches_; // sensors entered since the last step
    StepEvents events_;
    double time_ = 0.0;
    int score_ = 0;
    int jumps_ = 0;
    int stepsOnMoving_ = 0;
    int stepsOnOneWay_ = 0;
    bool grounded_ = false;
    bool won_ = false;
    bool dead_ = false;
    glm::vec2 groundVelocity_{0.0f, 0.0f};
    bool onMoving_ = false;
    bool onOneWay_ = false;
};

} // namespace platformer
