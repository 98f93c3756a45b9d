// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/component.hpp>

namespace e2d::audio {

class AudioSystem;

/// The ears of the scene: every frame it gives the mixer its GameObject's world
/// position and orientation, from which every spatial voice is heard. One listener is active at
/// a time: a second one that enters the scene while another is active warns once through the
/// logger and stays inactive (even after the first one goes). Unique per object.
class AudioListener : public core::Component {
public:
    static constexpr bool kUnique = true;

    AudioListener() = default;
    ~AudioListener() override;

    /// True for the listener the mix is heard from.
    [[nodiscard]] bool isActive() const noexcept { return active_; }

    void onInitialize() override;
    void onTerminate() override;
    void update(double dt) override;

private:
    friend class AudioSystem;

    void push() const;

    AudioSystem* system_ = nullptr;
    bool active_ = false;
};

} // namespace e2d::audio
