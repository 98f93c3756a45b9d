// SPDX-License-Identifier: MIT
#include <e2d/physics/world.hpp>

#include "world_impl.hpp"

#include <cstdint>

namespace e2d::physics {

void World::updatePairs() {
    Impl& w = *impl_;
    w.requireUnlocked("updatePairs");
    w.broadPhase.updatePairs(
        [&w](std::uint64_t a, std::uint64_t b) {
            return w.shouldPair(static_cast<int>(a), static_cast<int>(b));
        },
        [&w](std::uint64_t ud) { return w.pairQueryMask(static_cast<int>(ud)); });
    // A pair lives while the fat boxes overlap. A fat box changes only when its proxy moves,
    // and the next update looks at moved proxies again, so a dropped pair whose boxes come
    // back into overlap is found again.
    w.broadPhase.prunePairs();
}

int World::candidatePairCount() const { return impl_->broadPhase.pairCount(); }

void World::forEachCandidatePair(FunctionRef<void(ShapeId, ShapeId)> callback) const {
    const Impl& w = *impl_;
    Impl::CallbackLock lock(w, "forEachCandidatePair");
    w.broadPhase.forEachPair([&](const detail::ProxyPair& pair) {
        callback(w.shapeId(static_cast<int>(pair.userDataA)),
                 w.shapeId(static_cast<int>(pair.userDataB)));
    });
}

} // namespace e2d::physics
