// SPDX-License-Identifier: MIT
// The Mixer's voice pool: starting, stealing, fades, gains, streams, and the per-frame update.
#include "mixer_impl.hpp"

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace e2d::audio {

using core::throwInvalid;
using detail::Voice;

namespace {

constexpr float kCentre = std::numbers::sqrt2_v<float> / 2.0f;

void checkPlayDef(const PlayDef& def, const char* fn) {
    if (!std::isfinite(def.gain) || def.gain < 0.0f) {
        throwInvalid(fn, "gain", ">= 0", def.gain);
    }
    if (!(def.pitch >= 0.01f && def.pitch <= 16.0f)) {
        throwInvalid(fn, "pitch", "in 0.01..16", def.pitch);
    }
    if (!std::isfinite(def.position.x) || !std::isfinite(def.position.y)) {
        throwInvalid(fn, "position", "finite", def.position);
    }
    if (!std::isfinite(def.attenuationFactor) || def.attenuationFactor < 0.0f) {
        throwInvalid(fn, "attenuationFactor", ">= 0", def.attenuationFactor);
    }
    if (static_cast<int>(def.bus) >= kBusCount) {
        throwInvalid(fn, "bus", "Music or Effects", static_cast<int>(def.bus));
    }
    if (!std::isfinite(def.fadeIn) || def.fadeIn < 0.0) {
        throwInvalid(fn, "fadeIn", ">= 0 seconds", def.fadeIn);
    }
}

void checkFade(double seconds, const char* fn, const char* field) {
    if (!std::isfinite(seconds) || seconds < 0.0) {
        throwInvalid(fn, field, ">= 0 seconds", seconds);
    }
}

void beginFade(Voice& voice, float to, double duration, detail::FadeEnd end) {
    voice.fading = true;
    voice.fadeFrom = voice.fade;
    voice.fadeTo = to;
    voice.fadeElapsed = 0.0;
    voice.fadeDuration = duration;
    voice.fadeEnd = end;
}

} // namespace

// Impl: voices ------------------------------------------------------------------------------

Voice* Mixer::Impl::find(VoiceId id) noexcept {
    const std::optional<std::uint32_t> index =
        core::findSlot(id, voices.size(), [this](std::uint32_t i) {
            return voices[i].busy ? voices[i].generation : 0u;
        });
    return index ? &voices[*index] : nullptr;
}

const Voice* Mixer::Impl::find(VoiceId id) const noexcept {
    return const_cast<Impl*>(this)->find(id);
}

int Mixer::Impl::allocateVoice(int priority) {
    for (std::size_t i = 0; i < voices.size(); ++i) {
        if (!voices[i].busy) {
            return static_cast<int>(i);
        }
    }
    int lowest = std::numeric_limits<int>::max();
    for (const Voice& voice : voices) {
        lowest = std::min(lowest, voice.def.priority);
    }
    if (lowest >= priority) {
        ++stats.playsRefused;
        return -1;
    }
    // The quietest voice of the lowest priority; the oldest of equally quiet ones.
    int victim = -1;
    for (std::size_t i = 0; i < voices.size(); ++i) {
        const Voice& voice = voices[i];
        if (voice.def.priority != lowest) {
            continue;
        }
        if (victim < 0) {
            victim = static_cast<int>(i);
            continue;
        }
        const Voice& best = voices[static_cast<std::size_t>(victim)];
        if (voice.gain < best.gain ||
            (voice.gain == best.gain && voice.startOrder < best.startOrder)) {
            victim = static_cast<int>(i);
        }
    }
    releaseVoice(voices[static_cast<std::size_t>(victim)]);
    ++stats.voicesStolen;
    return victim;
}

void Mixer::Impl::stopSources(Voice& voice) {
    if (!device || voice.sourceLeft == 0) {
        return;
    }
    const ALuint ids[2] = {voice.sourceLeft, voice.sourceRight};
    alSourceStopv(2, ids);
    // Detaching the buffer also empties a stream's queue.
    alSourcei(voice.sourceLeft, AL_BUFFER, 0);
    alSourcei(voice.sourceRight, AL_BUFFER, 0);
    if (voice.stream) {
        detail::Stream& stream = *voice.stream;
        if (!stream.allLeft.empty()) {
            alDeleteBuffers(static_cast<ALsizei>(stream.allLeft.size()), stream.allLeft.data());
        }
        if (!stream.allRight.empty()) {
            alDeleteBuffers(static_cast<ALsizei>(stream.allRight.size()), stream.allRight.data());
        }
        stream.allLeft.clear();
        stream.allRight.clear();
        stream.freeLeft.clear();
        stream.freeRight.clear();
        stream.queuedFrames.clear();
    }
}

void Mixer::Impl::releaseVoice(Voice& voice) {
    stopSources(voice);
    voice.stream.reset();
    voice.busy = false;
    voice.state = VoiceState::Stopped;
    voice.fading = false;
    voice.gain = 0.0f;
    voice.appliedLeft = voice.appliedRight = -1.0f;
    voice.generation = core::nextGeneration(voice.generation);
}

void Mixer::Impl::computeGain(Voice& voice, float& left, float& right) const {
    const detail::Sound& sound = sounds[voice.sound.index()];
    float gain = voice.def.gain * voice.fade * busGains[static_cast<std::size_t>(voice.def.bus)] *
                 masterGain;
    StereoGains pan{kCentre, kCentre};
    if (voice.def.spatial) {
        const glm::vec2 d = voice.def.position - listener;
        gain *=
            attenuationGain(spatial, std::sqrt(d.x * d.x + d.y * d.y), voice.def.attenuationFactor);
        pan = panGains(spatial,
                       listenerSpaceOffset(voice.def.position, listener, listenerOrientation).x);
    }
    if (sound.info.channels == 2) {
        // Stereo keeps its channels apart: full on both sides when centred (or 2D), the pan
        // curve scaled by sqrt(2) as a balance towards one side.
        pan.left = std::min(1.0f, pan.left / kCentre);
        pan.right = std::min(1.0f, pan.right / kCentre);
    }
    voice.gain = gain;
    left = gain * pan.left;
    right = gain * pan.right;
}

void Mixer::Impl::applyGains(Voice& voice) {
    float left = 0.0f;
    float right = 0.0f;
    computeGain(voice, left, right);
    if (!device || voice.sourceLeft == 0) {
        return;
    }
    if (left != voice.appliedLeft) {
        alSourcef(voice.sourceLeft, AL_GAIN, left);
        voice.appliedLeft = left;
    }
    if (right != voice.appliedRight) {
        alSourcef(voice.sourceRight, AL_GAIN, right);
        voice.appliedRight = right;
    }
}

void Mixer::Impl::startVoice(Voice& voice, double startFrame) {
    voice.silentFrame = startFrame;
    if (!device) {
        applyGains(voice);
        return;
    }
    const detail::Sound& sound = sounds[voice.sound.index()];
    const ALuint ids[2] = {voice.sourceLeft, voice.sourceRight};
    alSourceStopv(2, ids);
    alSourcei(voice.sourceLeft, AL_BUFFER, 0);
    alSourcei(voice.sourceRight, AL_BUFFER, 0);
    for (ALuint source : ids) {
        alSourcef(source, AL_PITCH, voice.def.pitch);
    }
    voice.appliedLeft = voice.appliedRight = -1.0f;
    applyGains(voice);
    if (sound.info.mode == LoadMode::Whole) {
        alSourcei(voice.sourceLeft, AL_BUFFER, static_cast<ALint>(sound.bufferLeft));
        alSourcei(
            voice.sourceRight, AL_BUFFER,
            static_cast<ALint>(sound.bufferRight != 0 ? sound.bufferRight : sound.bufferLeft));
        const auto offset = static_cast<ALint>(std::floor(startFrame));
        for (ALuint source : ids) {
            alSourcei(source, AL_LOOPING, voice.def.loop ? AL_TRUE : AL_FALSE);
            if (offset > 0) {
                alSourcei(source, AL_SAMPLE_OFFSET, offset);
            }
        }
    } else {
        for (ALuint source : ids) {
            alSourcei(source, AL_LOOPING, AL_FALSE); // the stream loops by rewinding its decoder
        }
        if (!openStream(voice, startFrame)) {
            return;
        }
    }
    // Both sides start in the same mixing pass, so they stay sample-aligned.
    alSourcePlayv(2, ids);
    if (voice.state == VoiceState::Paused) {
        alSourcePausev(2, ids);
    }
}

double Mixer::Impl::voicePosition(const Voice& voice) const {
    if (!device || voice.sourceLeft == 0) {
        return voice.silentFrame;
    }
    ALint offset = 0;
    alGetSourcei(voice.sourceLeft, AL_SAMPLE_OFFSET, &offset);
    if (!voice.stream) {
        return offset;
    }
    const std::int64_t frames = sounds[voice.sound.index()].info.frames;
    const std::int64_t position = voice.stream->playedFrames + offset;
    return static_cast<double>(frames > 0 ? position % frames : position);
}

// Streams -----------------------------------------------------------------------------------

bool Mixer::Impl::openStream(Voice& voice, double startFrame) {
    const detail::Sound& sound = sounds[voice.sound.index()];
    if (!voice.stream) {
        voice.stream = std::make_unique<detail::Stream>();
    }
    detail::Stream& stream = *voice.stream;
    std::string error;
    if (!stream.decoder) {
        stream.decoder = detail::Decoder::open(sound.info.path, def.limits, error, true);
    }
    auto start = static_cast<std::int64_t>(std::floor(startFrame));
    if (sound.info.frames > 0) {
        start %= sound.info.frames;
    }
    if (stream.decoder && !stream.decoder->seek(start)) {
        error = stream.decoder->error();
    }
    if (!error.empty()) {
        logger->error("audio::Mixer: cannot stream " + error);
        stream.exhausted = true;
        return false;
    }
    stream.nextFrame = start;
    stream.playedFrames = start;
    stream.exhausted = false;
    stream.queuedFrames.clear();
    const auto chunk = static_cast<std::size_t>(
        std::max(1.0, std::round(def.streamChunkSeconds * sound.info.sampleRate)));
    stream.interleaved.resize(chunk * static_cast<std::size_t>(sound.info.channels));
    const auto count = static_cast<std::size_t>(def.streamChunkCount);
    stream.allLeft.assign(count, 0);
    alGenBuffers(static_cast<ALsizei>(count), stream.allLeft.data());
    stream.freeLeft = stream.allLeft;
    if (sound.info.channels == 2) {
        stream.left.resize(chunk);
        stream.right.resize(chunk);
        stream.allRight.assign(count, 0);
        alGenBuffers(static_cast<ALsizei>(count), stream.allRight.data());
        stream.freeRight = stream.allRight;
    }
    feedStream(voice);
    return true;
}

bool Mixer::Impl::fillChunk(Voice& voice, ALuint left, ALuint right) {
    detail::Stream& stream = *voice.stream;
    const detail::Sound& sound = sounds[voice.sound.index()];
    const int channels = sound.info.channels;
    const auto chunk = static_cast<std::int64_t>(stream.interleaved.size()) / channels;
    std::int64_t filled = 0;
    bool rewound = false;
    while (filled < chunk && !stream.exhausted) {
        const std::int64_t got =
            stream.decoder->read(stream.interleaved.data() + filled * channels, chunk - filled);
        if (got < 0) {
            detail::Sound& damaged = sounds[voice.sound.index()];
            if (!damaged.streamErrorLogged) {
                logger->error("audio::Mixer: stream stopped: " + stream.decoder->error());
                damaged.streamErrorLogged = true;
            }
            stream.exhausted = true;
            break;
        }
        if (got > 0) {
            rewound = false;
        }
        filled += got;
        stream.nextFrame += got;
        if (filled < chunk) {
            // End of the file: go on from its start when looping (in the same chunk, so the
            // loop point has no gap), unless the file gave nothing since the last rewind.
            if (!voice.def.loop || rewound || !stream.decoder->seek(0)) {
                stream.exhausted = true;
                break;
            }
            rewound = true;
            stream.nextFrame = 0;
        }
    }
    if (filled == 0) {
        return false;
    }
    const auto bytes = static_cast<ALsizei>(filled * static_cast<std::int64_t>(sizeof(float)));
    if (channels == 1) {
        alBufferData(left, AL_FORMAT_MONO_FLOAT32, stream.interleaved.data(), bytes,
                     sound.info.sampleRate);
        alSourceQueueBuffers(voice.sourceLeft, 1, &left);
        alSourceQueueBuffers(voice.sourceRight, 1, &left);
    } else {
        for (std::int64_t i = 0; i < filled; ++i) {
            stream.left[static_cast<std::size_t>(i)] =
                stream.interleaved[static_cast<std::size_t>(2 * i)];
            stream.right[static_cast<std::size_t>(i)] =
                stream.interleaved[static_cast<std::size_t>(2 * i + 1)];
        }
        alBufferData(left, AL_FORMAT_MONO_FLOAT32, stream.left.data(), bytes,
                     sound.info.sampleRate);
        alBufferData(right, AL_FORMAT_MONO_FLOAT32, stream.right.data(), bytes,
                     sound.info.sampleRate);
        alSourceQueueBuffers(voice.sourceLeft, 1, &left);
        alSourceQueueBuffers(voice.sourceRight, 1, &right);
    }
    stream.queuedFrames.push_back(filled);
    return true;
}

void Mixer::Impl::feedStream(Voice& voice) {
    detail::Stream& stream = *voice.stream;
    const bool stereo = !stream.allRight.empty();
    ALint processedLeft = 0;
    ALint processedRight = 0;
    alGetSourcei(voice.sourceLeft, AL_BUFFERS_PROCESSED, &processedLeft);
    alGetSourcei(voice.sourceRight, AL_BUFFERS_PROCESSED, &processedRight);
    const ALint processed = std::min(processedLeft, processedRight);
    for (ALint i = 0; i < processed && !stream.queuedFrames.empty(); ++i) {
        ALuint left = 0;
        ALuint right = 0;
        alSourceUnqueueBuffers(voice.sourceLeft, 1, &left);
        alSourceUnqueueBuffers(voice.sourceRight, 1, &right);
        stream.freeLeft.push_back(left);
        if (stereo) {
            stream.freeRight.push_back(right);
        }
        stream.playedFrames += stream.queuedFrames.front();
        stream.queuedFrames.pop_front();
    }
    while (!stream.exhausted && !stream.freeLeft.empty()) {
        const ALuint left = stream.freeLeft.back();
        const ALuint right = stereo ? stream.freeRight.back() : 0;
        if (!fillChunk(voice, left, right)) {
            break;
        }
        stream.freeLeft.pop_back();
        if (stereo) {
            stream.freeRight.pop_back();
        }
    }
}

// Impl: per-frame update --------------------------------------------------------------------

bool Mixer::Impl::advanceFade(Voice& voice, double dt) {
    if (!voice.fading) {
        return true;
    }
    voice.fadeElapsed += dt;
    const double t =
        voice.fadeDuration > 0.0 ? std::min(1.0, voice.fadeElapsed / voice.fadeDuration) : 1.0;
    voice.fade = voice.fadeFrom + (voice.fadeTo - voice.fadeFrom) * static_cast<float>(t);
    if (t < 1.0) {
        return true;
    }
    voice.fading = false;
    const detail::FadeEnd end = voice.fadeEnd;
    voice.fadeEnd = detail::FadeEnd::None;
    if (end == detail::FadeEnd::Stop) {
        releaseVoice(voice);
        return false;
    }
    if (end == detail::FadeEnd::Pause) {
        voice.state = VoiceState::Paused;
        if (device && voice.sourceLeft != 0) {
            const ALuint ids[2] = {voice.sourceLeft, voice.sourceRight};
            alSourcePausev(2, ids);
        }
    }
    return true;
}

void Mixer::Impl::updateVoice(Voice& voice, double dt) {
    if (voice.state == VoiceState::Playing && !advanceFade(voice, dt)) {
        return;
    }
    const detail::Sound& sound = sounds[voice.sound.index()];
    if (!device || voice.sourceLeft == 0) {
        if (voice.state == VoiceState::Playing) {
            voice.silentFrame += dt * sound.info.sampleRate * voice.def.pitch;
            const auto frames = static_cast<double>(sound.info.frames);
            if (frames > 0.0 && voice.silentFrame >= frames) {
                if (!voice.def.loop) {
                    releaseVoice(voice);
                    return;
                }
                voice.silentFrame = std::fmod(voice.silentFrame, frames);
            }
        }
        applyGains(voice);
        return;
    }
    if (voice.state == VoiceState::Playing) {
        if (voice.stream) {
            feedStream(voice);
        }
        ALint state = AL_PLAYING;
        alGetSourcei(voice.sourceLeft, AL_SOURCE_STATE, &state);
        if (state == AL_STOPPED) {
            if (!voice.stream || voice.stream->queuedFrames.empty()) {
                releaseVoice(voice);
                return;
            }
            // The stream ran dry (a frame longer than its buffers): go on with what is queued.
            ++stats.streamUnderruns;
            const ALuint ids[2] = {voice.sourceLeft, voice.sourceRight};
            alSourcePlayv(2, ids);
        }
    }
    applyGains(voice);
}

// Mixer: voices -----------------------------------------------------------------------------

VoiceId Mixer::play(SoundId sound, const PlayDef& def) {
    constexpr const char* fn = "audio::Mixer::play()";
    Impl& m = *impl_;
    if (!core::slotOf(sound, m.sounds.size())) {
        throw core::Error(std::string(fn) + ": unknown sound id " + std::to_string(sound.index1));
    }
    checkPlayDef(def, fn);
    if (!m.sounds[sound.index()].info.ok()) {
        return {};
    }
    m.makeCurrent();
    const int index = m.allocateVoice(def.priority);
    if (index < 0) {
        return {};
    }
    Voice& voice = m.voices[static_cast<std::size_t>(index)];
    voice.busy = true;
    voice.state = VoiceState::Playing;
    voice.sound = sound;
    voice.def = def;
    voice.fading = false;
    voice.fadeEnd = detail::FadeEnd::None;
    voice.fade = 1.0f;
    if (def.fadeIn > 0.0) {
        voice.fade = 0.0f;
        beginFade(voice, 1.0f, def.fadeIn, detail::FadeEnd::None);
    }
    voice.startOrder = ++m.startCounter;
    m.startVoice(voice, 0.0);
    if (voice.stream && voice.stream->queuedFrames.empty()) {
        m.releaseVoice(voice); // the file could not be streamed (already logged)
        return {};
    }
    return VoiceId::forSlot(static_cast<std::uint32_t>(index), voice.generation);
}

bool Mixer::stop(VoiceId id, double fadeOut) {
    checkFade(fadeOut, "audio::Mixer::stop()", "fadeOut");
    Voice* voice = impl_->find(id);
    if (voice == nullptr) {
        return false;
    }
    impl_->makeCurrent();
    if (fadeOut == 0.0 || voice->state == VoiceState::Paused) {
        impl_->releaseVoice(*voice);
    } else {
        beginFade(*voice, 0.0f, fadeOut, detail::FadeEnd::Stop);
    }
    return true;
}

bool Mixer::pause(VoiceId id, double fadeOut) {
    checkFade(fadeOut, "audio::Mixer::pause()", "fadeOut");
    Voice* voice = impl_->find(id);
    if (voice == nullptr) {
        return false;
    }
    if (voice->state == VoiceState::Paused) {
        return true;
    }
    impl_->makeCurrent();
    if (fadeOut > 0.0) {
        beginFade(*voice, 0.0f, fadeOut, detail::FadeEnd::Pause);
        return true;
    }
    voice->fading = false;
    voice->fadeEnd = detail::FadeEnd::None;
    voice->state = VoiceState::Paused;
    if (impl_->device && voice->sourceLeft != 0) {
        const ALuint ids[2] = {voice->sourceLeft, voice->sourceRight};
        alSourcePausev(2, ids);
    }
    return true;
}

bool Mixer::resume(VoiceId id, double fadeIn) {
    checkFade(fadeIn, "audio::Mixer::resume()", "fadeIn");
    Voice* voice = impl_->find(id);
    if (voice == nullptr) {
        return false;
    }
    impl_->makeCurrent();
    const bool wasPaused = voice->state == VoiceState::Paused;
    if (!wasPaused && voice->fadeEnd != detail::FadeEnd::Pause) {
        return true; // already playing
    }
    if (wasPaused) {
        voice->fade = fadeIn > 0.0 ? 0.0f : 1.0f;
    }
    if (fadeIn > 0.0) {
        beginFade(*voice, 1.0f, fadeIn, detail::FadeEnd::None);
    } else {
        voice->fading = false;
        voice->fadeEnd = detail::FadeEnd::None;
        voice->fade = 1.0f;
    }
    voice->state = VoiceState::Playing;
    impl_->applyGains(*voice);
    if (wasPaused && impl_->device && voice->sourceLeft != 0) {
        const ALuint ids[2] = {voice->sourceLeft, voice->sourceRight};
        alSourcePlayv(2, ids);
    }
    return true;
}

void Mixer::stopAll() {
    impl_->makeCurrent();
    for (Voice& voice : impl_->voices) {
        if (voice.busy) {
            impl_->releaseVoice(voice);
        }
    }
}

VoiceState Mixer::state(VoiceId id) const noexcept {
    const Voice* voice = impl_->find(id);
    return voice != nullptr ? voice->state : VoiceState::Stopped;
}

SoundId Mixer::sound(VoiceId id) const noexcept {
    const Voice* voice = impl_->find(id);
    return voice != nullptr ? voice->sound : SoundId{};
}

bool Mixer::setGain(VoiceId id, float gain) {
    PlayDef check;
    check.gain = gain;
    checkPlayDef(check, "audio::Mixer::setGain()");
    Voice* voice = impl_->find(id);
    if (voice != nullptr) {
        voice->def.gain = gain;
    }
    return voice != nullptr;
}

bool Mixer::setPitch(VoiceId id, float pitch) {
    PlayDef check;
    check.pitch = pitch;
    checkPlayDef(check, "audio::Mixer::setPitch()");
    Voice* voice = impl_->find(id);
    if (voice == nullptr) {
        return false;
    }
    voice->def.pitch = pitch;
    if (impl_->device && voice->sourceLeft != 0) {
        impl_->makeCurrent();
        alSourcef(voice->sourceLeft, AL_PITCH, pitch);
        alSourcef(voice->sourceRight, AL_PITCH, pitch);
    }
    return true;
}

bool Mixer::setLoop(VoiceId id, bool loop) {
    Voice* voice = impl_->find(id);
    if (voice == nullptr) {
        return false;
    }
    voice->def.loop = loop;
    if (impl_->device && voice->sourceLeft != 0 && !voice->stream) {
        impl_->makeCurrent();
        alSourcei(voice->sourceLeft, AL_LOOPING, loop ? AL_TRUE : AL_FALSE);
        alSourcei(voice->sourceRight, AL_LOOPING, loop ? AL_TRUE : AL_FALSE);
    }
    return true;
}

bool Mixer::setPosition(VoiceId id, glm::vec2 position) {
    if (!std::isfinite(position.x)) {
        throwInvalid("audio::Mixer::setPosition()", "position.x", "finite", position.x);
    }
    if (!std::isfinite(position.y)) {
        throwInvalid("audio::Mixer::setPosition()", "position.y", "finite", position.y);
    }
    Voice* voice = impl_->find(id);
    if (voice != nullptr) {
        voice->def.position = position;
    }
    return voice != nullptr;
}

bool Mixer::setAttenuationFactor(VoiceId id, float factor) {
    PlayDef check;
    check.attenuationFactor = factor;
    checkPlayDef(check, "audio::Mixer::setAttenuationFactor()");
    Voice* voice = impl_->find(id);
    if (voice != nullptr) {
        voice->def.attenuationFactor = factor;
    }
    return voice != nullptr;
}

bool Mixer::setSpatial(VoiceId id, bool spatial) {
    Voice* voice = impl_->find(id);
    if (voice != nullptr) {
        voice->def.spatial = spatial;
    }
    return voice != nullptr;
}

float Mixer::effectiveGain(VoiceId id) const noexcept {
    const Voice* voice = impl_->find(id);
    if (voice == nullptr) {
        return 0.0f;
    }
    Voice copy;
    copy.sound = voice->sound;
    copy.def = voice->def;
    copy.fade = voice->fade;
    float left = 0.0f;
    float right = 0.0f;
    impl_->computeGain(copy, left, right);
    return copy.gain;
}

double Mixer::playbackPosition(VoiceId id) const {
    const Voice* voice = impl_->find(id);
    if (voice == nullptr) {
        return 0.0;
    }
    impl_->makeCurrent();
    const int rate = impl_->sounds[voice->sound.index()].info.sampleRate;
    return rate > 0 ? impl_->voicePosition(*voice) / rate : 0.0;
}

void Mixer::update(double dt) {
    if (!std::isfinite(dt) || dt < 0.0) {
        throwInvalid("audio::Mixer::update()", "dt", ">= 0 seconds", dt);
    }
    Impl& m = *impl_;
    if (m.device && !m.device->connected()) {
        const std::string name = m.device->name();
        for (Voice& voice : m.voices) {
            if (voice.busy) {
                voice.silentFrame = m.voicePosition(voice);
            }
        }
        m.releaseDeviceObjects();
        m.device.reset();
        m.goSilent("the audio device '" + name + "' was disconnected");
    }
    if (m.device) {
        m.device->makeCurrent();
        m.device->deferUpdates();
    }
    for (Voice& voice : m.voices) {
        if (voice.busy) {
            m.updateVoice(voice, dt);
        }
    }
    if (m.device) {
        m.device->processUpdates();
    }
}

} // namespace e2d::audio
