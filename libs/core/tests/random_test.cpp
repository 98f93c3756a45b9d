// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
#include <e2d/core/random.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

using e2d::core::Error;
using e2d::core::Random;
using testing::ThrowsMessage;

namespace {
constexpr int kIntMin = std::numeric_limits<int>::min();
constexpr int kIntMax = std::numeric_limits<int>::max();
} // namespace

TEST(Random, EngineIsTheStandardMt19937_64) {
    // The C++ standard fixes the 10000th output of a default-seeded (5489) mt19937_64.
    Random random(5489);
    for (int i = 0; i < 9999; ++i) {
        random.next();
    }
    EXPECT_EQ(random.next(), 9981545732273789042ull);
}

TEST(Random, RangeMappingIsPlatformIndependent) {
    // First output of mt19937_64(5489) is 14514284786278117030. For range(0, 9):
    // span 10, rejection threshold 2^64 mod 10 = 6 (draw accepted), 14514284786278117030 mod
    // 10 = 0. For range01(): the top 24 bits, 14514284786278117030 >> 40 = 13200665, / 2^24.
    Random a(5489);
    EXPECT_EQ(a.next(), 14514284786278117030ull);
    Random b(5489);
    EXPECT_EQ(b.range(0, 9), 0);
    Random c(5489);
    EXPECT_EQ(c.range01(), 13200665.0f / 16777216.0f);
    Random d(5489);
    EXPECT_EQ(d.range(100, 109), 100);
}

TEST(Random, SameSeedSameSequence) {
    Random a(42);
    Random b(42);
    for (int i = 0; i < 1000; ++i) {
        ASSERT_EQ(a.range(-1000, 1000), b.range(-1000, 1000));
        ASSERT_EQ(a.range(-1.0f, 1.0f), b.range(-1.0f, 1.0f));
        ASSERT_EQ(a.range01(), b.range01());
    }
}

TEST(Random, ReseedingRestartsTheSequence) {
    Random a(7);
    const int first = a.range(0, 1000000);
    a.range(0, 1000000);
    a.seed(7);
    EXPECT_EQ(a.range(0, 1000000), first);
}

TEST(Random, DifferentSeedsDiffer) {
    Random a(1);
    Random b(2);
    int equal = 0;
    for (int i = 0; i < 100; ++i) {
        equal += a.range(0, 1000000) == b.range(0, 1000000) ? 1 : 0;
    }
    // Two independent streams agree on a draw with probability 1e-6.
    EXPECT_LT(equal, 3);
}

TEST(Random, IntRangeIncludesBothEndsAndIsUniform) {
    Random random(123);
    std::array<int, 6> counts{};
    constexpr int kDraws = 60000;
    for (int i = 0; i < kDraws; ++i) {
        const int v = random.range(1, 6);
        ASSERT_GE(v, 1);
        ASSERT_LE(v, 6);
        ++counts[static_cast<std::size_t>(v - 1)];
    }
    // Expected 10000 each; the standard deviation is sqrt(60000 * 1/6 * 5/6) ~ 91, so +-500
    // is more than 5 sigma.
    for (const int count : counts) {
        EXPECT_NEAR(count, 10000, 500);
    }
}

TEST(Random, DegenerateIntRange) {
    Random random(9);
    for (int i = 0; i < 100; ++i) {
        ASSERT_EQ(random.range(5, 5), 5);
        ASSERT_EQ(random.range(kIntMin, kIntMin), kIntMin);
        ASSERT_EQ(random.range(kIntMax, kIntMax), kIntMax);
    }
}

TEST(Random, IntRangeExtremes) {
    Random random(77);
    bool sawLow = false;
    bool sawHigh = false;
    bool sawMin = false;
    bool sawMinPlusOne = false;
    bool sawNegative = false;
    bool sawPositive = false;
    for (int i = 0; i < 1000; ++i) {
        const int top = random.range(kIntMax - 1, kIntMax);
        ASSERT_TRUE(top == kIntMax - 1 || top == kIntMax);
        (top == kIntMax ? sawHigh : sawLow) = true;

        const int bottom = random.range(kIntMin, kIntMin + 1);
        ASSERT_TRUE(bottom == kIntMin || bottom == kIntMin + 1);
        (bottom == kIntMin ? sawMin : sawMinPlusOne) = true;

        const int any = random.range(kIntMin, kIntMax);
        (any < 0 ? sawNegative : sawPositive) = true;
    }
    EXPECT_TRUE(sawLow && sawHigh && sawMin && sawMinPlusOne);
    EXPECT_TRUE(sawNegative && sawPositive);
}

TEST(Random, FloatRangeIsHalfOpen) {
    Random random(5);
    float lowest = 1e9f;
    float highest = -1e9f;
    for (int i = 0; i < 100000; ++i) {
        const float v = random.range(-2.0f, 3.0f);
        ASSERT_GE(v, -2.0f);
        ASSERT_LT(v, 3.0f);
        lowest = std::min(lowest, v);
        highest = std::max(highest, v);
    }
    // 1e5 uniform draws over a width of 5 come within 0.01 of each end with probability
    // 1 - (1 - 0.002)^1e5, which is 1 for all practical purposes.
    EXPECT_LT(lowest, -1.99f);
    EXPECT_GT(highest, 2.99f);
}

TEST(Random, FloatRangeNeverReturnsMaxEvenWhenOneUlpWide) {
    Random random(11);
    const float min = 1.0f;
    const float max = std::nextafter(1.0f, 2.0f);
    for (int i = 0; i < 1000; ++i) {
        ASSERT_EQ(random.range(min, max), min);
    }
    EXPECT_EQ(random.range(2.5f, 2.5f), 2.5f);
}

TEST(Random, Range01IsOnA24BitGrid) {
    Random random(3);
    for (int i = 0; i < 10000; ++i) {
        const float v = random.range01();
        ASSERT_GE(v, 0.0f);
        ASSERT_LT(v, 1.0f);
        const float scaled = v * 16777216.0f;
        ASSERT_EQ(scaled, std::floor(scaled));
    }
}

TEST(Random, RejectsInvertedOrNonFiniteBounds) {
    Random random(1);
    EXPECT_THAT(
        [&] { random.range(5, 3); },
        ThrowsMessage<Error>("core::Random::range(): min must be <= max, got min 5, max 3"));
    EXPECT_THAT(
        [&] { random.range(1.5f, -1.0f); },
        ThrowsMessage<Error>(
            "core::Random::range(): bounds must be finite with min <= max, got min 1.5, max -1"));
    EXPECT_THROW(random.range(0.0f, std::numeric_limits<float>::infinity()), Error);
    EXPECT_THROW(random.range(std::numeric_limits<float>::quiet_NaN(), 1.0f), Error);
    EXPECT_THAT(
        [&] {
            random.range(-std::numeric_limits<float>::max(), std::numeric_limits<float>::max());
        },
        ThrowsMessage<Error>(testing::HasSubstr("max - min overflows a float")));
}
