// SPDX-License-Identifier: MIT
#include "pair_set.hpp"

#include <cstddef>

namespace e2d::physics::detail {

void PairSet::grow() {
    const std::size_t newCapacity = slots_.empty() ? 32 : 2 * slots_.size();
    std::vector<PairEntry> old(newCapacity);
    old.swap(slots_);
    const std::size_t mask = slots_.size() - 1;
    for (const PairEntry& entry : old) {
        if (entry.key == 0) {
            continue;
        }
        std::size_t i = static_cast<std::size_t>(hash(entry.key)) & mask;
        while (slots_[i].key != 0) {
            i = (i + 1) & mask;
        }
        slots_[i] = entry;
    }
}

bool PairSet::insert(const PairEntry& entry) {
    if (find(entry.key) != nullptr) {
        return false;
    }
    if (2 * static_cast<std::size_t>(size_ + 1) > slots_.size()) {
        grow();
    }
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = static_cast<std::size_t>(hash(entry.key)) & mask;
    while (slots_[i].key != 0) {
        i = (i + 1) & mask;
    }
    slots_[i] = entry;
    ++size_;
    return true;
}

bool PairSet::erase(std::uint64_t key, PairEntry* removed) {
    const PairEntry* found = find(key);
    if (found == nullptr) {
        return false;
    }
    if (removed != nullptr) {
        *removed = *found;
    }
    const std::size_t mask = slots_.size() - 1;
    std::size_t hole = static_cast<std::size_t>(found - slots_.data());
    // Backward shift: pull later entries of the probe run into the hole when their home slot
    // does not lie cyclically in (hole, j], so every remaining key stays reachable.
    std::size_t j = hole;
    for (;;) {
        j = (j + 1) & mask;
        if (slots_[j].key == 0) {
            break;
        }
        const std::size_t home = static_cast<std::size_t>(hash(slots_[j].key)) & mask;
        const bool homeInRange =
            hole <= j ? (hole < home && home <= j) : (hole < home || home <= j);
        if (!homeInRange) {
            slots_[hole] = slots_[j];
            hole = j;
        }
    }
    slots_[hole] = PairEntry{};
    --size_;
    return true;
}

void PairSet::clear() {
    for (PairEntry& entry : slots_) {
        entry = PairEntry{};
    }
    size_ = 0;
}

} // namespace e2d::physics::detail
