// SPDX-License-Identifier: MIT
#include <e2d/audio/audio_listener.hpp>
#include <e2d/audio/audio_system.hpp>

namespace e2d::audio {

AudioSystem::AudioSystem(const MixerDef& def) : mixer_(def) {}

AudioSystem::~AudioSystem() {
    if (listener_ != nullptr) {
        listener_->system_ = nullptr;
        listener_->active_ = false;
    }
}

void AudioSystem::update(double dt) {
    // The listener's object may have moved after the listener's own update this frame.
    if (listener_ != nullptr) {
        listener_->push();
    }
    mixer_.update(dt);
}

void AudioSystem::clear() {
    mixer_.stopAll();
    if (listener_ != nullptr) {
        listener_->active_ = false;
        listener_ = nullptr;
    }
}

bool AudioSystem::claimListener(AudioListener& listener) noexcept {
    if (listener_ != nullptr && listener_ != &listener) {
        return false;
    }
    listener_ = &listener;
    return true;
}

void AudioSystem::releaseListener(AudioListener& listener) noexcept {
    if (listener_ == &listener) {
        listener_ = nullptr;
    }
}

} // namespace e2d::audio
