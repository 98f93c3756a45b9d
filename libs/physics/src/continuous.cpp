// SPDX-License-Identifier: MIT
// The solved bodies' final poses, then continuous collision: a fast body (or a bullet) is swept
// from where it started the step to where the solver put it, against static shapes (bullets:
// also against kinematic and non-bullet dynamic shapes at their end-of-step poses), and stopped
// at the first time of impact. The next step's speculative contact then does the rest.
#include <e2d/physics/time_of_impact.hpp>

#include "body_solver.hpp"
#include "world_impl.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <span>

namespace e2d::physics {

using detail::kNullIndex;

namespace {

Rot nlerp(Rot q1, Rot q2, float t) {
    float c = (1.0f - t) * q1.c + t * q2.c;
    float s = (1.0f - t) * q1.s + t * q2.s;
    float mag = std::sqrt(c * c + s * s);
    return mag > 0.0f ? Rot{c / mag, s / mag} : q2;
}

} // namespace

void World::Impl::finalizeAndSweep(bool continuous) {
    // Decided from the step's own arrays (the bullet flag copied at the start of the step, the
    // fast flag set by finalizePositions()), so the bodies that stay slow, nearly all of them,
    // never read their world slot.
    // A fast body that is no bullet is swept against static shapes only and changes its own
    // pose only: those sweeps run on the workers, right after the final poses of their row of
    // bodies. Bullets go after them, alone, against every other body's final pose. The pair
    // filter is the game's code, called from the stepping thread only: with one set, every
    // sweep runs here, in body order, after all the poses.
    const int n = static_cast<int>(sim.sims.size());
    if (continuous) {
        for (BodyType type : {BodyType::Static, BodyType::Kinematic, BodyType::Dynamic}) {
            (void)broadPhase.tree(type); // proxies created since the pair update go in now, here
        }
    }
    std::atomic<bool> bullets{false};
    std::atomic<bool> sweeps{false};
    auto sweepFast = [&](int begin, int end) {
        bool bullet = false;
        for (int k = begin; k < end; ++k) {
            const detail::BodySim& bs = sim.sims[static_cast<std::size_t>(k)];
            if ((bs.flags & detail::kIsBullet) != 0) {
                bullet = true;
                continue;
            }
            // Slow bodies (detail::movedFast()) are left to their speculative contacts.
            if ((bs.flags & detail::kIsFast) != 0) {
                sweepBody(k);
            }
        }
        if (bullet) {
            bullets.store(true, std::memory_order_relaxed);
        }
    };
    const bool sweepHere = continuous && !hooks.pairFilter;
    // In pieces of whole rows of eight bodies: each body goes through the same lanes of
    // detail::finalizePositions() as in one call over all of them.
    constexpr int kRow = 8;
    auto piece = [&](int beginRow, int endRow, int /*worker*/) {
        const int begin = beginRow * kRow;
        const int end = std::min(endRow * kRow, n);
        const auto at = static_cast<std::size_t>(begin);
        const auto count = static_cast<std::size_t>(end - begin);
        // Whether a body of these is fast or a bullet.
        if (detail::finalizePositions(
                std::span(sim.sims).subspan(at, count),
                std::span<const detail::BodyState>(sim.states).subspan(at, count))) {
            sweeps.store(true, std::memory_order_relaxed);
            if (sweepHere) {
                sweepFast(begin, end);
            }
        }
    };
    // A body's final pose is about 10 ns (its BodySim streams in from memory).
    tasks.parallelFor((n + kRow - 1) / kRow, tasks.minRange(10 * kRow), piece);
    if (continuous && !sweepHere && sweeps.load(std::memory_order_relaxed)) {
        sweepFast(0, n);
    }
    if (bullets.load(std::memory_order_relaxed)) {
        for (int k = 0; k < n; ++k) {
            if ((sim.sims[static_cast<std::size_t>(k)].flags & detail::kIsBullet) != 0) {
                sweepBody(k);
            }
        }
    }
}

void World::Impl::sweepBody(int simIndex) {
    detail::BodySim& bs = sim.sims[static_cast<std::size_t>(simIndex)];
    const detail::Body& b = body(bs.bodyIndex);
    if (b.type != BodyType::Dynamic || b.headShape == kNullIndex) {
        return;
    }
    if (!isFinite(bs.center) || !isFinite(bs.center0)) {
        return;
    }

    Sweep sweep{bs.localCenter, bs.center0, bs.center, bs.rotation0, bs.transform.q};
    Transform xf1 = sweepTransform(sweep, 0.0f);
    const Transform& xf2 = bs.transform;
    float fraction = 1.0f;
    // Where another body ends this step: a bullet meets moving bodies where the solver put
    // them (Box2D v3 does the same: bullets go after everything else, against end poses).
    auto endTransform = [&](const detail::Body& other) -> const Transform& {
        int k = other.motion.solverIndex;
        return k == kNullIndex ? other.transform : sim.sims[static_cast<std::size_t>(k)].transform;
    };
    // Everything is swept against static shapes; bullets also against kinematic and non-bullet
    // dynamic ones (two bullets meet through their speculative contact).
    const BodyType treeTypes[] = {BodyType::Static, BodyType::Kinematic, BodyType::Dynamic};
    int treeCount = b.motion.isBullet ? 3 : 1;
    for (int si = b.headShape; si != kNullIndex; si = shape(si).nextShape) {
        const detail::Shape& s = shape(si);
        if (s.isSensor) {
            continue;
        }
        Aabb box = unionOf(computeAabb(s.geometry, xf1), computeAabb(s.geometry, xf2));
        ShapeProxy proxyB = makeProxy(s.geometry);
        for (int t = 0; t < treeCount; ++t) {
            const DynamicTree& tree = broadPhase.tree(treeTypes[t]);
            tree.query(box, s.filter.maskBits, [&](int, std::uint64_t userData) {
                auto otherIndex = static_cast<int>(userData);
                const detail::Shape& other = shape(otherIndex);
                if (other.body == bs.bodyIndex || other.isSensor ||
                    !shouldCollide(s.filter, other.filter)) {
                    return;
                }
                const detail::Body& otherBody = body(other.body);
                if (otherBody.type == BodyType::Dynamic && otherBody.motion.isBullet) {
                    return;
                }
                const Transform& xfOther = endTransform(otherBody);
                if (!passesChainAndFilter(si, otherIndex, xf1, xfOther)) {
                    return;
                }
                TOIInput input;
                input.proxyA = makeProxy(other.geometry);
                input.proxyB = proxyB;
                input.sweepA = Sweep{{0.0f, 0.0f}, xfOther.p, xfOther.p, xfOther.q, xfOther.q};
                input.sweepB = sweep;
                input.maxFraction = fraction;
                TOIOutput out = timeOfImpact(input);
                // Overlapping at the start is the contacts' business, not a time of impact.
                if (out.state == TOIState::Hit && out.fraction > 0.0f && out.fraction < fraction) {
                    fraction = out.fraction;
                }
            });
        }
    }
    if (fraction < 1.0f) {
        Rot q = nlerp(sweep.q1, sweep.q2, fraction);
        Vec2 c = (1.0f - fraction) * sweep.c1 + fraction * sweep.c2;
        bs.center = c;
        bs.transform = {c - rotate(q, bs.localCenter), q};
        bs.positionResidual = {0.0f, 0.0f}; // the time of impact is not that precise anyway
    }
}

} // namespace e2d::physics
