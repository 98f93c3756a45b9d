// SPDX-License-Identifier: MIT
// Loading: every format libsndfile writes here, real files nobody here made, and broken files.
#include "audio_test_support.hpp"

#include <e2d/audio/sound_data.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <random>

namespace e2d::audio {
namespace {

using ::testing::HasSubstr;
using namespace test;

struct Format {
    const char* name;
    int format;
    double tolerance; // largest sample error the encoding may add
};

class DecodeFormats : public ::testing::TestWithParam<Format> {};

TEST_P(DecodeFormats, RoundTripsATone) {
    const Format f = GetParam();
    for (int channels : {1, 2}) {
        const int rate = 44100;
        const auto written = sine(440.0, 0.5, rate, 0.5f, channels, 0.5f);
        const auto path = writeSound(std::string("tone_") + f.name + std::to_string(channels),
                                     f.format, channels, rate, written);
        const DecodeResult result = decodeSoundFile(path);
        ASSERT_TRUE(result.ok()) << result.error;
        EXPECT_EQ(result.data.channels, channels);
        EXPECT_EQ(result.data.sampleRate, rate);
        ASSERT_EQ(result.data.samples.size(), written.size());
        double worst = 0.0;
        double sumSq = 0.0;
        for (std::size_t i = 0; i < written.size(); ++i) {
            worst =
                std::max(worst, static_cast<double>(std::abs(result.data.samples[i] - written[i])));
            sumSq += static_cast<double>(result.data.samples[i]) * result.data.samples[i];
        }
        EXPECT_LE(worst, f.tolerance) << f.name;
        // The RMS of the decoded tone: 0.5/sqrt(2) on the left, half that on the right.
        const double expected =
            std::sqrt((sineRms(0.5) * sineRms(0.5) * (channels == 2 ? 1.25 : 1.0)) / channels);
        EXPECT_NEAR(std::sqrt(sumSq / static_cast<double>(written.size())), expected,
                    0.01 * expected);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Formats, DecodeFormats,
    ::testing::Values(Format{"wav8", SF_FORMAT_WAV | SF_FORMAT_PCM_U8, 1.0 / 64},
                      Format{"wav16", SF_FORMAT_WAV | SF_FORMAT_PCM_16, 1.0 / 16384},
                      Format{"wav24", SF_FORMAT_WAV | SF_FORMAT_PCM_24, 1e-6},
                      Format{"wav32", SF_FORMAT_WAV | SF_FORMAT_PCM_32, 1e-6},
                      Format{"wavfloat", SF_FORMAT_WAV | SF_FORMAT_FLOAT, 0.0},
                      Format{"flac16", SF_FORMAT_FLAC | SF_FORMAT_PCM_16, 1.0 / 16384},
                      Format{"flac24", SF_FORMAT_FLAC | SF_FORMAT_PCM_24, 1e-6},
                      // Lossy: only close in level (checked by RMS) and bounded in error.
                      Format{"ogg", SF_FORMAT_OGG | SF_FORMAT_VORBIS, 0.05}),
    [](const auto& param) { return std::string(param.param.name); });

TEST(Decode, RealFreedesktopSounds) {
    const std::filesystem::path dir = "/usr/share/sounds/freedesktop/stereo";
    ASSERT_TRUE(std::filesystem::is_directory(dir)) << "package sound-theme-freedesktop";
    int loaded = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".oga") {
            continue;
        }
        const DecodeResult result = decodeSoundFile(entry.path());
        ASSERT_TRUE(result.ok()) << result.error;
        EXPECT_GE(result.data.channels, 1);
        EXPECT_LE(result.data.channels, 2);
        EXPECT_GE(result.data.sampleRate, 8000);
        EXPECT_GT(result.data.frames(), 100);
        double peak = 0.0;
        for (float s : result.data.samples) {
            ASSERT_TRUE(std::isfinite(s));
            peak = std::max(peak, static_cast<double>(std::abs(s)));
        }
        EXPECT_GT(peak, 0.01) << entry.path() << " decoded to silence";
        ++loaded;
    }
    EXPECT_GE(loaded, 10);
}

// Broken files: an error naming the file and the reason, no data, no crash.

std::filesystem::path goodWav(const std::string& name, int channels = 1) {
    return writeSound(name, SF_FORMAT_WAV | SF_FORMAT_PCM_16, channels, 22050,
                      sine(440.0, 0.2, 22050, 0.5f, channels));
}

void putU32(std::vector<char>& bytes, std::size_t at, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) {
        bytes[at + static_cast<std::size_t>(i)] = static_cast<char>((value >> (8 * i)) & 0xff);
    }
}

void expectError(const std::filesystem::path& path, const std::string& reasonPart) {
    const DecodeResult result = decodeSoundFile(path);
    EXPECT_FALSE(result.ok());
    EXPECT_TRUE(result.data.samples.empty());
    EXPECT_THAT(result.error, HasSubstr(path.string()));
    EXPECT_THAT(result.error, HasSubstr(reasonPart));
}

TEST(DecodeBroken, MissingFile) { expectError(tempDir() / "nope.wav", "no such file"); }

TEST(DecodeBroken, TruncatedHeader) {
    auto bytes = readBytes(goodWav("th_src.wav"));
    bytes.resize(20);
    expectError(writeBytes("truncated_header.wav", bytes), "'");
}

TEST(DecodeBroken, TruncatedData) {
    auto bytes = readBytes(goodWav("td_src.wav"));
    bytes.resize(44 + 1000);
    expectError(writeBytes("truncated_data.wav", bytes), "truncated");
}

TEST(DecodeBroken, WrongFmtChunkSize) {
    auto bytes = readBytes(goodWav("wc_src.wav"));
    putU32(bytes, 16, 0x7fff0000); // fmt chunk claims 2 GB
    expectError(writeBytes("wrong_fmt_size.wav", bytes), "'");
}

TEST(DecodeBroken, DataChunkLongerThanFile) {
    auto bytes = readBytes(goodWav("wd_src.wav"));
    ASSERT_EQ(std::memcmp(bytes.data() + 36, "data", 4), 0);
    putU32(bytes, 40, 0x7ffffff0);
    expectError(writeBytes("wrong_data_size.wav", bytes), "truncated");
}

TEST(DecodeBroken, ZeroLengthData) {
    expectError(writeSound("empty.wav", SF_FORMAT_WAV | SF_FORMAT_PCM_16, 1, 44100, {}),
                "no audio frames");
}

TEST(DecodeBroken, RandomBytes) {
    std::mt19937 random(12);
    std::vector<char> bytes(4096);
    for (char& b : bytes) {
        b = static_cast<char>(random() & 0xff);
    }
    expectError(writeBytes("random.wav", bytes), "'");
    const DecodeResult memory =
        decodeSoundMemory(std::as_bytes(std::span(bytes)), "random-in-memory");
    EXPECT_FALSE(memory.ok());
    EXPECT_THAT(memory.error, HasSubstr("random-in-memory"));
}

TEST(DecodeBroken, TooManyChannels) {
    expectError(writeSound("three.wav", SF_FORMAT_WAV | SF_FORMAT_PCM_16, 3, 44100,
                           std::vector<float>(300, 0.1f)),
                "3 channels, at most 2");
}

TEST(DecodeBroken, AbsurdSampleRates) {
    auto bytes = readBytes(goodWav("rate_src.wav"));
    putU32(bytes, 24, 5);
    expectError(writeBytes("rate5.wav", bytes), "sample rate 5 Hz");
    putU32(bytes, 24, 50'000'000);
    expectError(writeBytes("rate50M.wav", bytes), "sample rate 50000000 Hz");
}

TEST(DecodeBroken, LongerThanTheLimit) {
    DecodeLimits limits;
    limits.maxFrames = 1000;
    const auto path = goodWav("long.wav");
    const DecodeResult result = decodeSoundFile(path, limits);
    EXPECT_THAT(result.error, HasSubstr("more than the limit of 1000"));
}

TEST(DecodeMemory, SameAsFromFile) {
    const auto path = writeSound("mem.flac", SF_FORMAT_FLAC | SF_FORMAT_PCM_16, 2, 32000,
                                 sine(300.0, 0.3, 32000, 0.4f, 2));
    const auto bytes = readBytes(path);
    const DecodeResult fromMemory = decodeSoundMemory(std::as_bytes(std::span(bytes)), "mem.flac");
    const DecodeResult fromFile = decodeSoundFile(path);
    ASSERT_TRUE(fromMemory.ok()) << fromMemory.error;
    EXPECT_EQ(fromMemory.data.samples, fromFile.data.samples);
}

} // namespace
} // namespace e2d::audio
