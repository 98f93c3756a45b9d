// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
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

// Graph colouring of the contact constraints, as Box2D v3 colours its constraint graph: each
// constraint, in the order offered, takes the lowest colour neither of its moving bodies has
// yet, so a colour's constraints share no moving body and the wide solver takes them several
// at a time, colour after colour. A stack of n boxes is two colours of n / 2 where levels
// (ConstraintLevels) make n levels of one: the lanes are full. The order differs from the
// sequential sweep's (the constraints of one colour first, then the next colour's), so the
// results differ from the scalar passes'.
//
// As in v3, a constraint against a static side never takes colour 0, and one between two
// moving bodies never takes the last kStaticOnlyColors colours: the moving pairs fill the low
// colours, each body's static contacts come after its first moving contact, and a body with
// many moving contacts still has colours left for the ground. A constraint for which no colour
// is left goes to the overflow levels after the colours (ConstraintLevels over the overflow
// constraints alone).
class ConstraintColors {
public:
    static constexpr int kColorCount = 24;
    static constexpr int kStaticOnlyColors = 4;

    // Forgets every colour; `stateCount` moving bodies (BodyState indices 0..stateCount-1).
    void reset(int stateCount);

    // The colour of the next constraint, between moving bodies `a` and `b` (as
    // ConstraintLevels::assign()); kColorCount + k for the overflow's level k.
    int assign(int a, int b);

private:
    std::vector<std::uint32_t> used_; // per body: a bit per colour it is in
    ConstraintLevels overflow_;
};

} // namespace e2d::physics::detail
