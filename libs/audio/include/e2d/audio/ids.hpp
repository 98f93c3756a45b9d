// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

/// Handles handed out by an audio::Mixer: small values, never pointers into its pools. The slot
/// index plus one (so a zero-initialised handle is null) and, for voices, the slot's generation,
/// which changes every time the voice ends or is taken by another sound; an old VoiceId then
/// does nothing instead of reaching the new sound.
namespace e2d::audio {

/// A sound in a Mixer's cache. Sounds live as long as their mixer. Default: null.
struct SoundId {
    std::uint32_t index1 = 0; ///< slot index + 1; 0 means null

    [[nodiscard]] constexpr bool isNull() const { return index1 == 0; }
    friend constexpr bool operator==(SoundId, SoundId) = default;
};

/// A playing (or paused) sound. Default: null.
struct VoiceId {
    std::uint32_t index1 = 0;     ///< slot index + 1; 0 means null
    std::uint32_t generation = 0; ///< the slot's generation when the id was handed out

    [[nodiscard]] constexpr bool isNull() const { return index1 == 0; }
    friend constexpr bool operator==(VoiceId, VoiceId) = default;
};

} // namespace e2d::audio
