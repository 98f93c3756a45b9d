// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/audio/mixer.hpp>
#include <e2d/core/system.hpp>

/// The scene-graph side of the audio library: a core::System that owns the Mixer of a running
/// game, and the AudioSource and AudioListener components that attach game objects to it.
/// Nothing here is needed to use Mixer on its own.
namespace e2d::audio {

class AudioListener;

/// Owns the Mixer and updates it once per frame, after the scene's update (so the positions
/// the components gave it this frame are heard this frame). Components find it through
/// `scene()->system<AudioSystem>()`. On a scene change (clear()) every voice stops and the
/// listener is released; loaded sounds stay cached.
class AudioSystem : public core::System {
public:
    /// Throws core::Error naming the invalid field of `def` (see Mixer).
    explicit AudioSystem(const MixerDef& def = {});
    ~AudioSystem() override;
    AudioSystem(const AudioSystem&) = delete;
    AudioSystem& operator=(const AudioSystem&) = delete;

    [[nodiscard]] Mixer& mixer() noexcept { return mixer_; }
    [[nodiscard]] const Mixer& mixer() const noexcept { return mixer_; }

    /// The listener the mix is heard from, or nullptr.
    [[nodiscard]] AudioListener* activeListener() const noexcept { return listener_; }

    void update(double dt) override;
    void clear() override;

private:
    friend class AudioListener;

    /// Makes `listener` the active one unless another is; returns whether it is.
    bool claimListener(AudioListener& listener) noexcept;
    void releaseListener(AudioListener& listener) noexcept;

    Mixer mixer_;
    AudioListener* listener_ = nullptr;
};

} // namespace e2d::audio
