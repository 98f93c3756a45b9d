// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
#include <e2d/core/mask.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

using e2d::core::Error;
using e2d::core::Mask;
using e2d::core::MaskRegistry;
using testing::ThrowsMessage;

TEST(Mask, MatchesWhenABitIsShared) {
    const Mask a(0b0011);
    const Mask b(0b0110);
    const Mask c(0b1000);
    EXPECT_TRUE(a.matches(b));
    EXPECT_TRUE(b.matches(a));
    EXPECT_FALSE(a.matches(c));
    EXPECT_FALSE(Mask().matches(Mask::all()));
    EXPECT_TRUE(Mask::all().matches(c));
}

TEST(Mask, PlusIsUnion) {
    const Mask a(0b01);
    const Mask b(0b10);
    const Mask c = a + b;
    EXPECT_EQ(c.bits(), 0b11u);
    EXPECT_EQ(c, a | b);
    // The seed's property: a combination matches both parts even if they do not match each other.
    EXPECT_FALSE(a.matches(b));
    EXPECT_TRUE(c.matches(a));
    EXPECT_TRUE(c.matches(b));

    Mask d(0b100);
    d += a;
    EXPECT_EQ(d.bits(), 0b101u);
    d |= b;
    EXPECT_EQ(d.bits(), 0b111u);
    EXPECT_NE(d, c);
    EXPECT_TRUE(Mask().empty());
}

TEST(MaskRegistry, CreatesConsecutiveBits) {
    MaskRegistry masks;
    EXPECT_EQ(masks.create("player").bits(), 1u);
    EXPECT_EQ(masks.create("enemy").bits(), 2u);
    EXPECT_EQ(masks.create("ground").bits(), 4u);
    EXPECT_EQ(masks.size(), 3);
}

TEST(MaskRegistry, CreatingAnExistingNameReturnsTheSameMask) {
    MaskRegistry masks;
    const Mask player = masks.create("player");
    masks.create("enemy");
    EXPECT_EQ(masks.create("player"), player);
    EXPECT_EQ(masks.size(), 2);
}

TEST(MaskRegistry, GetAndContains) {
    MaskRegistry masks;
    masks.create("a");
    const Mask b = masks.create("b");
    EXPECT_EQ(masks.get("b"), b);
    EXPECT_TRUE(masks.contains("a"));
    EXPECT_FALSE(masks.contains("c"));
    EXPECT_THAT([&] { (void)masks.get("c"); },
                ThrowsMessage<Error>("core::MaskRegistry::get(): no mask named 'c'"));
    EXPECT_THAT([&] { masks.create(""); },
                ThrowsMessage<Error>("core::MaskRegistry::create(): name must not be empty"));
}

TEST(MaskRegistry, SixtyFourMasksAtMost) {
    MaskRegistry masks;
    for (int i = 0; i < MaskRegistry::kMaxMasks; ++i) {
        // Appended, not "m" + to_string(i): GCC 12 at -O3 warns (-Wrestrict) about the
        // inlined insert of operator+(const char*, std::string&&), a known false positive.
        std::string name = "m";
        name += std::to_string(i);
        ASSERT_EQ(masks.create(name).bits(), std::uint64_t{1} << i);
    }
    EXPECT_EQ(masks.get("m63").bits(), std::uint64_t{1} << 63);
    EXPECT_THAT(
        [&] { masks.create("one-too-many"); },
        ThrowsMessage<Error>("core::MaskRegistry::create(): cannot create mask 'one-too-many', "
                             "the limit of 64 masks is reached"));
    EXPECT_EQ(masks.size(), 64);
    EXPECT_FALSE(masks.contains("one-too-many"));
    // Existing names are still fine at the limit.
    EXPECT_EQ(masks.create("m0").bits(), 1u);
}
