// SPDX-License-Identifier: MIT
#pragma once

#include "al_device.hpp"
#include "sound_decoder.hpp"

#include <e2d/audio/mixer.hpp>
#include <e2d/core/log.hpp>

#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace e2d::audio {

namespace detail {

/// A sound in the cache. Whole sounds keep their samples (planar) so they can be uploaded
/// again after a device change; streamed ones keep only what is needed to open the file.
struct Sound {
    SoundInfo info;
    std::vector<float> left;  // mono: the only channel
    std::vector<float> right; // empty for mono
    ALuint bufferLeft = 0;
    ALuint bufferRight = 0;         // 0 for mono
    bool streamErrorLogged = false; // a stream of it met damaged data (logged once per sound)
};

/// A streaming voice's decoder and its queue of buffers (one per channel for stereo).
struct Stream {
    std::unique_ptr<Decoder> decoder;
    std::vector<ALuint> freeLeft, freeRight; // buffers ready to be filled
    std::vector<ALuint> allLeft, allRight;   // every buffer this stream owns
    std::deque<std::int64_t> queuedFrames;   // frames in each queued chunk, oldest first
    std::vector<float> interleaved, left, right;
    std::int64_t nextFrame = 0;    // file frame the decoder reads next
    std::int64_t playedFrames = 0; // frames of chunks already played and unqueued
    bool exhausted = false;        // no more data (end of a non-looping file, or an error)
};

enum class FadeEnd : std::uint8_t { None, Stop, Pause };

struct Voice {
    std::uint32_t generation = 1;
    bool busy = false;
    VoiceState state = VoiceState::Stopped;
    SoundId sound{};
    PlayDef def{};
    // Fade: fade = from + (to - from) * min(1, elapsed / duration).
    float fade = 1.0f;
    float fadeFrom = 1.0f;
    float fadeTo = 1.0f;
    double fadeElapsed = 0.0;
    double fadeDuration = 0.0;
    bool fading = false;
    FadeEnd fadeEnd = FadeEnd::None;
    // The gains last computed and set on the two sources (-1: not set yet).
    float gain = 0.0f; // before panning
    float appliedLeft = -1.0f;
    float appliedRight = -1.0f;
    ALuint sourceLeft = 0;  // at (-1, 0, 0): heard only on the left
    ALuint sourceRight = 0; // at (+1, 0, 0): heard only on the right
    // Sound frames played, kept up to date while running silent (or moving to a new device).
    double silentFrame = 0.0;
    std::unique_ptr<Stream> stream;
    std::uint64_t startOrder = 0;
};

} // namespace detail

struct Mixer::Impl {
    MixerDef def;
    core::Logger ownLogger;
    core::Logger* logger = nullptr;
    std::unique_ptr<detail::Device> device;
    bool silentReported = false;
    float masterGain = 1.0f;
    std::array<float, kBusCount> busGains{1.0f, 1.0f};
    SpatialDef spatial;
    glm::vec2 listener{0.0f, 0.0f};
    float listenerOrientation = 0.0f;
    std::vector<detail::Sound> sounds;
    std::map<std::pair<std::string, LoadMode>, SoundId> cache;
    std::vector<detail::Voice> voices;
    std::uint64_t startCounter = 0;
    MixerStats stats;

    explicit Impl(const MixerDef& d);
    ~Impl();

    // Device (mixer.cpp)
    bool openOutput(bool reopening);
    // Logs, once until a device opens again, that the mixer runs silent and why.
    void goSilent(const std::string& why, std::string_view hint = {});
    void releaseDeviceObjects();
    void createDeviceObjects();
    void uploadSound(detail::Sound& sound);
    void makeCurrent() const {
        if (device) {
            device->makeCurrent();
        }
    }

    // Voices (voices.cpp)
    detail::Voice* find(VoiceId id) noexcept;
    const detail::Voice* find(VoiceId id) const noexcept;
    int allocateVoice(int priority);
    void startVoice(detail::Voice& voice, double startFrame);
    void releaseVoice(detail::Voice& voice);
    void stopSources(detail::Voice& voice);
    void computeGain(detail::Voice& voice, float& left, float& right) const;
    void applyGains(detail::Voice& voice);
    bool advanceFade(detail::Voice& voice, double dt); // false: the voice was released
    void updateVoice(detail::Voice& voice, double dt);
    double voicePosition(const detail::Voice& voice) const; // frames into the sound
    bool openStream(detail::Voice& voice, double startFrame);
    void feedStream(detail::Voice& voice);
    bool fillChunk(detail::Voice& voice, ALuint left, ALuint right);
};

} // namespace e2d::audio
