// SPDX-License-Identifier: MIT
// Streaming: identical to the whole sound, seamless loops, long frames, broken streams.
#include "audio_test_support.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace e2d::audio {
namespace {

using namespace test;
using ::testing::HasSubstr;

std::vector<float> renderSound(const std::filesystem::path& path, LoadMode mode, double seconds,
                               bool loop, int* underruns = nullptr) {
    Rig rig;
    const SoundId sound = rig.mixer.load(path, mode);
    EXPECT_TRUE(rig.mixer.soundInfo(sound).ok()) << rig.mixer.soundInfo(sound).error;
    PlayDef play;
    play.loop = loop;
    EXPECT_FALSE(rig.mixer.play(sound, play).isNull());
    auto out = rig.render(seconds, 1.0 / 60.0);
    if (underruns != nullptr) {
        *underruns = rig.mixer.stats().streamUnderruns;
    }
    return out;
}

TEST(Stream, RendersSampleIdenticalToTheWholeSound) {
    // 1.37 s: not a whole number of 0.1 s chunks. Stereo with different channels, and mono.
    for (int channels : {2, 1}) {
        const auto path = writeSound("identical" + std::to_string(channels) + ".flac",
                                     SF_FORMAT_FLAC | SF_FORMAT_PCM_16, channels, Rig::kRate,
                                     sine(523.0, 1.37, Rig::kRate, 0.6f, channels, -0.3f));
        const auto whole = renderSound(path, LoadMode::Whole, 1.6, false);
        const auto streamed = renderSound(path, LoadMode::Stream, 1.6, false);
        ASSERT_EQ(whole.size(), streamed.size());
        EXPECT_GT(rms(whole, 0, 48000).left, 0.1);
        std::size_t differing = 0;
        for (std::size_t i = 0; i < whole.size(); ++i) {
            differing += whole[i] != streamed[i] ? 1 : 0;
        }
        EXPECT_EQ(differing, 0u) << channels << " channels";
    }
}

TEST(Stream, LoopsWithoutGapOrClick) {
    // 0.25 s of 1 kHz at 48 kHz is exactly 250 periods, so the loop point continues the wave.
    const float amplitude = 0.5f;
    const auto path = writeSound("loop.ogg", SF_FORMAT_OGG | SF_FORMAT_VORBIS, 1, Rig::kRate,
                                 sine(1000.0, 0.25, Rig::kRate, amplitude));
    const auto out = renderSound(path, LoadMode::Stream, 1.3, true); // five loop points
    // The largest step of a sine of amplitude a (here centred: a cos(pi/4)) between two samples
    // is a * 2 pi f / rate; a gap or a jump at the loop point steps far more.
    const double centre = std::cos(std::numbers::pi / 4);
    const double bound = 1.15 * amplitude * centre * 2.0 * std::numbers::pi * 1000.0 / Rig::kRate;
    double worst = 0.0;
    for (std::size_t i = 1; i < out.size() / 2; ++i) {
        worst = std::max(worst, static_cast<double>(std::abs(out[2 * i] - out[2 * i - 2])));
    }
    EXPECT_LT(worst, bound);
    // No quiet stretch either: every 10 ms window has the tone's level.
    for (std::size_t from = 0; from + 480 <= out.size() / 2; from += 480) {
        EXPECT_NEAR(rms(out, from, from + 480).left, sineRms(amplitude) * centre,
                    0.05 * sineRms(amplitude))
            << from;
    }
}

TEST(Stream, LoopedStreamMatchesLoopedWholeSound) {
    const auto path = writeSound("loopsame.flac", SF_FORMAT_FLAC | SF_FORMAT_PCM_24, 2, Rig::kRate,
                                 sine(700.0, 0.23, Rig::kRate, 0.5f, 2, 0.5f));
    const auto whole = renderSound(path, LoadMode::Whole, 1.0, true);
    const auto streamed = renderSound(path, LoadMode::Stream, 1.0, true);
    EXPECT_EQ(whole, streamed);
}

TEST(Stream, SurvivesAFrameOfAQuarterSecond) {
    const auto path = writeSound("hitch.flac", SF_FORMAT_FLAC | SF_FORMAT_PCM_16, 1, Rig::kRate,
                                 sine(1000.0, 2.0, Rig::kRate, 0.5f));
    Rig rig;
    const VoiceId voice = rig.mixer.play(rig.mixer.load(path, LoadMode::Stream));
    rig.render(0.3, 1.0 / 60.0);
    // 0.28 s without any update (a long frame), then frames again.
    std::vector<float> hitch(2 * static_cast<std::size_t>(0.28 * Rig::kRate));
    rig.mixer.render(hitch);
    rig.mixer.update(0.28);
    const auto after = rig.render(0.3, 1.0 / 60.0);
    EXPECT_EQ(rig.mixer.stats().streamUnderruns, 0);
    EXPECT_EQ(rig.mixer.state(voice), VoiceState::Playing);
    const double level = sineRms(0.5) * std::cos(std::numbers::pi / 4);
    for (std::size_t from = 0; from + 480 <= hitch.size() / 2; from += 480) {
        ASSERT_NEAR(rms(hitch, from, from + 480).left, level, 0.05 * level) << from;
    }
    EXPECT_NEAR(rms(after, 0, after.size() / 2).left, level, 0.05 * level);
    EXPECT_NEAR(rig.mixer.playbackPosition(voice), 0.88, 0.02);
}

TEST(Stream, EachVoiceReadsTheFileItself) {
    const auto path = writeSound("twice.flac", SF_FORMAT_FLAC | SF_FORMAT_PCM_16, 1, Rig::kRate,
                                 sine(1000.0, 1.0, Rig::kRate, 0.25f));
    Rig rig;
    const SoundId music = rig.mixer.load(path, LoadMode::Stream);
    EXPECT_EQ(rig.mixer.load(path, LoadMode::Stream), music);
    EXPECT_NE(rig.mixer.load(path, LoadMode::Whole), music);
    rig.mixer.play(music);
    rig.mixer.play(music); // same start: in phase, twice the level
    const auto out = rig.render(0.3);
    const double level = 2.0 * sineRms(0.25) * std::cos(std::numbers::pi / 4);
    EXPECT_NEAR(rms(out, 2400, out.size() / 2).left, level, 0.01 * level);
}

TEST(Stream, BrokenStreamsAreErrorsAndPlayNothing) {
    Rig rig;
    const auto missing = tempDir() / "missing-music.ogg";
    const SoundId a = rig.mixer.load(missing, LoadMode::Stream);
    EXPECT_THAT(rig.mixer.soundInfo(a).error, HasSubstr(missing.string()));
    EXPECT_TRUE(rig.mixer.play(a).isNull());
    const auto noise = writeBytes("noise.ogg", std::vector<char>(3000, '\x5a'));
    const SoundId b = rig.mixer.load(noise, LoadMode::Stream);
    EXPECT_THAT(rig.mixer.soundInfo(b).error, HasSubstr(noise.string()));
    EXPECT_EQ(rig.count(core::LogLevel::Error, "plays as silence"), 2);
}

} // namespace
} // namespace e2d::audio
