// SPDX-License-Identifier: MIT
// The connected components of a pass's joints over the moving bodies, in an order that only
// the joints decide (their slots): the unit the direct solve and the position passes work in,
// so that their results do not depend on how the step happened to lay out bodies and joints.
#include "joint_solver.hpp"

#include <algorithm>

namespace e2d::physics::detail {

namespace {

// Starts a union-find over `stateCount` body states for one call (JointComponents::stamp).
void beginUnionFind(std::size_t stateCount, JointComponents& out) {
    if (out.stamp.size() < stateCount) {
        out.parent.resize(stateCount);
        out.componentOfRoot.resize(stateCount);
        out.stamp.resize(stateCount, 0);
    }
    if (++out.generation == 0) { // wrapped: every old stamp could match again
        std::fill(out.stamp.begin(), out.stamp.end(), 0u);
        out.generation = 1;
    }
}

// The root of body state x's set (a state first met this call is a set of its own).
int rootOf(JointComponents& out, int x) {
    const auto at = static_cast<std::size_t>(x);
    if (out.stamp[at] != out.generation) {
        out.stamp[at] = out.generation;
        out.parent[at] = x;
        out.componentOfRoot[at] = -1;
        return x;
    }
    while (out.parent[static_cast<std::size_t>(x)] != x) {
        int& up = out.parent[static_cast<std::size_t>(x)];
        up = out.parent[static_cast<std::size_t>(up)];
        x = up;
    }
    return x;
}

// Joins the sets of a joint's two moving sides; true when they were one already (the joint
// closes a loop). A side to a static or sleeping body joins nothing.
bool join(JointComponents& out, const Joint& j) {
    if (j.indexA < 0 || j.indexB < 0) {
        return false;
    }
    const int a = rootOf(out, j.indexA);
    const int b = rootOf(out, j.indexB);
    if (a == b) {
        return true;
    }
    out.parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    return false;
}

} // namespace

void markLoopyJoints(std::span<Joint> joints, std::span<const int> slots, std::size_t stateCount,
                     JointComponents& out) {
    beginUnionFind(stateCount, out);
    out.closesLoop.resize(slots.size());
    for (std::size_t i = 0; i < slots.size(); ++i) {
        out.closesLoop[i] = join(out, joints[static_cast<std::size_t>(slots[i])]) ? 1 : 0;
    }
    // Once every set is joined: componentOfRoot counts the joints of each root (from -1, its
    // value when the state was first met), cursor its loops.
    out.cursor.assign(stateCount, 0);
    for (std::size_t i = 0; i < slots.size(); ++i) {
        const Joint& j = joints[static_cast<std::size_t>(slots[i])];
        const int side = j.indexA >= 0 ? j.indexA : j.indexB;
        if (side >= 0) {
            const auto r = static_cast<std::size_t>(rootOf(out, side));
            ++out.componentOfRoot[r];
            out.cursor[r] += out.closesLoop[i];
        }
    }
    for (int k : slots) {
        Joint& j = joints[static_cast<std::size_t>(k)];
        const int side = j.indexA >= 0 ? j.indexA : j.indexB;
        j.loopy = false;
        if (side >= 0) {
            const auto r = static_cast<std::size_t>(rootOf(out, side));
            j.loopy = tooLoopy(static_cast<std::size_t>(out.componentOfRoot[r] + 1),
                               static_cast<std::size_t>(out.cursor[r]));
        }
    }
}

void findJointComponents(std::span<const Joint> joints, std::span<const int> order,
                         std::size_t stateCount, JointComponents& out, bool skipLoopy) {
    out.sorted.clear();
    for (int k : order) {
        if (k >= 0 && !(skipLoopy && joints[static_cast<std::size_t>(k)].loopy)) {
            out.sorted.push_back(k);
        }
    }
    std::sort(out.sorted.begin(), out.sorted.end());
    beginUnionFind(stateCount, out);
    auto root = [&](int x) { return rootOf(out, x); };
    const std::size_t n = out.sorted.size();
    out.closesLoop.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        out.closesLoop[i] = join(out, joints[static_cast<std::size_t>(out.sorted[i])]) ? 1 : 0;
    }
    // Components numbered as their smallest slot is met, then the slots sorted by component
    // (stable: ascending within each).
    out.componentOf.resize(n);
    out.start.assign(1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const Joint& j = joints[static_cast<std::size_t>(out.sorted[i])];
        const int side = j.indexA >= 0 ? j.indexA : j.indexB;
        int c = -1;
        if (side >= 0) {
            int& named = out.componentOfRoot[static_cast<std::size_t>(root(side))];
            if (named < 0) {
                named = static_cast<int>(out.start.size()) - 1;
                out.start.push_back(0);
            }
            c = named;
        } else { // no moving body (not prepared for a pass; kept alone all the same)
            c = static_cast<int>(out.start.size()) - 1;
            out.start.push_back(0);
        }
        out.componentOf[i] = c;
        ++out.start[static_cast<std::size_t>(c) + 1];
    }
    const std::size_t count = out.start.size() - 1;
    out.loops.assign(count, 0);
    for (std::size_t c = 0; c < count; ++c) {
        out.start[c + 1] += out.start[c];
    }
    out.slots.resize(n);
    std::vector<int>& next = out.cursor;
    next.assign(out.start.begin(), out.start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) {
        const auto c = static_cast<std::size_t>(out.componentOf[i]);
        out.slots[static_cast<std::size_t>(next[c]++)] = out.sorted[i];
        out.loops[c] += out.closesLoop[i];
    }
}

} // namespace e2d::physics::detail
