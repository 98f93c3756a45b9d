// SPDX-License-Identifier: MIT
// Shared helpers for the audio tests: sound files written with libsndfile, a loopback mixer
// and RMS measurements of what it renders.
#pragma once

#include <e2d/audio/mixer.hpp>
#include <e2d/core/log.hpp>

#include <sndfile.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace e2d::audio::test {

/// OpenAL Soft must not probe PulseAudio from the tests (HEADLESS.md); it reads the variable
/// when it first initialises, so every fixture calls this before touching OpenAL.
inline void useNullDriver() { ::setenv("ALSOFT_DRIVERS", "null", 0); }

/// A fresh folder per test process for the sound files the tests write, removed with
/// everything in it when the process ends (ctest runs each test in a process of its own, so
/// thousands of runs used to leave thousands of folders behind).
inline const std::filesystem::path& tempDir() {
    struct Owned {
        std::filesystem::path dir;
        Owned()
            : dir(std::filesystem::temp_directory_path() /
                  ("e2d_audio_test_" + std::to_string(::getpid()))) {
            std::filesystem::create_directories(dir);
        }
        Owned(const Owned&) = delete;
        Owned& operator=(const Owned&) = delete;
        ~Owned() {
            std::error_code ignored;
            std::filesystem::remove_all(dir, ignored);
        }
    };
    static const Owned owned;
    return owned.dir;
}

/// `seconds` of a sine wave of `frequency` Hz and `amplitude` at `rate` Hz; stereo gets the same
/// wave on the left and `rightScale` times it on the right.
inline std::vector<float> sine(double frequency, double seconds, int rate, float amplitude = 0.5f,
                               int channels = 1, float rightScale = 1.0f) {
    const auto frames = static_cast<std::size_t>(std::llround(seconds * rate));
    std::vector<float> samples(frames * static_cast<std::size_t>(channels));
    for (std::size_t i = 0; i < frames; ++i) {
        const auto value =
            static_cast<float>(amplitude * std::sin(2.0 * std::numbers::pi * frequency *
                                                    static_cast<double>(i) / rate));
        samples[i * static_cast<std::size_t>(channels)] = value;
        if (channels == 2) {
            samples[i * 2 + 1] = value * rightScale;
        }
    }
    return samples;
}

/// Writes `samples` (interleaved) with libsndfile in `format` (e.g. SF_FORMAT_WAV | SF_FORMAT_PCM_16).
inline std::filesystem::path writeSound(const std::string& name, int format, int channels, int rate,
                                        const std::vector<float>& samples) {
    const auto path = tempDir() / name;
    SF_INFO info{};
    info.channels = channels;
    info.samplerate = rate;
    info.format = format;
    SNDFILE* file = sf_open(path.c_str(), SFM_WRITE, &info);
    if (file == nullptr) {
        throw std::runtime_error("cannot write " + path.string() + ": " + sf_strerror(nullptr));
    }
    sf_writef_float(file, samples.data(),
                    static_cast<sf_count_t>(samples.size() / static_cast<std::size_t>(channels)));
    sf_close(file);
    return path;
}

inline std::vector<char> readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline std::filesystem::path writeBytes(const std::string& name, const std::vector<char>& bytes) {
    const auto path = tempDir() / name;
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return path;
}

/// Per-channel RMS of frames [from, to) of interleaved stereo.
struct ChannelRms {
    double left = 0.0;
    double right = 0.0;
};

inline ChannelRms rms(const std::vector<float>& stereo, std::size_t from, std::size_t to) {
    double l = 0.0;
    double r = 0.0;
    for (std::size_t i = from; i < to; ++i) {
        l += static_cast<double>(stereo[2 * i]) * stereo[2 * i];
        r += static_cast<double>(stereo[2 * i + 1]) * stereo[2 * i + 1];
    }
    const auto n = static_cast<double>(to - from);
    return {std::sqrt(l / n), std::sqrt(r / n)};
}

/// A loopback mixer with a logger that keeps its messages.
struct Rig {
    static constexpr int kRate = 48000;

    std::vector<std::pair<core::LogLevel, std::string>> messages;
    core::Logger logger{core::LogLevel::Trace, [this](core::LogLevel level, std::string_view text) {
                            messages.emplace_back(level, std::string(text));
                        }};
    Mixer mixer;

    explicit Rig(MixerDef def = {}) : mixer(prepare(def, logger)) {}

    static MixerDef prepare(MixerDef def, core::Logger& logger) {
        useNullDriver();
        if (def.output == Output::Device && def.deviceName.empty()) {
            def.output = Output::Loopback;
        }
        def.loopbackSampleRate = kRate;
        def.logger = &logger;
        return def;
    }

    /// Renders `seconds` in blocks of `step` seconds, calling update(step) after each block (time
    /// passes by rendering, then the game updates), and returns interleaved stereo.
    std::vector<float> render(double seconds, double step = 0.01) {
        const auto frames = static_cast<std::size_t>(std::llround(seconds * kRate));
        const auto block = static_cast<std::size_t>(std::llround(step * kRate));
        std::vector<float> out(frames * 2);
        for (std::size_t done = 0; done < frames;) {
            const std::size_t n = std::min(block, frames - done);
            mixer.render(std::span<float>(out.data() + 2 * done, 2 * n));
            done += n;
            mixer.update(static_cast<double>(n) / kRate);
        }
        return out;
    }

    int count(core::LogLevel level, const std::string& part) const {
        int n = 0;
        for (const auto& [l, text] : messages) {
            n += (l == level && text.find(part) != std::string::npos) ? 1 : 0;
        }
        return n;
    }
};

/// RMS of a full-scale-`amplitude` sine: amplitude / sqrt(2).
inline double sineRms(double amplitude) { return amplitude / std::numbers::sqrt2; }

} // namespace e2d::audio::test
