// SPDX-License-Identifier: MIT
#include "level.hpp"

#include <algorithm>
#include <cmath>

namespace platformer {

namespace ph = e2d::physics;

namespace {

// Collision categories.
constexpr std::uint64_t kWorldBit = 1;
constexpr std::uint64_t kPlayerBit = 2;
constexpr std::uint64_t kTriggerBit = 4;

constexpr float kGravity = -25.0f;
// The ground probes reach this far below the feet, metres.
constexpr float kProbeDepth = 0.08f;

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

Level::Level(ph::World& world, const PlayerTuning& tuning) : world_(world), controller_(tuning) {
    world_.setGravity({0.0f, kGravity});

    // Terrain: one chain along the level's surface, listed right to left so that every segment
    // faces into the level (a chain is solid from its right-hand side).
    terrain_ = {{36.0f, 24.0f}, {36.0f, 6.0f}, {14.0f, 6.0f}, {14.0f, 0.0f}, {9.0f, 0.0f},
                {9.0f, -3.0f},  {6.0f, -3.0f}, {6.0f, 0.0f},  {-4.0f, 0.0f}, {-4.0f, 24.0f}};
    ph::BodyId ground = world_.createBody({});
    bodies_.push_back(ground);
    ph::ChainDef chain;
    chain.points = terrain_;
    chain.shape.friction = 0.0f;
    chain.shape.filter.categoryBits = kWorldBit;
    world_.createChain(ground, chain);

    // Spikes at the bottom of the pit.
    ph::ShapeDef sensor;
    sensor.isSensor = true;
    sensor.filter.categoryBits = kTriggerBit;
    sensor.filter.maskBits = kPlayerBit;
    hazards_.push_back({{7.5f, -2.6f}, {1.5f, 0.4f}});
    for (const Box& hazard : hazards_) {
        hazardShapes_.push_back(world_.createShape(
            ground, sensor, ph::makeOffsetBox(hazard.half.x, hazard.half.y, hazard.center, 0.0f)));
    }

    // Coins: on the start ground, in the lift's shaft, on the one-way platform, and a bonus
    // high above the goal that only the shuttle reaches.
    for (glm::vec2 at : {glm::vec2{3.0f, 0.8f}, glm::vec2{13.3f, 3.5f}, glm::vec2{23.0f, 8.7f},
                         glm::vec2{32.2f, 11.0f}}) {
        Coin coin;
        coin.position = at;
        ph::Circle circle;
        circle.center = at;
        circle.radius = 0.35f;
        coin.shape = world_.createShape(ground, sensor, circle);
        coins_.push_back(coin);
    }

    // The goal flag.
    goal_ = {{31.0f, 7.5f}, {0.5f, 1.5f}};
    goalShape_ = world_.createShape(
        ground, sensor, ph::makeOffsetBox(goal_.half.x, goal_.half.y, goal_.center, 0.0f));

    // The one-way platform: solid from above only (see the pre-solve callback below).
    oneWay_ = {{23.0f, 7.9f}, {4.0f, 0.1f}};
    ph::ShapeDef solid;
    solid.friction = 0.0f;
    solid.filter.categoryBits = kWorldBit;
    oneWayShape_ = world_.createShape(
        ground, solid, ph::makeOffsetBox(oneWay_.half.x, oneWay_.half.y, oneWay_.center, 0.0f));
    oneWayShapes_.push_back(oneWayShape_);

    // The lift in front of the cliff: waits at the bottom, rises above the ledge, waits, returns.
    MovingPlatform lift;
    lift.half = {1.5f, 0.25f};
    lift.from = {12.35f, 0.75f};
    lift.to = {12.35f, 6.05f};
    lift.dwell = 2.5f;
    lift.travel = 2.65f;
    platforms_.push_back(lift);
    // The shuttle above the end of the one-way platform, one-way itself: jump up through it
    // from the platform while it waits there, ride it to the bonus coin above the goal.
    MovingPlatform shuttle;
    shuttle.half = {1.5f, 0.2f};
    shuttle.from = {26.5f, 9.8f};
    shuttle.to = {32.5f, 9.8f};
    shuttle.dwell = 1.5f;
    shuttle.travel = 2.0f;
    shuttle.oneWay = true;
    platforms_.push_back(shuttle);
    for (MovingPlatform& platform : platforms_) {
        ph::BodyDef def;
        def.type = ph::BodyType::Kinematic;
        def.position = platform.positionAt(0.0);
        platform.body = world_.createBody(def);
        bodies_.push_back(platform.body);
        const ph::ShapeId shape =
            world_.createShape(platform.body, solid, ph::makeBox(platform.half.x, platform.half.y));
        if (platform.oneWay) {
            oneWayShapes_.push_back(shape);
        }
    }

    // The player: a rounded box that never turns, frictionless so it does not stick to walls
    // (the controller sets its horizontal speed).
    ph::BodyDef playerDef;
    playerDef.type = ph::BodyType::Dynamic;
    playerDef.position = {1.0f, playerHalfSize().y + 0.01f};
    playerDef.fixedRotation = true;
    playerDef.enableSleep = false;
    player_ = world_.createBody(playerDef);
    bodies_.push_back(player_);
    ph::ShapeDef playerShape;
    playerShape.friction = 0.0f;
    playerShape.density = 1.0f;
    playerShape.filter.categoryBits = kPlayerBit;
    playerShape.filter.maskBits = kWorldBit | kTriggerBit;
    const float radius = 0.08f;
    playerShape_ = world_.createShape(
        player_, playerShape,
        ph::makeRoundedBox(playerHalfSize().x - radius, playerHalfSize().y - radius, radius));

    world_.setPreSolveCallback([this](ph::ShapeId a, ph::ShapeId b, const ph::Manifold& m) {
        const auto isOneWay = [this](ph::ShapeId shape) {
            return std::find(oneWayShapes_.begin(), oneWayShapes_.end(), shape) !=
                   oneWayShapes_.end();
        };
        const bool aOneWay = isOneWay(a);
        if (!aOneWay && !isOneWay(b)) {
            return true;
        }
        // Solid only for something above it coming down: the normal from the platform to the
        // other shape points up, and the other shape has not sunk into it from below.
        const float up = aOneWay ? m.normal.y : -m.normal.y;
        if (up < 0.7f) {
            return false;
        }
        for (int i = 0; i < m.pointCount; ++i) {
            if (m.points[i].separation < -0.05f) {
                return false;
            }
        }
        return true;
    });
}

Level::~Level() {
    world_.setPreSolveCallback({});
    for (auto it = bodies_.rbegin(); it != bodies_.rend(); ++it) {
        if (world_.isValid(*it)) {
            world_.destroyBody(*it);
        }
    }
}

glm::vec2 Level::playerPosition() const { return world_.transform(player_).p; }

glm::vec2 Level::playerVelocity() const { return world_.linearVelocity(player_); }

glm::vec2 Level::platformPosition(std::size_t index) const {
    return world_.transform(platforms_.at(index).body).p;
}

void Level::fixedUpdate(const PlayerInput& input, float dt) {
    events_ = {};
    if (won_ || dead_) {
        return;
    }
    readSensorEvents();
    if (playerPosition().y < killPlaneY()) {
        dead_ = true;
        events_.died = true;
    }
    if (won_ || dead_) {
        world_.setLinearVelocity(player_, {0.0f, 0.0f});
        for (const MovingPlatform& platform : platforms_) {
            world_.setLinearVelocity(platform.body, {0.0f, 0.0f});
        }
        return;
    }
    movePlatforms(dt);
    const bool wasGrounded = grounded_;
    probeGround();
    events_.landed = grounded_ && !wasGrounded;
    if (grounded_ && onMoving_) {
        ++stepsOnMoving_;
    }
    if (grounded_ && onOneWay_) {
        ++stepsOnOneWay_;
    }
    const PlayerStep step =
        controller_.step(input, playerVelocity(), grounded_, groundVelocity_, dt);
    world_.setLinearVelocity(player_, step.velocity);
    if (step.jumped) {
        ++jumps_;
        events_.jumped = true;
    }
    time_ += dt;
}

void Level::readSensorEvents() {
    for (const ph::SensorBeginTouchEvent& event : world_.sensorBeginEvents()) {
        if (event.visitorShape != playerShape_) {
            continue;
        }
        if (event.sensorShape == goalShape_) {
            won_ = true;
            events_.won = true;
        }
        for (ph::ShapeId hazard : hazardShapes_) {
            if (event.sensorShape == hazard && !won_) {
                dead_ = true;
                events_.died = true;
            }
        }
        for (Coin& coin : coins_) {
            if (event.sensorShape == coin.shape && !coin.collected) {
                coin.collected = true;
                ++score_;
                ++events_.coinsCollected;
            }
        }
    }
}

void Level::movePlatforms(float dt) {
    // Velocities that reach the timetable's position at the end of the step: the platform
    // never drifts from it, and pushes and carries the player like any moving body.
    for (const MovingPlatform& platform : platforms_) {
        world_.setTargetTransform(platform.body, platform.positionAt(time_ + dt), 0.0f, dt);
    }
}

void Level::probeGround() {
    // Three short rays down from just inside the feet: grounded when one hits a surface facing
    // up. Rays ignore back faces, so the one-way platform is seen only from above.
    const glm::vec2 p = playerPosition();
    const glm::vec2 half = playerHalfSize();
    ph::QueryFilter filter;
    filter.categoryBits = kPlayerBit;
    filter.maskBits = kWorldBit;
    grounded_ = false;
    onMoving_ = false;
    onOneWay_ = false;
    groundVelocity_ = {0.0f, 0.0f};
    float best = 2.0f;
    for (float dx : {-half.x + 0.05f, 0.0f, half.x - 0.05f}) {
        const glm::vec2 origin{p.x + dx, p.y - half.y + 0.1f};
        auto hit = world_.castRayClosest(origin, {0.0f, -(0.1f + kProbeDepth)}, filter);
        if (!hit || hit->normal.y < 0.7f || hit->fraction >= best) {
            continue;
        }
        best = hit->fraction;
        grounded_ = true;
        const ph::BodyId body = world_.shapeBody(hit->shape);
        groundVelocity_ = world_.linearVelocity(body);
        onMoving_ = world_.bodyType(body) == ph::BodyType::Kinematic;
        onOneWay_ = hit->shape == oneWayShape_;
    }
}

} // namespace platformer
