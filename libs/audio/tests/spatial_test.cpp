// SPDX-License-Identifier: MIT
// The spatial model's curves against the seed's text, computed here from first principles.
#include <e2d/audio/spatial.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace e2d::audio {
namespace {

SpatialDef def() {
    SpatialDef s;
    s.minAttenuationDistance = 2.0f;
    s.maxAttenuationDistance = 12.0f;
    s.minPanningDistance = 1.0f;
    s.maxPanningDistance = 5.0f;
    return s;
}

TEST(Spatial, AttenuationIsLinearBetweenMinAndTheScaledMax) {
    const SpatialDef s = def();
    EXPECT_EQ(attenuationGain(s, 0.0f, 1.0f), 1.0f);
    EXPECT_EQ(attenuationGain(s, 2.0f, 1.0f), 1.0f);
    EXPECT_FLOAT_EQ(attenuationGain(s, 4.5f, 1.0f), 0.75f);
    EXPECT_FLOAT_EQ(attenuationGain(s, 7.0f, 1.0f), 0.5f);
    EXPECT_EQ(attenuationGain(s, 12.0f, 1.0f), 0.0f);
    EXPECT_EQ(attenuationGain(s, 1e9f, 1.0f), 0.0f);
    // Factor 2: range 10 / 2 = 5, silent from 7 on; factor 0.5: range 20.
    EXPECT_FLOAT_EQ(attenuationGain(s, 4.5f, 2.0f), 0.5f);
    EXPECT_EQ(attenuationGain(s, 7.0f, 2.0f), 0.0f);
    EXPECT_FLOAT_EQ(attenuationGain(s, 12.0f, 0.5f), 0.5f);
    EXPECT_EQ(attenuationGain(s, 1e9f, 0.0f), 1.0f);
}

TEST(Spatial, PanningIsEqualPowerAndFullAtMax) {
    const SpatialDef s = def();
    for (float x : {0.0f, 0.5f, -1.0f}) {
        const StereoGains g = panGains(s, x);
        EXPECT_FLOAT_EQ(g.left, std::numbers::sqrt2_v<float> / 2) << x;
        EXPECT_FLOAT_EQ(g.right, std::numbers::sqrt2_v<float> / 2) << x;
    }
    for (float x : {5.0f, 6.0f, 1e30f}) {
        const StereoGains g = panGains(s, x);
        EXPECT_EQ(g.left, 0.0f);
        EXPECT_EQ(g.right, 1.0f);
        const StereoGains m = panGains(s, -x);
        EXPECT_EQ(m.left, 1.0f);
        EXPECT_EQ(m.right, 0.0f);
    }
    for (float x = -6.0f; x <= 6.0f; x += 0.25f) {
        const StereoGains g = panGains(s, x);
        EXPECT_NEAR(g.left * g.left + g.right * g.right, 1.0f, 1e-6f) << x;
    }
    // x = 2 is a quarter of the way from 1 to 5: p = 0.25, angle = 1.25 pi / 4.
    const StereoGains q = panGains(s, 2.0f);
    EXPECT_NEAR(q.left, std::cos(1.25 * std::numbers::pi / 4), 1e-6);
    EXPECT_NEAR(q.right, std::sin(1.25 * std::numbers::pi / 4), 1e-6);
}

TEST(Spatial, ListenerSpaceTurnsWithTheListener) {
    const glm::vec2 o = listenerSpaceOffset({3.0f, 5.0f}, {1.0f, 1.0f}, 0.0f);
    EXPECT_EQ(o, glm::vec2(2.0f, 4.0f));
    // Turned half a turn: left and right swap.
    const glm::vec2 h = listenerSpaceOffset({3.0f, 1.0f}, {1.0f, 1.0f}, std::numbers::pi_v<float>);
    EXPECT_NEAR(h.x, -2.0f, 1e-5f);
    EXPECT_NEAR(h.y, 0.0f, 1e-5f);
}

} // namespace
} // namespace e2d::audio
