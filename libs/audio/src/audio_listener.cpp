// SPDX-License-Identifier: MIT
#include <e2d/audio/audio_listener.hpp>
#include <e2d/audio/audio_system.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/log.hpp>
#include <e2d/core/scene.hpp>

namespace e2d::audio {

AudioListener::~AudioListener() {
    if (system_ != nullptr) {
        system_->releaseListener(*this);
    }
}

void AudioListener::onInitialize() {
    system_ = &scene()->system<AudioSystem>();
    active_ = system_->claimListener(*this);
    if (active_) {
        push();
    } else {
        system_->mixer().logger().warning(
            "audio::AudioListener: another listener is already active; this one stays inactive");
    }
}

void AudioListener::onTerminate() {
    if (system_ != nullptr) {
        system_->releaseListener(*this);
    }
    system_ = nullptr;
    active_ = false;
}

void AudioListener::update(double dt) {
    static_cast<void>(dt);
    push();
}

void AudioListener::push() const {
    if (!active_ || system_ == nullptr) {
        return;
    }
    const glm::vec3 position = gameObject()->worldPosition();
    system_->mixer().setListener({position.x, position.y}, gameObject()->worldOrientation());
}

} // namespace e2d::audio
