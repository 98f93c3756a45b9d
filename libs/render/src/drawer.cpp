// SPDX-License-Identifier: MIT
#include <e2d/render/drawer.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace e2d::render {
namespace {

bool finite(glm::vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

float cross(glm::vec2 o, glm::vec2 a, glm::vec2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

int segmentsFor(float radius, int requested) {
    if (requested >= 3) {
        return std::min(requested, 4096);
    }
    // About one segment per 4 px of circumference at 1 world unit per pixel.
    const float count = 2.0f * std::numbers::pi_v<float> * radius / 4.0f;
    return static_cast<int>(std::clamp(count, 16.0f, 128.0f));
}

bool insideTriangle(glm::vec2 p, glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    // Counter-clockwise a, b, c; points on an edge count as inside so no ear swallows them.
    return cross(a, b, p) >= 0.0f && cross(b, c, p) >= 0.0f && cross(c, a, p) >= 0.0f;
}

} // namespace

std::uint32_t packColor(glm::vec4 color) noexcept {
    const auto channel = [](float v) {
        const float c = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
        return static_cast<std::uint32_t>(std::lround(c * 255.0f));
    };
    return channel(color.r) | (channel(color.g) << 8) | (channel(color.b) << 16) |
           (channel(color.a) << 24);
}

void Drawer::line(glm::vec2 a, glm::vec2 b, glm::vec4 color, float width, DrawSpace space) {
    if (!finite(a) || !finite(b) || !std::isfinite(width) || width <= 0.0f) {
        return;
    }
    lines_.push_back({a, b, width, packColor(color), space});
}

void Drawer::rect(glm::vec2 min, glm::vec2 max, glm::vec4 color, float width, DrawSpace space) {
    const glm::vec2 points[4] = {min, {max.x, min.y}, max, {min.x, max.y}};
    polygon(points, color, width, space);
}

void Drawer::fillRect(glm::vec2 min, glm::vec2 max, glm::vec4 color, DrawSpace space) {
    if (!finite(min) || !finite(max)) {
        return;
    }
    const std::uint32_t c = packColor(color);
    triangle(min, {max.x, min.y}, max, c, space);
    triangle(min, max, {min.x, max.y}, c, space);
}

void Drawer::circle(glm::vec2 center, float radius, glm::vec4 color, float width, DrawSpace space,
                    int segments) {
    if (!finite(center) || !std::isfinite(radius) || radius < 0.0f || !std::isfinite(width) ||
        width <= 0.0f) {
        return;
    }
    const int n = segmentsFor(radius, segments);
    const std::uint32_t c = packColor(color);
    glm::vec2 previous = center + glm::vec2(radius, 0.0f);
    for (int i = 1; i <= n; ++i) {
        const float angle =
            2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / static_cast<float>(n);
        const glm::vec2 next = center + radius * glm::vec2(std::cos(angle), std::sin(angle));
        lines_.push_back({previous, next, width, c, space});
        previous = next;
    }
}

void Drawer::fillCircle(glm::vec2 center, float radius, glm::vec4 color, DrawSpace space,
                        int segments) {
    if (!finite(center) || !std::isfinite(radius) || radius < 0.0f) {
        return;
    }
    const int n = segmentsFor(radius, segments);
    const std::uint32_t c = packColor(color);
    glm::vec2 previous = center + glm::vec2(radius, 0.0f);
    for (int i = 1; i <= n; ++i) {
        const float angle =
            2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / static_cast<float>(n);
        const glm::vec2 next = center + radius * glm::vec2(std::cos(angle), std::sin(angle));
        triangle(center, previous, next, c, space);
        previous = next;
    }
}

void Drawer::polygon(std::span<const glm::vec2> points, glm::vec4 color, float width,
                     DrawSpace space) {
    if (points.size() < 2 || !std::isfinite(width) || width <= 0.0f ||
        !std::all_of(points.begin(), points.end(), finite)) {
        return;
    }
    const std::uint32_t c = packColor(color);
    const std::size_t edges = points.size() == 2 ? 1 : points.size();
    for (std::size_t i = 0; i < edges; ++i) {
        lines_.push_back({points[i], points[(i + 1) % points.size()], width, c, space});
    }
}

void Drawer::fillPolygon(std::span<const glm::vec2> points, glm::vec4 color, DrawSpace space) {
    if (points.size() < 3 || !std::all_of(points.begin(), points.end(), finite)) {
        return;
    }
    const std::uint32_t c = packColor(color);
    // Ear clipping over a ring of indices in counter-clockwise order.
    double area = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::vec2 p = points[i];
        const glm::vec2 q = points[(i + 1) % points.size()];
        area += static_cast<double>(p.x) * q.y - static_cast<double>(q.x) * p.y;
    }
    scratch_.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        scratch_[i] = static_cast<int>(area >= 0.0 ? i : points.size() - 1 - i);
    }
    const auto at = [&](std::size_t i) { return points[static_cast<std::size_t>(scratch_[i])]; };
    while (scratch_.size() > 3) {
        const std::size_t n = scratch_.size();
        bool clipped = false;
        for (std::size_t i = 0; i < n && !clipped; ++i) {
            const glm::vec2 a = at((i + n - 1) % n);
            const glm::vec2 b = at(i);
            const glm::vec2 d = at((i + 1) % n);
            if (cross(a, b, d) <= 0.0f) {
                continue; // reflex or degenerate corner: not an ear
            }
            bool empty = true;
            for (std::size_t k = 0; k < n && empty; ++k) {
                if (k == i || k == (i + n - 1) % n || k == (i + 1) % n) {
                    continue;
                }
                const glm::vec2 p = at(k);
                empty = (p == a || p == b || p == d) || !insideTriangle(p, a, b, d);
            }
            if (empty) {
                triangle(a, b, d, c, space);
                scratch_.erase(scratch_.begin() + static_cast<std::ptrdiff_t>(i));
                clipped = true;
            }
        }
        if (!clipped) {
            // Self-intersecting or degenerate input: no ear left; fan what remains.
            for (std::size_t i = 1; i + 1 < scratch_.size(); ++i) {
                triangle(at(0), at(i), at(i + 1), c, space);
            }
            return;
        }
    }
    triangle(at(0), at(1), at(2), c, space);
}

void Drawer::triangle(glm::vec2 a, glm::vec2 b, glm::vec2 c, std::uint32_t color, DrawSpace space) {
    triangles_.push_back({a, color, space});
    triangles_.push_back({b, color, space});
    triangles_.push_back({c, color, space});
}

void Drawer::clear() noexcept {
    lines_.clear();
    triangles_.clear();
}

} // namespace e2d::render
