// SPDX-License-Identifier: MIT
#include "canvas.hpp"

#include <e2d/core/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace e2d::assetgen {
namespace {

struct Vec {
    double x = 0;
    double y = 0;
};

std::uint8_t* pixelAt(render::Image& image, int x, int y) {
    return image.pixels.data() +
           (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
            static_cast<std::size_t>(x)) *
               4;
}

std::uint8_t toByte(double v) {
    return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L));
}

// Signed distance from p to a rectangle of half size (hx, hy) centred on the origin whose
// corners are rounded by r: negative inside.
double roundedBoxDistance(Vec p, double hx, double hy, double r) {
    const double qx = std::abs(p.x) - (hx - r);
    const double qy = std::abs(p.y) - (hy - r);
    const double outside = std::hypot(std::max(qx, 0.0), std::max(qy, 0.0));
    return outside + std::min(std::max(qx, qy), 0.0) - r;
}

double segmentDistance(Vec p, Vec a, Vec b) {
    const double abx = b.x - a.x;
    const double aby = b.y - a.y;
    const double len2 = abx * abx + aby * aby;
    double t = len2 > 0 ? ((p.x - a.x) * abx + (p.y - a.y) * aby) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(p.x - (a.x + t * abx), p.y - (a.y + t * aby));
}

} // namespace

Colour mix(Colour a, Colour b, double t) noexcept {
    t = std::clamp(t, 0.0, 1.0);
    auto m = [t](std::uint8_t u, std::uint8_t v) { return toByte(u + (v - u) * t); };
    return {m(a.r, b.r), m(a.g, b.g), m(a.b, b.b), m(a.a, b.a)};
}

Canvas::Canvas(int width, int height, Colour background) {
    if (width <= 0 || height <= 0) {
        throw core::Error("assetgen::Canvas: size must be positive, got " + std::to_string(width) +
                          " x " + std::to_string(height));
    }
    image_.width = width;
    image_.height = height;
    image_.pixels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    fill(background);
}

Colour Canvas::pixel(int x, int y) const {
    if (x < 0 || y < 0 || x >= width() || y >= height()) {
        throw core::Error("assetgen::Canvas::pixel(): (" + std::to_string(x) + ", " +
                          std::to_string(y) + ") is outside the " + std::to_string(width()) +
                          " x " + std::to_string(height()) + " canvas");
    }
    const std::uint8_t* p = image_.at(x, y);
    return {p[0], p[1], p[2], p[3]};
}

void Canvas::fill(Colour colour) {
    for (std::size_t i = 0; i < image_.pixels.size(); i += 4) {
        image_.pixels[i] = colour.r;
        image_.pixels[i + 1] = colour.g;
        image_.pixels[i + 2] = colour.b;
        image_.pixels[i + 3] = colour.a;
    }
}

namespace {

// Blends `shade(p)` weighted by the coverage of the shape whose signed distance is `sdf(p)`
// over the pixels of the box [x0, x1) x [y0, y1). Coverage is 1 - distance over half a pixel
// either side of the edge: a cheap, smooth antialiasing.
template <class Sdf, class Shade>
void paint(render::Image& image, double x0, double y0, double x1, double y1, Sdf sdf, Shade shade) {
    const int ix0 = std::max(0, static_cast<int>(std::floor(x0 - 1)));
    const int iy0 = std::max(0, static_cast<int>(std::floor(y0 - 1)));
    const int ix1 = std::min(image.width, static_cast<int>(std::ceil(x1 + 1)));
    const int iy1 = std::min(image.height, static_cast<int>(std::ceil(y1 + 1)));
    for (int y = iy0; y < iy1; ++y) {
        for (int x = ix0; x < ix1; ++x) {
            const Vec p{x + 0.5, y + 0.5};
            const double coverage = std::clamp(0.5 - sdf(p), 0.0, 1.0);
            if (coverage <= 0) {
                continue;
            }
            const Colour c = shade(p);
            const double sa = c.a / 255.0 * coverage;
            std::uint8_t* d = pixelAt(image, x, y);
            const double da = d[3] / 255.0;
            const double outA = sa + da * (1 - sa);
            if (outA <= 0) {
                continue;
            }
            auto channel = [&](std::uint8_t s, std::uint8_t dst) {
                return toByte((s * sa + dst * da * (1 - sa)) / outA);
            };
            d[0] = channel(c.r, d[0]);
            d[1] = channel(c.g, d[1]);
            d[2] = channel(c.b, d[2]);
            d[3] = toByte(outA * 255.0);
        }
    }
}

auto solid(Colour c) {
    return [c](Vec) { return c; };
}

} // namespace

void Canvas::fillRect(float x, float y, float w, float h, Colour colour) {
    fillRoundedRect(x, y, w, h, 0, colour);
}

void Canvas::fillCircle(float cx, float cy, float radius, Colour colour) {
    paint(
        image_, cx - radius, cy - radius, cx + radius, cy + radius,
        [=](Vec p) { return std::hypot(p.x - cx, p.y - cy) - radius; }, solid(colour));
}

void Canvas::strokeCircle(float cx, float cy, float radius, float thickness, Colour colour) {
    const float outer = radius + thickness / 2;
    paint(
        image_, cx - outer, cy - outer, cx + outer, cy + outer,
        [=](Vec p) { return std::abs(std::hypot(p.x - cx, p.y - cy) - radius) - thickness / 2; },
        solid(colour));
}

void Canvas::fillRoundedRect(float x, float y, float w, float h, float radius, Colour colour) {
    const double hx = w / 2.0;
    const double hy = h / 2.0;
    const double r = std::clamp<double>(radius, 0.0, std::min(hx, hy));
    paint(
        image_, x, y, x + w, y + h,
        [=](Vec p) {
            return roundedBoxDistance({p.x - x - hx, p.y - y - hy}, hx, hy, r);
        },
        solid(colour));
}

void Canvas::strokeRoundedRect(float x, float y, float w, float h, float radius, float thickness,
                               Colour colour) {
    const double hx = w / 2.0;
    const double hy = h / 2.0;
    const double r = std::clamp<double>(radius, 0.0, std::min(hx, hy));
    paint(
        image_, x, y, x + w, y + h,
        [=](Vec p) {
            const double d = roundedBoxDistance({p.x - x - hx, p.y - y - hy}, hx, hy, r);
            return std::max(d, -d - thickness);
        },
        solid(colour));
}

void Canvas::linearGradient(float x, float y, float w, float h, Colour from, Colour to,
                            bool vertical) {
    const double hx = w / 2.0;
    const double hy = h / 2.0;
    paint(
        image_, x, y, x + w, y + h,
        [=](Vec p) {
            return roundedBoxDistance({p.x - x - hx, p.y - y - hy}, hx, hy, 0);
        },
        [=](Vec p) {
            const double t = vertical ? (h > 1 ? (p.y - y - 0.5) / (h - 1) : 0.0)
                                      : (w > 1 ? (p.x - x - 0.5) / (w - 1) : 0.0);
            return mix(from, to, t);
        });
}

void Canvas::radialGradient(float cx, float cy, float radius, Colour centre, Colour edge) {
    paint(
        image_, cx - radius, cy - radius, cx + radius, cy + radius,
        [=](Vec p) { return std::hypot(p.x - cx, p.y - cy) - radius; },
        [=](Vec p) {
            return mix(centre, edge, radius > 0 ? std::hypot(p.x - cx, p.y - cy) / radius : 0.0);
        });
}

void Canvas::line(float x0, float y0, float x1, float y1, float thickness, Colour colour) {
    const float pad = thickness / 2;
    paint(
        image_, std::min(x0, x1) - pad, std::min(y0, y1) - pad, std::max(x0, x1) + pad,
        std::max(y0, y1) + pad,
        [=](Vec p) {
            return segmentDistance(p, {x0, y0}, {x1, y1}) - pad;
        },
        solid(colour));
}

void Canvas::fillTriangle(float x0, float y0, float x1, float y1, float x2, float y2,
                          Colour colour) {
    const Vec v[3] = {{x0, y0}, {x1, y1}, {x2, y2}};
    const double area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    const double sign = area < 0 ? -1.0 : 1.0;
    paint(
        image_, std::min({x0, x1, x2}), std::min({y0, y1, y2}), std::max({x0, x1, x2}),
        std::max({y0, y1, y2}),
        [=](Vec p) {
            double edge = std::numeric_limits<double>::infinity();
            bool inside = true;
            for (int i = 0; i < 3; ++i) {
                const Vec a = v[i];
                const Vec b = v[(i + 1) % 3];
                const double cross = ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) * sign;
                inside = inside && cross >= 0;
                edge = std::min(edge, segmentDistance(p, a, b));
            }
            return inside ? -edge : edge;
        },
        solid(colour));
}

void Canvas::copyFrom(const Canvas& source, int x, int y) {
    for (int sy = 0; sy < source.height(); ++sy) {
        const int dy = y + sy;
        if (dy < 0 || dy >= height()) {
            continue;
        }
        for (int sx = 0; sx < source.width(); ++sx) {
            const int dx = x + sx;
            if (dx < 0 || dx >= width()) {
                continue;
            }
            std::copy_n(source.image_.at(sx, sy), 4, pixelAt(image_, dx, dy));
        }
    }
}

void Canvas::writePng(const std::filesystem::path& path) const { render::writePng(image_, path); }

} // namespace e2d::assetgen
