// SPDX-License-Identifier: MIT
#include "broad_phase.hpp"

#include <e2d/core/error.hpp>

#include <algorithm>
#include <string>
#include <vector>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

namespace e2d::physics::detail {

namespace {

// A moved proxy's fat box extends this many of its displacements ahead. Box2D 2.4 takes 4 of
// the last step's; here the displacement is the next step's, which the box must hold anyway,
// and 4 made 17 % more contacts (fat boxes overlapping, shapes apart) in a settling pile of
// circles for no gain on a swinging joint net.
constexpr float kAabbPredictSteps = 2.0f;
// A proxy whose fat box still contains its shape is reinserted anyway when the box is wider or
// taller than the one it would get now by more than this (Box2D 2.4's limit: 4 margins).
constexpr float kAabbSlack = 4.0f * kAabbMargin;

Aabb fatten(const Aabb& box, BodyType type) {
    // Static proxies never move by themselves: a margin would only create extra pairs.
    if (type == BodyType::Static) {
        return box;
    }
    const Vec2 margin{kAabbMargin, kAabbMargin};
    return {box.lower - margin, box.upper + margin};
}

// Room for one more element, growing geometrically: reserve(size() + 1) reallocates and copies
// the whole buffer on every call once it is full (100 000 shapes created one by one spent most
// of their time copying it).
void reserveOneMore(std::vector<int>& buffer) {
    if (buffer.size() == buffer.capacity()) {
        buffer.reserve(std::max<std::size_t>(64, 2 * buffer.capacity()));
    }
}

} // namespace

void BroadPhase::throwBadKey(int proxyKey, const char* function) {
    throw core::Error(std::string("physics::BroadPhase::") + function + "(): no proxy with key " +
                      std::to_string(proxyKey));
}

int BroadPhase::createProxy(const Aabb& aabb, BodyType type, std::uint64_t categoryBits,
                            std::uint64_t userData) {
    if (userData > 0xFFFFFFFFu) {
        throw core::Error("physics::BroadPhase::createProxy(): userData must fit in 32 bits, got " +
                          std::to_string(userData));
    }
    const int typeIndex = static_cast<int>(type);
    if (typeIndex < 0 || typeIndex >= kBodyTypeCount) {
        throw core::Error("physics::BroadPhase::createProxy(): bad body type " +
                          std::to_string(typeIndex));
    }
    // Reserve first so that nothing can throw after the tree changed.
    reserveOneMore(moveBuffer_);
    DynamicTree& tree = trees_[static_cast<std::size_t>(typeIndex)];
    const int proxyId = tree.createProxyDeferred(fatten(aabb, type), categoryBits, userData);
    const int key = makeProxyKey(proxyId, type);
    if (static_cast<std::size_t>(key) >= infos_.size()) {
        try {
            infos_.resize(static_cast<std::size_t>(key) + 1 + infos_.size() / 2);
        } catch (...) {
            tree.destroyProxy(proxyId); // leave the broad phase as it was
            throw;
        }
    }
    info(key) = ProxyInfo{};
    bufferMove(key);
    return key;
}

void BroadPhase::destroyProxy(int proxyKey) {
    checkKey(proxyKey, "destroyProxy");
    ProxyInfo& pi = info(proxyKey);
    if (pi.moveIndex >= 0) {
        moveBuffer_[static_cast<std::size_t>(pi.moveIndex)] = kNullProxyKey;
        pi.moveIndex = -1;
    }
    if (pi.pairCount > 0) {
        scratchKeys_.clear();
        pairs_.forEach([&](const PairEntry& e) {
            if (e.proxyKeyA == proxyKey || e.proxyKeyB == proxyKey) {
                scratchKeys_.push_back(e.key);
            }
        });
        for (const std::uint64_t key : scratchKeys_) {
            erasePair(key);
        }
    }
    trees_[treeIndex(proxyKey)].destroyProxy(proxyIdOf(proxyKey));
    info(proxyKey) = ProxyInfo{};
}

namespace {

// The fat box of a shape of `type` with tight box `aabb` that moves `displacement` next: it
// reaches kAabbPredictSteps displacements ahead, so a steadily moving shape stays inside it for
// that many steps instead of leaving a fixed margin every step or two. Inlined: needsMove()
// asks it for every awake shape each step.
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

} // namespace

bool BroadPhase::needsMove(int proxyKey, const Aabb& aabb, Vec2 displacement) const {
    checkKey(proxyKey, "needsMove");
    return needsMoveLive(proxyKey, aabb, displacement);
}

bool BroadPhase::needsMoveLive(int proxyKey, const Aabb& aabb, Vec2 displacement) const {
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

bool BroadPhase::moveProxy(int proxyKey, const Aabb& aabb, Vec2 displacement) {
    if (!needsMove(proxyKey, aabb, displacement)) {
        return false;
    }
    reserveOneMore(moveBuffer_);
    trees_[treeIndex(proxyKey)].moveProxy(
        proxyIdOf(proxyKey), predictedFatBox(aabb, proxyTypeOf(proxyKey), displacement));
    bufferMove(proxyKey);
    return true;
}

void BroadPhase::bufferMove(int proxyKey) {
    checkKey(proxyKey, "bufferMove");
    ProxyInfo& pi = info(proxyKey);
    if (pi.moveIndex >= 0) {
        return;
    }
    pi.moveIndex = static_cast<int>(moveBuffer_.size());
    moveBuffer_.push_back(proxyKey);
}

int BroadPhase::proxyCount() const {
    int count = 0;
    for (const DynamicTree& tree : trees_) {
        count += tree.proxyCount();
    }
    return count;
}

void BroadPhase::erasePair(std::uint64_t key) {
    PairEntry removed;
    if (pairs_.erase(key, &removed)) {
        --info(removed.proxyKeyA).pairCount;
        --info(removed.proxyKeyB).pairCount;
    }
}

bool BroadPhase::removePair(std::uint64_t userDataA, std::uint64_t userDataB) {
    if (userDataA == userDataB) {
        return false;
    }
    const std::uint64_t key = makePairKey(userDataA, userDataB);
    if (!pairs_.contains(key)) {
        return false;
    }
    erasePair(key);
    return true;
}

int BroadPhase::prunePairs() {
    scratchKeys_.clear();
    pairs_.forEach([&](const PairEntry& e) {
        if (!overlaps(fatAabb(e.proxyKeyA), fatAabb(e.proxyKeyB))) {
            scratchKeys_.push_back(e.key);
        }
    });
    for (const std::uint64_t key : scratchKeys_) {
        erasePair(key);
    }
    return static_cast<int>(scratchKeys_.size());
}

} // namespace e2d::physics::detail
