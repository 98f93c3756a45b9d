// SPDX-License-Identifier: MIT
// game_system.hpp is "the one include" of a scene: this file includes nothing else of e2d, so
// it stops compiling when something a scene needs is reached only by luck.
#include <e2d/engine/game_system.hpp>

#include <gtest/gtest.h>

#include <string>

namespace {

TEST(GameSystemInclude, GivesCoreErrorToCatch) {
    try {
        throw e2d::core::Error("engine test: thrown");
    } catch (const e2d::core::Error& error) {
        EXPECT_EQ(std::string(error.what()), "engine test: thrown");
    }
}

} // namespace
