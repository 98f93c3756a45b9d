// SPDX-License-Identifier: MIT
#include "svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace e2d::validation {

std::string escapeHtml(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::vector<std::pair<double, double>> paretoFront(std::vector<std::pair<double, double>> points) {
    std::sort(points.begin(), points.end());
    std::vector<std::pair<double, double>> front;
    double best = std::numeric_limits<double>::infinity();
    for (const auto& p : points) {
        if (p.second < best) {
            front.push_back(p);
            best = p.second;
        }
    }
    return front;
}

namespace {

struct Axis {
    bool log = false;
    double lo = 0.0;
    double hi = 1.0;

    [[nodiscard]] double map(double v) const { return log ? std::log10(v) : v; }
    [[nodiscard]] double fraction(double v) const { return (map(v) - lo) / (hi - lo); }
    [[nodiscard]] bool usable(double v) const { return std::isfinite(v) && (!log || v > 0.0); }
};

std::string num(double v) {
    std::ostringstream out;
    out.precision(4);
    out << v;
    return out.str();
}

// Round-ish tick values covering [lo, hi] in mapped units.
std::vector<double> ticks(const Axis& a) {
    std::vector<double> out;
    if (a.log) {
        for (double e = std::floor(a.lo); e <= std::ceil(a.hi) + 1e-9; e += 1.0) {
            if (e >= a.lo - 1e-9 && e <= a.hi + 1e-9) {
                out.push_back(std::pow(10.0, e));
            }
        }
        return out;
    }
    const double span = a.hi - a.lo;
    const double raw = span / 5.0;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = mag;
    for (double m : {1.0, 2.0, 5.0, 10.0}) {
        if (m * mag >= raw) {
            step = m * mag;
            break;
        }
    }
    for (double v = std::ceil(a.lo / step) * step; v <= a.hi + 1e-9 * span; v += step) {
        out.push_back(std::abs(v) < 1e-12 * span ? 0.0 : v);
    }
    return out;
}

void fitAxis(Axis& a, const std::vector<double>& values) {
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (double v : values) {
        if (a.usable(v)) {
            lo = std::min(lo, a.map(v));
            hi = std::max(hi, a.map(v));
        }
    }
    if (!std::isfinite(lo)) {
        lo = 0.0;
        hi = 1.0;
    }
    if (a.log) {
        lo = std::floor(lo);
        hi = std::max(std::ceil(hi), lo + 1.0);
    } else {
        const double pad = hi > lo ? 0.05 * (hi - lo) : std::max(1.0, std::abs(hi) * 0.1);
        lo -= pad;
        hi += pad;
    }
    a.lo = lo;
    a.hi = hi;
}

} // namespace

std::string renderSvg(const Plot& plot) {
    const double left = 64.0;
    const double right = 16.0;
    const double top = 28.0;
    const double bottom = 44.0;
    // The legend sits below the plot area, one line per series.
    const double legendHeight = 16.0 * static_cast<double>(plot.series.size()) + 4.0;
    const double w = plot.width;
    const double h = plot.height + legendHeight;
    const double pw = w - left - right;
    const double ph = plot.height - top - bottom;

    Axis x{plot.logX};
    Axis y{plot.logY};
    std::vector<double> xs;
    std::vector<double> ys;
    for (const PlotSeries& s : plot.series) {
        for (const auto& [px, py] : s.points) {
            if (x.usable(px) && y.usable(py)) {
                xs.push_back(px);
                ys.push_back(py);
            }
        }
    }
    for (const auto& [v, label] : plot.hLines) {
        ys.push_back(v);
    }
    fitAxis(x, xs);
    fitAxis(y, ys);
    auto sx = [&](double v) { return left + pw * x.fraction(v); };
    auto sy = [&](double v) { return top + ph * (1.0 - y.fraction(v)); };

    std::ostringstream o;
    o << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot\" width=\"" << num(w)
      << "\" height=\"" << num(h) << "\" viewBox=\"0 0 " << num(w) << ' ' << num(h)
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n";
    o << "<rect x=\"0\" y=\"0\" width=\"" << num(w) << "\" height=\"" << num(h)
      << "\" fill=\"#fff\"/>\n";
    o << "<text x=\"" << num(w / 2)
      << "\" y=\"16\" text-anchor=\"middle\" font-size=\"13\" "
         "font-weight=\"bold\">"
      << escapeHtml(plot.title) << "</text>\n";
    // Grid and ticks.
    for (double t : ticks(x)) {
        const double px = sx(t);
        o << "<line x1=\"" << num(px) << "\" y1=\"" << num(top) << "\" x2=\"" << num(px)
          << "\" y2=\"" << num(top + ph) << "\" stroke=\"#e4e4e4\"/>\n";
        o << "<text x=\"" << num(px) << "\" y=\"" << num(top + ph + 14)
          << "\" text-anchor=\"middle\">" << num(t) << "</text>\n";
    }
    for (double t : ticks(y)) {
        const double py = sy(t);
        o << "<line x1=\"" << num(left) << "\" y1=\"" << num(py) << "\" x2=\"" << num(left + pw)
          << "\" y2=\"" << num(py) << "\" stroke=\"#e4e4e4\"/>\n";
        o << "<text x=\"" << num(left - 4) << "\" y=\"" << num(py + 4) << "\" text-anchor=\"end\">"
          << num(t) << "</text>\n";
    }
    o << "<rect x=\"" << num(left) << "\" y=\"" << num(top) << "\" width=\"" << num(pw)
      << "\" height=\"" << num(ph) << "\" fill=\"none\" stroke=\"#888\"/>\n";
    o << "<text x=\"" << num(left + pw / 2) << "\" y=\"" << num(top + ph + 32)
      << "\" text-anchor=\"middle\">" << escapeHtml(plot.xLabel) << (plot.logX ? " (log)" : "")
      << "</text>\n";
    o << "<text transform=\"translate(14," << num(top + ph / 2)
      << ") rotate(-90)\" text-anchor=\"middle\">" << escapeHtml(plot.yLabel)
      << (plot.logY ? " (log)" : "") << "</text>\n";
    for (const auto& [v, label] : plot.hLines) {
        if (!y.usable(v)) {
            continue;
        }
        o << "<line x1=\"" << num(left) << "\" y1=\"" << num(sy(v)) << "\" x2=\"" << num(left + pw)
          << "\" y2=\"" << num(sy(v)) << "\" stroke=\"#c00\" stroke-dasharray=\"2,3\"/>\n";
        o << "<text x=\"" << num(left + pw - 4) << "\" y=\"" << num(sy(v) - 4)
          << "\" text-anchor=\"end\" fill=\"#c00\">" << escapeHtml(label) << "</text>\n";
    }
    // Curves, clipped to the plot area.
    o << "<g>\n";
    for (const PlotSeries& s : plot.series) {
        std::ostringstream path;
        bool open = false;
        for (const auto& [px, py] : s.points) {
            if (!x.usable(px) || !y.usable(py)) {
                open = false;
                continue;
            }
            path << (open ? " L" : " M") << num(sx(px)) << ',' << num(sy(py));
            open = true;
        }
        o << "<path d=\"" << path.str() << "\" fill=\"none\" stroke=\"" << s.color
          << "\" stroke-width=\"" << (s.dashed ? "1.5" : "2") << '"'
          << (s.dashed ? " stroke-dasharray=\"6,4\"" : "") << "/>\n";
        if (s.markers) {
            for (std::size_t i = 0; i < s.points.size(); ++i) {
                const auto& [px, py] = s.points[i];
                if (!x.usable(px) || !y.usable(py)) {
                    continue;
                }
                o << "<circle cx=\"" << num(sx(px)) << "\" cy=\"" << num(sy(py))
                  << "\" r=\"3\" fill=\"" << s.color << "\">";
                if (i < s.labels.size()) {
                    o << "<title>" << escapeHtml(s.labels[i]) << "</title>";
                }
                o << "</circle>\n";
            }
        }
    }
    o << "</g>\n";
    // Legend.
    double ly = plot.height + 4.0;
    for (const PlotSeries& s : plot.series) {
        o << "<line x1=\"" << num(left) << "\" y1=\"" << num(ly) << "\" x2=\"" << num(left + 24)
          << "\" y2=\"" << num(ly) << "\" stroke=\"" << s.color << "\" stroke-width=\"2\""
          << (s.dashed ? " stroke-dasharray=\"6,4\"" : "") << "/>\n";
        o << "<text x=\"" << num(left + 30) << "\" y=\"" << num(ly + 4) << "\">"
          << escapeHtml(s.name) << "</text>\n";
        ly += 16.0;
    }
    o << "</svg>\n";
    return o.str();
}

} // namespace e2d::validation
