// SPDX-License-Identifier: MIT
#pragma once

#include "pair_set.hpp"
#include "task_pool.hpp"

#include <e2d/physics/constants.hpp>
#include <e2d/physics/dynamic_tree.hpp>
#include <e2d/physics/types.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace e2d::physics::detail {

/// A moved proxy's fat box extends this many of its displacements ahead. Box2D 2.4 takes 4 of
/// the last step's; here the displacement is the next step's, which the box must hold anyway,
/// and 4 made 17 % more contacts (fat boxes overlapping, shapes apart) in a settling pile of
/// circles for no gain on a swinging joint net.
inline constexpr float kAabbPredictSteps = 2.0f;
/// A proxy whose fat box still contains its shape is reinserted anyway when the box is wider or
/// taller than the one it would get now by more than this (Box2D 2.4's limit: 4 margins).
inline constexpr float kAabbSlack = 4.0f * kAabbMargin;

/// A tight box of a shape of `type` as its proxy stores it before any displacement: fattened
/// by kAabbMargin, except static ones.
inline Aabb fatten(const Aabb& box, BodyType type) {
    // Static proxies never move by themselves: a margin would only create extra pairs.
    if (type == BodyType::Static) {
        return box;
    }
    const Vec2 margin{kAabbMargin, kAabbMargin};
    return {box.lower - margin, box.upper + margin};
}

/// The fat box of a shape of `type` with tight box `aabb` that moves `displacement` next: it
/// reaches kAabbPredictSteps displacements ahead, so a steadily moving shape stays inside it for
/// that many steps instead of leaving a fixed margin every step or two.
[[gnu::always_inline]] inline Aabb predictedFatBox(const Aabb& aabb, BodyType type,
                                                   Vec2 displacement) {
    Aabb fat = fatten(aabb, type);
    if (type != BodyType::Static) {
        const Vec2 ahead = kAabbPredictSteps * displacement;
        fat.lower += Vec2{std::min(ahead.x, 0.0f), std::min(ahead.y, 0.0f)};
        fat.upper += Vec2{std::max(ahead.x, 0.0f), std::max(ahead.y, 0.0f)};
    }
    return fat;
}

/// A proxy key packs a tree proxy id and the tree it lives in (one tree per BodyType).
inline constexpr int kNullProxyKey = -1;
constexpr int makeProxyKey(int proxyId, BodyType type) {
    return (proxyId << 2) | static_cast<int>(type);
}
constexpr int proxyIdOf(int proxyKey) { return proxyKey >> 2; }
constexpr BodyType proxyTypeOf(int proxyKey) { return static_cast<BodyType>(proxyKey & 3); }

/// A pair of proxies whose fat boxes overlap. userDataA < userDataB (shape indices).
struct ProxyPair {
    std::uint64_t userDataA = 0;
    std::uint64_t userDataB = 0;
    int proxyKeyA = kNullProxyKey; ///< proxy of userDataA
    int proxyKeyB = kNullProxyKey; ///< proxy of userDataB
};

/// The World's broad phase: one DynamicTree per BodyType, fat boxes, a move buffer and a
/// persistent set of pairs found incrementally.
///
/// The caller gives tight boxes; moving proxies are stored fattened by kAabbMargin and, when
/// moved with a displacement, stretched two displacements ahead (static ones are not
/// fattened); a move only touches the tree when the tight box swept by the displacement leaves
/// the fat one, or the fat one is far larger than needed.
/// updatePairs() queries the trees for the proxies moved since the last update only: dynamic
/// against every tree, kinematic and static against the dynamic tree, so static-static (and
/// kinematic-kinematic, kinematic-static) pairs are never looked for. Pairs stay in the set
/// until the caller removes them (removePair(), prunePairs()) or a proxy is destroyed.
///
/// userData is the shape index and must fit in 32 bits; two proxies never share a userData.
class BroadPhase {
public:
    /// updatePairs()'s default query mask: every category.
    struct AllCategories {
        std::uint64_t operator()(std::uint64_t) const { return DynamicTree::kAllBits; }
    };

    /// Adds a proxy for the tight box `aabb` and buffers it as moved, so the next
    /// updatePairs() finds its pairs. Returns its proxy key. Throws core::Error on a bad box.
    /// The proxy enters its tree deferred (DynamicTree::createProxyDeferred()): the trees take
    /// their new proxies in bulk at the next updatePairs() or tree() call, whichever is first.
    int createProxy(const Aabb& aabb, BodyType type, std::uint64_t categoryBits,
                    std::uint64_t userData);
    /// Removes the proxy and every pair it is part of. Cheap when it has no pairs left (the
    /// World usually removes them first); otherwise one pass over the pair table.
    void destroyProxy(int proxyKey);
    /// Reports the new tight box and the shape's expected displacement over the next step
    /// (metres; zero for a shape placed by hand). Returns true (and buffers a move) when the box
    /// swept by the displacement left the fat box, or the fat box is more than four margins
    /// wider or taller than a new one would be; the fat box is then recomputed: the tight box
    /// plus kAabbMargin, stretched by two displacements in their direction.
    bool moveProxy(int proxyKey, const Aabb& aabb, Vec2 displacement = {0.0f, 0.0f});
    /// Whether moveProxy() with these arguments would move the proxy. Reads the proxy's own fat
    /// box only, which moving or destroying other proxies leaves as it is: the step asks it for
    /// every shape on several workers, then moves the ones that need it in shape order.
    [[nodiscard]] bool needsMove(int proxyKey, const Aabb& aabb, Vec2 displacement) const;
    /// needsMove() without the key check, for the write-back's loop over the awake shapes, whose
    /// keys are live by construction (the check was about 30 instructions a shape, a third of
    /// the call); a bad key here reads out of bounds. Inline (below): every awake shape asks
    /// each step.
    [[nodiscard]] bool needsMoveLive(int proxyKey, const Aabb& aabb, Vec2 displacement) const;
    /// Buffers the proxy as moved so the next update looks for its pairs again (e.g. after its
    /// filter changed or its body woke up).
    void bufferMove(int proxyKey);

    [[nodiscard]] const Aabb& fatAabb(int proxyKey) const {
        return trees_[treeIndex(proxyKey)].aabb(proxyIdOf(proxyKey));
    }
    /// Whether the fat boxes of two proxies overlap (touching counts), without the key check:
    /// for the narrow phase's loop over contacts, whose shapes' keys are live by construction (a
    /// shape's contacts go before its proxy). The check cost about 28 instructions per contact;
    /// a bad key here reads out of bounds.
    [[nodiscard]] bool fatAabbsOverlapLive(int proxyKeyA, int proxyKeyB) const {
        const Aabb& a = fatAabbLive(proxyKeyA);
        const Aabb& b = fatAabbLive(proxyKeyB);
#if defined(__SSE2__)
        return overlapsBox(a, _mm_loadu_ps(&b.lower.x));
#else
        return overlaps(a, b);
#endif
    }
    /// How many times a fat box changed: every proxy created, destroyed or moved counts one.
    /// While it stays the same, so does every fat box (the narrow phase then skips its fat-box
    /// test: contact.cpp).
    [[nodiscard]] std::uint64_t fatBoxChanges() const { return fatBoxChanges_; }
    [[nodiscard]] std::uint64_t userData(int proxyKey) const {
        return trees_[treeIndex(proxyKey)].userData(proxyIdOf(proxyKey));
    }
    /// The tree of one body type, with every proxy created so far inserted (queries see new
    /// proxies at once). Inserting is a change behind a const call: fine under the World's rule
    /// that one thread uses it at a time.
    [[nodiscard]] const DynamicTree& tree(BodyType type) const {
        DynamicTree& t = trees_[static_cast<std::size_t>(type)];
        if (t.deferredCount() > 0) [[unlikely]] {
            t.insertDeferred();
        }
        return t;
    }
    [[nodiscard]] int proxyCount() const;

    /// Finds the pairs of moved proxies that are not in the set yet, asks
    /// `bool shouldPair(std::uint64_t userDataA, std::uint64_t userDataB)` (A < B) about each,
    /// adds the accepted ones to the set and lists them in newPairs(), sorted by (A, B).
    /// Clears the move buffer. With nothing moved it queries nothing.
    /// `std::uint64_t queryMask(std::uint64_t userData)` gives the category bits a moved
    /// proxy's partners must share a bit with (the trees skip the others whole); it must
    /// admit every partner shouldPair() could accept, from either side (default: all bits).
    /// With `tasks`, the moved proxies' queries run on its workers, each into its own list
    /// (the lists are joined and sorted after, so the pairs are the same for any worker
    /// count): shouldPair and queryMask must then be safe to call from several threads at once.
    template <class ShouldPair, class QueryMask = AllCategories>
    void updatePairs(ShouldPair&& shouldPair, QueryMask&& queryMask = QueryMask{},
                     Tasks* tasks = nullptr);

    /// The pairs the last updatePairs() added, sorted; valid until the next updatePairs().
    [[nodiscard]] std::span<const ProxyPair> newPairs() const { return newPairs_; }

    /// Removes a pair; returns false if it was not in the set.
    bool removePair(std::uint64_t userDataA, std::uint64_t userDataB);
    [[nodiscard]] bool containsPair(std::uint64_t userDataA, std::uint64_t userDataB) const {
        return userDataA != userDataB && pairs_.contains(makePairKey(userDataA, userDataB));
    }
    [[nodiscard]] int pairCount() const { return pairs_.size(); }
    /// Calls f(const ProxyPair&) for every pair, in table order (deterministic). f must not
    /// modify the broad phase.
    template <class F>
    void forEachPair(F&& f) const {
        pairs_.forEach([&](const PairEntry& e) {
            f(ProxyPair{pairKeyLow(e.key), pairKeyHigh(e.key), e.proxyKeyA, e.proxyKeyB});
        });
    }
    /// Removes every pair whose fat boxes no longer overlap; returns how many.
    int prunePairs();

    /// Proxies waiting in the move buffer (destroyed ones included until the next update).
    [[nodiscard]] int moveCount() const { return static_cast<int>(moveBuffer_.size()); }
    /// Tree queries the last updatePairs() ran (a debug counter).
    [[nodiscard]] int lastQueryCount() const { return queryCount_; }

private:
    friend struct SnapshotAccess;
    struct ProxyInfo {
        int pairCount = 0;
        int moveIndex = -1; // index in moveBuffer_, -1 when not buffered
    };

    static std::size_t treeIndex(int proxyKey) { return static_cast<std::size_t>(proxyKey & 3); }
    // fatAabb() without the key check.
    [[nodiscard]] const Aabb& fatAabbLive(int proxyKey) const {
        return trees_[treeIndex(proxyKey)]
            .nodes_[static_cast<std::size_t>(proxyIdOf(proxyKey))]
            .aabb;
    }
    ProxyInfo& info(int proxyKey) { return infos_[static_cast<std::size_t>(proxyKey)]; }
    [[nodiscard]] bool isMoved(int proxyKey) const {
        return infos_[static_cast<std::size_t>(proxyKey)].moveIndex >= 0;
    }
    // Inline: moveProxy() checks every awake shape's key every step.
    void checkKey(int proxyKey, const char* function) const {
        if (proxyKey < 0 || static_cast<std::size_t>(proxyKey) >= infos_.size() ||
            (proxyKey & 3) >= kBodyTypeCount ||
            !trees_[treeIndex(proxyKey)].isProxy(proxyIdOf(proxyKey))) [[unlikely]] {
            throwBadKey(proxyKey, function);
        }
    }
    [[noreturn]] static void throwBadKey(int proxyKey, const char* function);
    // bufferMove() without the key check, for keys just checked or created.
    void bufferMoveLive(int proxyKey);
    // updatePairs()'s queries for moved proxy `key`: the accepted pairs not in the set yet
    // into `found`, the tree queries counted into `queries`.
    template <class ShouldPair, class QueryMask>
    void findPairsOf(int key, ShouldPair& shouldPair, QueryMask& queryMask,
                     std::vector<ProxyPair>& found, int& queries) const;
    void erasePair(std::uint64_t key);

    // Mutable: tree() inserts deferred proxies on demand.
    mutable std::array<DynamicTree, kBodyTypeCount> trees_;
    std::vector<ProxyInfo> infos_; // indexed by proxy key
    std::vector<int> moveBuffer_;
    std::uint64_t fatBoxChanges_ = 0; // fatBoxChanges(); not in snapshots
    std::vector<ProxyPair> newPairs_;
    // updatePairs() on several workers: each worker's pairs found and tree queries run.
    std::vector<std::vector<ProxyPair>> workerPairs_;
    std::vector<int> workerQueries_;
    std::vector<std::uint64_t> scratchKeys_;
    PairSet pairs_;
    int queryCount_ = 0;
};

inline bool BroadPhase::needsMoveLive(int proxyKey, const Aabb& aabb, Vec2 displacement) const {
    const BodyType type = proxyTypeOf(proxyKey);
#if defined(__SSE2__)
    // The scalar code below with a box in one register (lower x y, upper x y), operation for
    // operation: minps(0, d) is std::min(d, 0.0f) and maxps(0, d) std::max(d, 0.0f), NaN
    // included, and x - m is x + (-m). Every awake shape asks each step.
    static_assert(sizeof(Aabb) == 4 * sizeof(float));
    const __m128 zero = _mm_setzero_ps();
    // The displacement's negative parts for the lower corner, positive ones for the upper.
    auto spread = [zero](__m128 v) {
        return _mm_movelh_ps(_mm_min_ps(zero, v), _mm_max_ps(zero, v));
    };
    const __m128 box = _mm_loadu_ps(&aabb.lower.x);
    const __m128 current = _mm_loadu_ps(&fatAabbLive(proxyKey).lower.x);
    const __m128 d = _mm_setr_ps(displacement.x, displacement.y, displacement.x, displacement.y);
    const __m128 swept = _mm_add_ps(box, spread(d));
    // contains(current, swept): current.lower <= swept.lower, swept.upper <= current.upper.
    const __m128 small = _mm_shuffle_ps(current, swept, _MM_SHUFFLE(3, 2, 1, 0));
    const __m128 large = _mm_shuffle_ps(swept, current, _MM_SHUFFLE(3, 2, 1, 0));
    if (_mm_movemask_ps(_mm_cmple_ps(small, large)) != 0xF) {
        return true;
    }
    if (type == BodyType::Static) {
        return false;
    }
    // predictedFatBox() for a moving proxy, and the excess of the current box over it.
    const __m128 margin = _mm_setr_ps(-kAabbMargin, -kAabbMargin, kAabbMargin, kAabbMargin);
    const __m128 fat =
        _mm_add_ps(_mm_add_ps(box, margin), spread(_mm_mul_ps(_mm_set1_ps(kAabbPredictSteps), d)));
    const __m128 excess = _mm_sub_ps(_mm_sub_ps(_mm_movehl_ps(current, current), current),
                                     _mm_sub_ps(_mm_movehl_ps(fat, fat), fat));
    return (_mm_movemask_ps(_mm_cmple_ps(excess, _mm_set1_ps(kAabbSlack))) & 3) != 3;
#else
    // Where the shape is now and where it will be after `displacement`.
    Aabb swept = aabb;
    swept.lower += Vec2{std::min(displacement.x, 0.0f), std::min(displacement.y, 0.0f)};
    swept.upper += Vec2{std::max(displacement.x, 0.0f), std::max(displacement.y, 0.0f)};
    const Aabb& current = fatAabbLive(proxyKey);
    if (!contains(current, swept)) {
        return true;
    }
    if (type == BodyType::Static) {
        return false;
    }
    // Still inside; kept unless it is much larger than the shape needs now (a shape that moved
    // fast and slowed down), which would only keep extra pairs alive. A steadily moving
    // shape's box is as large as a new one would be, wherever it lags.
    const Aabb fat = predictedFatBox(aabb, type, displacement);
    const Vec2 excess = (current.upper - current.lower) - (fat.upper - fat.lower);
    return !(excess.x <= kAabbSlack && excess.y <= kAabbSlack);
#endif
}

template <class ShouldPair, class QueryMask>
void BroadPhase::updatePairs(ShouldPair&& shouldPair, QueryMask&& queryMask, Tasks* tasks) {
    newPairs_.clear();
    queryCount_ = 0;
    for (DynamicTree& t : trees_) {
        t.insertDeferred(); // new proxies in bulk
    }
    // The pairs of the moved proxies [begin, end) not in the set yet, into `found`; counts the
    // tree queries into `queries`. Reads the trees, the set and the move marks only.
    auto findPairs = [&](int begin, int end, std::vector<ProxyPair>& found, int& queries) {
        for (int m = begin; m < end; ++m) {
            const int key = moveBuffer_[static_cast<std::size_t>(m)];
            if (key == kNullProxyKey) {
                continue; // destroyed after it moved
            }
            findPairsOf(key, shouldPair, queryMask, found, queries);
        }
    };
    const int moved = static_cast<int>(moveBuffer_.size());
    // A query is about 600 ns (falling circles).
    const int minRange = tasks == nullptr ? moved : tasks->minRange(600);
    if (tasks == nullptr || tasks->workerCount() == 1 || moved / 2 < minRange) {
        findPairs(0, moved, newPairs_, queryCount_);
    } else {
        const auto workers = static_cast<std::size_t>(tasks->workerCount());
        workerPairs_.resize(workers);
        workerQueries_.assign(workers, 0);
        for (std::vector<ProxyPair>& found : workerPairs_) {
            found.clear();
        }
        tasks->parallelFor(moved, minRange, [&](int begin, int end, int worker) {
            const auto w = static_cast<std::size_t>(worker);
            findPairs(begin, end, workerPairs_[w], workerQueries_[w]);
        });
        for (std::size_t w = 0; w < workers; ++w) {
            newPairs_.insert(newPairs_.end(), workerPairs_[w].begin(), workerPairs_[w].end());
            queryCount_ += workerQueries_[w];
        }
    }
    for (const int key : moveBuffer_) {
        if (key != kNullProxyKey) {
            info(key).moveIndex = -1;
        }
    }
    moveBuffer_.clear();

    // Query order depends on tree shape (and on the workers); sorted pairs (and insertion in
    // that order) do not.
    std::sort(newPairs_.begin(), newPairs_.end(), [](const ProxyPair& x, const ProxyPair& y) {
        return x.userDataA < y.userDataA ||
               (x.userDataA == y.userDataA && x.userDataB < y.userDataB);
    });
    for (const ProxyPair& p : newPairs_) {
        pairs_.insert({makePairKey(p.userDataA, p.userDataB), p.proxyKeyA, p.proxyKeyB});
        ++info(p.proxyKeyA).pairCount;
        ++info(p.proxyKeyB).pairCount;
    }
}

template <class ShouldPair, class QueryMask>
void BroadPhase::findPairsOf(int key, ShouldPair& shouldPair, QueryMask& queryMask,
                             std::vector<ProxyPair>& found, int& queries) const {
    const BodyType type = proxyTypeOf(key);
    const DynamicTree& own = trees_[treeIndex(key)];
    const Aabb box = own.aabb(proxyIdOf(key));
    const std::uint64_t ud = own.userData(proxyIdOf(key));
    const std::uint64_t mask = queryMask(ud);

    auto queryTree = [&](BodyType otherType) {
        ++queries;
        const DynamicTree& tree = trees_[static_cast<std::size_t>(otherType)];
        if (tree.isEmpty()) {
            return; // often the kinematic tree
        }
        // The box is a tree's own: valid, no need to check it again.
        auto report = [&](int otherId, std::uint64_t otherUd) {
            const int otherKey = makeProxyKey(otherId, otherType);
            // When both moved, the one with the lower key reports the pair (the queries
            // are symmetric: each one's query covers the other's tree).
            if (otherKey == key || (otherKey < key && isMoved(otherKey))) {
                return;
            }
            const std::uint64_t pairKey = makePairKey(ud, otherUd);
            if (pairs_.contains(pairKey)) {
                return;
            }
            const bool mineIsA = ud < otherUd;
            const std::uint64_t a = mineIsA ? ud : otherUd;
            const std::uint64_t b = mineIsA ? otherUd : ud;
            if (!shouldPair(a, b)) {
                return;
            }
            found.push_back({a, b, mineIsA ? key : otherKey, mineIsA ? otherKey : key});
        };
        tree.queryValid(box, mask, report);
    };
    switch (type) {
    case BodyType::Dynamic:
        queryTree(BodyType::Dynamic);
        queryTree(BodyType::Kinematic);
        queryTree(BodyType::Static);
        break;
    case BodyType::Kinematic:
    case BodyType::Static:
        queryTree(BodyType::Dynamic);
        break;
    }
}

} // namespace e2d::physics::detail
