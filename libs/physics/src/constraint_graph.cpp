// SPDX-License-Identifier: MIT
#include "constraint_graph.hpp"

#include <algorithm>
#include <cstddef>

namespace e2d::physics::detail {

void ConstraintLevels::reset(int stateCount) {
    next_.assign(static_cast<std::size_t>(std::max(stateCount, 0)), 0);
    counts_.clear();
}

int ConstraintLevels::assign(int a, int b) {
    int level = 0;
    if (a >= 0) {
        level = std::max(level, next_[static_cast<std::size_t>(a)]);
    }
    if (b >= 0) {
        level = std::max(level, next_[static_cast<std::size_t>(b)]);
    }
    if (a >= 0) {
        next_[static_cast<std::size_t>(a)] = level + 1;
    }
    if (b >= 0) {
        next_[static_cast<std::size_t>(b)] = level + 1;
    }
    if (static_cast<std::size_t>(level) >= counts_.size()) {
        counts_.resize(static_cast<std::size_t>(level) + 1, 0);
    }
    ++counts_[static_cast<std::size_t>(level)];
    return level;
}

} // namespace e2d::physics::detail
