// SPDX-License-Identifier: MIT
#include <e2d/physics/manifold.hpp>

#include "manifold_detail.hpp"

namespace e2d::physics {
namespace {

Manifold collidePolygonPair(const Polygon& a, const Transform& xfA, const Polygon& b,
                            const Transform& xfB, CollisionAlgorithm algorithm, float margin) {
    return algorithm == CollisionAlgorithm::GjkEpa ? collidePolygonsGjkEpa(a, xfA, b, xfB, margin)
                                                   : collidePolygons(a, xfA, b, xfB, margin);
}

} // namespace

Manifold collide(const ShapeGeometry& a, const Transform& xfA, const ShapeGeometry& b,
                 const Transform& xfB, CollisionAlgorithm algorithm, float margin) {
    // Each pair routine takes its shapes in one order; the reverse order runs it with the
    // arguments swapped and swaps the result back, so the normal always points from a to b.
    constexpr auto kCircle = static_cast<int>(ShapeType::Circle);
    constexpr auto kCapsule = static_cast<int>(ShapeType::Capsule);
    constexpr auto kSegment = static_cast<int>(ShapeType::Segment);
    constexpr auto kPolygon = static_cast<int>(ShapeType::Polygon);
    constexpr int kTypes = 4;
    const int ta = static_cast<int>(a.index());
    const int tb = static_cast<int>(b.index());
    // Chain segments (one-sided, with neighbours) have their own routine.
    constexpr auto kChain = static_cast<int>(ShapeType::ChainSegment);
    if (ta == kChain) {
        return collideChainSegment(std::get<ChainSegment>(a), xfA, b, xfB, margin);
    }
    if (tb == kChain) {
        return detail::swapped(collideChainSegment(std::get<ChainSegment>(b), xfB, a, xfA, margin));
    }
    switch (ta * kTypes + tb) {
    case kCircle* kTypes + kCircle:
        return collideCircles(std::get<Circle>(a), xfA, std::get<Circle>(b), xfB, margin);
    case kCircle* kTypes + kCapsule:
        return detail::swapped(
            collideCapsuleAndCircle(std::get<Capsule>(b), xfB, std::get<Circle>(a), xfA, margin));
    case kCircle* kTypes + kSegment:
        return detail::swapped(
            collideSegmentAndCircle(std::get<Segment>(b), xfB, std::get<Circle>(a), xfA, margin));
    case kCircle* kTypes + kPolygon:
        return detail::swapped(
            collidePolygonAndCircle(std::get<Polygon>(b), xfB, std::get<Circle>(a), xfA, margin));

    case kCapsule* kTypes + kCircle:
        return collideCapsuleAndCircle(std::get<Capsule>(a), xfA, std::get<Circle>(b), xfB, margin);
    case kCapsule* kTypes + kCapsule:
        return collideCapsules(std::get<Capsule>(a), xfA, std::get<Capsule>(b), xfB, margin);
    case kCapsule* kTypes + kSegment:
        return detail::swapped(
            collideSegmentAndCapsule(std::get<Segment>(b), xfB, std::get<Capsule>(a), xfA, margin));
    case kCapsule* kTypes + kPolygon:
        return detail::swapped(
            collidePolygonAndCapsule(std::get<Polygon>(b), xfB, std::get<Capsule>(a), xfA, margin));

    case kSegment* kTypes + kCircle:
        return collideSegmentAndCircle(std::get<Segment>(a), xfA, std::get<Circle>(b), xfB, margin);
    case kSegment* kTypes + kCapsule:
        return collideSegmentAndCapsule(std::get<Segment>(a), xfA, std::get<Capsule>(b), xfB,
                                        margin);
    case kSegment* kTypes + kSegment:
        return Manifold{}; // segments are static level geometry and have no area to push apart
    case kSegment* kTypes + kPolygon:
        return collideSegmentAndPolygon(std::get<Segment>(a), xfA, std::get<Polygon>(b), xfB,
                                        margin);

    case kPolygon* kTypes + kCircle:
        return collidePolygonAndCircle(std::get<Polygon>(a), xfA, std::get<Circle>(b), xfB, margin);
    case kPolygon* kTypes + kCapsule:
        return collidePolygonAndCapsule(std::get<Polygon>(a), xfA, std::get<Capsule>(b), xfB,
                                        margin);
    case kPolygon* kTypes + kSegment:
        return detail::swapped(
            collideSegmentAndPolygon(std::get<Segment>(b), xfB, std::get<Polygon>(a), xfA, margin));
    case kPolygon* kTypes + kPolygon:
        return collidePolygonPair(std::get<Polygon>(a), xfA, std::get<Polygon>(b), xfB, algorithm,
                                  margin);
    default:
        return Manifold{};
    }
}

} // namespace e2d::physics
