// SPDX-License-Identifier: MIT
#include "level.hpp"

#include <e2d/core/component.hpp>
#include <e2d/physics/character_controller.hpp>
#include <e2d/physics/collider.hpp>
#include <e2d/physics/contact_info.hpp>
#include <e2d/physics/physics_system.hpp>
#include <e2d/physics/rigidbody.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

namespace platformer {

namespace ph = e2d::physics;
using e2d::core::GameObject;

namespace {

// Collision categories.
constexpr e2d::core::Mask kWorld{1};
constexpr e2d::core::Mask kPlayer{2};
constexpr e2d::core::Mask kTrigger{4};

constexpr float kGravity = -25.0f * kTile;

// Tells the level which sensors the player's object entered.
class SensorRelay final : public e2d::core::Component,
                          public e2d::core::Handles<e2d::physics::TriggerEnter> {
public:
    explicit SensorRelay(std::function<void(const GameObject*)> entered)
        : entered_(std::move(entered)) {}
    void on(const e2d::physics::TriggerEnter& contact) override { entered_(contact.other); }

private:
    std::function<void(const GameObject*)> entered_;
};

GameObject& place(e2d::core::Scene& scene, const char* name, glm::vec2 at) {
    GameObject& object = scene.createGameObject();
    object.setName(name);
    object.setPosition(at);
    return object;
}

} // namespace

glm::vec2 MovingPlatform::positionAt(double t) const {
    const double cycle = 2.0 * (dwell + travel);
    double u = std::fmod(t + phase, cycle);
    if (u < 0.0) {
        u += cycle;
    }
    // Smooth start and stop (smoothstep) so a rider is not jolted.
    auto blend = [this](double s) {
        const float k = static_cast<float>(s * s * (3.0 - 2.0 * s));
        return from + (to - from) * k;
    };
    if (u < dwell) {
        return from;
    }
    u -= dwell;
    if (u < travel) {
        return blend(u / travel);
    }
    u -= travel;
    if (u < dwell) {
        return to;
    }
    u -= dwell;
    return blend(1.0 - u / travel);
}

Level::Level(e2d::core::Scene& scene, const PlayerTuning& tuning)
    : physics_(scene.system<ph::PhysicsSystem>()), controller_(tuning) {
    const ph::ColliderDef solid{.friction = 0.0f, .category = kWorld};
    const ph::ColliderDef sensor{.isSensor = true, .category = kTrigger, .mask = kPlayer};

    // Terrain: one-sided segments along the level's surface, listed right to left so that each
    // faces into the level, each with its neighbours as ghosts so nothing catches on the joints.
    for (glm::vec2 tile : {glm::vec2{36, 24}, glm::vec2{36, 6}, glm::vec2{14, 6}, glm::vec2{14, 0},
                           glm::vec2{9, 0}, glm::vec2{9, -3}, glm::vec2{6, -3}, glm::vec2{6, 0},
                           glm::vec2{-4, 0}, glm::vec2{-4, 24}}) {
        terrain_.push_back(tile * kTile);
    }
    GameObject& ground = place(scene, "terrain", {0.0f, 0.0f});
    for (std::size_t i = 0; i + 1 < terrain_.size(); ++i) {
        ph::ChainSegment segment;
        segment.segment = {terrain_[i], terrain_[i + 1]};
        segment.hasGhost1 = i > 0;
        segment.ghost1 = segment.hasGhost1 ? terrain_[i - 1] : terrain_[i];
        segment.hasGhost2 = i + 2 < terrain_.size();
        segment.ghost2 = segment.hasGhost2 ? terrain_[i + 2] : terrain_[i + 1];
        ground.addComponent<ph::Collider>(segment, solid);
    }

    // Spikes at the bottom of the pit.
    hazards_.push_back({glm::vec2{7.5f, -2.6f} * kTile, glm::vec2{1.5f, 0.4f} * kTile});
    for (const Box& hazard : hazards_) {
        GameObject& spikes = place(scene, "spikes", hazard.center);
        spikes.addComponent<ph::Collider>(ph::makeBox(hazard.half.x, hazard.half.y), sensor);
        hazardObjects_.push_back(&spikes);
    }

    // Coins: on the start ground, in the lift's shaft, on the one-way platform, and a bonus
    // high above the goal that only the shuttle reaches.
    for (glm::vec2 tile : {glm::vec2{3.0f, 0.8f}, glm::vec2{13.3f, 3.5f}, glm::vec2{23.0f, 8.7f},
                           glm::vec2{32.2f, 11.0f}}) {
        Coin coin;
        coin.position = tile * kTile;
        coin.object = &place(scene, "coin", coin.position);
        coin.object->addComponent<ph::Collider>(ph::Circle{{0.0f, 0.0f}, 0.35f * kTile}, sensor);
        coins_.push_back(coin);
    }

    // The goal flag.
    goal_ = {glm::vec2{31.0f, 7.5f} * kTile, glm::vec2{0.5f, 1.5f} * kTile};
    GameObject& flag = place(scene, "goal", goal_.center);
    flag.addComponent<ph::Collider>(ph::makeBox(goal_.half.x, goal_.half.y), sensor);
    goalObject_ = &flag;

    // The one-way platform: solid from above only.
    ph::ColliderDef oneWay = solid;
    oneWay.oneWay = true;
    oneWay_ = {glm::vec2{23.0f, 7.9f} * kTile, glm::vec2{4.0f, 0.1f} * kTile};
    place(scene, "one-way platform", oneWay_.center)
        .addComponent<ph::Collider>(ph::makeBox(oneWay_.half.x, oneWay_.half.y), oneWay);

    // The lift in front of the cliff: waits at the bottom, rises above the ledge, waits, returns.
    MovingPlatform lift;
    lift.half = glm::vec2{1.5f, 0.25f} * kTile;
    lift.from = glm::vec2{12.35f, 0.75f} * kTile;
    lift.to = glm::vec2{12.35f, 6.05f} * kTile;
    lift.dwell = 2.5f;
    lift.travel = 2.65f;
    platforms_.push_back(lift);
    // The shuttle above the end of the one-way platform, one-way itself: jump up through it
    // from the platform while it waits there, ride it to the bonus coin above the goal.
    MovingPlatform shuttle;
    shuttle.from = glm::vec2{26.5f, 9.8f} * kTile;
    shuttle.to = glm::vec2{32.5f, 9.8f} * kTile;
    shuttle.dwell = 1.5f;
    shuttle.travel = 2.0f;
    shuttle.oneWay = true;
    platforms_.push_back(shuttle);
    for (MovingPlatform& platform : platforms_) {
        platform.object =
            &place(scene, platform.oneWay ? "shuttle" : "lift", platform.positionAt(0.0));
        platform.object->addComponent<ph::Rigidbody>(
            ph::RigidbodyDef{.type = ph::BodyType::Kinematic});
        platform.object->addComponent<ph::Collider>(ph::makeBox(platform.half.x, platform.half.y),
                                                    platform.oneWay ? oneWay : solid);
    }

    // The player: a capsule moved by a CharacterController (the rules below give it gravity
    // and jumps); one-way platforms block it only from above.
    player_ = &place(scene, "player", {1.0f * kTile, playerHalfSize().y + 0.01f * kTile});
    const glm::vec2 half = playerHalfSize();
    ph::CharacterControllerDef character;
    character.capsule = {{0.0f, -(half.y - half.x)}, {0.0f, half.y - half.x}, half.x};
    character.skin = 0.01f * kTile;
    character.maxPushOut = 0.1f * kTile;
    character.groundSnapDistance = 0.05f * kTile;
    character.category = kPlayer;
    character.mask = kWorld | kTrigger;
    character.contactFilter = [this](const ph::MoverContact& contact) {
        const ph::Collider* collider = physics_.collider(contact.shape);
        return collider == nullptr || !collider->def().oneWay || contact.normal.y >= 0.7f;
    };
    character_ = player_->addComponent<ph::CharacterController>(character);
    player_->addComponent<SensorRelay>(
        [this](const GameObject* other) { touches_.push_back(other); });
}

glm::vec2 Level::playerPosition() const { return glm::vec2(player_->position()); }

glm::vec2 Level::playerVelocity() const { return velocity_; }

void Level::fixedUpdate(const PlayerInput& input, float dt) {
    events_ = {};
    if (won_ || dead_) {
        return;
    }
    for (const GameObject* other : std::exchange(touches_, {})) {
        touched(other);
    }
    if (playerPosition().y < killPlaneY()) {
        dead_ = true;
        events_.died = true;
    }
    if (won_ || dead_) {
        velocity_ = {0.0f, 0.0f};
        for (const MovingPlatform& platform : platforms_) {
            platform.object->getComponent<ph::Rigidbody>()->setLinearVelocity({0.0f, 0.0f});
        }
        return;
    }
    movePlatforms(dt);
    const bool wasGrounded = grounded_;
    readGround();
    events_.landed = grounded_ && !wasGrounded;
    if (grounded_ && onMoving_) {
        ++stepsOnMoving_;
    }
    if (grounded_ && onOneWay_) {
        ++stepsOnOneWay_;
    }
    const PlayerStep step = controller_.step(input, velocity_, grounded_, groundVelocity_, dt);
    // Gravity is the game's: on the ground the player goes with it, in the air it falls.
    glm::vec2 velocity = step.velocity;
    if (grounded_ && !step.jumped) {
        velocity.y = groundVelocity_.y;
    } else {
        velocity.y += kGravity * dt;
    }
    character_->move(velocity * dt);
    // No speed piles up against walls, ceilings or the ground it was stopped by.
    velocity_ = character_->clipVelocity(velocity - groundVelocity_) + groundVelocity_;
    if (step.jumped) {
        ++jumps_;
        events_.jumped = true;
    }
    time_ += dt;
}

LevelCheckpoint Level::save() const {
    LevelCheckpoint c;
    c.physics = physics_.saveSnapshot();
    c.controller = controller_;
    for (const Coin& coin : coins_) {
        c.collected.push_back(coin.collected);
    }
    c.velocity = velocity_;
    c.touches = touches_;
    c.time = time_;
    c.score = score_;
    c.jumps = jumps_;
    c.stepsOnMoving = stepsOnMoving_;
    c.stepsOnOneWay = stepsOnOneWay_;
    c.grounded = grounded_;
    c.won = won_;
    c.dead = dead_;
    c.groundVelocity = groundVelocity_;
    c.onMoving = onMoving_;
    c.onOneWay = onOneWay_;
    return c;
}

void Level::restore(const LevelCheckpoint& c) {
    physics_.restoreSnapshot(c.physics);
    controller_ = c.controller;
    for (std::size_t i = 0; i < coins_.size() && i < c.collected.size(); ++i) {
        coins_[i].collected = c.collected[i];
    }
    velocity_ = c.velocity;
    touches_ = c.touches;
    events_ = {};
    time_ = c.time;
    score_ = c.score;
    jumps_ = c.jumps;
    stepsOnMoving_ = c.stepsOnMoving;
    stepsOnOneWay_ = c.stepsOnOneWay;
    grounded_ = c.grounded;
    won_ = c.won;
    dead_ = c.dead;
    groundVelocity_ = c.groundVelocity;
    onMoving_ = c.onMoving;
    onOneWay_ = c.onOneWay;
}

void Level::touched(const GameObject* other) {
    if (other == goalObject_) {
        won_ = true;
        events_.won = true;
    }
    if (std::find(hazardObjects_.begin(), hazardObjects_.end(), other) != hazardObjects_.end() &&
        !won_) {
        dead_ = true;
        events_.died = true;
    }
    for (Coin& coin : coins_) {
        if (other == coin.object && !coin.collected) {
            coin.collected = true;
            ++score_;
            ++events_.coinsCollected;
        }
    }
}

void Level::movePlatforms(float dt) {
    // Velocities that reach the timetable's position at the end of the step: the platform
    // never drifts from it, and pushes and carries the player like any moving body.
    for (const MovingPlatform& platform : platforms_) {
        platform.object->getComponent<ph::Rigidbody>()->setTargetTransform(
            platform.positionAt(time_ + dt), 0.0f);
    }
}

void Level::readGround() {
    // What the character stood on after its last move.
    grounded_ = character_->isGrounded();
    groundVelocity_ = grounded_ ? character_->groundVelocity() : glm::vec2{0.0f, 0.0f};
    const ph::Collider* ground =
        grounded_ ? physics_.collider(character_->lastMove().groundShape) : nullptr;
    const ph::Rigidbody* moving = ground != nullptr ? ground->rigidbody() : nullptr;
    onMoving_ = moving != nullptr && moving->type() == ph::BodyType::Kinematic;
    onOneWay_ = ground != nullptr && ground->def().oneWay && moving == nullptr;
}

} // namespace platformer
