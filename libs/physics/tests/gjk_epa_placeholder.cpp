// SPDX-License-Identifier: MIT
// TEMPORARY, for the wip/geom branch only: collide() refers to collidePolygonsGjkEpa(), which
// the wip/gjk branch defines in src/manifold_gjk_epa.cpp. Delete this file when merging the two
// (the linker then reports a duplicate definition if it is forgotten).
#include <e2d/core/error.hpp>
#include <e2d/physics/manifold.hpp>

namespace e2d::physics {

Manifold collidePolygonsGjkEpa(const Polygon&, const Transform&, const Polygon&, const Transform&,
                               float) {
    throw core::Error("physics::collidePolygonsGjkEpa(): not in this branch (wip/geom placeholder)");
}

} // namespace e2d::physics
