// SPDX-License-Identifier: MIT
// The platformer's level played by scripts at the fixed step, in a real scene with the game's
// PhysicsSystem (48 units per metre) and no window, sound or input device: the same rules the
// game runs.
#include "level.hpp"

#include <e2d/core/log.hpp>
#include <e2d/core/scene_director.hpp>
#include <e2d/core/scene_registry.hpp>
#include <e2d/physics/physics_system.hpp>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

namespace {

using platformer::kTile;
using platformer::Level;
using platformer::PlayerController;
using platformer::PlayerInput;

constexpr float kDt = 1.0f / 60.0f;

// A timeline of held inputs: from `time` on (seconds), `move` and `jump` hold until the next entry.
struct Hold {
    double time = 0.0;
    float move = 0.0f;
    bool jump = false;
};

struct Outcome {
    bool won = false;
    bool dead = false;
    int score = 0;
    int jumps = 0;
    int stepsOnMoving = 0;
    int stepsOnOneWay = 0;
    int coinEvents = 0;
    double time = 0.0;
    float maxY = -1e9f;
    glm::vec2 end{0.0f, 0.0f};
};

// The level in a scene of its own, stepped as the engine does: the scene's fixed update (the
// level's), then the physics system's.
class LevelRun {
public:
    LevelRun() {
        registry.add("Level", e2d::core::SceneFunctions{.initialize = [this](e2d::core::Scene& s) {
                         level = std::make_unique<Level>(s);
                     }});
        director.addSystem(physics);
        director.start("Level");
    }
    void step(const PlayerInput& input) {
        director.applyPendingChange();
        director.scene()->beginFrame();
        level->fixedUpdate(input, kDt);
        physics.fixedUpdate(kDt);
    }

    e2d::core::Logger logger{e2d::core::LogLevel::Off};
    e2d::core::SceneRegistry registry;
    e2d::core::SceneDirector director{registry, logger};
    e2d::physics::PhysicsSystem physics{{}, kTile};
    std::unique_ptr<Level> level;
};

// A detour from the script: at step `at` the level is saved, played `steps` steps with `input`
// held (somewhere else entirely), then restored, and the script goes on from step `at`.
struct Detour {
    int at = -1;
    int steps = 0;
    PlayerInput input{};
    glm::vec2 from{0.0f, 0.0f};    // where the player was at the save (filled in)
    glm::vec2 reached{0.0f, 0.0f}; // where the detour took it
};

Outcome play(const std::vector<Hold>& script, double limit, double timeOffset = 0.0,
             Detour* detour = nullptr) {
    LevelRun game;
    Level& level = *game.level;
    Outcome run;
    bool jumpWasHeld = false;
    for (int i = 0; i < static_cast<int>(limit / kDt); ++i) {
        if (detour != nullptr && i == detour->at) {
            const platformer::LevelCheckpoint checkpoint = level.save();
            detour->from = level.playerPosition();
            for (int k = 0; k < detour->steps; ++k) {
                game.step(detour->input);
            }
            detour->reached = level.playerPosition();
            level.restore(checkpoint);
        }
        const double t = i * kDt + timeOffset;
        Hold now;
        for (const Hold& h : script) {
            if (h.time <= t + 1e-9) {
                now = h;
            }
        }
        PlayerInput input;
        input.move = now.move;
        input.jumpHeld = now.jump;
        input.jumpPressed = now.jump && !jumpWasHeld;
        jumpWasHeld = now.jump;
        game.step(input);
        run.coinEvents += level.events().coinsCollected;
        if (level.won() || level.dead()) {
            break;
        }
        run.maxY = std::max(run.maxY, level.playerPosition().y);
        if (std::getenv("TRACE") && i % 6 == 0) {
            std::printf("t=%.2f p=(%.2f,%.2f) v=(%.2f,%.2f) g=%d lift=%.2f score=%d\n", t,
                        level.playerPosition().x / kTile, level.playerPosition().y / kTile,
                        level.playerVelocity().x / kTile, level.playerVelocity().y / kTile,
                        level.grounded(), level.platforms()[0].object->position().y / kTile,
                        level.score());
        }
    }
    run.won = level.won();
    run.dead = level.dead();
    run.score = level.score();
    run.jumps = level.jumps();
    run.stepsOnMoving = level.stepsOnMovingPlatform();
    run.stepsOnOneWay = level.stepsOnOneWay();
    run.time = level.time();
    run.end = level.playerPosition();
    return run;
}

// Hold right; jump over the spike pit, onto the lift, and under the one-way platform.
// The winning run, then the bonus: stop on the one-way platform under the shuttle, jump up
// through it while it waits, ride it to the bonus coin and back, run off it onto the goal.
std::vector<Hold> bonusScript(double shift = 0.0) {
    return {{0.0, 1.0f, false},         {0.55, 1.0f, true},          {0.95, 1.0f, false},
            {1.6, 1.0f, true},          {2.0, 1.0f, false},          {5.75, 1.0f, true},
            {6.25, 1.0f, false},        {6.55 + shift, 0.0f, false}, {7.2 + shift, 0.0f, true},
            {7.6 + shift, 0.0f, false}, {14.4 + shift, 1.0f, false}};
}

std::vector<Hold> winningScript(double shift = 0.0) {
    return {{0.0, 1.0f, false},         {0.55 + shift, 1.0f, true}, {0.95 + shift, 1.0f, false},
            {1.6 + shift, 1.0f, true},  {2.0 + shift, 1.0f, false}, {5.75 + shift, 1.0f, true},
            {6.25 + shift, 1.0f, false}};
}

TEST(PlatformerLevel, ScriptedRunCollectsEveryCoinRidesTheLiftAndReachesTheGoal) {
    Outcome run = play(winningScript(), 20.0);
    EXPECT_TRUE(run.won);
    EXPECT_FALSE(run.dead);
    EXPECT_EQ(run.score, 3);
    EXPECT_EQ(run.coinEvents, 3);     // each coin counted once
    EXPECT_GT(run.stepsOnMoving, 30); // stood on the lift while it rose
    EXPECT_GT(run.stepsOnOneWay, 5);  // jumped up through the one-way platform and landed on it
    EXPECT_GT(run.maxY, 8.0f * kTile + Level::playerHalfSize().y - 0.05f * kTile);
    EXPECT_EQ(run.jumps, 3);
}

// A checkpoint saved mid-level (the level's rules and the scene's physics: contacts, the lift,
// the character), a second of play somewhere else, the checkpoint restored: the rest of the
// scripted run ends exactly as the run that never left.
TEST(PlatformerLevel, ACheckpointRestoredMidLevelFinishesTheRunTheSame) {
    const Outcome straight = play(winningScript(), 20.0);
    ASSERT_TRUE(straight.won);
    // At 3 s the player runs towards the lift, which is moving; the detour runs back left and
    // jumps for a second.
    for (int at : {180, 300}) {
        SCOPED_TRACE(at);
        Detour detour;
        detour.at = at;
        detour.steps = 60;
        detour.input.move = -1.0f;
        detour.input.jumpHeld = true;
        detour.input.jumpPressed = true;
        const Outcome restored = play(winningScript(), 20.0, 0.0, &detour);
        EXPECT_GT(glm::length(detour.reached - detour.from), 1.0f * kTile)
            << "the detour went elsewhere";
        EXPECT_TRUE(restored.won);
        EXPECT_EQ(restored.score, straight.score);
        EXPECT_EQ(restored.jumps, straight.jumps);
        EXPECT_EQ(restored.coinEvents, straight.coinEvents);
        EXPECT_EQ(restored.stepsOnMoving, straight.stepsOnMoving);
        EXPECT_EQ(restored.stepsOnOneWay, straight.stepsOnOneWay);
        EXPECT_EQ(restored.time, straight.time);
        EXPECT_EQ(restored.end, straight.end); // bit for bit
        EXPECT_EQ(restored.maxY, straight.maxY);
    }
}

TEST(PlatformerLevel, TheShuttleCarriesThePlayerToTheBonusCoin) {
    for (double shift : {-0.05, 0.0, 0.05}) {
        Outcome run = play(bonusScript(shift), 20.0);
        EXPECT_TRUE(run.won) << "shift " << shift;
        EXPECT_EQ(run.score, 4) << "shift " << shift;
        EXPECT_EQ(run.jumps, 4) << "shift " << shift;
        // Stood on the shuttle (top at 10 m).
        EXPECT_GT(run.maxY, 10.0f * kTile + Level::playerHalfSize().y - 0.05f * kTile)
            << "shift " << shift;
    }
}

TEST(PlatformerLevel, TheWinningScriptToleratesItsJumpsComingAFewFramesEarlyOrLate) {
    for (double shift : {-0.1, -0.05, 0.05, 0.1}) {
        Outcome run = play(winningScript(shift), 20.0);
        EXPECT_TRUE(run.won) << "shift " << shift;
        EXPECT_EQ(run.score, 3) << "shift " << shift;
    }
}

TEST(PlatformerLevel, RunningRightWithoutJumpingEndsOnTheSpikes) {
    Outcome run = play({{0.0, 1.0f, false}}, 10.0);
    EXPECT_TRUE(run.dead);
    EXPECT_FALSE(run.won);
    EXPECT_EQ(run.score, 1); // the coin on the start ground
    EXPECT_GT(run.end.x, 6.0f * kTile);
    EXPECT_LT(run.end.x, 9.0f * kTile);
    EXPECT_LT(run.end.y, -1.0f * kTile);
}

TEST(PlatformerLevel, StandingStillNothingHappens) {
    Outcome run = play({}, 5.0);
    EXPECT_FALSE(run.dead);
    EXPECT_FALSE(run.won);
    EXPECT_EQ(run.score, 0);
    EXPECT_NEAR(run.end.x, 1.0f * kTile, 1e-3f * kTile);
    EXPECT_NEAR(run.end.y, Level::playerHalfSize().y, 0.03f * kTile);
}

TEST(PlatformerLevel, TheOneWayPlatformHoldsFromAboveOnly) {
    // Without a jump under it the player walks under the one-way platform (never on it).
    std::vector<Hold> script = winningScript();
    script.resize(5);
    Outcome run = play(script, 20.0);
    EXPECT_TRUE(run.won);
    EXPECT_EQ(run.stepsOnOneWay, 0);
    EXPECT_LT(run.maxY, 7.9f * kTile);
    EXPECT_EQ(run.score, 2); // the coin on top of it is missed
}

TEST(PlatformerLevel, TheLiftFollowsItsTimetable) {
    LevelRun game;
    const platformer::MovingPlatform& lift = game.level->platforms().at(0);
    for (int i = 0; i < 900; ++i) {
        game.step({});
        const glm::vec2 expected = lift.positionAt((i + 1) * kDt);
        ASSERT_NEAR(lift.object->position().x, expected.x, 1e-3f * kTile) << i;
        ASSERT_NEAR(lift.object->position().y, expected.y, 1e-3f * kTile) << i;
    }
    // The timetable: waits at `from`, arrives at `to` after dwell + travel, back after a cycle.
    EXPECT_EQ(lift.positionAt(0.0), lift.from);
    EXPECT_EQ(lift.positionAt(lift.dwell + lift.travel + 0.01), lift.to);
    const double cycle = 2.0 * (lift.dwell + lift.travel);
    EXPECT_EQ(lift.positionAt(cycle + 0.01), lift.from);
}

// The controller's timers on their own.
TEST(PlayerController, CoyoteTimeAllowsAJumpJustAfterLeavingTheGround) {
    PlayerController c;
    c.step({}, {0, 0}, true, {0, 0}, kDt);
    // Three steps (0.05 s) in the air, then jump: still allowed.
    for (int i = 0; i < 3; ++i) {
        c.step({}, {0, -1}, false, {0, 0}, kDt);
    }
    auto step = c.step({0.0f, true, true}, {0, -1}, false, {0, 0}, kDt);
    EXPECT_TRUE(step.jumped);
    EXPECT_FLOAT_EQ(step.velocity.y, c.tuning().jumpSpeed);

    PlayerController late;
    late.step({}, {0, 0}, true, {0, 0}, kDt);
    for (int i = 0; i < 9; ++i) { // 0.15 s: past the 0.1 s coyote time
        late.step({}, {0, -1}, false, {0, 0}, kDt);
    }
    EXPECT_FALSE(late.step({0.0f, true, true}, {0, -1}, false, {0, 0}, kDt).jumped);
}

TEST(PlayerController, AJumpPressedJustBeforeLandingHappensOnLanding) {
    PlayerController c;
    for (int i = 0; i < 30; ++i) {
        c.step({}, {0, -5}, false, {0, 0}, kDt);
    }
    EXPECT_FALSE(c.step({0.0f, true, true}, {0, -5}, false, {0, 0}, kDt).jumped);
    EXPECT_FALSE(c.step({0.0f, false, true}, {0, -5}, false, {0, 0}, kDt).jumped);
    EXPECT_TRUE(c.step({0.0f, false, true}, {0, 0}, true, {0, 0}, kDt).jumped);

    PlayerController early;
    for (int i = 0; i < 30; ++i) {
        early.step({}, {0, -5}, false, {0, 0}, kDt);
    }
    early.step({0.0f, true, true}, {0, -5}, false, {0, 0}, kDt);
    for (int i = 0; i < 10; ++i) { // 0.17 s: past the 0.12 s buffer
        early.step({0.0f, false, true}, {0, -5}, false, {0, 0}, kDt);
    }
    EXPECT_FALSE(early.step({0.0f, false, true}, {0, 0}, true, {0, 0}, kDt).jumped);
}

TEST(PlayerController, NoSecondJumpInTheAirAndReleasingJumpCutsTheRise) {
    PlayerController c;
    auto first = c.step({0.0f, true, true}, {0, 0}, true, {0, 0}, kDt);
    ASSERT_TRUE(first.jumped);
    EXPECT_FALSE(c.step({0.0f, true, true}, first.velocity, false, {0, 0}, kDt).jumped);
    auto cut = c.step({0.0f, false, false}, {0, 8}, false, {0, 0}, kDt);
    EXPECT_FLOAT_EQ(cut.velocity.y, 8.0f * c.tuning().jumpCut);
}

TEST(PlayerController, StandingOnAMovingPlatformCarriesThePlayer) {
    PlayerController c;
    glm::vec2 v{0, 0};
    for (int i = 0; i < 60; ++i) {
        v = c.step({}, v, true, {2.0f, 0.0f}, kDt).velocity;
    }
    EXPECT_FLOAT_EQ(v.x, 2.0f);
    for (int i = 0; i < 60; ++i) {
        v = c.step({1.0f, false, false}, v, true, {2.0f, 0.0f}, kDt).velocity;
    }
    EXPECT_FLOAT_EQ(v.x, 2.0f + c.tuning().runSpeed);
    EXPECT_EQ(c.facing(), 1);
}

} // namespace
