// SPDX-License-Identifier: MIT
#include "constraint_graph.hpp"

#include <algorithm>
#include <bit>
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

void ConstraintColors::reset(int stateCount) {
    used_.assign(static_cast<std::size_t>(std::max(stateCount, 0)), 0u);
    overflow_.reset(stateCount);
}

int ConstraintColors::assign(int a, int b) {
    static_assert(kColorCount <= 32, "a body's colours are one 32-bit mask");
    constexpr std::uint32_t kAll = kColorCount == 32 ? ~0u : (1u << kColorCount) - 1u;
    std::uint32_t allowed = 0;
    if (a >= 0 && b >= 0) {
        allowed = kAll >> kStaticOnlyColors;
    } else if (a >= 0 || b >= 0) {
        allowed = kAll & ~1u;
    } else {
        return 0; // nothing moves: any colour
    }
    std::uint32_t taken = 0;
    if (a >= 0) {
        taken |= used_[static_cast<std::size_t>(a)];
    }
    if (b >= 0) {
        taken |= used_[static_cast<std::size_t>(b)];
    }
    const std::uint32_t free = allowed & ~taken;
    if (free == 0) {
        return kColorCount + overflow_.assign(a, b);
    }
    const int color = std::countr_zero(free);
    const std::uint32_t bit = 1u << color;
    if (a >= 0) {
        used_[static_cast<std::size_t>(a)] |= bit;
    }
    if (b >= 0) {
        used_[static_cast<std::size_t>(b)] |= bit;
    }
    return color;
}

} // namespace e2d::physics::detail
