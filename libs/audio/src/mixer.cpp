// SPDX-License-Identifier: MIT
// The Mixer's device handling, sound cache and public entry points. Voices: voices.cpp.
#include "mixer_impl.hpp"

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>

#include <cmath>

namespace e2d::audio {

using core::throwInvalid;

namespace {

constexpr const char* kCtor = "audio::Mixer::Mixer()";

void checkSpatial(const SpatialDef& s, const char* function) {
    auto check = [&](float value, const char* field) {
        if (!std::isfinite(value) || value < 0.0f) {
            throwInvalid(function, field, "finite and >= 0", value);
        }
    };
    check(s.minAttenuationDistance, "spatial.minAttenuationDistance");
    check(s.maxAttenuationDistance, "spatial.maxAttenuationDistance");
    check(s.minPanningDistance, "spatial.minPanningDistance");
    check(s.maxPanningDistance, "spatial.maxPanningDistance");
    if (s.maxAttenuationDistance <= s.minAttenuationDistance) {
        throwInvalid(function, "spatial.maxAttenuationDistance",
                     "> minAttenuationDistance (" + core::formatNumber(s.minAttenuationDistance) +
                         ")",
                     s.maxAttenuationDistance);
    }
    if (s.maxPanningDistance <= s.minPanningDistance) {
        throwInvalid(function, "spatial.maxPanningDistance",
                     "> minPanningDistance (" + core::formatNumber(s.minPanningDistance) + ")",
                     s.maxPanningDistance);
    }
}

void checkGain(float gain, const char* function, const char* field) {
    if (!std::isfinite(gain) || gain < 0.0f) {
        throwInvalid(function, field, ">= 0", gain);
    }
}

void checkDef(const MixerDef& def) {
    if (def.loopbackSampleRate < 8000 || def.loopbackSampleRate > 192000) {
        throwInvalid(kCtor, "loopbackSampleRate", "in 8000..192000", def.loopbackSampleRate);
    }
    if (def.loopbackDevice != nullptr && def.output != Output::Loopback) {
        throw core::Error(std::string(kCtor) +
                          ": loopbackDevice is given but output is not Output::Loopback");
    }
    if (def.voiceCount < 1 || def.voiceCount > 1024) {
        throwInvalid(kCtor, "voiceCount", "in 1..1024", def.voiceCount);
    }
    checkGain(def.masterGain, kCtor, "masterGain");
    checkSpatial(def.spatial, kCtor);
    const DecodeLimits& l = def.limits;
    if (l.maxChannels < 1 || l.maxChannels > 2) {
        throwInvalid(kCtor, "limits.maxChannels", "1 or 2", l.maxChannels);
    }
    if (l.minSampleRate < 1 || l.minSampleRate > l.maxSampleRate) {
        throwInvalid(kCtor, "limits.minSampleRate", "in 1..limits.maxSampleRate", l.minSampleRate);
    }
    if (l.maxFrames < 1) {
        throwInvalid(kCtor, "limits.maxFrames", ">= 1", l.maxFrames);
    }
    if (!(l.maxSampleMagnitude >= 1.0f) || !std::isfinite(l.maxSampleMagnitude)) {
        throwInvalid(kCtor, "limits.maxSampleMagnitude", "finite and >= 1", l.maxSampleMagnitude);
    }
    if (!(def.streamChunkSeconds >= 0.01 && def.streamChunkSeconds <= 1.0)) {
        throwInvalid(kCtor, "streamChunkSeconds", "in 0.01..1", def.streamChunkSeconds);
    }
    if (def.streamChunkCount < 3 || def.streamChunkCount > 16) {
        throwInvalid(kCtor, "streamChunkCount", "in 3..16", def.streamChunkCount);
    }
    if ((def.streamChunkCount - 1) * def.streamChunkSeconds < 0.25 - 1e-9) {
        throwInvalid(kCtor, "(streamChunkCount - 1) * streamChunkSeconds", ">= 0.25 s",
                     (def.streamChunkCount - 1) * def.streamChunkSeconds);
    }
}

} // namespace

// Impl: device -----------------------------------------------------------------------------

Mixer::Impl::Impl(const MixerDef& d)
    : def(d), logger(d.logger != nullptr ? d.logger : &ownLogger), masterGain(d.masterGain),
      spatial(d.spatial) {
    voices.resize(static_cast<std::size_t>(def.voiceCount));
    openOutput(false);
}

Mixer::Impl::~Impl() {
    if (device) {
        releaseDeviceObjects();
    }
}

bool Mixer::Impl::openOutput(bool reopening) {
    std::string error;
    std::vector<std::string> libraryLines;
    const int sources = 2 * def.voiceCount;
    if (def.output == Output::Loopback) {
        device = detail::Device::openLoopback(def.loopbackSampleRate, sources,
                                              static_cast<ALCdevice*>(def.loopbackDevice), error);
    } else if (def.output == Output::None && !reopening) {
        error = "no output requested (Output::None)";
    } else {
        // Reopening goes to the default device: the named one may be the one that went away.
        device = detail::Device::openDevice(reopening ? std::string() : def.deviceName, sources,
                                            error, libraryLines);
    }
    if (!device) {
        goSilent(error, def.output == Output::Device
                            ? " (ALSOFT_DRIVERS=null chooses silence without looking for a device)"
                            : "");
        for (const std::string& line : libraryLines) {
            logger->debug("audio::Mixer: while opening the device: " + line);
        }
        return false;
    }
    createDeviceObjects();
    if (!device) {
        return false;
    }
    silentReported = false;
    if (reopening) {
        logger->info("audio::Mixer: playing on '" + device->name() + "'");
    }
    return true;
}

void Mixer::Impl::goSilent(const std::string& why, std::string_view hint) {
    if (!silentReported) {
        logger->warning("audio::Mixer: " + why + "; running silent" + std::string(hint));
        silentReported = true;
    }
}

void Mixer::Impl::createDeviceObjects() {
    device->makeCurrent();
    alGetError();
    for (detail::Voice& voice : voices) {
        ALuint ids[2] = {0, 0};
        alGenSources(2, ids);
        if (alGetError() != AL_NO_ERROR) {
            const std::string name = device->name();
            releaseDeviceObjects();
            device.reset();
            goSilent("cannot create " + std::to_string(2 * def.voiceCount) +
                     " OpenAL sources on '" + name + "'");
            return;
        }
        voice.sourceLeft = ids[0];
        voice.sourceRight = ids[1];
        for (int side = 0; side < 2; ++side) {
            const ALuint source = ids[side];
            // Fixed at the two ends of the listener's ear axis, where OpenAL Soft sends a mono
            // source to one channel only; the mixer sets each side's gain itself.
            alSourcei(source, AL_SOURCE_RELATIVE, AL_TRUE);
            alSource3f(source, AL_POSITION, side == 0 ? -1.0f : 1.0f, 0.0f, 0.0f);
            alSourcef(source, AL_ROLLOFF_FACTOR, 0.0f);
            alSourcef(source, AL_MAX_GAIN, 16.0f);
            alSourcef(source, AL_GAIN, 0.0f);
        }
        voice.appliedLeft = voice.appliedRight = -1.0f;
    }
    for (detail::Sound& sound : sounds) {
        uploadSound(sound);
    }
    // Voices that lived on while silent go on from where they are.
    for (detail::Voice& voice : voices) {
        if (voice.busy) {
            startVoice(voice, voice.silentFrame);
        }
    }
}

void Mixer::Impl::releaseDeviceObjects() {
    device->makeCurrent();
    for (detail::Voice& voice : voices) {
        if (voice.sourceLeft != 0) {
            stopSources(voice);
            const ALuint ids[2] = {voice.sourceLeft, voice.sourceRight};
            alDeleteSources(2, ids);
            voice.sourceLeft = voice.sourceRight = 0;
        }
    }
    for (detail::Sound& sound : sounds) {
        if (sound.bufferLeft != 0) {
            alDeleteBuffers(1, &sound.bufferLeft);
        }
        if (sound.bufferRight != 0) {
            alDeleteBuffers(1, &sound.bufferRight);
        }
        sound.bufferLeft = sound.bufferRight = 0;
    }
}

void Mixer::Impl::uploadSound(detail::Sound& sound) {
    if (!device || sound.info.mode != LoadMode::Whole || !sound.info.ok()) {
        return;
    }
    device->makeCurrent();
    const int rate = sound.info.sampleRate;
    auto upload = [rate](const std::vector<float>& samples) {
        ALuint buffer = 0;
        alGenBuffers(1, &buffer);
        alBufferData(buffer, AL_FORMAT_MONO_FLOAT32, samples.data(),
                     static_cast<ALsizei>(samples.size() * sizeof(float)), rate);
        return buffer;
    };
    sound.bufferLeft = upload(sound.left);
    if (!sound.right.empty()) {
        sound.bufferRight = upload(sound.right);
    }
}

// Mixer -------------------------------------------------------------------------------------

Mixer::Mixer(const MixerDef& def) {
    checkDef(def);
    impl_ = std::make_unique<Impl>(def);
}

Mixer::~Mixer() = default;

bool Mixer::hasDevice() const noexcept { return impl_->device != nullptr; }

int Mixer::sampleRate() const noexcept {
    return impl_->device ? impl_->device->sampleRate() : 48000;
}

bool Mixer::reopen() {
    Impl& m = *impl_;
    if (m.device) {
        for (detail::Voice& voice : m.voices) {
            if (voice.busy) {
                voice.silentFrame = m.voicePosition(voice);
            }
        }
        m.releaseDeviceObjects();
        m.device.reset();
    }
    m.silentReported = false;
    return m.openOutput(true);
}

void Mixer::render(std::span<float> interleavedStereo) {
    constexpr const char* fn = "audio::Mixer::render()";
    if (impl_->def.output != Output::Loopback) {
        throw core::Error(std::string(fn) +
                          ": only a loopback mixer (Output::Loopback) renders into memory");
    }
    if (!impl_->device) {
        throw core::Error(std::string(fn) + ": the loopback device could not be opened");
    }
    if (interleavedStereo.size() % 2 != 0) {
        throwInvalid(fn, "interleavedStereo.size()", "even (L, R pairs)", interleavedStereo.size());
    }
    impl_->device->makeCurrent();
    impl_->device->render(interleavedStereo.data(), static_cast<int>(interleavedStereo.size() / 2));
}

// Sounds ------------------------------------------------------------------------------------

namespace {

void splitChannels(const SoundData& data, detail::Sound& sound) {
    const std::size_t frames = static_cast<std::size_t>(data.frames());
    if (data.channels == 1) {
        sound.left = data.samples;
        return;
    }
    sound.left.resize(frames);
    sound.right.resize(frames);
    for (std::size_t i = 0; i < frames; ++i) {
        sound.left[i] = data.samples[2 * i];
        sound.right[i] = data.samples[2 * i + 1];
    }
}

} // namespace

SoundId Mixer::load(const std::filesystem::path& path, LoadMode mode) {
    Impl& m = *impl_;
    auto key = std::make_pair(path.string(), mode);
    if (auto it = m.cache.find(key); it != m.cache.end()) {
        return it->second;
    }
    detail::Sound sound;
    sound.info.path = key.first;
    sound.info.mode = mode;
    if (mode == LoadMode::Whole) {
        DecodeResult result = decodeSoundFile(path, m.def.limits);
        if (result.ok()) {
            sound.info.channels = result.data.channels;
            sound.info.sampleRate = result.data.sampleRate;
            sound.info.frames = result.data.frames();
            splitChannels(result.data, sound);
        } else {
            sound.info.error = std::move(result.error);
        }
    } else {
        std::string error;
        auto decoder = detail::Decoder::open(path, m.def.limits, error);
        if (decoder) {
            // Decode a little now, so a file that opens but cannot be decoded fails here.
            std::vector<float> probe(static_cast<std::size_t>(256 * decoder->channels()));
            const std::int64_t got = decoder->read(probe.data(), 256);
            if (got < 0) {
                error = decoder->error();
            } else if (got == 0) {
                error = "'" + key.first + "': no audio frames";
            }
        }
        if (error.empty()) {
            sound.info.channels = decoder->channels();
            sound.info.sampleRate = decoder->sampleRate();
            sound.info.frames = std::max<std::int64_t>(decoder->headerFrames(), 0);
        } else {
            sound.info.error = std::move(error);
        }
    }
    if (!sound.info.ok()) {
        m.logger->error("audio::Mixer::load(): " + sound.info.error +
                        " (the sound plays as silence)");
    }
    m.uploadSound(sound);
    m.sounds.push_back(std::move(sound));
    const SoundId id{static_cast<std::uint32_t>(m.sounds.size())};
    m.cache.emplace(std::move(key), id);
    return id;
}

SoundId Mixer::add(SoundData data, std::string name) {
    constexpr const char* fn = "audio::Mixer::add()";
    Impl& m = *impl_;
    if (data.channels < 1 || data.channels > m.def.limits.maxChannels) {
        throwInvalid(fn, "data.channels", "in 1.." + std::to_string(m.def.limits.maxChannels),
                     data.channels);
    }
    if (data.sampleRate < m.def.limits.minSampleRate ||
        data.sampleRate > m.def.limits.maxSampleRate) {
        throwInvalid(fn, "data.sampleRate",
                     "in " + std::to_string(m.def.limits.minSampleRate) + ".." +
                         std::to_string(m.def.limits.maxSampleRate),
                     data.sampleRate);
    }
    if (data.frames() < 1 || data.samples.size() % static_cast<std::size_t>(data.channels) != 0) {
        throwInvalid(fn, "data.samples.size()", "a positive multiple of channels",
                     data.samples.size());
    }
    const float limit = m.def.limits.maxSampleMagnitude;
    for (std::size_t i = 0; i < data.samples.size(); ++i) {
        if (!(std::abs(data.samples[i]) <= limit)) {
            throwInvalid(fn, "data.samples[" + std::to_string(i) + "]",
                         "finite and within +-" + core::formatNumber(limit) +
                             " (limits.maxSampleMagnitude)",
                         data.samples[i]);
        }
    }
    detail::Sound sound;
    sound.info.path = std::move(name);
    sound.info.channels = data.channels;
    sound.info.sampleRate = data.sampleRate;
    sound.info.frames = data.frames();
    splitChannels(data, sound);
    m.uploadSound(sound);
    m.sounds.push_back(std::move(sound));
    return SoundId::forSlot(static_cast<std::uint32_t>(m.sounds.size() - 1));
}

const SoundInfo& Mixer::soundInfo(SoundId sound) const {
    if (!core::slotOf(sound, impl_->sounds.size())) {
        throw core::Error("audio::Mixer::soundInfo(): unknown sound id " +
                          std::to_string(sound.index1));
    }
    return impl_->sounds[sound.index()].info;
}

int Mixer::soundCount() const noexcept { return static_cast<int>(impl_->sounds.size()); }

// Mix ---------------------------------------------------------------------------------------

float Mixer::masterGain() const noexcept { return impl_->masterGain; }

void Mixer::setMasterGain(float gain) {
    checkGain(gain, "audio::Mixer::setMasterGain()", "gain");
    impl_->masterGain = gain;
}

float Mixer::busGain(Bus bus) const noexcept {
    return impl_->busGains[static_cast<std::size_t>(bus)];
}

void Mixer::setBusGain(Bus bus, float gain) {
    const auto index = static_cast<std::size_t>(bus);
    if (index >= impl_->busGains.size()) {
        throwInvalid("audio::Mixer::setBusGain()", "bus", "Music or Effects",
                     static_cast<int>(bus));
    }
    checkGain(gain, "audio::Mixer::setBusGain()", "gain");
    impl_->busGains[index] = gain;
}

void Mixer::setListener(glm::vec2 position, float orientation) noexcept {
    impl_->listener = position;
    impl_->listenerOrientation = orientation;
}

glm::vec2 Mixer::listenerPosition() const noexcept { return impl_->listener; }

const SpatialDef& Mixer::spatial() const noexcept { return impl_->spatial; }

void Mixer::setSpatial(const SpatialDef& def) {
    checkSpatial(def, "audio::Mixer::setSpatial()");
    impl_->spatial = def;
}

core::Logger& Mixer::logger() const noexcept { return *impl_->logger; }

int Mixer::voiceCount() const noexcept { return static_cast<int>(impl_->voices.size()); }

MixerStats Mixer::stats() const noexcept {
    MixerStats s = impl_->stats;
    s.voicesInUse = 0;
    for (const detail::Voice& voice : impl_->voices) {
        s.voicesInUse += voice.busy ? 1 : 0;
    }
    return s;
}

} // namespace e2d::audio
