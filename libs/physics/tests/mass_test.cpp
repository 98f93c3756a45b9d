// SPDX-License-Identifier: MIT
#include <e2d/physics/geometry.hpp>

#include "geometry_test_util.hpp"

#include <cmath>
#include <vector>

namespace e2d::physics {
namespace {

using test::errorMessage;
using test::kPi;

TEST(Mass, BoxMatchesTheClosedForm) {
    const float hx = 1.0f, hy = 0.5f, density = 2.0f;
    MassData md = computeMass(makeBox(hx, hy), density);
    const float m = 4.0f * hx * hy * density; // 4
    const float w = 2.0f * hx, h = 2.0f * hy;
    EXPECT_FLOAT_EQ(md.mass, m);
    E2D_EXPECT_VEC2_NEAR(md.center, 0.0f, 0.0f, 1e-6f);
    EXPECT_NEAR(md.rotationalInertia, m * (w * w + h * h) / 12.0f, 1e-5f);
}

TEST(Mass, OffsetRotatedBoxHasItsCentreAtTheOffset) {
    const Vec2 center{2.0f, -1.0f};
    MassData md = computeMass(makeOffsetBox(1.0f, 0.5f, center, 0.3f), 1.0f);
    EXPECT_NEAR(md.mass, 2.0f, 1e-5f);
    E2D_EXPECT_VEC2_NEAR(md.center, center.x, center.y, 1e-5f);
    // Inertia about the centre of mass does not depend on where the box is or how it is turned.
    EXPECT_NEAR(md.rotationalInertia, 2.0f * (4.0f + 1.0f) / 12.0f, 1e-5f);
}

TEST(Mass, BoxFarFromTheOriginKeepsItsPrecision) {
    MassData md = computeMass(makeOffsetBox(0.5f, 0.5f, {5000.0f, -3000.0f}, 0.0f), 1.0f);
    EXPECT_NEAR(md.mass, 1.0f, 1e-6f);
    EXPECT_NEAR(md.rotationalInertia, 1.0f * 2.0f / 12.0f, 1e-5f);
}

TEST(Mass, DiscMatchesTheClosedForm) {
    const float r = 0.5f, density = 3.0f;
    MassData md = computeMass(Circle{{1.0f, -2.0f}, r}, density);
    const float m = density * kPi * r * r;
    EXPECT_FLOAT_EQ(md.mass, m);
    E2D_EXPECT_VEC2_NEAR(md.center, 1.0f, -2.0f, 0.0f);
    EXPECT_FLOAT_EQ(md.rotationalInertia, 0.5f * m * r * r);
}

TEST(Mass, CapsuleIsARectangleAndTwoHalfDiscs) {
    // r = 1, L = 2, density 1. Rectangle 2 x 2: mass 4, I = 4 (2^2 + 2^2) / 12 = 8/3.
    // Two half discs (one disc): mass pi; each centroid 4/(3 pi) beyond its cap centre, so
    // I = pi (r^2/2 + L^2/4 + L * 4r/(3 pi)) = 1.5 pi + 8/3.
    const float expectedMass = 4.0f + kPi;
    const float expectedInertia = 16.0f / 3.0f + 1.5f * kPi;
    for (float angle : {0.0f, 0.7f, 2.0f}) {
        Vec2 u{std::cos(angle), std::sin(angle)};
        Vec2 mid{3.0f, 1.0f};
        MassData md = computeMass(Capsule{mid - u, mid + u, 1.0f}, 1.0f);
        EXPECT_NEAR(md.mass, expectedMass, 1e-5f);
        E2D_EXPECT_VEC2_NEAR(md.center, 3.0f, 1.0f, 1e-6f);
        EXPECT_NEAR(md.rotationalInertia, expectedInertia, 1e-4f);
    }
}

TEST(Mass, RegularPolygonsMatchTheClosedForm) {
    // Regular n-gon, circumradius R: area n/2 R^2 sin(2 pi/n), I = m R^2/6 (1 + 2 cos^2(pi/n)).
    const float radius = 1.5f, density = 2.0f;
    const Vec2 offset{-4.0f, 7.0f};
    for (int n = 3; n <= 8; ++n) {
        std::vector<Vec2> points;
        for (int i = 0; i < n; ++i) {
            float a = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(n) + 0.1f;
            points.push_back(offset + radius * Vec2{std::cos(a), std::sin(a)});
        }
        MassData md = computeMass(makePolygon(points), density);
        const float area = 0.5f * static_cast<float>(n) * radius * radius *
                           std::sin(2.0f * kPi / static_cast<float>(n));
        const float m = density * area;
        const float c = std::cos(kPi / static_cast<float>(n));
        EXPECT_NEAR(md.mass, m, 1e-5f * m) << n;
        E2D_EXPECT_VEC2_NEAR(md.center, offset.x, offset.y, 1e-5f);
        EXPECT_NEAR(md.rotationalInertia, m * radius * radius / 6.0f * (1.0f + 2.0f * c * c),
                    1e-4f * m)
            << n;
    }
}

TEST(Mass, RoundedBoxIsExact) {
    // Core 2hx x 2hy, four side strips of depth r, four quarter discs at the corners. A quarter
    // disc has area pi r^2/4, its centroid 4r/(3 pi) from the corner along both axes, and
    // I = m r^2/2 about the corner.
    const float hx = 1.0f, hy = 0.5f, r = 0.25f, density = 1.5f;
    MassData md = computeMass(makeRoundedBox(hx, hy, r), density);

    float area = 0.0f, inertia = 0.0f;
    auto rect = [&](float w, float h, float cx, float cy) {
        float a = w * h;
        area += a;
        inertia += a * (w * w + h * h) / 12.0f + a * (cx * cx + cy * cy);
    };
    rect(2 * hx, 2 * hy, 0, 0);
    rect(2 * hx, r, 0, hy + r / 2);
    rect(2 * hx, r, 0, -hy - r / 2);
    rect(r, 2 * hy, hx + r / 2, 0);
    rect(r, 2 * hy, -hx - r / 2, 0);
    const float quarter = kPi * r * r / 4.0f;
    const float d = 4.0f * r / (3.0f * kPi);
    for (float sx : {-1.0f, 1.0f}) {
        for (float sy : {-1.0f, 1.0f}) {
            float cx = sx * (hx + d), cy = sy * (hy + d);
            area += quarter;
            inertia += quarter * (r * r / 2.0f - 2.0f * d * d) + quarter * (cx * cx + cy * cy);
        }
    }
    EXPECT_NEAR(md.mass, density * area, 1e-5f);
    EXPECT_NEAR(md.mass, density * (4 * hx * hy + 4 * r * (hx + hy) + kPi * r * r), 1e-5f);
    E2D_EXPECT_VEC2_NEAR(md.center, 0.0f, 0.0f, 1e-6f);
    EXPECT_NEAR(md.rotationalInertia, density * inertia, 1e-5f);
}

TEST(Mass, TinyRoundedBoxTendsToADisc) {
    const float r = 1.0f;
    MassData md = computeMass(makeRoundedBox(1e-3f, 1e-3f, r), 1.0f);
    EXPECT_NEAR(md.mass, kPi * r * r, 1e-2f);
    EXPECT_NEAR(md.rotationalInertia, 0.5f * kPi * r * r * r * r, 1e-2f);
}

TEST(Mass, SegmentsHaveNoMass) {
    MassData md = computeMass(ShapeGeometry{Segment{{0, 0}, {2, 0}}}, 1.0f);
    EXPECT_EQ(md.mass, 0.0f);
    EXPECT_EQ(md.rotationalInertia, 0.0f);
}

TEST(Mass, VariantDispatchesToTheShape) {
    MassData viaVariant = computeMass(ShapeGeometry{makeBox(1.0f, 1.0f)}, 1.0f);
    EXPECT_FLOAT_EQ(viaVariant.mass, 4.0f);
}

TEST(Mass, NegativeOrNonFiniteDensityIsRejected) {
    EXPECT_EQ(
        errorMessage([] { computeMass(makeBox(1.0f, 1.0f), -1.0f); }),
        "physics::computeMass(): density must be finite and in [0, kHuge (500000 kg/m^2)], got -1");
    EXPECT_EQ(errorMessage([] {
                  computeMass(Circle{{0, 0}, 1.0f}, INFINITY);
              }),
              "physics::computeMass(): density must be finite and in [0, kHuge (500000 kg/m^2)], "
              "got inf");
}

} // namespace
} // namespace e2d::physics
