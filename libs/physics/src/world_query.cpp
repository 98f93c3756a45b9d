// SPDX-License-Identifier: MIT
#include <e2d/physics/world.hpp>

#include <e2d/physics/distance.hpp>

#include "world_check.hpp"
#include "world_impl.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace e2d::physics {

namespace check = detail::world_check;

namespace {

constexpr BodyType kAllTypes[] = {BodyType::Static, BodyType::Kinematic, BodyType::Dynamic};

bool passes(const detail::Shape& shape, const QueryFilter& filter) {
    if (shape.isSensor && !filter.includeSensors) {
        return false;
    }
    return (shape.filter.categoryBits & filter.maskBits) != 0 &&
           (shape.filter.maskBits & filter.categoryBits) != 0;
}

void checkRay(const char* function, Vec2 origin, Vec2 translation) {
    check::requirePosition(function, "origin", origin);
    if (!isFinite(translation) || (translation.x == 0.0f && translation.y == 0.0f)) {
        check::fail(function,
                    "translation must be finite and non-zero, got " + check::text(translation));
    }
    // Beyond kHuge nothing can be hit, and the end point must stay representable.
    if (!isWithinHuge(origin + translation)) {
        check::fail(function, "origin + translation must be within kHuge (" + check::text(kHuge) +
                                  " m), got " + check::text(origin + translation));
    }
}

void checkBox(const char* function, const Aabb& box) {
    if (!isFinite(box.lower) || !isFinite(box.upper) || !(box.lower.x <= box.upper.x) ||
        !(box.lower.y <= box.upper.y)) {
        check::fail(function, "box must be finite with lower <= upper, got lower " +
                                  check::text(box.lower) + ", upper " + check::text(box.upper));
    }
}

// Whether the segment from p to p + maxFraction * d meets the box (slab test; touching counts).
bool segmentMeetsBox(Vec2 p, Vec2 d, float maxFraction, const Aabb& box) {
    float lo = 0.0f;
    float hi = maxFraction;
    for (int axis = 0; axis < 2; ++axis) {
        float origin = axis == 0 ? p.x : p.y;
        float dir = axis == 0 ? d.x : d.y;
        float lower = axis == 0 ? box.lower.x : box.lower.y;
        float upper = axis == 0 ? box.upper.x : box.upper.y;
        if (dir == 0.0f) {
            if (origin < lower || origin > upper) {
                return false;
            }
            continue;
        }
        float t1 = (lower - origin) / dir;
        float t2 = (upper - origin) / dir;
        lo = std::max(lo, std::min(t1, t2));
        hi = std::min(hi, std::max(t1, t2));
        if (lo > hi) {
            return false;
        }
    }
    return true;
}

// Where the ray `input` (world space) enters one shape placed at `xf`.
std::optional<RayResult> entryHit(const detail::Shape& shape, const Transform& xf,
                                  const RayCastInput& input) {
    RayCastInput local{invTransformPoint(xf, input.origin), invRotate(xf.q, input.translation),
                       input.maxFraction};
    CastOutput out = rayCast(local, shape.geometry);
    if (!out.hit) {
        return std::nullopt;
    }
    return RayResult{
        {}, transformPoint(xf, out.point), rotate(xf.q, out.normal), out.fraction, false};
}

// Where the ray leaves the shape. The exit of a convex shape is the entry of the same ray cast
// backwards from its far end, so the shapes' own ray casts answer both. A segment has no
// inside, so its one hit is its entry.
std::optional<RayResult> exitHit(const detail::Shape& shape, const Transform& xf,
                                 const RayCastInput& input) {
    if (typeOf(shape.geometry) == ShapeType::Segment ||
        typeOf(shape.geometry) == ShapeType::ChainSegment) {
        return std::nullopt;
    }
    Vec2 end = input.origin + input.maxFraction * input.translation;
    std::optional<RayResult> hit =
        entryHit(shape, xf, {end, -input.maxFraction * input.translation, 1.0f});
    if (hit) {
        hit->fraction = input.maxFraction * (1.0f - hit->fraction);
        hit->exit = true;
    }
    return hit;
}

// The first hit on one shape: its entry, or with back faces its exit when the ray starts
// inside (an entry always comes before the exit of the same convex shape).
std::optional<RayResult> firstHit(const detail::Shape& shape, const Transform& xf,
                                  const RayCastInput& input, bool ignoreBackFaces) {
    std::optional<RayResult> hit = entryHit(shape, xf, input);
    if (!hit && !ignoreBackFaces) {
        hit = exitHit(shape, xf, input);
    }
    return hit;
}

} // namespace

std::optional<RayResult> World::castRayClosest(Vec2 origin, Vec2 translation,
                                               const QueryFilter& filter) const {
    checkRay("castRayClosest", origin, translation);
    const Impl& w = *impl_;
    std::optional<RayResult> best;
    RayCastInput input{origin, translation, 1.0f};
    for (BodyType type : kAllTypes) {
        w.broadPhase.tree(type).rayCast(
            input, filter.maskBits,
            [&](const RayCastInput& clipped, int, std::uint64_t userData) -> float {
                auto index = static_cast<int>(userData);
                const detail::Shape& shape = w.shape(index);
                if (!passes(shape, filter)) {
                    return clipped.maxFraction;
                }
                std::optional<RayResult> hit =
                    firstHit(shape, w.body(shape.body).transform, clipped, filter.ignoreBackFaces);
                if (!hit || hit->fraction > clipped.maxFraction) {
                    return clipped.maxFraction;
                }
                hit->shape = w.shapeId(index);
                best = hit;
                return hit->fraction;
            });
        if (best) {
            input.maxFraction = best->fraction;
        }
    }
    return best;
}

std::vector<RayResult> World::castRayAll(Vec2 origin, Vec2 translation,
                                         const QueryFilter& filter) const {
    checkRay("castRayAll", origin, translation);
    const Impl& w = *impl_;
    std::vector<RayResult> hits;
    RayCastInput input{origin, translation, 1.0f};
    for (BodyType type : kAllTypes) {
        w.broadPhase.tree(type).rayCast(
            input, filter.maskBits,
            [&](const RayCastInput& clipped, int, std::uint64_t userData) -> float {
                auto index = static_cast<int>(userData);
                const detail::Shape& shape = w.shape(index);
                if (!passes(shape, filter)) {
                    return clipped.maxFraction;
                }
                const Transform& xf = w.body(shape.body).transform;
                if (std::optional<RayResult> hit = entryHit(shape, xf, clipped)) {
                    hit->shape = w.shapeId(index);
                    hits.push_back(*hit);
                }
                if (!filter.ignoreBackFaces) {
                    if (std::optional<RayResult> hit = exitHit(shape, xf, clipped)) {
                        hit->shape = w.shapeId(index);
                        hits.push_back(*hit);
                    }
                }
                return clipped.maxFraction;
            });
    }
    std::sort(hits.begin(), hits.end(), [](const RayResult& a, const RayResult& b) {
        if (a.fraction != b.fraction) {
            return a.fraction < b.fraction;
        }
        if (a.shape.index1 != b.shape.index1) {
            return a.shape.index1 < b.shape.index1;
        }
        return !a.exit && b.exit;
    });
    return hits;
}

std::optional<RayResult> World::rayCastShape(ShapeId id, Vec2 origin, Vec2 translation,
                                             bool ignoreBackFaces) const {
    const Impl& w = *impl_;
    int index = w.require(id, "rayCastShape");
    checkRay("rayCastShape", origin, translation);
    const detail::Shape& shape = w.shape(index);
    std::optional<RayResult> hit =
        firstHit(shape, w.body(shape.body).transform, {origin, translation, 1.0f}, ignoreBackFaces);
    if (hit) {
        hit->shape = id;
    }
    return hit;
}

void World::overlapAabb(const Aabb& box, const QueryFilter& filter,
                        FunctionRef<bool(ShapeId)> callback) const {
    checkBox("overlapAabb", box);
    const Impl& w = *impl_;
    Impl::CallbackLock lock(w, "overlapAabb");
    bool go = true;
    for (BodyType type : kAllTypes) {
        w.broadPhase.tree(type).query(box, filter.maskBits, [&](int, std::uint64_t userData) {
            auto index = static_cast<int>(userData);
            const detail::Shape& shape = w.shape(index);
            // The tree holds fat boxes; report only shapes whose tight box overlaps.
            if (passes(shape, filter) && overlaps(shape.aabb, box)) {
                go = callback(w.shapeId(index));
            }
            return go;
        });
        if (!go) {
            return;
        }
    }
}

std::vector<ShapeId> World::overlapAabb(const Aabb& box, const QueryFilter& filter) const {
    checkBox("overlapAabb", box);
    std::vector<ShapeId> result;
    overlapAabb(box, filter, [&](ShapeId id) {
        result.push_back(id);
        return true;
    });
    std::sort(result.begin(), result.end(),
              [](ShapeId a, ShapeId b) { return a.index1 < b.index1; });
    return result;
}

std::vector<ShapeId> World::overlapPoint(Vec2 point, const QueryFilter& filter) const {
    check::requireFinite("overlapPoint", "point", point);
    const Impl& w = *impl_;
    std::vector<ShapeId> result;
    Aabb box{point, point};
    for (BodyType type : kAllTypes) {
        w.broadPhase.tree(type).query(box, filter.maskBits, [&](int, std::uint64_t userData) {
            auto index = static_cast<int>(userData);
            const detail::Shape& shape = w.shape(index);
            if (passes(shape, filter) &&
                testPoint(shape.geometry, invTransformPoint(w.body(shape.body).transform, point))) {
                result.push_back(w.shapeId(index));
            }
            return true;
        });
    }
    std::sort(result.begin(), result.end(),
              [](ShapeId a, ShapeId b) { return a.index1 < b.index1; });
    return result;
}

std::optional<RayResult> World::castShape(const ShapeGeometry& geometry, const Transform& transform,
                                          Vec2 translation, const QueryFilter& filter) const {
    const char* fn = "castShape";
    validate(geometry, "physics::World::castShape()");
    check::requirePosition(fn, "transform.p", transform.p);
    if (!isFinite(transform.q.c) || !isFinite(transform.q.s) ||
        std::abs(transform.q.c * transform.q.c + transform.q.s * transform.q.s - 1.0f) > 1e-3f) {
        check::fail(fn, "transform.q must be a unit rotation (c^2 + s^2 = 1), got (" +
                            check::text(transform.q.c) + ", " + check::text(transform.q.s) + ")");
    }
    checkRay(fn, transform.p, translation);

    const Impl& w = *impl_;
    ShapeCastPairInput input;
    input.proxyB = makeProxy(geometry);
    input.transformB = transform;
    input.translationB = translation;
    input.maxFraction = 1.0f;

    // Candidates come from one tree query over the box the shape sweeps; each candidate's box,
    // grown by the moving box's half-extents, must also meet the path of the moving box's centre
    // (a slab test) before the exact cast runs.
    Aabb start = computeAabb(geometry, transform);
    Aabb end{start.lower + translation, start.upper + translation};
    Aabb swept = unionOf(start, end);
    swept.lower -= Vec2(kLinearSlop, kLinearSlop);
    swept.upper += Vec2(kLinearSlop, kLinearSlop);
    Vec2 center = 0.5f * (start.lower + start.upper);
    // Grown by the slop because shapeCast() reports a hit slightly before the surfaces touch.
    Vec2 half = 0.5f * (start.upper - start.lower) + Vec2(kLinearSlop, kLinearSlop);

    std::optional<RayResult> best;
    for (BodyType type : kAllTypes) {
        w.broadPhase.tree(type).query(swept, filter.maskBits, [&](int, std::uint64_t userData) {
            auto index = static_cast<int>(userData);
            const detail::Shape& shape = w.shape(index);
            if (!passes(shape, filter) ||
                !segmentMeetsBox(center, translation, input.maxFraction,
                                 {shape.aabb.lower - half, shape.aabb.upper + half})) {
                return true;
            }
            input.proxyA = makeProxy(shape.geometry);
            input.transformA = w.body(shape.body).transform;
            if (const auto* chain = std::get_if<ChainSegment>(&shape.geometry)) {
                // One-sided: seen only by a shape in front of it moving against its normal.
                const Segment& seg = chain->segment;
                const Vec2 normal = rotate(input.transformA.q, rightPerp(seg.point2 - seg.point1));
                const Vec2 p1 = transformPoint(input.transformA, seg.point1);
                if (dot(center - p1, normal) < 0.0f || dot(translation, normal) >= 0.0f) {
                    return true;
                }
            }
            CastOutput out = shapeCast(input);
            if (out.hit && (!best || out.fraction < best->fraction)) {
                best = RayResult{w.shapeId(index), out.point, out.normal, out.fraction, false};
                input.maxFraction = out.fraction;
            }
            return true;
        });
    }
    return best;
}

} // namespace e2d::physics
