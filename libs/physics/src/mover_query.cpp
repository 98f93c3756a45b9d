// SPDX-License-Identifier: MIT
#include "mover_query.hpp"

#include <e2d/physics/distance.hpp>

#include <algorithm>

namespace e2d::physics::detail {

namespace {

// Closer cores than this have no direction between them (see DistanceOutput::normal), metres.
constexpr float kCoresTouching = 1.0e-6f;
// A cast that starts within skin of a shape starts this far from it instead, so that it reports
// a hit only when the move would take it deeper (shapeCast() reports contact below
// kShapeCastTolerance, which this must exceed).
constexpr float kEncroachGap = 2.0f * kShapeCastTolerance;

ShapeProxy capsuleProxy(const Capsule& capsule, Vec2 position, float radius) {
    ShapeProxy proxy;
    proxy.points[0] = capsule.center1 + position;
    proxy.points[1] = capsule.center2 + position;
    proxy.count = 2;
    proxy.radius = radius;
    return proxy;
}

void gatherCandidates(const MoverQuery& query, Aabb box, std::vector<ShapeId>& candidates) {
    candidates.clear();
    QueryFilter filter = query.filter;
    filter.includeSensors = false;
    query.world->overlapAabb(box, filter, [&](ShapeId id) {
        candidates.push_back(id);
        return true;
    });
}

// A chain segment is solid on its front only: whether `point` is behind it, and its front
// normal (not normalised; only signs are read).
bool behindChain(const ChainSegment& chain, const Transform& xf, Vec2 point, Vec2* front) {
    const Segment& seg = chain.segment;
    *front = rotate(xf.q, rightPerp(seg.point2 - seg.point1));
    return dot(point - transformPoint(xf, seg.point1), *front) < 0.0f;
}

bool accepted(const MoverQuery& query, ShapeId shape, Vec2 normal) {
    return query.contactFilter == nullptr || !*query.contactFilter ||
           (*query.contactFilter)(shape, normal);
}

} // namespace

void collideMover(const MoverQuery& query, Vec2 position, float reach,
                  std::vector<MoverContact>& planes, std::vector<ShapeId>& candidates) {
    planes.clear();
    const World& world = *query.world;
    Aabb box = computeAabb(query.capsule, Transform{position, {}});
    box.lower -= Vec2(reach, reach);
    box.upper += Vec2(reach, reach);
    gatherCandidates(query, box, candidates);
    const Vec2 center = position + 0.5f * (query.capsule.center1 + query.capsule.center2);

    DistanceInput input;
    input.proxyB = capsuleProxy(query.capsule, position, query.capsule.radius);
    input.useRadii = false;
    for (ShapeId id : candidates) {
        const BodyId body = world.shapeBody(id);
        if (body == query.ignoreBody) {
            continue;
        }
        const ShapeGeometry& geometry = world.shapeGeometry(id);
        input.transformA = world.transform(body);
        if (const auto* chain = std::get_if<ChainSegment>(&geometry)) {
            Vec2 front;
            if (behindChain(*chain, input.transformA, center, &front)) {
                continue;
            }
        }
        input.proxyA = makeProxy(geometry);
        const float radii = input.proxyA.radius + query.capsule.radius;
        MoverContact contact;
        const DistanceOutput cores = shapeDistance(input);
        if (cores.distance > kCoresTouching) {
            contact.separation = cores.distance - radii;
            contact.normal = cores.normal;
            contact.point = cores.pointA + input.proxyA.radius * cores.normal;
        } else {
            // The cores cross: only the penetration axis says which way is out.
            DistanceInput rounded = input;
            rounded.useRadii = true;
            const PenetrationOutput deep = penetration(rounded);
            contact.separation = -deep.depth;
            contact.normal = deep.normal;
            contact.point = deep.pointA;
        }
        if (contact.separation > reach || !accepted(query, id, contact.normal)) {
            continue;
        }
        contact.shape = id;
        contact.body = body;
        planes.push_back(contact);
    }
}

float castMover(const MoverQuery& query, Vec2 position, Vec2 translation,
                std::vector<ShapeId>& candidates) {
    const World& world = *query.world;
    const Capsule& capsule = query.capsule;
    const Aabb start = computeAabb(capsule, Transform{position, {}});
    const float margin = query.skin + kLinearSlop;
    Aabb box = unionOf(start, {start.lower + translation, start.upper + translation});
    box.lower -= Vec2(margin, margin);
    box.upper += Vec2(margin, margin);
    gatherCandidates(query, box, candidates);
    const Vec2 center = position + 0.5f * (capsule.center1 + capsule.center2);

    float best = 1.0f;
    DistanceInput gap;
    gap.proxyB = capsuleProxy(capsule, position, 0.0f);
    gap.useRadii = false;
    ShapeCastPairInput cast;
    cast.translationB = translation;
    for (ShapeId id : candidates) {
        const BodyId body = world.shapeBody(id);
        if (body == query.ignoreBody) {
            continue;
        }
        const ShapeGeometry& geometry = world.shapeGeometry(id);
        const Transform xf = world.transform(body);
        if (const auto* chain = std::get_if<ChainSegment>(&geometry)) {
            Vec2 front;
            if (behindChain(*chain, xf, center, &front) || dot(translation, front) >= 0.0f) {
                continue;
            }
        }
        gap.proxyA = makeProxy(geometry);
        gap.transformA = xf;
        const float cores = shapeDistance(gap).distance;
        const float shapeRadius = gap.proxyA.radius;
        const float separation = cores - shapeRadius - capsule.radius;
        // Clear of the shape: stop `skin` short of it. Within skin: stop only deeper than now.
        float radius = capsule.radius + query.skin;
        if (separation < query.skin + kEncroachGap) {
            radius = cores - shapeRadius - kEncroachGap;
            if (radius < 0.0f) {
                continue; // too deep to cast from; the planes push it out
            }
        }
        cast.proxyA = gap.proxyA;
        cast.transformA = xf;
        cast.proxyB = capsuleProxy(capsule, position, radius);
        cast.maxFraction = best;
        const CastOutput out = shapeCast(cast);
        if (out.hit) {
            if (out.fraction < best && accepted(query, id, out.normal)) {
                best = out.fraction;
            }
        } else if (out.iterations >= kMaxShapeCastIterations) {
            // A grazing approach that did not converge: only this much is known to be free.
            best = std::min(best, out.fraction);
        }
    }
    return best;
}

} // namespace e2d::physics::detail
