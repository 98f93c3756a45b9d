// SPDX-License-Identifier: MIT
// e2d platformer: run right, jump, collect the coins, ride the lift, reach the flag.
#include "scenes.hpp"

#include <e2d/engine/game.hpp>

#include <iostream>

int main(int argc, char** argv) {
    platformer::Session session;
    e2d::engine::Game game;
    platformer::registerScenes(game.scenes(), session);
    const int code = game.run(argc, argv, "config.txt");
    if (session.runs > 0 || session.lastScene != "TitleScene") {
        std::cout << platformer::stateLine(session) << '\n';
    }
    return code;
}
