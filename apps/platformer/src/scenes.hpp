// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/scene_registry.hpp>

#include <string>

/// The platformer's scenes: title, level, game over and win. They share one Session, owned by
/// main() and handed to the scenes' factories (no global state), which also gives main() the
/// state line it prints at exit.
namespace platformer {

/// What the runs so far came to, shared by the scenes.
struct Session {
    std::string lastScene = "TitleScene"; ///< the scene running when the game stopped
    int score = 0;                        ///< coins collected in the last run of the level
    int coinCount = 0;                    ///< coins in the level
    int coinVoices = 0;                   ///< coin sounds that started on a voice, over every run
    int jumps = 0;                        ///< jumps in the last run
    int runs = 0;                         ///< times the level was started
    int deaths = 0;
    int wins = 0;
    double levelTime = 0.0; ///< seconds of level time in the last run
    int stepsOnMovingPlatform = 0;
    int stepsOnOneWay = 0;
    bool musicStreaming = false; ///< the level's music was playing as a stream
    /// Bodies in the physics world once the last run's level joined its scene (the level
    /// makes 19: a static body per static collider (9 terrain segments, spikes, 4 coins, goal,
    /// one-way platform), lift, shuttle, player; more means an earlier run left some behind).
    int levelBodies = 0;
};

/// The line main() prints at exit, for tests and curious players:
/// `platformer: scene=WinScene score=3/4 coin_voices=3 jumps=3 runs=1 deaths=0 wins=1 ...`.
[[nodiscard]] std::string stateLine(const Session& session);

/// Registers TitleScene, LevelScene, GameOverScene and WinScene, each using `session`.
void registerScenes(e2d::core::SceneRegistry& registry, Session& session);

} // namespace platformer
