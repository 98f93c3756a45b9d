// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>

#include <gtest/gtest.h>

TEST(Error, CarriesItsMessage) {
    try {
        throw e2d::core::Error("core::test(): bad value 3");
    } catch (const std::exception& e) {
        EXPECT_STREQ(e.what(), "core::test(): bad value 3");
    }
}
