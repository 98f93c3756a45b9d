// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace e2d::assetgen {

/// Mono samples in [-1, 1] at `sampleRate` Hz (mono, so OpenAL can place it in space).
struct Sound {
    /// Samples per second. Default 44 100.
    int sampleRate = 44100;
    std::vector<float> samples;

    /// Length, seconds.
    [[nodiscard]] double seconds() const noexcept {
        return static_cast<double>(samples.size()) / sampleRate;
    }
};

enum class Wave { Sine, Square, Triangle, Saw };

/// `seconds` of silence.
[[nodiscard]] Sound silence(double seconds, int sampleRate = 44100);
/// A tone of `frequency` Hz (a glide to `endFrequency` when that is > 0), peak `amplitude`.
[[nodiscard]] Sound tone(Wave wave, double frequency, double seconds, double amplitude = 0.5,
                         double endFrequency = 0, int sampleRate = 44100);
/// White noise of peak `amplitude`, reproducible from `seed`.
[[nodiscard]] Sound noise(double seconds, double amplitude, std::uint64_t seed,
                          int sampleRate = 44100);

/// An attack-decay-sustain-release envelope, seconds and a level in [0, 1]. The release ends
/// at the sound's end, so a shaped note starts and ends at zero (no click).
struct Envelope {
    double attack = 0.005;
    double decay = 0.05;
    double sustain = 0.7;
    double release = 0.05;
};
/// Multiplies `sound` by `envelope`.
void shape(Sound& sound, const Envelope& envelope);
/// Adds `source` times `gain` into `target` starting `at` seconds in; `target` grows to fit.
/// Throws core::Error if the sample rates differ.
void mixInto(Sound& target, const Sound& source, double at, double gain = 1.0);
/// Scales `sound` so its largest magnitude is `peak`.
void normalise(Sound& sound, double peak = 0.9);

/// Equal-tempered frequency of MIDI note `note` (69 = A4 = 440 Hz).
[[nodiscard]] double noteFrequency(int note) noexcept;

/// One note of a melody: a MIDI note number (negative: a rest) and a length in beats.
struct Note {
    int note = -1;
    double beats = 1;
};
/// Plays `notes` one after the other at `bpm` beats per minute, each shaped by `envelope`
/// (so it ends at zero), peak `amplitude`. The result is exactly the notes' total length, so
/// a piece whose notes add up to whole bars loops seamlessly.
[[nodiscard]] Sound sequence(const std::vector<Note>& notes, double bpm, Wave wave,
                             const Envelope& envelope, double amplitude = 0.3,
                             int sampleRate = 44100);

/// Writes `sound` through libsndfile; the format comes from the extension: .wav (16-bit PCM),
/// .ogg (Vorbis), .flac. Throws core::Error naming the file and libsndfile's reason.
void writeSound(const Sound& sound, const std::filesystem::path& path);

} // namespace e2d::assetgen
