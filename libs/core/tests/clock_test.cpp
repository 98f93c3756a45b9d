// SPDX-License-Identifier: MIT
#include <e2d/core/clock.hpp>
#include <e2d/core/error.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

using e2d::core::Clock;
using testing::HasSubstr;

namespace {

// Binary fractions only, so every expected value below is exact.
struct ManualTime {
    double now = 100.0; // an arbitrary origin: only differences matter
    Clock::TimeSource source() {
        return [this] { return now; };
    }
};

} // namespace

TEST(Clock, StartsAtZero) {
    ManualTime t;
    const Clock clock(t.source());
    EXPECT_EQ(clock.time(), 0.0);
    EXPECT_EQ(clock.unscaledTime(), 0.0);
    EXPECT_EQ(clock.timeScale(), 1.0);
}

TEST(Clock, UnscaledFollowsTheSource) {
    ManualTime t;
    const Clock clock(t.source());
    t.now += 2.5;
    EXPECT_EQ(clock.unscaledTime(), 2.5);
    EXPECT_EQ(clock.time(), 2.5);
}

TEST(Clock, HalfScaleHalvesTime) {
    // The seed's example: scale 0.5, 10 s elapsed -> 5 s of game time.
    ManualTime t;
    Clock clock(t.source());
    clock.setTimeScale(0.5);
    t.now += 10.0;
    EXPECT_EQ(clock.time(), 5.0);
    EXPECT_EQ(clock.unscaledTime(), 10.0);
}

TEST(Clock, ChangingTheScaleDoesNotMakeTimeJump) {
    ManualTime t;
    Clock clock(t.source());
    t.now += 4.0; // 4 s at scale 1
    clock.setTimeScale(2.0);
    EXPECT_EQ(clock.time(), 4.0);
    t.now += 1.5; // 1.5 s at scale 2 -> +3
    EXPECT_EQ(clock.time(), 7.0);
    clock.setTimeScale(0.0); // paused
    t.now += 100.0;
    EXPECT_EQ(clock.time(), 7.0);
    EXPECT_EQ(clock.unscaledTime(), 105.5);
}

TEST(Clock, TickReturnsScaledDeltaSinceTheLastTick) {
    ManualTime t;
    Clock clock(t.source());
    t.now += 0.25;
    EXPECT_EQ(clock.tick(), 0.25);
    EXPECT_EQ(clock.unscaledDelta(), 0.25);
    clock.setTimeScale(0.5);
    t.now += 0.5;
    EXPECT_EQ(clock.tick(), 0.25);
    EXPECT_EQ(clock.unscaledDelta(), 0.5);
    EXPECT_EQ(clock.tick(), 0.0);
}

TEST(Clock, ScaleChangeBetweenTicksSplitsTheDelta) {
    ManualTime t;
    Clock clock(t.source());
    clock.tick();
    t.now += 1.0; // 1 s at scale 1
    clock.setTimeScale(3.0);
    t.now += 0.5; // 0.5 s at scale 3
    EXPECT_EQ(clock.tick(), 2.5);
}

TEST(Clock, SourceGoingBackwardsStandsStill) {
    ManualTime t;
    Clock clock(t.source());
    t.now += 2.0;
    EXPECT_EQ(clock.tick(), 2.0);
    t.now -= 1.0;
    EXPECT_EQ(clock.tick(), 0.0);
    EXPECT_EQ(clock.time(), 2.0);
    t.now += 1.5; // 0.5 s past the previous high mark
    EXPECT_EQ(clock.tick(), 0.5);
}

TEST(Clock, RejectsBadScaleAndKeepsTheOldOne) {
    ManualTime t;
    Clock clock(t.source());
    clock.setTimeScale(2.0);
    try {
        clock.setTimeScale(-1.0);
        FAIL() << "expected core::Error";
    } catch (const e2d::core::Error& e) {
        EXPECT_STREQ(e.what(),
                     "core::Clock::setTimeScale(): scale must be finite and >= 0, got -1");
    }
    EXPECT_THROW(clock.setTimeScale(std::numeric_limits<double>::infinity()), e2d::core::Error);
    EXPECT_THROW(clock.setTimeScale(std::numeric_limits<double>::quiet_NaN()), e2d::core::Error);
    EXPECT_EQ(clock.timeScale(), 2.0);
}

TEST(Clock, RejectsAnEmptySource) {
    EXPECT_THAT(
        [] { Clock clock{Clock::TimeSource{}}; },
        testing::ThrowsMessage<e2d::core::Error>(HasSubstr("time source must not be empty")));
}

TEST(Clock, DefaultSourceIsMonotonic) {
    Clock clock;
    const double a = clock.unscaledTime();
    const double b = clock.unscaledTime();
    EXPECT_GE(a, 0.0);
    EXPECT_GE(b, a);
    EXPECT_GE(clock.tick(), 0.0);
}
