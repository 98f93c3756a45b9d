// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/id.hpp>

#include <cstdint>

/// Handles handed out by an audio::Mixer (core::Id): small values, never pointers into its
/// pools. The slot index plus one (so a zero-initialised handle is null) and, for voices, the
/// slot's generation, which changes every time the voice ends or is taken by another sound; an
/// old VoiceId then does nothing instead of reaching the new sound.
namespace e2d::audio {

struct SoundIdTag;
struct VoiceIdTag;

/// A sound in a Mixer's cache. Sounds live as long as their mixer, so the id has no
/// generation (4 bytes). Default: null.
using SoundId = core::Id<SoundIdTag, core::NoGeneration>;
/// A playing (or paused) sound (8 bytes: index + 1 and a 32-bit generation). Default: null.
using VoiceId = core::Id<VoiceIdTag, std::uint32_t>;

static_assert(sizeof(SoundId) == 4 && sizeof(VoiceId) == 8);

} // namespace e2d::audio
