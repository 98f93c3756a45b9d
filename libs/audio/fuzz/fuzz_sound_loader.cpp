// SPDX-License-Identifier: MIT
// Random bytes into the sound loader (libsndfile reading from memory): either a sound within
// the limits (finite samples within maxSampleMagnitude included) or an error naming the input;
// never a crash, a leak or an unbounded allocation.
#include <e2d/audio/sound_data.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>

// libsndfile 1.2.0 with libvorbis 1.3.7 leaks the Vorbis info block of some corrupt Ogg
// streams (allocated in vorbis_info_init, never cleared on libsndfile's error path). The decoder
// checks every Ogg page's checksum before libsndfile reads any, so only a stream damaged with
// valid checksums gets there; the suppression names the third-party library only, so a leak in
// e2d still fails.
extern "C" const char* __lsan_default_suppressions() { return "leak:libvorbis.so\n"; }

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    e2d::audio::DecodeLimits limits;
    limits.maxFrames = 1 << 20; // keeps one input's memory small
    const auto bytes = std::as_bytes(std::span(data, size));
    const e2d::audio::DecodeResult result =
        e2d::audio::decodeSoundMemory(bytes, "fuzz-input", limits);
    if (!result.ok()) {
        if (!result.data.samples.empty() || result.error.find("fuzz-input") == std::string::npos) {
            std::fprintf(stderr, "error without the name or with data: %s\n", result.error.c_str());
            std::abort();
        }
        return 0;
    }
    const auto& sound = result.data;
    const bool valid =
        sound.channels >= 1 && sound.channels <= limits.maxChannels &&
        sound.sampleRate >= limits.minSampleRate && sound.sampleRate <= limits.maxSampleRate &&
        sound.frames() >= 1 && sound.frames() <= limits.maxFrames &&
        sound.samples.size() == static_cast<std::size_t>(sound.frames() * sound.channels);
    for (float s : sound.samples) {
        if (!(std::abs(s) <= limits.maxSampleMagnitude)) {
            std::fprintf(stderr, "a sample that is not finite or beyond the limit: %g\n",
                         static_cast<double>(s));
            std::abort();
        }
    }
    if (!valid) {
        std::fprintf(stderr, "sound outside the limits: %d channels, %d Hz, %lld frames\n",
                     sound.channels, sound.sampleRate, static_cast<long long>(sound.frames()));
        std::abort();
    }
    return 0;
}
