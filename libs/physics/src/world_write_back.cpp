// SPDX-License-Identifier: MIT
// The end of a solve: each solver body's state back to its world slot, its shapes' boxes, the
// broad-phase moves and the move events; a body whose state went non-finite or left the
// coordinate range (kHuge) is disabled instead.
#include "world_impl.hpp"

#include <algorithm>

namespace e2d::physics {

using detail::kNullIndex;

namespace {

bool isFiniteState(const detail::BodySim& s, const detail::BodyState& st) {
    return (st.flags & detail::kNonFinite) == 0 && isFinite(s.center) && isFinite(s.transform.p) &&
           isFinite(s.positionResidual) && isFinite(s.transform.q.c) && isFinite(s.transform.q.s) &&
           isFinite(st.linearVelocity) && isFinite(st.angularVelocity);
}

// What the parallel pass left for the ordered one, per solver body.
enum : unsigned char { kWritten, kMoveProxies, kNonFiniteBody, kOutOfRangeBody };

} // namespace

// Two passes. The first, on several workers, writes each body and its shapes' boxes (a body and
// its shapes are one worker's) and its move event at its own index, and asks the broad phase
// whether each proxy must move (BroadPhase::needsMove(), which reads that proxy alone). The
// second goes through the bodies in order, alone: it disables the bad ones and moves the
// proxies that must move, so the trees change in the same order for any worker count.
void World::Impl::writeBack(float dt) {
    detail::Simulation& s = sim;
    std::vector<BodyMoveEvent>& moveEvents = hooks.moveEvents;
    const int simCount = static_cast<int>(s.sims.size());
    moveEvents.clear();
    moveEvents.resize(static_cast<std::size_t>(simCount));
    s.writeBackResults.resize(static_cast<std::size_t>(simCount));
    auto writePiece = [&](int begin, int end, int /*worker*/) {
        for (int k = begin; k < end; ++k) {
            const detail::BodySim& bs = s.sims[static_cast<std::size_t>(k)];
            const detail::BodyState& st = s.states[static_cast<std::size_t>(k)];
            unsigned char& result = s.writeBackResults[static_cast<std::size_t>(k)];
            detail::Body& b = body(bs.bodyIndex);
            b.motion.force = {0.0f, 0.0f};
            b.motion.torque = 0.0f;
            const bool finite = isFiniteState(bs, st);
            if (!finite || !isWithinHuge(bs.transform.p)) {
                result = finite ? kOutOfRangeBody : kNonFiniteBody;
                continue;
            }
            b.transform = bs.transform;
            b.motion.positionResidual = bs.positionResidual;
            b.linearVelocity = st.linearVelocity;
            b.angularVelocity = st.angularVelocity;
            // The broad-phase box also covers where the body will be next step, so the pairs
            // (and speculative contacts) exist before a fast body arrives.
            const Vec2 ahead = dt * b.linearVelocity;
            result = kWritten;
            for (int si = b.headShape; si != kNullIndex; si = shape(si).nextShape) {
                detail::Shape& sh = shape(si);
                sh.aabb = computeAabb(sh.geometry, b.transform);
                if (sh.proxyKey != kNullIndex &&
                    broadPhase.needsMove(sh.proxyKey, sh.aabb, ahead)) {
                    result = kMoveProxies;
                }
            }
            // Field by field: a braced temporary is built on the stack and copied out in 16-byte
            // loads that wait for its 4-byte stores (a store-forwarding stall, about 1.5 % of the
            // joint grid's step).
            BodyMoveEvent& event = moveEvents[static_cast<std::size_t>(k)];
            event.body = bodyId(bs.bodyIndex);
            event.transform = b.transform;
        }
    };
    // A body is a few tens of nanoseconds: pieces of several microseconds at least.
    constexpr int kBodiesPerPiece = 256;
    tasks.parallelFor(simCount, kBodiesPerPiece, writePiece);

    s.disabledSims.clear();
    for (int k = 0; k < simCount; ++k) {
        const unsigned char result = s.writeBackResults[static_cast<std::size_t>(k)];
        if (result == kWritten) {
            continue;
        }
        const detail::BodySim& bs = s.sims[static_cast<std::size_t>(k)];
        detail::Body& b = body(bs.bodyIndex);
        if (result == kMoveProxies) {
            const Vec2 ahead = dt * b.linearVelocity;
            for (int si = b.headShape; si != kNullIndex; si = shape(si).nextShape) {
                const detail::Shape& sh = shape(si);
                if (sh.proxyKey != kNullIndex) {
                    s.counters.proxyMoves +=
                        broadPhase.moveProxy(sh.proxyKey, sh.aabb, ahead) ? 1 : 0;
                }
            }
            continue;
        }
        // Its last transform (finite, within kHuge) stays, so calls from where it is work.
        (result == kOutOfRangeBody ? s.outOfRangeBodies : s.nonFiniteBodies)
            .push_back(bodyId(bs.bodyIndex));
        s.disabledSims.push_back(k);
        b.linearVelocity = {0.0f, 0.0f};
        b.angularVelocity = 0.0f;
        b.enabled = false;
        b.motion.solverIndex = kNullIndex;
        for (int si = b.headShape; si != kNullIndex; si = shape(si).nextShape) {
            destroyProxy(si);
        }
    }
    // One event per body left enabled, in solver order (collectMoveEvents()).
    if (!s.disabledSims.empty()) {
        std::size_t kept = 0;
        std::size_t nextDisabled = 0;
        for (std::size_t k = 0; k < moveEvents.size(); ++k) {
            if (nextDisabled < s.disabledSims.size() &&
                static_cast<std::size_t>(s.disabledSims[nextDisabled]) == k) {
                ++nextDisabled;
                continue;
            }
            moveEvents[kept++] = moveEvents[k];
        }
        moveEvents.resize(kept);
    }
}

} // namespace e2d::physics
