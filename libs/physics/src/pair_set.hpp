// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace e2d::physics::detail {

struct SnapshotAccess; // world_snapshot.cpp

/// The key of an unordered pair of 32-bit ids: min in the high half, max in the low half.
/// Never 0 for a != b, which the set uses as its empty marker.
constexpr std::uint64_t makePairKey(std::uint64_t a, std::uint64_t b) {
    return a < b ? (a << 32) | b : (b << 32) | a;
}
constexpr std::uint64_t pairKeyLow(std::uint64_t key) { return key >> 32; }
constexpr std::uint64_t pairKeyHigh(std::uint64_t key) { return key & 0xFFFFFFFFu; }

/// One stored pair: its key and the two proxy keys (of the lower and the higher id).
struct PairEntry {
    std::uint64_t key = 0; // 0: empty slot
    int proxyKeyA = -1;
    int proxyKeyB = -1;
};

/// Open-addressing hash set of pair keys (linear probing, backward-shift deletion, load <= 1/2).
/// No tombstones, so a long-running simulation never degrades; iteration order depends only on
/// the sequence of operations, which keeps simulations reproducible.
class PairSet {
public:
    /// Inserts; returns false (and changes nothing) if the key is already there.
    bool insert(const PairEntry& entry);
    /// The entry for `key`, or nullptr. Inline: the broad phase asks for every overlap its
    /// queries find.
    [[nodiscard]] const PairEntry* find(std::uint64_t key) const;
    [[nodiscard]] bool contains(std::uint64_t key) const { return find(key) != nullptr; }
    /// Removes `key`; returns false if it was not there. Copies the removed entry to `removed`.
    bool erase(std::uint64_t key, PairEntry* removed = nullptr);
    [[nodiscard]] int size() const { return size_; }
    void clear();

    /// Calls f(const PairEntry&) for every entry. f must not modify the set.
    template <class F>
    void forEach(F&& f) const {
        for (const PairEntry& entry : slots_) {
            if (entry.key != 0) {
                f(entry);
            }
        }
    }

private:
    friend struct SnapshotAccess;
    static std::uint64_t hash(std::uint64_t key) {
        // Keys are structured (small ids in both halves); the splitmix64 finaliser spreads them
        // so that linear probing sees near-random slots.
        key ^= key >> 30;
        key *= 0xbf58476d1ce4e5b9ull;
        key ^= key >> 27;
        key *= 0x94d049bb133111ebull;
        key ^= key >> 31;
        return key;
    }
    void grow();

    std::vector<PairEntry> slots_;
    int size_ = 0;
};

inline const PairEntry* PairSet::find(std::uint64_t key) const {
    if (slots_.empty() || key == 0) {
        return nullptr;
    }
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = static_cast<std::size_t>(hash(key)) & mask;
    while (slots_[i].key != 0) {
        if (slots_[i].key == key) {
            return &slots_[i];
        }
        i = (i + 1) & mask;
    }
    return nullptr;
}

} // namespace e2d::physics::detail
