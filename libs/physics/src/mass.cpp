// SPDX-License-Identifier: MIT
#include <e2d/physics/geometry.hpp>

#include <e2d/core/error_text.hpp>

#include <numbers>

namespace e2d::physics {
namespace {

void checkDensity(float density) {
    if (!isWithinHuge(density) || density < 0.0f) {
        core::throwError("physics::computeMass()",
                         "density must be finite and in [0, kHuge (" + core::formatNumber(kHuge) +
                             " kg/m^2)], got " + core::formatNumber(density));
    }
}

// Area, first moment and polar second moment about a reference point, summed over parts.
struct Moments {
    float area = 0.0f;
    Vec2 first{0.0f, 0.0f};
    float second = 0.0f;

    // A part of `area` whose centroid is `c` (relative to the reference) and whose polar moment
    // about its own centroid is `ownSecond` (per unit density).
    void add(float partArea, Vec2 c, float ownSecond) {
        area += partArea;
        first += partArea * c;
        second += ownSecond + partArea * dot(c, c);
    }

    MassData toMassData(float density, Vec2 reference) const {
        MassData md;
        md.mass = density * area;
        Vec2 c = first / area;
        md.center = reference + c;
        md.rotationalInertia = density * (second - area * dot(c, c));
        return md;
    }
};

} // namespace

MassData computeMass(const Circle& shape, float density) {
    checkDensity(density);
    float rr = shape.radius * shape.radius;
    MassData md;
    md.mass = density * std::numbers::pi_v<float> * rr;
    md.center = shape.center;
    md.rotationalInertia = 0.5f * md.mass * rr;
    return md;
}

MassData computeMass(const Capsule& shape, float density) {
    checkDensity(density);
    // A rectangle 2r x L plus two half discs. Each half disc's centroid lies 4r/(3 pi) beyond
    // its cap centre; the parallel axis theorem moves it to the capsule centre, which sums to
    // m_disc * (r^2/2 + L^2/4 + L * 4r/(3 pi)) for the pair.
    constexpr float kPi = std::numbers::pi_v<float>;
    float r = shape.radius;
    float len = distance(shape.center1, shape.center2);
    float rectMass = density * 2.0f * r * len;
    float discMass = density * kPi * r * r;
    float d = 4.0f * r / (3.0f * kPi);
    MassData md;
    md.mass = rectMass + discMass;
    md.center = 0.5f * (shape.center1 + shape.center2);
    md.rotationalInertia = rectMass * (len * len + 4.0f * r * r) / 12.0f +
                           discMass * (0.5f * r * r + 0.25f * len * len + len * d);
    return md;
}

MassData computeMass(const Polygon& shape, float density) {
    checkDensity(density);
    const int n = shape.count;
    // Sums relative to vertex 0 keep the numbers small when the polygon is far from the origin.
    const Vec2 reference = shape.vertices[0];
    Moments m;
    for (int i = 1; i + 1 < n; ++i) {
        // Triangle (reference, v_i, v_i+1): area D/2, centroid (e1 + e2)/3, polar moment about
        // the reference D/12 (e1.e1 + e1.e2 + e2.e2).
        Vec2 e1 = shape.vertices[i] - reference;
        Vec2 e2 = shape.vertices[i + 1] - reference;
        float d = cross(e1, e2);
        float area = 0.5f * d;
        Vec2 c = (e1 + e2) / 3.0f;
        float aboutReference = d / 12.0f * (dot(e1, e1) + dot(e1, e2) + dot(e2, e2));
        m.add(area, c, aboutReference - area * dot(c, c));
    }

    const float r = shape.radius;
    if (r > 0.0f) {
        // Exact, not approximated: a rounded polygon is its core, plus a rectangle of depth r
        // outside each edge, plus a circular sector at each vertex (the sectors add up to one
        // disc).
        for (int i = 0; i < n; ++i) {
            Vec2 v1 = shape.vertices[i];
            Vec2 v2 = shape.vertices[i + 1 < n ? i + 1 : 0];
            float len = distance(v1, v2);
            float area = len * r;
            Vec2 c = 0.5f * (v1 + v2) + (0.5f * r) * shape.normals[i] - reference;
            m.add(area, c, area * (len * len + r * r) / 12.0f);
        }
        for (int i = 0; i < n; ++i) {
            Vec2 n1 = shape.normals[i > 0 ? i - 1 : n - 1];
            Vec2 n2 = shape.normals[i];
            float angle = std::atan2(cross(n1, n2), dot(n1, n2));
            float area = 0.5f * angle * r * r;
            // Sector centroid on the bisector, 4 r sin(angle/2) / (3 angle) from the apex.
            float half = 0.5f * angle;
            float d = half > 1.0e-6f ? 4.0f * r * std::sin(half) / (3.0f * angle) : 2.0f * r / 3.0f;
            Vec2 c = shape.vertices[i] + d * normalize(n1 + n2) - reference;
            m.add(area, c, area * (0.5f * r * r - d * d));
        }
    }
    return m.toMassData(density, reference);
}

MassData computeMass(const ShapeGeometry& shape, float density) {
    switch (typeOf(shape)) {
    case ShapeType::Circle:
        return computeMass(std::get<Circle>(shape), density);
    case ShapeType::Capsule:
        return computeMass(std::get<Capsule>(shape), density);
    case ShapeType::Segment: {
        checkDensity(density);
        const auto& segment = std::get<Segment>(shape);
        MassData md;
        md.center = 0.5f * (segment.point1 + segment.point2);
        return md;
    }
    case ShapeType::Polygon:
        return computeMass(std::get<Polygon>(shape), density);
    case ShapeType::ChainSegment: {
        checkDensity(density);
        const Segment& segment = std::get<ChainSegment>(shape).segment;
        MassData md;
        md.center = 0.5f * (segment.point1 + segment.point2);
        return md;
    }
    }
    return {};
}

} // namespace e2d::physics
