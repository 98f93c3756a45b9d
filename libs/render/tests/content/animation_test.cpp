// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
#include <e2d/render/animation.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

using e2d::core::Error;
using e2d::render::Animation;
using e2d::render::AnimationDef;
using e2d::render::AnimationMode;

namespace {

// The frame shown after `steps` whole frame durations, from first principles: where the
// sequence of frames for each mode stands after that many steps.
struct Expected {
    int frame;
    bool finished;
};

Expected afterSteps(int n, int start, AnimationMode mode, std::int64_t steps) {
    switch (mode) {
    case AnimationMode::Loop:
        return {static_cast<int>((start + steps) % n), false};
    case AnimationMode::Once:
        // Frames start..n-1 each shown one duration; finished once n-1 had its own.
        if (start + steps <= n - 1) {
            return {static_cast<int>(start + steps), false};
        }
        return {n - 1, true};
    case AnimationMode::PingPong: {
        // Walk the sequence one frame at a time.
        int frame = start;
        int direction = 1;
        for (std::int64_t i = 0; i < steps && n > 1; ++i) {
            if (frame + direction < 0 || frame + direction >= n) {
                direction = -direction;
            }
            frame += direction;
        }
        return {frame, false};
    }
    }
    return {-1, false};
}

std::string errorOf(const AnimationDef& def) {
    try {
        Animation a(def);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

} // namespace

TEST(Animation, EveryModeFrameCountStartAndUpdatePatternMatchesTheSequence) {
    // Durations and time steps are multiples of 1/64 s, exact in binary, so the total time in
    // frame durations is exact and the expected frame follows from it alone.
    std::mt19937 rng(12345);
    const double duration = 0.25;
    for (AnimationMode mode : {AnimationMode::Loop, AnimationMode::Once, AnimationMode::PingPong}) {
        for (int n = 1; n <= 7; ++n) {
            for (int start = 0; start < n; ++start) {
                for (int pattern = 0; pattern < 8; ++pattern) {
                    Animation anim({.frameCount = n,
                                    .frameDuration = duration,
                                    .startFrame = start,
                                    .mode = mode});
                    std::int64_t sixtyFourths = 0;
                    for (int update = 0; update < 60; ++update) {
                        // Small steps, exact one-frame steps and long steps that skip several frames.
                        const int kind = static_cast<int>(rng() % 3);
                        const int dt64 = kind == 0
                                             ? static_cast<int>(rng() % 16)
                                             : (kind == 1 ? 16 : static_cast<int>(rng() % 200));
                        anim.update(dt64 / 64.0);
                        sixtyFourths += dt64;
                        const Expected e = afterSteps(n, start, mode, sixtyFourths / 16);
                        ASSERT_EQ(anim.frame(), e.frame)
                            << "mode " << static_cast<int>(mode) << " n " << n << " start " << start
                            << " time " << sixtyFourths / 64.0;
                        ASSERT_EQ(anim.finished(), e.finished);
                        if (!e.finished) {
                            ASSERT_DOUBLE_EQ(anim.timeInFrame(), (sixtyFourths % 16) / 64.0);
                            ASSERT_EQ(anim.framesAdvanced(), sixtyFourths / 16);
                        }
                    }
                }
            }
        }
    }
}

TEST(Animation, AnUpdateOfExactlyOneFrameDurationMovesOneFrame) {
    // The seed compared with '>' and showed frame 0 twice here.
    Animation anim({.frameCount = 4, .frameDuration = 0.1});
    for (int i = 1; i <= 10; ++i) {
        anim.update(0.1);
        EXPECT_EQ(anim.frame(), i % 4) << "after " << i << " updates of 0.1 s";
    }
}

TEST(Animation, DecimalSumsDoNotLoseAFrameToRounding) {
    // 0.1 + 0.2 is 0.30000000000000004 and 0.7 * 3 is 2.0999999999999996 in binary: both must
    // count as 3 frames of 0.1 and 21 of 0.1.
    Animation a({.frameCount = 100, .frameDuration = 0.1});
    a.update(0.1);
    a.update(0.2);
    EXPECT_EQ(a.frame(), 3);
    Animation b({.frameCount = 100, .frameDuration = 0.1});
    for (int i = 0; i < 3; ++i) {
        b.update(0.7);
    }
    EXPECT_EQ(b.frame(), 21);
}

TEST(Animation, ALongFrameTimeSkipsTheRightNumberOfFrames) {
    Animation loop({.frameCount = 5, .frameDuration = 0.5});
    loop.update(3.75); // 7.5 durations: 7 frames on, half a frame left
    EXPECT_EQ(loop.frame(), 7 % 5);
    EXPECT_DOUBLE_EQ(loop.timeInFrame(), 0.25);
    loop.update(0.25);
    EXPECT_EQ(loop.frame(), 8 % 5);

    Animation once(
        {.frameCount = 5, .frameDuration = 0.5, .startFrame = 1, .mode = AnimationMode::Once});
    once.update(1.5);
    EXPECT_EQ(once.frame(), 4);
    EXPECT_FALSE(once.finished());
    once.update(0.5);
    EXPECT_TRUE(once.finished());
    once.update(100.0);
    EXPECT_EQ(once.frame(), 4);

    Animation ping({.frameCount = 4, .frameDuration = 1.0, .mode = AnimationMode::PingPong});
    ping.update(4.0); // 0 1 2 3 2
    EXPECT_EQ(ping.frame(), 2);
    ping.update(3.0); // 1 0 1
    EXPECT_EQ(ping.frame(), 1);
}

TEST(Animation, HugeTimeStepsStayInRange) {
    Animation loop({.frameCount = 7, .frameDuration = 1.0e-6});
    loop.update(1.0e12);
    EXPECT_GE(loop.frame(), 0);
    EXPECT_LT(loop.frame(), 7);
    Animation ping({.frameCount = 7, .frameDuration = 1.0e-6, .mode = AnimationMode::PingPong});
    ping.update(1.0e15);
    EXPECT_GE(ping.frame(), 0);
    EXPECT_LT(ping.frame(), 7);
    EXPECT_GT(ping.framesAdvanced(), 0);
}

TEST(Animation, SpeedScalesTimeAndZeroHolds) {
    Animation anim({.frameCount = 10, .frameDuration = 0.25, .speed = 2.0});
    anim.update(0.5); // 1 s of animation time
    EXPECT_EQ(anim.frame(), 4);
    anim.setSpeed(0.0);
    anim.update(10.0);
    EXPECT_EQ(anim.frame(), 4);
    anim.setSpeed(0.5);
    anim.update(1.0);
    EXPECT_EQ(anim.frame(), 6);
}

TEST(Animation, RestartAndSetFrame) {
    Animation anim(
        {.frameCount = 3, .frameDuration = 1.0, .startFrame = 1, .mode = AnimationMode::Once});
    anim.update(5.0);
    EXPECT_TRUE(anim.finished());
    anim.restart();
    EXPECT_EQ(anim.frame(), 1);
    EXPECT_FALSE(anim.finished());
    EXPECT_EQ(anim.framesAdvanced(), 0);
    anim.setFrame(0);
    anim.update(1.0);
    EXPECT_EQ(anim.frame(), 1);

    // A ping-pong set to its last frame runs down.
    Animation ping({.frameCount = 4, .frameDuration = 1.0, .mode = AnimationMode::PingPong});
    ping.setFrame(3);
    ping.update(1.0);
    EXPECT_EQ(ping.frame(), 2);
}

TEST(Animation, InvalidDefinitionsAndArgumentsNameFieldAndValue) {
    EXPECT_EQ(errorOf({.frameCount = 0}),
              "render::Animation::Animation(): frameCount must be >= 1, got 0");
    EXPECT_EQ(errorOf({.frameDuration = 0.0}),
              "render::Animation::Animation(): frameDuration must be finite and > 0, got 0");
    EXPECT_EQ(errorOf({.frameDuration = std::numeric_limits<double>::infinity()}),
              "render::Animation::Animation(): frameDuration must be finite and > 0, got inf");
    EXPECT_EQ(errorOf({.frameCount = 3, .startFrame = 3}),
              "render::Animation::Animation(): startFrame must be in [0, 3), got 3");
    EXPECT_EQ(errorOf({.frameCount = 3, .startFrame = -1}),
              "render::Animation::Animation(): startFrame must be in [0, 3), got -1");
    EXPECT_EQ(errorOf({.speed = -1.0}),
              "render::Animation::Animation(): speed must be finite and >= 0, got -1");

    Animation anim({.frameCount = 2});
    EXPECT_THROW(anim.update(-0.5), Error);
    EXPECT_THROW(anim.update(std::nan("")), Error);
    EXPECT_THROW(anim.setFrame(2), Error);
    EXPECT_THROW(anim.setSpeed(std::nan("")), Error);
    try {
        anim.update(-0.5);
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "render::Animation::update(): dt must be finite and >= 0, got -0.5");
    }
    EXPECT_EQ(anim.frame(), 0);
}
