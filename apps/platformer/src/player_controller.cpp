// SPDX-License-Identifier: MIT
#include "player_controller.hpp"

#include <algorithm>
#include <cmath>

namespace platformer {

namespace {

float approach(float value, float target, float maxDelta) {
    if (value < target) {
        return std::min(value + maxDelta, target);
    }
    return std::max(value - maxDelta, target);
}

} // namespace

PlayerController::PlayerController(const PlayerTuning& tuning) : tuning_(tuning) {}

PlayerStep PlayerController::step(const PlayerInput& input, glm::vec2 velocity, bool grounded,
                                  glm::vec2 groundVelocity, float dt) {
    const float move = std::clamp(input.move, -1.0f, 1.0f);
    if (move > 0.1f) {
        facing_ = 1;
    } else if (move < -0.1f) {
        facing_ = -1;
    }
    // A body still rising from its own jump is not grounded, whatever the feet touch: otherwise
    // the first step of a jump next to a ledge would count as a landing and allow a double jump.
    // ("rising": faster than the ground by a twentieth of a jump's start.)
    const bool onGround =
        grounded && !(rising_ && velocity.y > groundVelocity.y + 0.05f * tuning_.jumpSpeed);
    if (onGround) {
        airTime_ = 0.0f;
        jumpUsed_ = false;
        rising_ = false;
        lastGroundVelocity_ = groundVelocity;
    } else {
        airTime_ += dt;
    }
    if (input.jumpPressed) {
        bufferLeft_ = tuning_.jumpBuffer;
    } else {
        bufferLeft_ = std::max(0.0f, bufferLeft_ - dt);
    }

    PlayerStep out;
    out.velocity = velocity;
    if (onGround) {
        out.velocity.x = approach(velocity.x, groundVelocity.x + move * tuning_.runSpeed,
                                  tuning_.groundAcceleration * dt);
    } else if (std::abs(move) > 0.1f) {
        // In the air only an asked-for direction steers; letting go keeps the momentum (a jump
        // off a moving platform keeps its speed).
        out.velocity.x =
            approach(velocity.x, move * tuning_.runSpeed, tuning_.airAcceleration * dt);
    }

    const bool canJump = !jumpUsed_ && (onGround || airTime_ <= tuning_.coyoteTime);
    if (bufferLeft_ > 0.0f && canJump) {
        const float base = onGround ? groundVelocity.y : lastGroundVelocity_.y;
        out.velocity.y = tuning_.jumpSpeed + std::max(0.0f, base);
        out.jumped = true;
        bufferLeft_ = 0.0f;
        jumpUsed_ = true;
        rising_ = true;
        airTime_ = tuning_.coyoteTime + dt; // no second jump from the same coyote window
    } else if (rising_ && !input.jumpHeld && out.velocity.y > 0.0f) {
        // Let go early: a shorter hop.
        out.velocity.y *= tuning_.jumpCut;
        rising_ = false;
    } else if (rising_ && out.velocity.y <= 0.0f) {
        rising_ = false;
    }
    return out;
}

} // namespace platformer
