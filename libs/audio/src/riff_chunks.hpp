// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>

namespace e2d::audio::detail {

/// Random access to a file's bytes: copies up to `out.size()` bytes from `offset` into `out`
/// and returns how many it copied (fewer at the end of the file).
using ReadAt = std::function<std::size_t(std::uint64_t offset, std::span<std::byte> out)>;

/// Walks the chunks of a WAV file (RIFF, RIFX or RF64; `size` bytes read through `read`) and
/// returns what is wrong, or an empty string: an entry of a LIST chunk whose size, rounded up to
/// even, is 2 GiB or more ("damaged: ..."). libsndfile 1.2 steps over a LIST entry with a
/// signed 32-bit jump, so such a size moves it backwards, and an entry that leads back to
/// itself keeps sf_open() busy for ever (a 133-byte file found by the sound loader's fuzzer).
/// No real file holds a 2 GiB piece of metadata, so the file is refused before libsndfile
/// reads it. Nothing else is judged here: libsndfile reports the rest.
[[nodiscard]] std::string checkWavChunks(std::uint64_t size, const ReadAt& read);

} // namespace e2d::audio::detail
