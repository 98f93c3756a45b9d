// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec2.hpp>

/// The character's run and jump rules, apart from physics and input devices: given what the
/// player asks for, whether the feet are on something and how fast that something moves, it
/// says which velocity the body gets this step. It keeps the two timers players expect:
/// coyote time (a jump still works a moment after running off an edge) and jump buffering
/// (a jump pressed a moment before landing happens on landing).
namespace platformer {

/// World units (reference pixels) per tile of the level's grid; the game's unitsPerMetre makes
/// a tile a metre to the physics.
inline constexpr float kTile = 48.0f;

/// What the player asks for during one fixed step.
struct PlayerInput {
    /// -1 (left) .. 1 (right). Default 0.
    float move = 0.0f;
    /// The jump action went down since the last step. Default false.
    bool jumpPressed = false;
    /// The jump action is held. Default false.
    bool jumpHeld = false;
};

/// Tuning of PlayerController. Units: world units, seconds.
struct PlayerTuning {
    /// Top running speed, units/s. Default 7 tiles/s.
    float runSpeed = 7.0f * kTile;
    /// How fast the horizontal speed approaches the wanted one on the ground, units/s^2.
    /// Default 60 tiles/s^2.
    float groundAcceleration = 60.0f * kTile;
    /// The same in the air, units/s^2. Default 35 tiles/s^2.
    float airAcceleration = 35.0f * kTile;
    /// Upward speed a jump starts with, units/s. Default 11 tiles/s (2.4 tiles high under the
    /// level's 25 tiles/s^2).
    float jumpSpeed = 11.0f * kTile;
    /// Releasing jump while rising multiplies the upward speed by this. Default 0.5.
    float jumpCut = 0.5f;
    /// A jump still starts this long after the feet left the ground, s. Default 0.1.
    float coyoteTime = 0.1f;
    /// A jump pressed this long before landing starts on landing, s. Default 0.12.
    float jumpBuffer = 0.12f;
};

/// What the controller decides for one step.
struct PlayerStep {
    glm::vec2 velocity{0.0f, 0.0f}; ///< the body's new velocity, units/s
    bool jumped = false;            ///< a jump started this step
};

class PlayerController {
public:
    explicit PlayerController(const PlayerTuning& tuning = {});

    /// One fixed step of `dt` seconds. `velocity` is the body's velocity now, `grounded` whether
    /// its feet rest on something, `groundVelocity` that something's velocity (carried along:
    /// a player standing still on a moving platform moves with it).
    PlayerStep step(const PlayerInput& input, glm::vec2 velocity, bool grounded,
                    glm::vec2 groundVelocity, float dt);

    /// Seconds since the feet last touched ground (0 while grounded).
    [[nodiscard]] float airTime() const noexcept { return airTime_; }
    /// Direction the character faces: +1 right, -1 left.
    [[nodiscard]] int facing() const noexcept { return facing_; }
    [[nodiscard]] const PlayerTuning& tuning() const noexcept { return tuning_; }

private:
    PlayerTuning tuning_;
    float airTime_ = 0.0f;
    float bufferLeft_ = 0.0f; // time the last jump press stays valid
    bool rising_ = false;     // in a jump that the release of jump may still cut
    bool jumpUsed_ = false;   // the coyote window was spent on a jump
    int facing_ = 1;
    glm::vec2 lastGroundVelocity_{0.0f, 0.0f};
};

} // namespace platformer
