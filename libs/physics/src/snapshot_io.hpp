// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/error.hpp>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

// The byte layer of world snapshots (world_snapshot.cpp): fixed-width little-endian values, so a
// snapshot has the same bytes on every machine. One set of transfer() functions describes each
// structure's fields; SnapshotWriter and SnapshotReader walk them, the reader checking every
// read against the end of the input and naming the offset and the field's path
// ("bodies[3].motion.sleepTime") when it refuses one.
namespace e2d::physics::detail {

static_assert(std::numeric_limits<float>::is_iec559, "snapshots store floats as IEEE-754 bits");

template <class T>
concept SnapshotPrimitive = std::is_arithmetic_v<T> || std::is_enum_v<T>;

class SnapshotWriter {
public:
    static constexpr bool kReading = false;

    // A named part of the path; the writer has no use for it (the destructor keeps a scope
    // variable from counting as unused).
    struct Scope {
        Scope() = default;
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;
        ~Scope() {}
    };
    Scope scope(const char* /*name*/, std::size_t /*index*/ = kNoIndex) { return {}; }

    template <SnapshotPrimitive T>
    void primitive(const char* /*name*/, T value) {
        if constexpr (std::is_same_v<T, bool>) {
            put(value ? 1u : 0u, 1);
        } else if constexpr (std::is_enum_v<T>) {
            put(static_cast<std::uint64_t>(static_cast<std::underlying_type_t<T>>(value)),
                sizeof(T));
        } else if constexpr (std::is_same_v<T, float>) {
            put(std::bit_cast<std::uint32_t>(value), 4);
        } else {
            static_assert(std::is_integral_v<T>);
            put(static_cast<std::uint64_t>(static_cast<std::make_unsigned_t<T>>(value)), sizeof(T));
        }
    }
    // A sequence's length (u32); `minElementBytes` is the reader's business.
    void count(const char* name, std::size_t& n, std::size_t /*minElementBytes*/) {
        primitive(name, static_cast<std::uint32_t>(n));
    }
    void tag(const char* fourChars) {
        for (int i = 0; i < 4; ++i) {
            bytes_.push_back(static_cast<std::uint8_t>(fourChars[i]));
        }
    }

    [[nodiscard]] std::size_t size() const { return bytes_.size(); }
    std::vector<std::uint8_t>& bytes() { return bytes_; }
    // Overwrites `width` bytes at `offset` (a header field known only at the end).
    void patch(std::size_t offset, std::uint64_t value, int width) {
        for (int i = 0; i < width; ++i) {
            bytes_[offset + static_cast<std::size_t>(i)] =
                static_cast<std::uint8_t>(value >> (8 * i));
        }
    }

    static constexpr std::size_t kNoIndex = static_cast<std::size_t>(-1);

private:
    void put(std::uint64_t value, std::size_t width) {
        for (std::size_t i = 0; i < width; ++i) {
            bytes_.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
        }
    }

    std::vector<std::uint8_t> bytes_;
};

class SnapshotReader {
public:
    static constexpr bool kReading = true;
    static constexpr std::size_t kNoIndex = SnapshotWriter::kNoIndex;

    // `function`: the message prefix ("physics::World::restoreSnapshot()"); `base`: the offset of
    // bytes[0] in the whole snapshot (the payload follows the header).
    SnapshotReader(std::span<const std::uint8_t> bytes, std::size_t base, const char* function)
        : bytes_(bytes), base_(base), function_(function) {}

    // Pushes `name` (and `[index]`) on the path until the scope ends.
    class Scope {
    public:
        explicit Scope(SnapshotReader& reader) : reader_(&reader) {}
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;
        ~Scope() { reader_->path_.pop_back(); }

    private:
        SnapshotReader* reader_;
    };
    [[nodiscard]] Scope scope(const char* name, std::size_t index = kNoIndex) {
        path_.push_back({name, index});
        return Scope(*this);
    }

    template <SnapshotPrimitive T>
    void primitive(const char* name, T& value) {
        if constexpr (std::is_same_v<T, bool>) {
            const std::uint64_t raw = take(name, 1);
            if (raw > 1) {
                fail(name, "a bool must be 0 or 1, got " + std::to_string(raw), 1);
            }
            value = raw != 0;
        } else if constexpr (std::is_enum_v<T>) {
            using U = std::underlying_type_t<T>;
            const auto raw = static_cast<U>(take(name, sizeof(T)));
            // enumCount(T{}) is declared next to the transfer() functions.
            if (static_cast<long long>(raw) < 0 || static_cast<long long>(raw) >= enumCount(T{})) {
                fail(name,
                     "must be below " + std::to_string(enumCount(T{})) + ", got " +
                         std::to_string(static_cast<long long>(raw)),
                     sizeof(T));
            }
            value = static_cast<T>(raw);
        } else if constexpr (std::is_same_v<T, float>) {
            value = std::bit_cast<float>(static_cast<std::uint32_t>(take(name, 4)));
        } else {
            static_assert(std::is_integral_v<T>);
            value = static_cast<T>(static_cast<std::make_unsigned_t<T>>(take(name, sizeof(T))));
        }
    }
    // A sequence's length: at most what the bytes left can hold at `minElementBytes` each (a
    // damaged length never allocates more than the input could describe).
    void count(const char* name, std::size_t& n, std::size_t minElementBytes) {
        std::uint32_t raw = 0;
        primitive(name, raw);
        if (minElementBytes > 0 && raw > remaining() / minElementBytes) {
            fail(name,
                 "length " + std::to_string(raw) + " needs at least " +
                     std::to_string(static_cast<std::uint64_t>(raw) * minElementBytes) +
                     " more bytes, " + std::to_string(remaining()) + " left",
                 4);
        }
        n = raw;
    }
    void tag(const char* fourChars) {
        if (remaining() < 4) {
            fail("section", std::string("truncated: expected section '") + fourChars + "'", 0);
        }
        for (int i = 0; i < 4; ++i) {
            if (bytes_[pos_ + static_cast<std::size_t>(i)] !=
                static_cast<std::uint8_t>(fourChars[i])) {
                fail("section", std::string("expected section '") + fourChars + "'", 0);
            }
        }
        sections_.push_back({fourChars, offset()});
        pos_ += 4;
    }
    // Where the section `fourChars` began (0 if it was not read).
    [[nodiscard]] std::size_t sectionOffset(const char* fourChars) const {
        for (const Section& s : sections_) {
            if (std::string_view(s.tag, 4) == std::string_view(fourChars, 4)) {
                return s.offset;
            }
        }
        return 0;
    }

    [[nodiscard]] std::size_t remaining() const { return bytes_.size() - pos_; }
    [[nodiscard]] std::size_t offset() const { return base_ + pos_; }

    // "physics::World::restoreSnapshot(): offset 120, bodies[3].type: what". `back`: how many
    // bytes ago the field started.
    [[noreturn]] void fail(const char* name, const std::string& what, std::size_t back) const {
        std::string message(function_);
        message.append(": offset ").append(std::to_string(offset() - back)).append(", ");
        message.append(path(name)).append(": ").append(what);
        throw core::Error(message);
    }
    // The current path with `leaf` appended.
    [[nodiscard]] std::string path(const char* leaf) const {
        std::string text;
        for (const Part& part : path_) {
            if (!text.empty()) {
                text.push_back('.');
            }
            text.append(part.name);
            if (part.index != kNoIndex) {
                text.append("[").append(std::to_string(part.index)).append("]");
            }
        }
        if (leaf != nullptr) {
            if (!text.empty()) {
                text.push_back('.');
            }
            text.append(leaf);
        }
        return text;
    }

private:
    struct Part {
        const char* name;
        std::size_t index;
    };
    struct Section {
        const char* tag;
        std::size_t offset;
    };

    std::uint64_t take(const char* name, std::size_t width) {
        if (remaining() < width) {
            fail(name,
                 "truncated (needs " + std::to_string(width) + " bytes, " +
                     std::to_string(remaining()) + " left)",
                 0);
        }
        std::uint64_t value = 0;
        for (std::size_t i = 0; i < width; ++i) {
            value |= static_cast<std::uint64_t>(bytes_[pos_ + i]) << (8 * i);
        }
        pos_ += width;
        return value;
    }

    std::span<const std::uint8_t> bytes_;
    std::size_t base_ = 0;
    std::size_t pos_ = 0;
    const char* function_;
    std::vector<Part> path_;
    std::vector<Section> sections_;
};

// The field `name` of a structure: a primitive read or written, anything else walked by its
// transfer() under `name` on the path.
template <class Io, SnapshotPrimitive T>
void field(Io& io, const char* name, T& value) {
    io.primitive(name, value);
}
template <class Io, class T>
requires(!SnapshotPrimitive<T>) void field(Io& io, const char* name, T& value) {
    auto scope = io.scope(name);
    transfer(io, value);
}

// A fixed-size array field: every element, `name[i]`.
template <class Io, class T, std::size_t N>
void field(Io& io, const char* name, T (&values)[N]) {
    for (std::size_t i = 0; i < N; ++i) {
        auto scope = io.scope(name, i);
        if constexpr (SnapshotPrimitive<T>) {
            io.primitive("value", values[i]);
        } else {
            transfer(io, values[i]);
        }
    }
}

// A sequence (std::vector, SlotArray): its length, then each element as `name[i]`.
// `minElementBytes`: the fewest bytes an element takes (the reader's check on the length).
template <class Io, class C>
void sequence(Io& io, const char* name, C& container, std::size_t minElementBytes) {
    std::size_t n = container.size();
    io.count(name, n, minElementBytes);
    if constexpr (Io::kReading) {
        container.reserve(n);
        for (std::size_t i = 0; i < n; ++i) {
            container.emplace_back();
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        if constexpr (SnapshotPrimitive<std::remove_reference_t<decltype(container[i])>>) {
            auto scope = io.scope(name, i);
            io.primitive("value", container[i]);
        } else {
            auto scope = io.scope(name, i);
            transfer(io, container[i]);
        }
    }
}

// The bytes one T takes (a default one: the smallest for the variable-size structures).
template <class T>
std::size_t encodedSize() {
    SnapshotWriter writer;
    T value{};
    if constexpr (SnapshotPrimitive<T>) {
        writer.primitive("value", value);
    } else {
        transfer(writer, value);
    }
    return writer.size();
}

} // namespace e2d::physics::detail
