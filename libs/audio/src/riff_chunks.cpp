// SPDX-License-Identifier: MIT
// The chunks of a WAV file (RIFF): each is a four-character id, a 32-bit size and that many
// bytes, padded to an even length; a LIST chunk holds a list type and entries of the same form.
#include "riff_chunks.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <string_view>

namespace e2d::audio::detail {

namespace {

using Id = std::array<char, 4>;

constexpr std::uint64_t kHeaderSize = 12; // "RIFF", the file's size, "WAVE"
constexpr std::uint64_t kChunkHeader = 8; // id, size
constexpr std::uint32_t kHugeEntry = 0x80000000u;

bool printable(const Id& id) {
    for (const char c : id) {
        if (c < 0x20 || c > 0x7e) {
            return false;
        }
    }
    return true;
}

bool is(const Id& id, std::string_view tag) { return std::memcmp(id.data(), tag.data(), 4) == 0; }

std::string idText(const Id& id) {
    if (printable(id)) {
        // Appended piece by piece: GCC 12 at -O3 warns (-Wrestrict) on "'" + std::string + "'".
        std::string text(1, '\'');
        text.append(id.data(), id.size());
        text += '\'';
        return text;
    }
    std::array<char, 16> text{};
    std::snprintf(text.data(), text.size(), "0x%02x%02x%02x%02x", static_cast<unsigned char>(id[0]),
                  static_cast<unsigned char>(id[1]), static_cast<unsigned char>(id[2]),
                  static_cast<unsigned char>(id[3]));
    return text.data();
}

class Reader {
public:
    Reader(std::uint64_t size, const ReadAt& read, bool bigEndian)
        : size_(size), read_(read), bigEndian_(bigEndian) {}

    [[nodiscard]] std::uint64_t size() const { return size_; }

    // The id at `at`; false past the end of the file.
    bool id(std::uint64_t at, Id& out) const {
        return read_(at, std::as_writable_bytes(std::span(out))) == out.size();
    }

    // The size field at `at` in the file's byte order; false past the end of the file.
    bool size32(std::uint64_t at, std::uint32_t& out) const {
        std::array<unsigned char, 4> b{};
        if (read_(at, std::as_writable_bytes(std::span(b))) != b.size()) {
            return false;
        }
        out = bigEndian_ ? (std::uint32_t{b[0]} << 24) | (std::uint32_t{b[1]} << 16) |
                               (std::uint32_t{b[2]} << 8) | b[3]
                         : (std::uint32_t{b[3]} << 24) | (std::uint32_t{b[2]} << 16) |
                               (std::uint32_t{b[1]} << 8) | b[0];
        return true;
    }

private:
    std::uint64_t size_;
    const ReadAt& read_;
    bool bigEndian_;
};

// The entries of the LIST (or INFO) chunk at `chunk`, whose contents are `length` bytes from
// `begin`, walked as libsndfile 1.2 walks them: the list type and any nested "INFO" or "adtl"
// are bare ids, a zero id, "data" or "exif" ends the walk, every other id has a size.
std::string checkList(const Reader& file, std::uint64_t chunk, std::uint64_t begin,
                      std::uint64_t length) {
    const std::uint64_t end = begin + length;
    Id id{};
    for (std::uint64_t at = begin; at + 4 <= end && file.id(at, id);) {
        const std::uint64_t entry = at;
        at += 4;
        if (is(id, "INFO") || is(id, "adtl")) {
            continue;
        }
        if (is(id, std::string_view("\0\0\0\0", 4)) || is(id, "data") || is(id, "exif")) {
            break;
        }
        std::uint32_t size = 0;
        if (at + 4 > end || !file.size32(at, size)) {
            break;
        }
        at += 4;
        const std::uint32_t padded = size + (size & 1u);
        if (padded >= kHugeEntry) {
            return "damaged: entry " + idText(id) + " at byte " + std::to_string(entry) +
                   " (in the list chunk at byte " + std::to_string(chunk) + ") claims " +
                   std::to_string(size) + " bytes; the file has " + std::to_string(file.size());
        }
        at += padded;
    }
    return {};
}

} // namespace

std::string checkWavChunks(std::uint64_t size, const ReadAt& read) {
    Id riff{};
    if (read(0, std::as_writable_bytes(std::span(riff))) != riff.size()) {
        return {};
    }
    const Reader file(size, read, is(riff, "RIFX"));
    Id id{};
    Id before{};
    for (std::uint64_t at = kHeaderSize; at + kChunkHeader <= size && file.id(at, id);) {
        if (!printable(id)) {
            // A writer that left out the pad byte after an odd-sized chunk puts the next id one
            // byte earlier (libsndfile finds it there too); anything else ends the chunks.
            if (!file.id(at - 1, before) || !printable(before)) {
                break;
            }
            --at;
            id = before;
        }
        std::uint32_t chunkSize = 0;
        if (!file.size32(at + 4, chunkSize)) {
            break;
        }
        const std::uint64_t begin = at + kChunkHeader;
        if (is(id, "LIST") || is(id, "INFO")) { // libsndfile reads both as lists
            // libsndfile reads no further than the end of the file.
            const std::uint64_t length = std::min<std::uint64_t>(chunkSize, size - begin);
            std::string problem = checkList(file, at, begin, length);
            if (!problem.empty()) {
                return problem;
            }
        }
        if (chunkSize == 0xffffffffu) {
            break; // RF64 gives the size of "data" in its "ds64" chunk: nothing follows here
        }
        at = begin + chunkSize + (chunkSize & 1u);
    }
    return {};
}

} // namespace e2d::audio::detail
