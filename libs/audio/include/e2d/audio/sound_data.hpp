// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

/// Decoding sound files (libsndfile: WAV PCM 8/16/24/32-bit and float, OGG/Vorbis, FLAC, and
/// whatever else the installed libsndfile reads) into floating-point samples.
namespace e2d::audio {

/// What the loader accepts. A file outside these limits is an error, not a sound.
struct DecodeLimits {
    /// At most this many channels (1 = mono, 2 = stereo). Default 2; at most 2.
    int maxChannels = 2;
    /// Hz. Sample rates below are refused. Default 1000.
    int minSampleRate = 1000;
    /// Hz. Sample rates above are refused. Default 384000.
    int maxSampleRate = 384000;
    /// Frames (samples per channel) a sound decoded whole may have. Default 2^25 (about 11.6
    /// minutes at 48 kHz, 256 MiB of stereo floats). Streamed sounds are not limited.
    std::int64_t maxFrames = std::int64_t{1} << 25;
    /// Largest |sample| a sound may hold. A sample above it, NaN or infinite means damaged data
    /// (a float file whose bytes were overwritten decodes to values like 4e12): the sound is
    /// refused, as a truncated one is. Default 16 (+24 dB over full scale, far above what any
    /// encoder writes from real audio; float files may legitimately exceed 1 a little).
    float maxSampleMagnitude = 16.0f;
};

/// A decoded sound: interleaved samples, finite, in [-1, 1] (float files may exceed it, up to
/// DecodeLimits::maxSampleMagnitude).
struct SoundData {
    int channels = 0;           ///< 1 or 2
    int sampleRate = 0;         ///< Hz
    std::vector<float> samples; ///< frames * channels values, interleaved (L, R, L, R, ...)

    [[nodiscard]] std::int64_t frames() const noexcept {
        return channels == 0 ? 0 : static_cast<std::int64_t>(samples.size()) / channels;
    }
    /// Seconds.
    [[nodiscard]] double duration() const noexcept {
        return sampleRate == 0 ? 0.0 : static_cast<double>(frames()) / sampleRate;
    }
};

/// The outcome of a decode: either `data` (and an empty `error`) or an `error` naming the file
/// and the reason (libsndfile's own words where it gave some), and empty `data`.
struct DecodeResult {
    SoundData data;
    std::string error;

    [[nodiscard]] bool ok() const noexcept { return error.empty(); }
};

/// Decodes the whole file at `path`. Never throws for a bad file: every problem (missing,
/// unreadable, unsupported format, more than `limits.maxChannels` channels, a sample rate
/// outside the limits, zero frames, more than `limits.maxFrames` frames, a damaged or truncated
/// file) is an error in the result.
///
/// Damaged and truncated files follow one rule in every format, here and for streamed sounds
/// (Mixer::load): the error names the file and what is missing or wrong, e.g.
/// `"'music.ogg': truncated: the Ogg stream has no end-of-stream page ..."` or
/// `"'hit.wav': damaged: sample 4e+12 at 0.25 s (frame 11025) is beyond +-16"`. Problems the
/// file shows when opened (a cut WAV or Ogg file) refuse it whole in both modes; damage found
/// while decoding (data that ends before the length its header announces, a decoder that loses
/// sync, non-finite samples) refuses a whole sound and stops a stream at that point, with the
/// same message.
[[nodiscard]] DecodeResult decodeSoundFile(const std::filesystem::path& path,
                                           const DecodeLimits& limits = {});

/// Same, from bytes in memory; `name` is what the error messages call it.
[[nodiscard]] DecodeResult decodeSoundMemory(std::span<const std::byte> bytes,
                                             std::string_view name = "<memory>",
                                             const DecodeLimits& limits = {});

} // namespace e2d::audio
