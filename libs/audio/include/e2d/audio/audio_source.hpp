// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/audio/ids.hpp>
#include <e2d/audio/mixer.hpp>
#include <e2d/core/component.hpp>

#include <string>

namespace e2d::audio {

class AudioSystem;

/// How an AudioSource plays. Every field can be changed later through the component.
struct AudioSourceDef {
    /// Path of the sound file. Loaded (and shared through the mixer's cache) when the object
    /// enters the scene. Default empty: the source has nothing to play until setClip().
    std::string clip{};
    /// Stream the file while it plays instead of decoding it whole (music). Default false.
    bool stream = false;
    /// Start playing when the object enters the scene. Default true.
    bool playOnStart = true;
    /// Default false.
    bool loop = false;
    /// Heard from the object's world position, relative to the listener. Default false.
    bool spatial = false;
    /// >= 0. Default 1.
    float gain = 1.0f;
    /// 0.01..16. Default 1.
    float pitch = 1.0f;
    /// Divides the attenuation range; 0 = none; >= 0. Default 1.
    float attenuationFactor = 1.0f;
    /// Higher keeps its voice when voices run out. Default 0.
    int priority = 0;
    /// Default Effects.
    Bus bus = Bus::Effects;
    /// Seconds of fade-in used by play() and resume() when not given; >= 0. Default 0.
    double fadeIn = 0.0;
    /// Seconds of fade-out used by stop() and pause() when not given; >= 0. Default 0.
    double fadeOut = 0.0;
};

/// Plays a sound for its GameObject; a spatial source follows the object's world position every
/// frame. Needs an AudioSystem registered with the scene's host (core::Error otherwise, when
/// the object enters the scene).
class AudioSource : public core::Component {
public:
    /// Throws core::Error naming an invalid field of `def`.
    explicit AudioSource(AudioSourceDef def = {});
    ~AudioSource() override;

    [[nodiscard]] const AudioSourceDef& def() const noexcept { return def_; }
    /// The sound (null before the object entered the scene or without a clip).
    [[nodiscard]] SoundId sound() const noexcept { return sound_; }
    /// The voice playing it (null when stopped, refused or finished).
    [[nodiscard]] VoiceId voice() const noexcept { return voice_; }

    /// Starts from the beginning (stopping a voice still playing), fading in over `fadeIn`
    /// seconds (negative: the def's fadeIn). Before the object is in the scene it marks the
    /// source to play when it gets there. Returns false when nothing plays (no clip, a clip
    /// that failed to load, or no voice free).
    bool play(double fadeIn = -1.0);
    /// Fading out over `fadeOut` seconds (negative: the def's fadeOut).
    void stop(double fadeOut = -1.0);
    void pause(double fadeOut = -1.0);
    void resume(double fadeIn = -1.0);
    [[nodiscard]] bool isPlaying() const;
    [[nodiscard]] bool isPaused() const;

    /// Takes effect on the next play().
    void setClip(std::string path, bool stream = false);
    void setGain(float gain);
    void setPitch(float pitch);
    void setLoop(bool loop);
    void setSpatial(bool spatial);
    void setAttenuationFactor(float factor);
    void setPriority(int priority);

    void onInitialize() override;
    void onTerminate() override;
    void update(double dt) override;

private:
    PlayDef playDef(double fadeIn) const;
    [[nodiscard]] Mixer* mixer() const noexcept;

    AudioSourceDef def_;
    AudioSystem* system_ = nullptr;
    SoundId sound_{};
    VoiceId voice_{};
    bool playWhenReady_ = false;
};

} // namespace e2d::audio
