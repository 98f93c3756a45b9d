// SPDX-License-Identifier: MIT
#include <e2d/render/drawer.hpp>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

using e2d::render::DebugVertex;
using e2d::render::Drawer;
using e2d::render::DrawSpace;
using e2d::render::packColor;

namespace {

double signedArea(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    return 0.5 * ((static_cast<double>(b.x) - a.x) * (static_cast<double>(c.y) - a.y) -
                  (static_cast<double>(b.y) - a.y) * (static_cast<double>(c.x) - a.x));
}

// Sum of triangle areas; every triangle must be counter-clockwise.
double filledArea(const Drawer& d) {
    double total = 0.0;
    const auto v = d.triangles();
    for (std::size_t i = 0; i + 2 < v.size(); i += 3) {
        const double a = signedArea(v[i].position, v[i + 1].position, v[i + 2].position);
        EXPECT_GE(a, 0.0) << "triangle " << i / 3 << " is clockwise";
        total += a;
    }
    return total;
}

} // namespace

TEST(Drawer, PackColorIsRgba8RedLowest) {
    EXPECT_EQ(packColor({1.0f, 0.0f, 0.0f, 1.0f}), 0xFF0000FFu);
    EXPECT_EQ(packColor({0.0f, 0.0f, 1.0f, 0.5f}), 0x80FF0000u);
    EXPECT_EQ(packColor({2.0f, -1.0f, NAN, 1.0f}), 0xFF0000FFu);
}

TEST(Drawer, OutlinesAreOneLinePerEdge) {
    Drawer d;
    d.line({0, 0}, {1, 1}, {1, 1, 1, 1}, 3.0f, DrawSpace::Screen);
    d.rect({0, 0}, {4, 2}, {1, 0, 0, 1});
    d.circle({0, 0}, 10.0f, {0, 1, 0, 1}, 1.0f, DrawSpace::World, 24);
    const glm::vec2 tri[] = {{0, 0}, {1, 0}, {0, 1}};
    d.polygon(tri, {0, 0, 1, 1});
    ASSERT_EQ(d.lines().size(), 1u + 4u + 24u + 3u);
    EXPECT_EQ(d.lines()[0].width, 3.0f);
    EXPECT_EQ(d.lines()[0].space, DrawSpace::Screen);
    EXPECT_EQ(d.lines()[1].a, glm::vec2(0, 0));
    EXPECT_EQ(d.lines()[2].a, glm::vec2(4, 0));
    EXPECT_EQ(d.lines()[4].b, glm::vec2(0, 0)); // closed
    // Circle points lie on the circle.
    for (std::size_t i = 5; i < 29; ++i) {
        EXPECT_NEAR(glm::length(d.lines()[i].a), 10.0f, 1e-4f);
    }
    EXPECT_TRUE(d.triangles().empty());
    d.clear();
    EXPECT_TRUE(d.empty());
}

TEST(Drawer, FilledShapesCoverTheirArea) {
    Drawer d;
    d.fillRect({1, 1}, {4, 3}, {1, 1, 1, 1});
    EXPECT_DOUBLE_EQ(filledArea(d), 6.0);
    d.clear();
    const int n = 64;
    d.fillCircle({5, 5}, 2.0f, {1, 1, 1, 1}, DrawSpace::World, n);
    // A regular n-gon inscribed in the circle.
    EXPECT_NEAR(filledArea(d), 0.5 * n * 4.0 * std::sin(2.0 * std::numbers::pi / n), 1e-4);
    EXPECT_EQ(d.triangles().size(), static_cast<std::size_t>(3 * n));
}

TEST(Drawer, ConcavePolygonsAreTriangulatedInEitherWinding) {
    // An L: 3x3 square minus its top-right 2x2, area 5; and a comb with three teeth.
    const std::vector<glm::vec2> ell = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
    const std::vector<glm::vec2> reversed(ell.rbegin(), ell.rend());
    const std::vector<glm::vec2> comb = {{0, 0}, {5, 0}, {5, 3}, {4, 3}, {4, 1}, {3, 1},
                                         {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
    for (const auto* shape : {&ell, &reversed}) {
        Drawer d;
        d.fillPolygon(*shape, {1, 1, 1, 1});
        EXPECT_DOUBLE_EQ(filledArea(d), 5.0);
        EXPECT_EQ(d.triangles().size(), 3u * (shape->size() - 2));
    }
    Drawer d;
    d.fillPolygon(comb, {1, 1, 1, 1});
    EXPECT_DOUBLE_EQ(filledArea(d), 5.0 + 3.0 * 2.0);
    // Every triangle centroid lies inside the comb (not in a gap between teeth).
    const auto v = d.triangles();
    for (std::size_t i = 0; i < v.size(); i += 3) {
        const glm::vec2 c = (v[i].position + v[i + 1].position + v[i + 2].position) / 3.0f;
        const bool inGap = c.y > 1.0f && ((c.x > 1.0f && c.x < 2.0f) || (c.x > 3.0f && c.x < 4.0f));
        EXPECT_FALSE(inGap) << c.x << ", " << c.y;
    }
}

TEST(Drawer, BadShapesAreSkippedNotThrown) {
    Drawer d;
    const float inf = std::numeric_limits<float>::infinity();
    d.line({0, 0}, {inf, 0}, {1, 1, 1, 1});
    d.line({0, 0}, {1, 0}, {1, 1, 1, 1}, 0.0f);
    d.line({0, 0}, {1, 0}, {1, 1, 1, 1}, NAN);
    d.circle({0, 0}, -1.0f, {1, 1, 1, 1});
    d.fillCircle({0, 0}, NAN, {1, 1, 1, 1});
    const glm::vec2 two[] = {{0, 0}, {1, 1}};
    d.fillPolygon(two, {1, 1, 1, 1});
    const glm::vec2 bad[] = {{0, 0}, {1, 1}, {NAN, 0}};
    d.fillPolygon(bad, {1, 1, 1, 1});
    d.polygon(bad, {1, 1, 1, 1});
    EXPECT_TRUE(d.empty());
    // Degenerate (collinear) and self-intersecting polygons still end without looping forever.
    const glm::vec2 line3[] = {{0, 0}, {1, 0}, {2, 0}};
    d.fillPolygon(line3, {1, 1, 1, 1});
    const glm::vec2 bowtie[] = {{0, 0}, {2, 2}, {2, 0}, {0, 2}};
    d.fillPolygon(bowtie, {1, 1, 1, 1});
    EXPECT_LE(d.triangles().size(), 3u * 3u);
}
