// SPDX-License-Identifier: MIT
// Uses the installed physics library: two boxes, a ray, a manifold.
#include <e2d/physics/geometry.hpp>
#include <e2d/physics/manifold.hpp>

#include <cstdio>

int main() {
    using namespace e2d::physics;
    const Polygon box = makeBox(0.5f, 0.5f);
    const Transform a{};
    const Transform b{{0.9f, 0.0f}, Rot{}};
    const Manifold m = collidePolygons(box, a, box, b);
    if (m.pointCount != 2 || m.normal.x < 0.99f) {
        std::fprintf(stderr, "consumer: unexpected manifold (%d points)\n", m.pointCount);
        return 1;
    }
    std::printf("consumer: two boxes overlap by %.3f m at %d points\n", -m.points[0].separation,
                m.pointCount);
    return 0;
}
