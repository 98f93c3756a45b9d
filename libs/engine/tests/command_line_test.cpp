// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
#include <e2d/engine/command_line.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using namespace e2d;
using engine::CommandLine;
using engine::parseCommandLine;

CommandLine parse(std::vector<std::string_view> args) { return parseCommandLine(args); }

std::string errorOf(std::vector<std::string_view> args) {
    try {
        static_cast<void>(parse(args));
    } catch (const core::Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(CommandLine, NothingGivesTheDefaults) {
    const CommandLine c = parse({});
    EXPECT_FALSE(c.frames.has_value());
    EXPECT_TRUE(c.screenshot.empty());
    EXPECT_TRUE(c.config.empty());
    EXPECT_FALSE(c.seed.has_value());
    EXPECT_TRUE(c.inputScript.empty());
    EXPECT_FALSE(c.debugDraw);
    EXPECT_FALSE(c.profile);
    EXPECT_FALSE(c.show);
    EXPECT_FALSE(c.help);
}

TEST(CommandLine, EveryOptionInBothSpellings) {
    const CommandLine c = parse({"--frames", "300", "--screenshot=out/shot.png", "--config",
                                 "my game.txt", "--seed=42", "--input-script", "run.txt",
                                 "--debug-draw", "--profile", "--show", "-h"});
    EXPECT_EQ(c.frames, 300);
    EXPECT_EQ(c.screenshot, "out/shot.png");
    EXPECT_EQ(c.config, "my game.txt");
    EXPECT_EQ(c.seed, 42u);
    EXPECT_EQ(c.inputScript, "run.txt");
    EXPECT_TRUE(c.debugDraw);
    EXPECT_TRUE(c.profile);
    EXPECT_TRUE(c.show);
    EXPECT_TRUE(c.help);
    EXPECT_EQ(parse({"--frames=1"}).frames, 1);
    EXPECT_EQ(parse({"--seed", "18446744073709551615"}).seed, 18446744073709551615u);
    EXPECT_TRUE(parse({"--help"}).help);
}

TEST(CommandLine, ErrorsNameTheArgument) {
    EXPECT_EQ(errorOf({"--frames", "ten"}), "--frames: expected a whole number >= 1, got 'ten'");
    EXPECT_EQ(errorOf({"--frames", "0"}), "--frames: expected a whole number >= 1, got '0'");
    EXPECT_EQ(errorOf({"--frames", "-5"}), "--frames: expected a whole number >= 1, got '-5'");
    EXPECT_EQ(errorOf({"--frames", "12.5"}), "--frames: expected a whole number >= 1, got '12.5'");
    EXPECT_EQ(errorOf({"--seed", "-1"}), "--seed: expected a whole number >= 0, got '-1'");
    EXPECT_EQ(errorOf({"--screenshot"}), "--screenshot: missing value");
    EXPECT_EQ(errorOf({"--config="}), "--config: missing value");
    EXPECT_EQ(errorOf({"--fast"}), "unknown argument '--fast'");
    EXPECT_EQ(errorOf({"level2"}), "unknown argument 'level2'");
    EXPECT_EQ(errorOf({"--show=yes"}), "--show: takes no value");
}

TEST(CommandLine, UsageListsEveryOption) {
    const std::string text = engine::usage("e2d_demo");
    for (const char* option : {"--config", "--frames", "--screenshot", "--seed", "--input-script",
                               "--debug-draw", "--profile", "--show", "--help"}) {
        EXPECT_THAT(text, testing::HasSubstr(option));
    }
    EXPECT_THAT(text, testing::StartsWith("usage: e2d_demo"));
}

} // namespace
