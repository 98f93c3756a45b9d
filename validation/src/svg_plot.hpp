// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace e2d::validation {

/// One curve of a plot.
struct PlotSeries {
    std::string name;
    std::string color; ///< CSS colour
    std::vector<std::pair<double, double>> points;
    bool dashed = false;
    bool markers = false;            ///< a dot at each point
    std::vector<std::string> labels; ///< optional, one per point, shown on hover
};

struct Plot {
    std::string title;
    std::string xLabel;
    std::string yLabel;
    bool logX = false;
    bool logY = false;
    double width = 640.0;
    double height = 360.0;
    std::vector<PlotSeries> series;
    /// Horizontal reference lines (value, label), drawn dotted.
    std::vector<std::pair<double, std::string>> hLines;
};

/// Renders `plot` as a self-contained inline <svg> element (no scripts, no external fonts).
/// Non-finite points and, on log axes, non-positive ones are skipped.
[[nodiscard]] std::string renderSvg(const Plot& plot);

/// The points of `points` that no other point beats on both axes (lower x and lower y are
/// better), sorted by x: the Pareto front of a speed-against-error sweep.
[[nodiscard]] std::vector<std::pair<double, double>>
paretoFront(std::vector<std::pair<double, double>> points);

/// Escapes &, <, >, " for HTML text and attributes.
[[nodiscard]] std::string escapeHtml(const std::string& text);

} // namespace e2d::validation
