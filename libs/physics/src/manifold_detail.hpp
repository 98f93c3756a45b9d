// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/physics/manifold.hpp>

namespace e2d::physics::detail {

// Moves a manifold computed in A's local frame to world space. On entry each point's `point`
// holds its position in A's frame; on exit `point` is the world point and the anchors are
// relative to each transform's origin along world axes, as ManifoldPoint documents.
inline Manifold localToWorld(Manifold m, const Transform& xfA, const Transform& xfB) {
    m.normal = rotate(xfA.q, m.normal);
    Vec2 shift = xfA.p - xfB.p;
    for (int i = 0; i < m.pointCount; ++i) {
        ManifoldPoint& mp = m.points[i];
        mp.anchorA = rotate(xfA.q, mp.point);
        mp.anchorB = mp.anchorA + shift;
        mp.point = mp.anchorA + xfA.p;
    }
    return m;
}

// A manifold's A and B swapped: the normal flips, the anchors and the two halves of each
// feature id trade places, so ids keep the (feature of A, feature of B) layout.
inline Manifold swapped(Manifold m) {
    m.normal = -m.normal;
    for (int i = 0; i < m.pointCount; ++i) {
        ManifoldPoint& mp = m.points[i];
        Vec2 anchor = mp.anchorA;
        mp.anchorA = mp.anchorB;
        mp.anchorB = anchor;
        mp.id = static_cast<std::uint16_t>((mp.id >> 8) | ((mp.id & 0xFF) << 8));
    }
    return m;
}

} // namespace e2d::physics::detail
