// SPDX-License-Identifier: MIT
#include <e2d/audio/audio_source.hpp>

#include <e2d/audio/audio_system.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>

#include <cmath>
#include <utility>

namespace e2d::audio {

using core::throwInvalid;

namespace {

void checkSourceDef(const AudioSourceDef& def, const char* fn) {
    if (!std::isfinite(def.gain) || def.gain < 0.0f) {
        throwInvalid(fn, "gain", ">= 0", def.gain);
    }
    if (!(def.pitch >= 0.01f && def.pitch <= 16.0f)) {
        throwInvalid(fn, "pitch", "in 0.01..16", def.pitch);
    }
    if (!std::isfinite(def.attenuationFactor) || def.attenuationFactor < 0.0f) {
        throwInvalid(fn, "attenuationFactor", ">= 0", def.attenuationFactor);
    }
    if (!std::isfinite(def.fadeIn) || def.fadeIn < 0.0) {
        throwInvalid(fn, "fadeIn", ">= 0 seconds", def.fadeIn);
    }
    if (!std::isfinite(def.fadeOut) || def.fadeOut < 0.0) {
        throwInvalid(fn, "fadeOut", ">= 0 seconds", def.fadeOut);
    }
}

} // namespace

AudioSource::AudioSource(AudioSourceDef def) : def_(std::move(def)) {
    checkSourceDef(def_, "audio::AudioSource::AudioSource()");
    playWhenReady_ = def_.playOnStart;
}

AudioSource::~AudioSource() = default;

Mixer* AudioSource::mixer() const noexcept {
    return system_ != nullptr ? &system_->mixer() : nullptr;
}

PlayDef AudioSource::playDef(double fadeIn) const {
    PlayDef play;
    play.gain = def_.gain;
    play.pitch = def_.pitch;
    play.loop = def_.loop;
    play.spatial = def_.spatial;
    const glm::vec3 position = gameObject()->worldPosition();
    play.position = {position.x, position.y};
    play.attenuationFactor = def_.attenuationFactor;
    play.priority = def_.priority;
    play.bus = def_.bus;
    play.fadeIn = fadeIn < 0.0 ? def_.fadeIn : fadeIn;
    return play;
}

void AudioSource::onInitialize() {
    system_ = &scene()->system<AudioSystem>();
    if (!def_.clip.empty()) {
        sound_ = system_->mixer().load(def_.clip, def_.stream ? LoadMode::Stream : LoadMode::Whole);
    }
    if (playWhenReady_) {
        playWhenReady_ = false;
        play();
    }
}

void AudioSource::onTerminate() {
    if (Mixer* m = mixer()) {
        m->stop(voice_);
    }
    voice_ = {};
    system_ = nullptr;
}

void AudioSource::update(double dt) {
    static_cast<void>(dt);
    Mixer* m = mixer();
    if (m == nullptr || voice_.isNull()) {
        return;
    }
    if (!m->isValid(voice_)) {
        voice_ = {}; // finished, stopped or taken by another sound
        return;
    }
    if (def_.spatial) {
        const glm::vec3 position = gameObject()->worldPosition();
        m->setPosition(voice_, {position.x, position.y});
    }
}

bool AudioSource::play(double fadeIn) {
    Mixer* m = mixer();
    if (m == nullptr) {
        playWhenReady_ = true;
        return false;
    }
    m->stop(voice_);
    voice_ = {};
    if (sound_.isNull()) {
        return false;
    }
    voice_ = m->play(sound_, playDef(fadeIn));
    return !voice_.isNull();
}

void AudioSource::stop(double fadeOut) {
    playWhenReady_ = false;
    if (Mixer* m = mixer()) {
        m->stop(voice_, fadeOut < 0.0 ? def_.fadeOut : fadeOut);
    }
}

void AudioSource::pause(double fadeOut) {
    if (Mixer* m = mixer()) {
        m->pause(voice_, fadeOut < 0.0 ? def_.fadeOut : fadeOut);
    }
}

void AudioSource::resume(double fadeIn) {
    if (Mixer* m = mixer()) {
        m->resume(voice_, fadeIn < 0.0 ? def_.fadeIn : fadeIn);
    }
}

bool AudioSource::isPlaying() const {
    const Mixer* m = mixer();
    return m != nullptr && m->state(voice_) == VoiceState::Playing;
}

bool AudioSource::isPaused() const {
    const Mixer* m = mixer();
    return m != nullptr && m->state(voice_) == VoiceState::Paused;
}

void AudioSource::setClip(std::string path, bool stream) {
    def_.clip = std::move(path);
    def_.stream = stream;
    if (Mixer* m = mixer()) {
        sound_ = def_.clip.empty()
                     ? SoundId{}
                     : m->load(def_.clip, stream ? LoadMode::Stream : LoadMode::Whole);
    }
}

void AudioSource::setGain(float gain) {
    AudioSourceDef check = def_;
    check.gain = gain;
    checkSourceDef(check, "audio::AudioSource::setGain()");
    def_.gain = gain;
    if (Mixer* m = mixer()) {
        m->setGain(voice_, gain);
    }
}

void AudioSource::setPitch(float pitch) {
    AudioSourceDef check = def_;
    check.pitch = pitch;
    checkSourceDef(check, "audio::AudioSource::setPitch()");
    def_.pitch = pitch;
    if (Mixer* m = mixer()) {
        m->setPitch(voice_, pitch);
    }
}

void AudioSource::setLoop(bool loop) {
    def_.loop = loop;
    if (Mixer* m = mixer()) {
        m->setLoop(voice_, loop);
    }
}

void AudioSource::setSpatial(bool spatial) {
    def_.spatial = spatial;
    if (Mixer* m = mixer()) {
        m->setSpatial(voice_, spatial);
    }
}

void AudioSource::setAttenuationFactor(float factor) {
    AudioSourceDef check = def_;
    check.attenuationFactor = factor;
    checkSourceDef(check, "audio::AudioSource::setAttenuationFactor()");
    def_.attenuationFactor = factor;
    if (Mixer* m = mixer()) {
        m->setAttenuationFactor(voice_, factor);
    }
}

void AudioSource::setPriority(int priority) { def_.priority = priority; }

} // namespace e2d::audio
