// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

namespace e2d::physics::detail {

struct SnapshotAccess; // world_snapshot.cpp

/// Hands out dense slot indices and takes them back. Freed slots are reused last-in first-out,
/// so the same sequence of calls gives the same indices (determinism).
class IdPool {
public:
    int allocate() {
        if (!free_.empty()) {
            int index = free_.back();
            free_.pop_back();
            return index;
        }
        return next_++;
    }
    void release(int index) { free_.push_back(index); }
    void reserve(int capacity) { free_.reserve(static_cast<std::size_t>(capacity)); }
    /// One past the highest slot ever handed out.
    [[nodiscard]] int capacity() const { return next_; }
    [[nodiscard]] int count() const { return next_ - static_cast<int>(free_.size()); }

private:
    friend struct SnapshotAccess;
    std::vector<int> free_;
    int next_ = 0;
};

} // namespace e2d::physics::detail
