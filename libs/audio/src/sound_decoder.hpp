// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/audio/sound_data.hpp>

#include <sndfile.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace e2d::audio::detail {

/// One open sound file (or block of memory) read through libsndfile, as float frames. Used
/// whole by the loader and chunk by chunk by streams.
class Decoder {
public:
    /// Opens `path` and checks its header against `limits` (channels, sample rate, at least one
    /// frame) and, before libsndfile reads any of it, the container: every page of an Ogg file
    /// (checkOggPages: a Vorbis stream libsndfile fails to open leaks its info block) and the
    /// chunks of a WAV file (checkWavChunks: some sizes keep libsndfile's parser busy for ever).
    /// Returns null and sets `error` ("'<name>': <reason>") when that fails. `checked`: the file
    /// passed these checks before (a streaming voice reopening a loaded sound), so they are not
    /// run again.
    static std::unique_ptr<Decoder> open(const std::filesystem::path& path,
                                         const DecodeLimits& limits, std::string& error,
                                         bool checked = false);
    /// Same over bytes that must outlive the decoder.
    static std::unique_ptr<Decoder> open(std::span<const std::byte> bytes, std::string_view name,
                                         const DecodeLimits& limits, std::string& error);
    ~Decoder();
    Decoder(const Decoder&) = delete;
    Decoder& operator=(const Decoder&) = delete;

    [[nodiscard]] int channels() const noexcept { return info_.channels; }
    [[nodiscard]] int sampleRate() const noexcept { return info_.samplerate; }
    /// Frames the header announces (-1 when it does not say).
    [[nodiscard]] std::int64_t headerFrames() const noexcept { return headerFrames_; }
    [[nodiscard]] const std::string& name() const noexcept { return name_; }

    /// Reads up to `frames` interleaved frames into `out` (frames * channels floats). Returns
    /// the frames read (fewer only at the end of the data), 0 at the end, or -1 when the data is
    /// damaged (then `error()` says why and where): a decoding error, a sample that is not
    /// finite or beyond DecodeLimits::maxSampleMagnitude, or data that ends before the length
    /// the header announces.
    std::int64_t read(float* out, std::int64_t frames);
    /// Moves to `frame`; false (and `error()`) when the file cannot seek there.
    bool seek(std::int64_t frame);
    [[nodiscard]] const std::string& error() const noexcept { return error_; }

    /// Reads everything left (at most `maxFrames` frames, else an error).
    DecodeResult readAll(std::int64_t maxFrames);

    /// Bytes read through libsndfile's virtual I/O, and where it reads next.
    struct Memory {
        std::span<const std::byte> bytes;
        sf_count_t position = 0;
    };

private:
    Decoder() = default;
    bool finishOpen(const DecodeLimits& limits, std::string& error);
    void setError(std::string_view reason);
    // "1.25 s (frame 55125)": where in the sound `frame` is, for messages.
    [[nodiscard]] std::string where(std::int64_t frame) const;

    SNDFILE* file_ = nullptr;
    SF_INFO info_{};
    Memory memory_;
    std::int64_t headerFrames_ = -1;
    std::int64_t position_ = 0; // the frame read next
    float maxMagnitude_ = 0.0f;
    std::string name_;
    std::string error_;
};

} // namespace e2d::audio::detail
