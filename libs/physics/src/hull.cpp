// SPDX-License-Identifier: MIT
#include <e2d/physics/geometry.hpp>

#include <e2d/core/error_text.hpp>

#include "shape_detail.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace e2d::physics {
namespace detail {

Hull computeHull(std::span<const Vec2> points, const char* function) {
    if (points.size() < 3) {
        core::throwError(function,
                         "expected at least 3 points, got " + std::to_string(points.size()));
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!isFinite(points[i])) {
            core::throwError(function, "point " + std::to_string(i) + " is not finite, got " +
                                           core::formatVector(points[i]));
        }
        if (!isWithinHuge(points[i])) {
            core::throwError(function, "point " + std::to_string(i) + " is beyond kHuge (" +
                                           core::formatNumber(kHuge) + " m), got " +
                                           core::formatVector(points[i]));
        }
    }

    // Weld first so that near-duplicates can neither create sliver edges nor hide the fact
    // that there are fewer than 3 distinct points. Sorted by x, a point can only weld to kept
    // points less than kLinearSlop to its left, so the scan stays short even for big clouds.
    std::vector<Vec2> sorted(points.begin(), points.end());
    std::sort(sorted.begin(), sorted.end(),
              [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    std::vector<Vec2> unique;
    unique.reserve(sorted.size());
    constexpr float kWeldSquared = kLinearSlop * kLinearSlop;
    for (Vec2 p : sorted) {
        bool welded = false;
        for (std::size_t k = unique.size(); k-- > 0 && p.x - unique[k].x < kLinearSlop;) {
            if (distanceSquared(p, unique[k]) < kWeldSquared) {
                welded = true;
                break;
            }
        }
        if (!welded) {
            unique.push_back(p);
        }
    }
    if (unique.size() < 3) {
        core::throwError(function,
                         "expected at least 3 distinct points (points closer than kLinearSlop are "
                         "welded), got " +
                             std::to_string(unique.size()));
    }

    // Andrew's monotone chain over the x-sorted points; exact collinear points are dropped by
    // the <= 0 test.
    std::vector<Vec2> hull(2 * unique.size());
    std::size_t k = 0;
    for (Vec2 p : unique) {
        while (k >= 2 && cross(hull[k - 1] - hull[k - 2], p - hull[k - 2]) <= 0.0f) {
            --k;
        }
        hull[k++] = p;
    }
    for (std::size_t i = unique.size() - 1, lower = k + 1; i-- > 0;) {
        Vec2 p = unique[i];
        while (k >= lower && cross(hull[k - 1] - hull[k - 2], p - hull[k - 2]) <= 0.0f) {
            --k;
        }
        hull[k++] = p;
    }
    hull.resize(k - 1); // the last point repeats the first

    // Drop points within kLinearSlop of the line through their neighbours: nearly collinear
    // points make short, badly conditioned edges. Repeat until stable, since removing one point
    // changes its neighbours' lines.
    bool removed = true;
    while (removed && hull.size() >= 3) {
        removed = false;
        for (std::size_t i = 0; i < hull.size(); ++i) {
            Vec2 prev = hull[(i + hull.size() - 1) % hull.size()];
            Vec2 next = hull[(i + 1) % hull.size()];
            Vec2 e = next - prev;
            float len = length(e);
            float distance = cross(hull[i] - prev, e) / len;
            if (len == 0.0f || distance < kLinearSlop) {
                hull.erase(hull.begin() + static_cast<std::ptrdiff_t>(i));
                removed = true;
                break;
            }
        }
    }
    if (hull.size() < 3) {
        core::throwError(function, "the points are collinear (the hull has no area)");
    }
    if (hull.size() > static_cast<std::size_t>(kMaxPolygonVertices)) {
        core::throwError(function, std::to_string(hull.size()) +
                                       " points on the convex hull, at most " +
                                       std::to_string(kMaxPolygonVertices) + " allowed");
    }

    Hull result;
    result.count = static_cast<int>(hull.size());
    std::copy(hull.begin(), hull.end(), result.points.begin());
    return result;
}

} // namespace detail

Hull computeHull(std::span<const Vec2> points) {
    return detail::computeHull(points, "physics::computeHull()");
}

} // namespace e2d::physics
