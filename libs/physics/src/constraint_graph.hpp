// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

// Level scheduling of the contact constraints (a graph colouring that keeps the solve order).
// Constraints are offered in the order the sequential solver visits them; each one gets the
// level one above the highest level of the earlier constraints it shares a moving body with.
// So the constraints of one level share no moving body, and every constraint's predecessors
// on each of its bodies sit in lower levels and its successors in higher ones: solving level
// after level (in any order, or several at once, within a level) gives bit for bit what the
// sequential sweep gives, and the reversed levels what the reversed sweep gives.
namespace e2d::physics::detail {

class ConstraintLevels {
public:
    // Forgets every level; `stateCount` moving bodies (BodyState indices 0..stateCount-1).
    void reset(int stateCount);

    // The level of the next constraint, between moving bodies `a` and `b` (a BodyState index,
    // or -1 for a side whose velocity the constraint never changes: static, or zero inverse
    // mass and inertia).
    int assign(int a, int b);

    // Constraints in each level so far.
    [[nodiscard]] const std::vector<int>& counts() const { return counts_; }
    [[nodiscard]] int levelCount() const { return static_cast<int>(counts_.size()); }

private:
    std::vector<int> next_; // per body: the lowest level its next constraint may take
    std::vector<int> counts_;
};

} // namespace e2d::physics::detail
