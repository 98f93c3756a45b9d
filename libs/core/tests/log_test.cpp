// SPDX-License-Identifier: MIT
#include <e2d/core/log.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

using e2d::core::Logger;
using e2d::core::LogLevel;

namespace {

struct Captured {
    std::vector<std::pair<LogLevel, std::string>> messages;
    Logger::Sink sink() {
        return [this](LogLevel level, std::string_view message) {
            messages.emplace_back(level, std::string(message));
        };
    }
};

} // namespace

TEST(Logger, DefaultsToInfo) {
    const Logger logger;
    EXPECT_EQ(logger.level(), LogLevel::Info);
    EXPECT_FALSE(logger.enabled(LogLevel::Debug));
    EXPECT_TRUE(logger.enabled(LogLevel::Info));
    EXPECT_TRUE(logger.enabled(LogLevel::Error));
}

TEST(Logger, CustomSinkReceivesMessagesAtOrAboveTheLevel) {
    Captured captured;
    Logger logger(LogLevel::Warning, captured.sink());
    logger.trace("t");
    logger.debug("d");
    logger.info("i");
    logger.warning("w");
    logger.error("e");
    ASSERT_EQ(captured.messages.size(), 2u);
    EXPECT_EQ(captured.messages[0], std::make_pair(LogLevel::Warning, std::string("w")));
    EXPECT_EQ(captured.messages[1], std::make_pair(LogLevel::Error, std::string("e")));
}

TEST(Logger, TraceLevelLetsEverythingThrough) {
    Captured captured;
    Logger logger(LogLevel::Trace, captured.sink());
    logger.trace("a");
    logger.debug("b");
    logger.log(LogLevel::Info, "c");
    ASSERT_EQ(captured.messages.size(), 3u);
    EXPECT_EQ(captured.messages[0].first, LogLevel::Trace);
    EXPECT_EQ(captured.messages[2].second, "c");
}

TEST(Logger, OffSilencesEverythingAndIsNeverSent) {
    Captured captured;
    Logger logger(LogLevel::Off, captured.sink());
    logger.error("e");
    logger.log(LogLevel::Off, "off");
    EXPECT_TRUE(captured.messages.empty());

    logger.setLevel(LogLevel::Trace);
    logger.log(LogLevel::Off, "off");
    EXPECT_TRUE(captured.messages.empty());
    EXPECT_FALSE(logger.enabled(LogLevel::Off));
}

TEST(Logger, LevelCanBeChanged) {
    Captured captured;
    Logger logger(LogLevel::Error, captured.sink());
    logger.warning("dropped");
    logger.setLevel(LogLevel::Debug);
    logger.debug("kept");
    ASSERT_EQ(captured.messages.size(), 1u);
    EXPECT_EQ(captured.messages[0].second, "kept");
}

TEST(Logger, DefaultSinkWritesLevelAndMessageToStderr) {
    Logger logger;
    testing::internal::CaptureStderr();
    logger.warning("disk almost full");
    const std::string out = testing::internal::GetCapturedStderr();
    EXPECT_EQ(out, "[warning] disk almost full\n");
}

TEST(Logger, EmptySinkRestoresTheDefault) {
    Captured captured;
    Logger logger(LogLevel::Info, captured.sink());
    logger.setSink({});
    testing::internal::CaptureStderr();
    logger.error("x");
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "[error] x\n");
    EXPECT_TRUE(captured.messages.empty());
}

TEST(Logger, LevelNames) {
    EXPECT_EQ(e2d::core::toString(LogLevel::Trace), "trace");
    EXPECT_EQ(e2d::core::toString(LogLevel::Warning), "warning");
    EXPECT_EQ(e2d::core::toString(LogLevel::Off), "off");
}
