// SPDX-License-Identifier: MIT
#include <e2d/physics/world.hpp>

#include "world_impl.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace e2d::physics {

void World::updatePairs() {
    Impl& w = *impl_;
    w.broadPhase.updatePairs([&w](std::uint64_t a, std::uint64_t b) {
        return w.shouldPair(static_cast<int>(a), static_cast<int>(b));
    });

    // A pair lives while the fat boxes overlap; a fat box only changes when its proxy moves,
    // and a moved proxy is looked at again by the next update, so a dropped pair that comes
    // back into overlap is found again.
    std::vector<std::pair<std::uint64_t, std::uint64_t>>& stale = w.stalePairs;
    stale.clear();
    w.broadPhase.forEachPair([&](std::uint64_t a, std::uint64_t b) {
        const detail::Shape& sa = w.shape(static_cast<int>(a));
        const detail::Shape& sb = w.shape(static_cast<int>(b));
        if (!overlaps(w.broadPhase.fatAabb(sa.proxyKey), w.broadPhase.fatAabb(sb.proxyKey))) {
            stale.emplace_back(a, b);
        }
    });
    for (auto [a, b] : stale) {
        w.broadPhase.removePair(a, b);
    }
}

int World::candidatePairCount() const { return impl_->broadPhase.pairCount(); }

void World::forEachCandidatePair(FunctionRef<void(ShapeId, ShapeId)> callback) const {
    const Impl& w = *impl_;
    w.broadPhase.forEachPair([&](std::uint64_t a, std::uint64_t b) {
        auto lo = static_cast<int>(std::min(a, b));
        auto hi = static_cast<int>(std::max(a, b));
        callback(w.shapeId(lo), w.shapeId(hi));
    });
}

} // namespace e2d::physics
