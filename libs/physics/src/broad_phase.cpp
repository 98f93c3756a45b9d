// SPDX-License-Identifier: MIT
#include "broad_phase.hpp"

#include <e2d/core/error.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace e2d::physics::detail {

namespace {

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
    bufferMoveLive(key);
    ++fatBoxChanges_;
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
    ++fatBoxChanges_;
}

bool BroadPhase::needsMove(int proxyKey, const Aabb& aabb, Vec2 displacement) const {
    checkKey(proxyKey, "needsMove");
    return needsMoveLive(proxyKey, aabb, displacement);
}

bool BroadPhase::moveProxy(int proxyKey, const Aabb& aabb, Vec2 displacement) {
    if (!needsMove(proxyKey, aabb, displacement)) {
        return false;
    }
    reserveOneMore(moveBuffer_);
    trees_[treeIndex(proxyKey)].moveProxy(
        proxyIdOf(proxyKey), predictedFatBox(aabb, proxyTypeOf(proxyKey), displacement));
    bufferMoveLive(proxyKey);
    ++fatBoxChanges_;
    return true;
}

void BroadPhase::bufferMove(int proxyKey) {
    checkKey(proxyKey, "bufferMove");
    bufferMoveLive(proxyKey);
}

void BroadPhase::bufferMoveLive(int proxyKey) {
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
