// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
#include <e2d/core/fixed_stepper.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

using e2d::core::Error;
using e2d::core::FixedStepper;
using testing::HasSubstr;
using testing::ThrowsMessage;

// Step 0.25 and binary-fraction frame times keep every expected value exact.

TEST(FixedStepper, AccumulatesUntilAStepIsDue) {
    FixedStepper stepper(0.25, 4);
    EXPECT_EQ(stepper.advance(0.125), 0);
    EXPECT_EQ(stepper.alpha(), 0.5);
    EXPECT_EQ(stepper.advance(0.125), 1);
    EXPECT_EQ(stepper.alpha(), 0.0);
    EXPECT_EQ(stepper.accumulated(), 0.0);
}

TEST(FixedStepper, SeveralStepsInOneFrame) {
    FixedStepper stepper(0.25, 4);
    EXPECT_EQ(stepper.advance(0.875), 3); // 3 steps, 0.125 left
    EXPECT_EQ(stepper.alpha(), 0.5);
    EXPECT_EQ(stepper.droppedTime(), 0.0);
}

TEST(FixedStepper, ZeroFrameTimeRunsNothing) {
    FixedStepper stepper(0.25, 4);
    EXPECT_EQ(stepper.advance(0.0), 0);
    EXPECT_EQ(stepper.alpha(), 0.0);
}

TEST(FixedStepper, ClampsToMaxStepsAndDropsWholeSteps) {
    FixedStepper stepper(0.25, 3);
    // 2.125 s is 8 steps + 0.125: 3 run, 5 steps (1.25 s) dropped, the 0.125 remainder kept.
    EXPECT_EQ(stepper.advance(2.125), 3);
    EXPECT_EQ(stepper.droppedTime(), 1.25);
    EXPECT_EQ(stepper.totalDroppedTime(), 1.25);
    EXPECT_EQ(stepper.accumulated(), 0.125);
    EXPECT_EQ(stepper.alpha(), 0.5);

    // The next frame starts from the remainder only: no spiral of death.
    EXPECT_EQ(stepper.advance(0.125), 1);
    EXPECT_EQ(stepper.droppedTime(), 0.0);
    EXPECT_EQ(stepper.totalDroppedTime(), 1.25);
}

TEST(FixedStepper, ExactlyMaxStepsDropsNothing) {
    FixedStepper stepper(0.25, 2);
    EXPECT_EQ(stepper.advance(0.5), 2);
    EXPECT_EQ(stepper.droppedTime(), 0.0);
    EXPECT_EQ(stepper.alpha(), 0.0);
}

TEST(FixedStepper, SixtyHertzOverOneSecondRunsSixtySteps) {
    FixedStepper stepper(1.0 / 60.0, 5);
    int total = 0;
    for (int frame = 0; frame < 60; ++frame) {
        total += stepper.advance(1.0 / 60.0);
    }
    EXPECT_EQ(total, 60);
    EXPECT_GE(stepper.alpha(), 0.0);
    EXPECT_LT(stepper.alpha(), 1.0);
}

TEST(FixedStepper, ExactSixtyHertzFramesRunOneStepEachForAnHour) {
    // 1/60 is not exact in binary: without the tolerance some frames ran none and some two.
    for (const double step : {1.0 / 60.0, 1.0 / 120.0 * 2.0, 0.1}) {
        FixedStepper stepper(step, 5);
        int frames = 0;
        for (int frame = 0; frame < 60 * 3600; ++frame) {
            frames += stepper.advance(step) == 1 ? 1 : 0;
        }
        EXPECT_EQ(frames, 60 * 3600) << step;
        EXPECT_LT(stepper.accumulated(), step * 1e-6);
    }
}

TEST(FixedStepper, FramesOfAClockReadingGiveOneStepEach) {
    // The loop's dt is a difference of clock readings: (n + 1) / 60 - n / 60 rounds
    // differently every frame, and grows less exact as the time grows.
    FixedStepper stepper(1.0 / 60.0, 5);
    double previous = 0.0;
    int wrong = 0;
    for (int frame = 1; frame <= 60 * 600; ++frame) {
        const double now = 1000.0 + frame / 60.0;
        wrong += stepper.advance(frame == 1 ? 1.0 / 60.0 : now - previous) == 1 ? 0 : 1;
        previous = now;
    }
    EXPECT_EQ(wrong, 0);
}

TEST(FixedStepper, HalfStepFramesAlternate) {
    FixedStepper stepper(1.0 / 60.0, 5);
    int total = 0;
    for (int frame = 0; frame < 1200; ++frame) {
        const int steps = stepper.advance(1.0 / 120.0);
        EXPECT_EQ(steps, frame % 2) << frame;
        total += steps;
    }
    EXPECT_EQ(total, 600);
}

TEST(FixedStepper, ResetForgetsLeftoverAndDroppedTime) {
    FixedStepper stepper(0.25, 1);
    stepper.advance(1.125);
    stepper.reset();
    EXPECT_EQ(stepper.accumulated(), 0.0);
    EXPECT_EQ(stepper.totalDroppedTime(), 0.0);
}

TEST(FixedStepper, ValidatesConstructorArguments) {
    EXPECT_THAT([] { FixedStepper s(0.0, 5); },
                ThrowsMessage<Error>(
                    "core::FixedStepper::FixedStepper(): step must be finite and > 0, got 0"));
    EXPECT_THAT([] { FixedStepper s(-0.5, 5); }, ThrowsMessage<Error>(HasSubstr("got -0.5")));
    EXPECT_THAT([] { FixedStepper s(std::numeric_limits<double>::infinity(), 5); },
                ThrowsMessage<Error>(HasSubstr("step must be finite and > 0, got inf")));
    EXPECT_THAT([] { FixedStepper s(0.25, 0); },
                ThrowsMessage<Error>(
                    "core::FixedStepper::FixedStepper(): maxStepsPerFrame must be >= 1, got 0"));
}

TEST(FixedStepper, RejectsBadFrameTimeAndStaysUnchanged) {
    FixedStepper stepper(0.25, 4);
    stepper.advance(0.125);
    EXPECT_THAT([&] { stepper.advance(-1.0); },
                ThrowsMessage<Error>(
                    "core::FixedStepper::advance(): frameDt must be finite and >= 0, got -1"));
    EXPECT_THROW(stepper.advance(std::numeric_limits<double>::quiet_NaN()), Error);
    EXPECT_EQ(stepper.accumulated(), 0.125);
}
