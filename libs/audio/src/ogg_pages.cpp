// SPDX-License-Identifier: MIT
// The Ogg container's pages (RFC 3533, section 6): capture pattern, checksum, end-of-stream flag.
#include "ogg_pages.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>

namespace e2d::audio::detail {

namespace {

constexpr std::size_t kHeaderSize = 27;
constexpr std::uint8_t kEndOfStream = 0x04;

// Ogg's CRC-32: polynomial 0x04c11db7, not reflected, initial value 0, no final xor.
constexpr std::array<std::uint32_t, 256> makeCrcTable() {
    std::array<std::uint32_t, 256> table{};
    for (std::uint32_t i = 0; i < 256; ++i) {
        std::uint32_t r = i << 24;
        for (int bit = 0; bit < 8; ++bit) {
            r = (r & 0x80000000u) != 0 ? (r << 1) ^ 0x04c11db7u : r << 1;
        }
        table[i] = r;
    }
    return table;
}

constexpr std::array<std::uint32_t, 256> kCrcTable = makeCrcTable();

std::uint8_t byteAt(std::span<const std::byte> bytes, std::size_t i) {
    return static_cast<std::uint8_t>(bytes[i]);
}

enum class Page { Complete, Cut, NotAPage, BadChecksum };

// Reads the page starting at `at`; `size` is set when the page is complete.
Page readPage(std::span<const std::byte> bytes, std::size_t at, std::size_t& size) {
    const std::size_t left = bytes.size() - at;
    if (std::memcmp(bytes.data() + at, "OggS", std::min<std::size_t>(left, 4)) != 0 ||
        (left > 4 && byteAt(bytes, at + 4) != 0)) {
        return Page::NotAPage;
    }
    if (left < kHeaderSize) {
        return Page::Cut;
    }
    const std::size_t segments = byteAt(bytes, at + 26);
    if (left < kHeaderSize + segments) {
        return Page::Cut;
    }
    size = kHeaderSize + segments;
    for (std::size_t i = 0; i < segments; ++i) {
        size += byteAt(bytes, at + kHeaderSize + i);
    }
    if (left < size) {
        return Page::Cut;
    }
    std::uint32_t stored = 0;
    for (int i = 3; i >= 0; --i) {
        stored = (stored << 8) | byteAt(bytes, at + 22 + static_cast<std::size_t>(i));
    }
    std::uint32_t crc = 0;
    for (std::size_t i = 0; i < size; ++i) {
        // The checksum field itself counts as zeros.
        const std::uint8_t b = i >= 22 && i < 26 ? 0 : byteAt(bytes, at + i);
        crc = (crc << 8) ^ kCrcTable[((crc >> 24) ^ b) & 0xffu];
    }
    return crc == stored ? Page::Complete : Page::BadChecksum;
}

} // namespace

std::string checkOggPages(std::span<const std::byte> bytes) {
    std::size_t at = 0;
    int page = 0;
    bool ended = false; // the last page read carried the end-of-stream flag
    const auto where = [&] {
        return "page " + std::to_string(page + 1) + " at byte " + std::to_string(at);
    };
    while (at < bytes.size()) {
        std::size_t size = 0;
        switch (readPage(bytes, at, size)) {
        case Page::Complete:
            ended = (byteAt(bytes, at + 5) & kEndOfStream) != 0;
            at += size;
            ++page;
            continue;
        case Page::Cut:
            return "truncated: the file ends inside Ogg " + where() + " (" +
                   std::to_string(bytes.size() - at) + " bytes of it are there)";
        case Page::NotAPage:
            if (ended) {
                return {};
            }
            return "damaged: no Ogg page where " + where() + " should start";
        case Page::BadChecksum:
            return "damaged: Ogg " + where() + " fails its checksum";
        }
    }
    if (page == 0) {
        return "damaged: no Ogg page";
    }
    if (!ended) {
        return "truncated: the Ogg stream has no end-of-stream page (the file ends after page " +
               std::to_string(page) + ", at byte " + std::to_string(at) + ")";
    }
    return {};
}

} // namespace e2d::audio::detail
