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
    // Rounding may leave the 60th step a hair short; it must not run more than 60 or fewer
    // than 59, and alpha must stay in [0, 1).
    EXPECT_GE(total, 59);
    EXPECT_LE(total, 60);
    EXPECT_GE(stepper.alpha(), 0.0);
    EXPECT_LT(stepper.alpha(), 1.0);
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
                ThrowsMessage<Error>("core::FixedStepper::FixedStepper(): step must be finite and > 0, got 0"));
    EXPECT_THAT([] { FixedStepper s(-0.5, 5); }, ThrowsMessage<Error>(HasSubstr("got -0.5")));
    EXPECT_THAT([] { FixedStepper s(std::numeric_limits<double>::infinity(), 5); },
                ThrowsMessage<Error>(HasSubstr("step must be finite and > 0, got inf")));
    EXPECT_THAT([] { FixedStepper s(0.25, 0); },
                ThrowsMessage<Error>("core::FixedStepper::FixedStepper(): maxStepsPerFrame must be >= 1, got 0"));
}

TEST(FixedStepper, RejectsBadFrameTimeAndStaysUnchanged) {
    FixedStepper stepper(0.25, 4);
    stepper.advance(0.125);
    EXPECT_THAT([&] { stepper.advance(-1.0); },
                ThrowsMessage<Error>("core::FixedStepper::advance(): frameDt must be finite and >= 0, got -1"));
    EXPECT_THROW(stepper.advance(std::numeric_limits<double>::quiet_NaN()), Error);
    EXPECT_EQ(stepper.accumulated(), 0.125);
}
