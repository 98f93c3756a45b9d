// SPDX-License-Identifier: MIT
#include "sound.hpp"

#include <e2d/core/error.hpp>
#include <e2d/core/random.hpp>

#include <sndfile.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace e2d::assetgen {
namespace {

std::size_t sampleCount(double seconds, int sampleRate) {
    return static_cast<std::size_t>(std::max(0.0, std::round(seconds * sampleRate)));
}

} // namespace

Sound silence(double seconds, int sampleRate) {
    Sound s;
    s.sampleRate = sampleRate;
    s.samples.assign(sampleCount(seconds, sampleRate), 0.0f);
    return s;
}

Sound tone(Wave wave, double frequency, double seconds, double amplitude, double endFrequency,
           int sampleRate) {
    Sound s = silence(seconds, sampleRate);
    const double f1 = endFrequency > 0 ? endFrequency : frequency;
    double phase = 0; // in cycles, integrated so a glide has no jumps
    const std::size_t n = s.samples.size();
    for (std::size_t i = 0; i < n; ++i) {
        const double t = n > 1 ? static_cast<double>(i) / static_cast<double>(n - 1) : 0.0;
        const double f = frequency + (f1 - frequency) * t;
        const double p = phase - std::floor(phase);
        double v = 0;
        switch (wave) {
        case Wave::Sine:
            v = std::sin(2 * std::numbers::pi * p);
            break;
        case Wave::Square:
            v = p < 0.5 ? 1.0 : -1.0;
            break;
        case Wave::Triangle:
            v = p < 0.5 ? 4 * p - 1 : 3 - 4 * p;
            break;
        case Wave::Saw:
            v = 2 * p - 1;
            break;
        }
        s.samples[i] = static_cast<float>(amplitude * v);
        phase += f / sampleRate;
    }
    return s;
}

Sound noise(double seconds, double amplitude, std::uint64_t seed, int sampleRate) {
    Sound s = silence(seconds, sampleRate);
    core::Random random(seed);
    for (float& v : s.samples) {
        v = static_cast<float>(amplitude) * random.range(-1.0f, 1.0f);
    }
    return s;
}

void shape(Sound& sound, const Envelope& e) {
    const double length = sound.seconds();
    const double releaseStart = std::max(0.0, length - e.release);
    for (std::size_t i = 0; i < sound.samples.size(); ++i) {
        const double t = static_cast<double>(i) / sound.sampleRate;
        double level;
        if (t < e.attack) {
            level = t / e.attack;
        } else if (t < e.attack + e.decay) {
            level = 1 - (1 - e.sustain) * (t - e.attack) / e.decay;
        } else {
            level = e.sustain;
        }
        if (t >= releaseStart && e.release > 0) {
            level *= std::max(0.0, (length - t) / e.release);
        }
        sound.samples[i] *= static_cast<float>(level);
    }
}

void mixInto(Sound& target, const Sound& source, double at, double gain) {
    if (target.sampleRate != source.sampleRate) {
        throw core::Error("assetgen::mixInto(): sample rates differ, " +
                          std::to_string(target.sampleRate) + " and " +
                          std::to_string(source.sampleRate));
    }
    const std::size_t start = sampleCount(at, target.sampleRate);
    if (target.samples.size() < start + source.samples.size()) {
        target.samples.resize(start + source.samples.size(), 0.0f);
    }
    for (std::size_t i = 0; i < source.samples.size(); ++i) {
        target.samples[start + i] += static_cast<float>(gain) * source.samples[i];
    }
}

void normalise(Sound& sound, double peak) {
    float largest = 0;
    for (float v : sound.samples) {
        largest = std::max(largest, std::abs(v));
    }
    if (largest > 0) {
        const float k = static_cast<float>(peak) / largest;
        for (float& v : sound.samples) {
            v *= k;
        }
    }
}

double noteFrequency(int note) noexcept { return 440.0 * std::pow(2.0, (note - 69) / 12.0); }

Sound sequence(const std::vector<Note>& notes, double bpm, Wave wave, const Envelope& envelope,
               double amplitude, int sampleRate) {
    Sound out;
    out.sampleRate = sampleRate;
    const double beat = 60.0 / bpm;
    double at = 0;
    for (const Note& n : notes) {
        const double length = n.beats * beat;
        if (n.note >= 0) {
            Sound s = tone(wave, noteFrequency(n.note), length, amplitude, 0, sampleRate);
            shape(s, envelope);
            mixInto(out, s, at);
        }
        at += length;
    }
    // Rests at the end still count: the piece lasts its full length.
    out.samples.resize(sampleCount(at, sampleRate), 0.0f);
    return out;
}

void writeSound(const Sound& sound, const std::filesystem::path& path) {
    const std::string ext = path.extension().string();
    SF_INFO info{};
    info.samplerate = sound.sampleRate;
    info.channels = 1;
    if (ext == ".wav") {
        info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
    } else if (ext == ".ogg") {
        info.format = SF_FORMAT_OGG | SF_FORMAT_VORBIS;
    } else if (ext == ".flac") {
        info.format = SF_FORMAT_FLAC | SF_FORMAT_PCM_16;
    } else {
        throw core::Error("assetgen::writeSound(): '" + path.string() +
                          "': unknown extension, expected .wav, .ogg or .flac");
    }
    SNDFILE* file = sf_open(path.c_str(), SFM_WRITE, &info);
    if (file == nullptr) {
        throw core::Error("assetgen::writeSound(): '" + path.string() +
                          "': " + sf_strerror(nullptr));
    }
    // Clip rather than wrap when a mix goes past full scale.
    sf_command(file, SFC_SET_CLIPPING, nullptr, SF_TRUE);
    const auto count = static_cast<sf_count_t>(sound.samples.size());
    const sf_count_t written = sf_writef_float(file, sound.samples.data(), count);
    const std::string reason = sf_strerror(file);
    sf_close(file);
    if (written != count) {
        throw core::Error("assetgen::writeSound(): '" + path.string() + "': wrote " +
                          std::to_string(written) + " of " + std::to_string(count) +
                          " frames: " + reason);
    }
}

} // namespace e2d::assetgen
