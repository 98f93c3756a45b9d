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

// A shape near the mover that may block it.
struct Candidate {
    ShapeId id;
    BodyId body;
    const ShapeGeometry* geometry = nullptr;
    Transform transform{};
    // A chain segment's front normal (not normalised; only signs are read), else zero.
    Vec2 front{0.0f, 0.0f};
};

// Calls `visit(candidate)` for each shape whose box meets `box` and that can block the mover:
// seen by the filter, not a sensor, not on the ignored body, and not a one-sided chain segment
// the mover's centre is behind.
template <class Visit>
void forEachCandidate(const MoverQuery& query, const Aabb& box, Vec2 center,
                      std::vector<ShapeId>& candidates, Visit&& visit) {
    const World& world = *query.world;
    candidates.clear();
    QueryFilter filter = query.filter;
    filter.includeSensors = false;
    world.overlapAabb(box, filter, [&](ShapeId id) {
        candidates.push_back(id);
        return true;
    });
    for (ShapeId id : candidates) {
        Candidate c{id, world.shapeBody(id)};
        if (c.body == query.ignoreBody) {
            continue;
        }
        c.geometry = &world.shapeGeometry(id);
        c.transform = world.transform(c.body);
        if (const auto* chain = std::get_if<ChainSegment>(c.geometry)) {
            const Segment& seg = chain->segment;
            c.front = rotate(c.transform.q, rightPerp(seg.point2 - seg.point1));
            if (dot(center - transformPoint(c.transform, seg.point1), c.front) < 0.0f) {
                continue;
            }
        }
        visit(c);
    }
}

// Whether a contact on a chain segment is one at an end of it, beyond its face (the normal
// leans past the end), where the chain goes on flat or turns up (towards its front): the
// neighbouring segment's face already holds the mover there, and the corner's tilted normal would
// make it bump over every seam. Where the chain turns down (a hilltop) the corner is real and kept.
bool coveredByNeighbour(const ChainSegment& chain, const Transform& xf,
                        const MoverContact& contact) {
    const Segment& seg = chain.segment;
    const Vec2 edge = seg.point2 - seg.point1;
    const Vec2 normal = invRotate(xf.q, contact.normal);
    const float past = dot(normal, edge) / length(edge); // < 0 beyond point1, > 0 beyond point2
    constexpr float kLean = 1.0e-4f;
    constexpr float kStraight = 1.0e-3f; // sine of the turn below which the chain goes on flat
    if (past < -kLean && chain.hasGhost1) {
        const Vec2 before = seg.point1 - chain.ghost1;
        return cross(before, edge) <= kStraight * length(before) * length(edge);
    }
    if (past > kLean && chain.hasGhost2) {
        const Vec2 after = chain.ghost2 - seg.point2;
        return cross(edge, after) <= kStraight * length(edge) * length(after);
    }
    return false;
}

bool accepted(const MoverQuery& query, const MoverContact& contact) {
    return query.contactFilter == nullptr || !*query.contactFilter ||
           (*query.contactFilter)(contact);
}

} // namespace

MoverSurface surfaceOf(const MoverQuery& query, Vec2 normal) {
    const float facing = dot(normal, query.up);
    return facing >= query.cosMaxSlope    ? MoverSurface::Ground
           : facing <= -query.cosMaxSlope ? MoverSurface::Ceiling
                                          : MoverSurface::Wall;
}

void collideMover(const MoverQuery& query, Vec2 position, float reach,
                  std::vector<MoverContact>& planes, std::vector<ShapeId>& candidates) {
    planes.clear();
    Aabb box = computeAabb(query.capsule, Transform{position, {}});
    box.lower -= Vec2(reach, reach);
    box.upper += Vec2(reach, reach);
    const Vec2 center = position + 0.5f * (query.capsule.center1 + query.capsule.center2);

    DistanceInput input;
    input.proxyB = capsuleProxy(query.capsule, position, query.capsule.radius);
    input.useRadii = false;
    forEachCandidate(query, box, center, candidates, [&](const Candidate& candidate) {
        input.transformA = candidate.transform;
        input.proxyA = makeProxy(*candidate.geometry);
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
        if (const auto* chain = std::get_if<ChainSegment>(candidate.geometry);
            chain != nullptr && coveredByNeighbour(*chain, candidate.transform, contact)) {
            return;
        }
        contact.shape = candidate.id;
        contact.body = candidate.body;
        contact.surface = surfaceOf(query, contact.normal);
        if (contact.separation <= reach && accepted(query, contact)) {
            planes.push_back(contact);
        }
    });
}

float castMover(const MoverQuery& query, Vec2 position, Vec2 translation,
                std::vector<ShapeId>& candidates) {
    const Capsule& capsule = query.capsule;
    const Aabb start = computeAabb(capsule, Transform{position, {}});
    const float margin = query.skin + kLinearSlop;
    Aabb box = unionOf(start, {start.lower + translation, start.upper + translation});
    box.lower -= Vec2(margin, margin);
    box.upper += Vec2(margin, margin);
    const Vec2 center = position + 0.5f * (capsule.center1 + capsule.center2);

    float best = 1.0f;
    DistanceInput gap;
    gap.proxyB = capsuleProxy(capsule, position, 0.0f);
    gap.useRadii = false;
    ShapeCastPairInput cast;
    cast.translationB = translation;
    forEachCandidate(query, box, center, candidates, [&](const Candidate& candidate) {
        if (dot(translation, candidate.front) > 0.0f) {
            return; // leaving a chain segment's front
        }
        gap.proxyA = makeProxy(*candidate.geometry);
        gap.transformA = candidate.transform;
        const float cores = shapeDistance(gap).distance;
        const float shapeRadius = gap.proxyA.radius;
        const float separation = cores - shapeRadius - capsule.radius;
        // Clear of the shape: stop `skin` short of it. Within skin: stop only deeper than now.
        float radius = capsule.radius + query.skin;
        if (separation < query.skin + kEncroachGap) {
            radius = cores - shapeRadius - kEncroachGap;
            if (radius < 0.0f) {
                return; // too deep to cast from; the planes push it out
            }
        }
        cast.proxyA = gap.proxyA;
        cast.transformA = candidate.transform;
        cast.proxyB = capsuleProxy(capsule, position, radius);
        cast.maxFraction = best;
        const CastOutput out = shapeCast(cast);
        if (out.hit) {
            const MoverContact met{candidate.id, candidate.body, out.point,
                                   out.normal,   0.0f,           surfaceOf(query, out.normal)};
            if (out.fraction < best && accepted(query, met)) {
                best = out.fraction;
            }
        } else if (out.iterations >= kMaxShapeCastIterations) {
            // A grazing approach that did not converge: only this much is known to be free.
            best = std::min(best, out.fraction);
        }
    });
    return best;
}

} // namespace e2d::physics::detail
