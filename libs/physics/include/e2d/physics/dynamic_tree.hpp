// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/geometry.hpp>
#include <e2d/physics/math.hpp>

#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

namespace e2d::physics {

namespace detail {

struct SnapshotAccess; // World's snapshots (world_snapshot.cpp) read and write the tree whole.
class BroadPhase;      // reads its own live proxies' boxes unchecked (BroadPhase::fatAabbLive()).

/// A LIFO stack of node indices that lives on the call stack while it holds at most `N` entries
/// and spills into a std::vector past that, so tree traversals allocate nothing for trees of
/// sane height (a traversal holds at most about height + 1 entries).
template <int N>
class TreeStack {
public:
    void push(int value) {
        if (count_ < N) {
            fixed_[count_++] = value;
        } else {
            overflow_.push_back(value);
        }
    }
    // The overflow holds entries only while the fixed part is full, so count_ alone says
    // whether the stack is empty, and the overflow is looked at only when count_ is N.
    int pop() {
        if (count_ == N && !overflow_.empty()) [[unlikely]] {
            int value = overflow_.back();
            overflow_.pop_back();
            return value;
        }
        return fixed_[--count_];
    }
    [[nodiscard]] bool empty() const { return count_ == 0; }

private:
    int fixed_[N];
    int count_ = 0;
    std::vector<int> overflow_;
};

#if defined(__SSE2__)
/// overlaps(a, b) (touching counts) with b loaded in a register (lower x y, upper x y): apart
/// when (a.lower, b.lower) > (b.upper, a.upper) in any lane, one comparison for the four of
/// overlaps(); a NaN compares false there as in overlaps().
inline bool overlapsBox(const Aabb& a, __m128 b) {
    static_assert(sizeof(Aabb) == 4 * sizeof(float));
    const __m128 va = _mm_loadu_ps(&a.lower.x);
    return _mm_movemask_ps(_mm_cmpgt_ps(_mm_movelh_ps(va, b), _mm_movehl_ps(va, b))) == 0;
}
#endif

} // namespace detail

/// A dynamic bounding-volume hierarchy of axis-aligned boxes ("proxies"), for fast overlap
/// queries and ray casts over objects that are created, moved and destroyed all the time.
///
/// Leaves hold the boxes the user gives; internal nodes hold the union of their children's
/// boxes and categories. New leaves are placed by the surface-area heuristic (in 2D the
/// perimeter is the cost metric) and tree rotations keep the hierarchy shallow and tight.
/// All nodes live in one contiguous array with a free list; a proxy id is the index of its
/// leaf and stays valid until destroyProxy(). The tree stores boxes as given: fattening them
/// (so that small motions need no update) is the caller's business, as the broad phase does.
///
/// A tree is a plain value: copyable, movable, no shared state. It is not thread-safe to modify
/// while another thread queries it; concurrent const queries are fine.
class DynamicTree {
public:
    /// The null proxy id.
    static constexpr int kNullProxy = -1;
    /// Category bits that match every mask.
    static constexpr std::uint64_t kAllBits = ~std::uint64_t{0};

    DynamicTree();

    /// Adds a proxy for `aabb` (finite, lower <= upper, metres) with collision category
    /// `categoryBits` and an opaque `userData`, and returns its id (>= 0). Throws core::Error on a
    /// non-finite or inverted box.
    int createProxy(const Aabb& aabb, std::uint64_t categoryBits, std::uint64_t userData);

    /// Adds a proxy like createProxy() but leaves it out of the hierarchy until the next
    /// insertDeferred(): its id, box and user data are valid at once, moveProxy(),
    /// enlargeProxy() and destroyProxy() work on it, but query() and rayCast() do not see it
    /// yet. Creating many proxies this way and inserting them together is much cheaper than one
    /// by one (a level load); rebuild() and insertDeferred() insert them.
    int createProxyDeferred(const Aabb& aabb, std::uint64_t categoryBits, std::uint64_t userData);

    /// Inserts every deferred proxy. When they are at least a quarter of all proxies the whole
    /// hierarchy is rebuilt top-down along a Z-order curve of the box centres (cheaper than
    /// rebuild()'s surface-area heuristic, as tight for evenly spread boxes), otherwise they are
    /// inserted one by one in the order they were created. Does nothing when none is waiting.
    /// Allocates temporary arrays for a rebuild.
    void insertDeferred();

    /// Number of live proxies waiting for insertDeferred().
    [[nodiscard]] int deferredCount() const { return deferredCount_; }

    /// Removes the proxy. Its id may be reused by a later createProxy(). Throws core::Error if
    /// `proxyId` is not a live proxy.
    void destroyProxy(int proxyId);

    /// Gives the proxy a new box and reinserts it (the tree stays tight). The search for its new
    /// place starts at the lowest ancestor whose box holds the new one (a few levels up after a
    /// small move), so a small move costs a few node visits instead of a search from the root.
    /// Throws core::Error on a bad id or box; the tree is unchanged then.
    void moveProxy(int proxyId, const Aabb& aabb);

    /// Gives the proxy a new box without reinserting it: its ancestors grow in place to contain
    /// the box, and never shrink. Cheaper than moveProxy() for a box that grew a little, but the
    /// tree gets looser; moveProxy() or rebuild() tightens it again. Throws like moveProxy().
    void enlargeProxy(int proxyId, const Aabb& aabb);

    /// The box of a proxy, as last given. Throws core::Error on a bad id.
    [[nodiscard]] const Aabb& aabb(int proxyId) const {
        checkProxy(proxyId, "aabb");
        return nodes_[static_cast<std::size_t>(proxyId)].aabb;
    }
    /// The user data of a proxy. Throws core::Error on a bad id.
    [[nodiscard]] std::uint64_t userData(int proxyId) const {
        checkProxy(proxyId, "userData");
        return nodes_[static_cast<std::size_t>(proxyId)].userData;
    }
    /// The category bits of a proxy. Throws core::Error on a bad id.
    [[nodiscard]] std::uint64_t categoryBits(int proxyId) const {
        checkProxy(proxyId, "categoryBits");
        return nodes_[static_cast<std::size_t>(proxyId)].categoryBits;
    }
    /// Whether `proxyId` names a live proxy.
    [[nodiscard]] bool isProxy(int proxyId) const {
        return proxyId >= 0 && static_cast<std::size_t>(proxyId) < nodes_.size() &&
               nodes_[static_cast<std::size_t>(proxyId)].height == 0;
    }

    /// Calls `callback(int proxyId, std::uint64_t userData)` for every proxy whose box overlaps
    /// `box` (touching counts) and whose category bits share a bit with `maskBits`. The callback
    /// returns bool: false stops the query (a callback returning void never stops it). The
    /// callback must not modify the tree. Order is the tree's, not the ids'. Throws core::Error if
    /// `box` is not finite. Allocates nothing unless the tree is more than 128 levels deep.
    template <class F>
    void query(const Aabb& box, std::uint64_t maskBits, F&& callback) const;

    /// Casts the ray `input` (world space: from origin to origin + maxFraction * translation)
    /// through the tree and calls
    /// `float callback(const RayCastInput& clipped, int proxyId, std::uint64_t userData)` for
    /// every proxy (matching `maskBits`) whose box the current ray segment may cross. `clipped`
    /// is the input with maxFraction lowered to the closest hit reported so far; the callback
    /// does the exact test against its object and returns:
    ///   - 0: stop the cast now;
    ///   - a fraction f with 0 < f < clipped.maxFraction: clip the ray to f (closest-hit casts
    ///     return the hit fraction);
    ///   - clipped.maxFraction or more: keep going unclipped (all-hits casts);
    ///   - a negative value, e.g. -1: ignore this proxy (filtered out) and keep going.
    /// The callback must not modify the tree. Throws core::Error if any number in `input` is not
    /// finite or maxFraction < 0.
    template <class F>
    void rayCast(const RayCastInput& input, std::uint64_t maskBits, F&& callback) const;

    /// Number of live proxies.
    [[nodiscard]] int proxyCount() const { return proxyCount_; }
    /// Height of the root (a single leaf has height 0; an empty tree reports 0).
    [[nodiscard]] int height() const;
    /// Sum of the perimeters of the internal nodes divided by the perimeter of the root: a
    /// measure of tree quality (lower is better; 0 for trees with fewer than two proxies).
    [[nodiscard]] float areaRatio() const;

    /// Rebuilds the whole hierarchy top-down with a binned surface-area heuristic, deferred
    /// proxies included. Proxy ids, boxes and user data are unchanged; typically lowers
    /// areaRatio(), e.g. after a level load or many enlargeProxy() calls. Allocates temporary
    /// arrays.
    void rebuild();

    /// Removes every proxy. Keeps the node storage.
    void clear();

    /// Checks the whole structure: parent/child links, free list, leaf count, heights, that every
    /// internal box contains its children's and that internal categories are the union of the
    /// children's. For tests and debugging: O(nodes).
    [[nodiscard]] bool validate() const;

private:
    friend struct detail::SnapshotAccess;
    friend class detail::BroadPhase;
    struct Node {
        Aabb aabb;                  // leaf: as given; internal: union of the children
        std::uint64_t categoryBits; // internal: union of the children's
        std::uint64_t userData;     // leaves only
        int parent;                 // free nodes: next free node
        int child1;                 // kNullProxy for leaves
        int child2;
        int height; // leaf 0, free -1

        [[nodiscard]] bool isLeaf() const { return child1 == kNullProxy; }
    };

    // query() without the box check, for a box taken from a tree (BroadPhase::findPairsOf()).
    template <class F>
    void queryValid(const Aabb& box, std::uint64_t maskBits, F& callback) const;
    // Whether no proxy is in the hierarchy (deferred ones aside): every query finds nothing.
    [[nodiscard]] bool isEmpty() const { return root_ == kNullProxy; }
    int allocateNode();
    void freeNode(int index);
    void insertLeaf(int leaf);
    // moveProxy()'s cheap path: reinserts the leaf below the lowest ancestor that holds the
    // new box; false (nothing changed) when even the root does not.
    bool reinsertNearby(int leaf, const Aabb& box);
    // Refits from `index` up to the root and stops at the first unchanged node at or above
    // `mustReach` (anywhere when it is kNullProxy). Nodes below `mustReach` may be rotated for
    // area or balance, those above only where their children's heights are out of balance.
    void refitUpward(int index, int mustReach);
    void removeLeaf(int leaf);
    // The best sibling for a new leaf `box` in the subtree of `start` (the root, or a node whose
    // box holds `box`).
    [[nodiscard]] int findBestSibling(const Aabb& box, int start) const;
    [[nodiscard]] bool isDeferred(int index) const {
        const Node& node = nodes_[static_cast<std::size_t>(index)];
        return node.height == 0 && node.parent == kDeferredParent;
    }
    void compactDeferred();
    // Inserts the deferred leaves one by one (insertLeaf()) and empties the deferred list.
    void insertDeferredOneByOne();
    // Frees every internal node and builds the hierarchy over all leaves, deferred ones
    // included: binned SAH (rebuild()) or Morton order (insertDeferred()).
    void rebuildAll(bool morton);
    // Top-down builds of `leaves` (ids, sorted by id for a result independent of the old tree)
    // into a fresh hierarchy; every internal node must be free already. buildFrom(): binned
    // surface-area heuristic, a few passes over the leaves per level. buildMorton(): the leaves
    // sorted along a Z-order curve of their centres (radix sort) and split where the curve
    // crosses into the next quadrant: linear after the sort, tight for level-like scenes.
    void buildFrom(std::vector<int>& leaves);
    void buildMorton(const std::vector<int>& leaves);
    // Makes `child` the child `slot` (1 or 2) of `parent`, or the root when parent is null.
    void attach(int child, int parent, int slot);
    void refit(int index);
    bool rotate(int index);
    void refitAncestors(int index);
    void checkProxy(int proxyId, const char* function) const {
        if (!isProxy(proxyId)) {
            throwBadProxy(proxyId, function);
        }
    }

    static bool isValidBox(const Aabb& box) {
        return std::isfinite(box.lower.x) && std::isfinite(box.lower.y) &&
               std::isfinite(box.upper.x) && std::isfinite(box.upper.y);
    }
    static Aabb segmentBox(Vec2 p1, Vec2 p2) {
        return {{p1.x < p2.x ? p1.x : p2.x, p1.y < p2.y ? p1.y : p2.y},
                {p1.x < p2.x ? p2.x : p1.x, p1.y < p2.y ? p2.y : p1.y}};
    }
    [[noreturn]] static void throwBadQueryBox(const Aabb& box);
    [[noreturn]] static void throwBadRay(const RayCastInput& input);
    [[noreturn]] static void throwBadProxy(int proxyId, const char* function);

    // Parent of a deferred leaf (never a node index).
    static constexpr int kDeferredParent = -2;

    std::vector<Node> nodes_;
    // Leaves created by createProxyDeferred(), in creation order. May hold stale entries (a
    // deferred leaf destroyed, its id reused): isDeferred() and a first-seen check skip them.
    std::vector<int> deferred_;
    int deferredCount_ = 0;
    int root_ = kNullProxy;
    int freeList_ = kNullProxy;
    int proxyCount_ = 0;
};

template <class F>
void DynamicTree::query(const Aabb& box, std::uint64_t maskBits, F&& callback) const {
    if (!isValidBox(box)) {
        throwBadQueryBox(box);
    }
    queryValid(box, maskBits, callback);
}

template <class F>
void DynamicTree::queryValid(const Aabb& box, std::uint64_t maskBits, F& callback) const {
    if (root_ == kNullProxy) {
        return;
    }
#if defined(__SSE2__)
    const __m128 query = _mm_loadu_ps(&box.lower.x);
#endif
    // The callback must not modify the tree: the array stays where it is.
    const Node* const nodes = nodes_.data();
    auto hits = [&](const Node& node) {
#if defined(__SSE2__)
        return (node.categoryBits & maskBits) != 0 && detail::overlapsBox(node.aabb, query);
#else
        return (node.categoryBits & maskBits) != 0 && overlaps(node.aabb, box);
#endif
    };
    if (!hits(nodes[static_cast<std::size_t>(root_)])) {
        return;
    }
    // Depth first, child1 before child2. A node is tested from its parent, both children at
    // once, so the stack holds matching nodes only: a matching internal node goes on to its
    // matching child1 at once and leaves a matching child2 on the stack, and a child that
    // misses costs no trip through the loop.
    detail::TreeStack<128> stack;
    // The node and its index: the index for the stack and the callback, the node as found when
    // its parent tested it.
    int index = root_;
    const Node* node = &nodes[static_cast<std::size_t>(index)];
    for (;;) {
        if (!node->isLeaf()) {
            const int child1 = node->child1;
            const int child2 = node->child2;
            const Node* const node1 = &nodes[static_cast<std::size_t>(child1)];
            const Node* const node2 = &nodes[static_cast<std::size_t>(child2)];
            const bool hit1 = hits(*node1);
            const bool hit2 = hits(*node2);
            if (hit1) {
                if (hit2) {
                    stack.push(child2);
                }
                index = child1;
                node = node1;
                continue;
            }
            if (hit2) {
                index = child2;
                node = node2;
                continue;
            }
        } else if constexpr (std::is_void_v<std::invoke_result_t<F&, int, std::uint64_t>>) {
            callback(index, node->userData);
        } else {
            if (!callback(index, node->userData)) {
                return;
            }
        }
        if (stack.empty()) {
            return;
        }
        index = stack.pop();
        node = &nodes[static_cast<std::size_t>(index)];
    }
}

template <class F>
void DynamicTree::rayCast(const RayCastInput& input, std::uint64_t maskBits, F&& callback) const {
    if (!isFinite(input.origin) || !isFinite(input.translation) ||
        !std::isfinite(input.maxFraction) || input.maxFraction < 0.0f) {
        throwBadRay(input);
    }
    if (root_ == kNullProxy) {
        return;
    }
    const Vec2 p1 = input.origin;
    const Vec2 d = input.translation;
    // Unit normal of the ray: a box lies off the ray's line when its centre is farther from the
    // line than its extent projected on this normal.
    const Vec2 n = normalize(leftPerp(d));
    const Vec2 absN{std::fabs(n.x), std::fabs(n.y)};

    float maxFraction = input.maxFraction;
    Vec2 p2 = p1 + maxFraction * d;
    Aabb segment = segmentBox(p1, p2);

    detail::TreeStack<128> stack;
    stack.push(root_);
    while (!stack.empty()) {
        const int index = stack.pop();
        const Node& node = nodes_[static_cast<std::size_t>(index)];
        if ((node.categoryBits & maskBits) == 0 || !overlaps(node.aabb, segment)) {
            continue;
        }
        const Vec2 c = 0.5f * (node.aabb.lower + node.aabb.upper);
        const Vec2 h = 0.5f * (node.aabb.upper - node.aabb.lower);
        if (std::fabs(dot(n, p1 - c)) - dot(absN, h) > 0.0f) {
            continue;
        }
        if (node.isLeaf()) {
            const RayCastInput clipped{input.origin, input.translation, maxFraction};
            const float value = callback(clipped, index, node.userData);
            if (value == 0.0f) {
                return;
            }
            if (value > 0.0f && value < maxFraction) {
                maxFraction = value;
                p2 = p1 + maxFraction * d;
                segment = segmentBox(p1, p2);
            }
        } else {
            stack.push(node.child2);
            stack.push(node.child1);
        }
    }
}

} // namespace e2d::physics
