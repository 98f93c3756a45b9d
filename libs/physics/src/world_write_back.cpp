// SPDX-License-Identifier: MIT
// The end of a solve: each solver body's state back to its world slot, its shapes' boxes, the
// broad-phase moves and the move events; a body whose state went non-finite or left the
// coordinate range (kHuge) is disabled instead.
#include "world_impl.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace e2d::physics {

using detail::kNullIndex;

namespace {

bool isFiniteState(const detail::BodySim& s, const detail::BodyState& st) {
    return (st.flags & detail::kNonFinite) == 0 && isFinite(s.center) && isFinite(s.transform.p) &&
           isFinite(s.positionResidual) && isFinite(s.transform.q.c) && isFinite(s.transform.q.s) &&
           isFinite(st.linearVelocity) && isFinite(st.angularVelocity);
}

// isFiniteState() and the origin within kHuge: the body is written back. Every body asks, so
// on SSE2 the ten values are tested four at a time (|x| <= limit is false for NaN and
// infinities alike).
bool isWritable(const detail::BodySim& s, const detail::BodyState& st) {
#if defined(__SSE2__)
    static_assert(sizeof(Transform) == 4 * sizeof(float) && offsetof(Transform, q) == 8 &&
                  offsetof(detail::BodyState, angularVelocity) == 8);
    const __m128 absMask = _mm_castsi128_ps(_mm_set1_epi32(0x7FFFFFFF));
    const __m128 largest = _mm_set1_ps(3.40282347e38f);
    // p within kHuge, q finite.
    const __m128 transform = _mm_and_ps(_mm_loadu_ps(&s.transform.p.x), absMask);
    const __m128 transformOk =
        _mm_cmple_ps(transform, _mm_setr_ps(kHuge, kHuge, 3.40282347e38f, 3.40282347e38f));
    const __m128 points = _mm_and_ps(
        _mm_loadh_pi(_mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(&s.center)),
                     reinterpret_cast<const __m64*>(&s.positionResidual)),
        absMask);
    // v and w; the flags lane cleared (a zero is finite).
    const __m128 velocity =
        _mm_and_ps(_mm_loadu_ps(&st.linearVelocity.x),
                   _mm_castsi128_ps(_mm_setr_epi32(0x7FFFFFFF, 0x7FFFFFFF, 0x7FFFFFFF, 0)));
    const __m128 ok = _mm_and_ps(
        transformOk, _mm_and_ps(_mm_cmple_ps(points, largest), _mm_cmple_ps(velocity, largest)));
    return _mm_movemask_ps(ok) == 0xF && (st.flags & detail::kNonFinite) == 0;
#else
    return isFiniteState(s, st) && isWithinHuge(s.transform.p);
#endif
}

// What the parallel pass left for the ordered one, per solver body.
enum : unsigned char { kWritten = 0, kMoveProxies, kNonFiniteBody, kOutOfRangeBody };

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
    // Every event is written below (or dropped with its disabled body): no need to clear them
    // first, which zeroed them all each step.
    moveEvents.resize(static_cast<std::size_t>(simCount));
    s.writeBackResults.resize(static_cast<std::size_t>(simCount));
    auto writePiece = [&](int begin, int end, int /*worker*/) {
        // The arrays in locals: the stores below may alias them for the compiler, which then
        // loaded them from the world again at every use.
        const detail::BodySim* const sims = s.sims.data();
        const detail::BodyState* const states = s.states.data();
        unsigned char* const results = s.writeBackResults.data();
        BodyMoveEvent* const events = moveEvents.data();
        detail::Body* const bodySlots = bodies.data();
        detail::Shape* const shapeSlots = shapes.data();
        const detail::BroadPhase& bp = broadPhase;
        const float stepDt = dt;
        for (int k = begin; k < end; ++k) {
            const detail::BodySim& bs = sims[k];
            const detail::BodyState& st = states[k];
            unsigned char& result = results[k];
            detail::Body& b = bodySlots[bs.bodyIndex];
            b.motion.force = {0.0f, 0.0f};
            b.motion.torque = 0.0f;
            if (!isWritable(bs, st)) [[unlikely]] {
                result = isFiniteState(bs, st) ? kOutOfRangeBody : kNonFiniteBody;
                continue;
            }
            b.transform = bs.transform;
            b.motion.positionResidual = bs.positionResidual;
            b.linearVelocity = st.linearVelocity;
            b.angularVelocity = st.angularVelocity;
            // The broad-phase box also covers where the body will be next step, so the pairs
            // (and speculative contacts) exist before a fast body arrives.
            const Vec2 ahead = stepDt * b.linearVelocity;
            unsigned char written = kWritten;
            for (int si = b.headShape; si != kNullIndex; si = shapeSlots[si].nextShape) {
                detail::Shape& sh = shapeSlots[si];
                sh.aabb = computeAabb(sh.geometry, b.transform);
                // An enabled body's shapes have live proxies (kNullIndex while disabled).
                if (sh.proxyKey != kNullIndex && bp.needsMoveLive(sh.proxyKey, sh.aabb, ahead)) {
                    written = kMoveProxies;
                }
            }
            result = written;
            // Field by field: a braced temporary is built on the stack and copied out in 16-byte
            // loads that wait for its 4-byte stores (a store-forwarding stall, about 1.5 % of the
            // joint grid's step).
            BodyMoveEvent& event = events[k];
            event.body =
                BodyId::forSlot(static_cast<std::uint32_t>(bs.bodyIndex), b.generation, tag);
            event.transform = b.transform;
            event.fellAsleep = false;
        }
    };
    // A body is about 30 ns.
    tasks.parallelFor(simCount, tasks.minRange(30), writePiece);

    s.disabledSims.clear();
    const unsigned char* const results = s.writeBackResults.data();
    for (int k = 0; k < simCount; ++k) {
        // Most bodies of a resting pile need nothing more: their results (kWritten, zero) are
        // skipped eight at a time.
        if ((k & 7) == 0 && k + 8 <= simCount) {
            std::uint64_t eight = 0;
            std::memcpy(&eight, results + k, sizeof eight);
            if (eight == 0) {
                k += 7;
                continue;
            }
        }
        const unsigned char result = results[k];
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
