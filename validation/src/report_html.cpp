// SPDX-License-Identifier: MIT
#include "report.hpp"
#include "svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace e2d::validation {
namespace {

std::string fmt(double v, int precision = 3) {
    if (!std::isfinite(v)) {
        return "n/a";
    }
    std::ostringstream out;
    out.precision(precision);
    out << v;
    return out.str();
}

std::string colorOf(const std::string& family, const std::vector<std::string>& families) {
    static constexpr const char* kPalette[] = {"#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e",
                                               "#8c564b", "#17becf", "#e377c2", "#7f7f7f"};
    const auto it = std::find(families.begin(), families.end(), family);
    const auto i = static_cast<std::size_t>(it - families.begin());
    return kPalette[i % std::size(kPalette)];
}

const char* kStyle = R"(
body { font-family: sans-serif; margin: 24px; color: #222; max-width: 1360px; }
h1 { font-size: 24px; } h2 { font-size: 19px; border-bottom: 1px solid #ccc; margin-top: 32px; }
h3 { font-size: 15px; margin-bottom: 4px; }
table { border-collapse: collapse; margin: 8px 0; font-size: 12px; }
th, td { border: 1px solid #ccc; padding: 3px 6px; text-align: left; vertical-align: top; }
th { background: #f0f0f0; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
td.pass { background: #e3f4e3; } td.fail { background: #fde0dc; color: #900; font-weight: bold; }
td.worse { background: #e53935; color: #fff; font-weight: bold; }
.plots { display: flex; flex-wrap: wrap; gap: 12px; }
.note { color: #555; font-size: 12px; max-width: 1100px; }
svg.plot { border: 1px solid #ddd; }
)";

void environmentSection(std::ostringstream& o, const Report& r) {
    const Environment& e = r.env;
    o << "<table class=\"env\">\n";
    auto row = [&](const char* k, const std::string& v) {
        o << "<tr><th>" << k << "</th><td>" << escapeHtml(v) << "</td></tr>\n";
    };
    row("date", e.date);
    row("command", e.command);
    row("e2d", e.e2dVersion);
    row("Box2D", e.box2dVersion);
    row("compiler", e.compiler);
    row("build", e.buildType + ": " + e.flags);
    row("CPU", e.cpu + " (" + std::to_string(e.cores) + " hardware threads, " +
                   std::to_string(e.threads) + " used)");
    row("sweep", e.sweep);
    row("wall time", fmt(e.wallSeconds, 4) + " s for " + std::to_string(r.runs.size()) + " runs");
    o << "</table>\n";
    o << "<p class=\"note\">Timings are wall-clock ms per step measured around the engine's step "
         "call only, after the scenario's settle time; runs execute in parallel (one world per "
         "thread), so absolute numbers include contention from the other runs; compare "
         "engines within one report.</p>\n";
}

void enginesSection(std::ostringstream& o, const Report& r) {
    o << "<h2>Engines, settings and translation</h2>\n<table>\n"
         "<tr><th>engine</th><th>baseline settings</th><th>translation and fixed "
         "settings</th></tr>\n";
    std::set<std::string> seen;
    for (const RunResult& run : r.runs) {
        const std::string f = run.spec.config.family();
        if (run.spec.role != RunRole::Baseline || !seen.insert(f).second) {
            continue;
        }
        o << "<tr><td>" << escapeHtml(f) << "</td><td>" << escapeHtml(run.spec.config.describe())
          << "</td><td>" << escapeHtml(translationNotes(run.spec.config)) << "</td></tr>\n";
    }
    o << "</table>\n<p class=\"note\">Every scenario is run with these settings (a scenario file "
         "may set iterations or sub-steps for itself; the shipped ones do not). Checks and "
         "tolerances are the same for every engine. Sweep points vary only the solver effort; "
         "feature runs switch one option of the baseline.</p>\n";
}

// The scenarios marked hardCase, first: pass or fail per engine and every check's numbers.
void hardCaseTableHtml(std::ostringstream& o, const Report& r) {
    const std::vector<HardCaseRow> rows = hardCaseTable(r);
    if (rows.empty()) {
        return;
    }
    o << "<h3 id=\"hard-cases\">Hard cases</h3>\n<table class=\"hard\">\n<tr><th>scenario</th>";
    for (const auto& [family, run] : rows.front().runs) {
        o << "<th>" << escapeHtml(family) << "</th>";
    }
    o << "<th>key numbers (each check: expected, tolerance, each engine's measurement)</th></tr>\n";
    for (const HardCaseRow& row : rows) {
        const Scenario& s = r.scenarios[row.scenario];
        o << "<tr><td title=\"" << escapeHtml(s.description) << "\">" << escapeHtml(s.name)
          << "</td>";
        for (const auto& [family, run] : row.runs) {
            if (run == nullptr) {
                o << "<td>-</td>";
                continue;
            }
            o << "<td class=\"" << (run->passed ? "pass" : "fail") << "\" title=\""
              << escapeHtml(run->failure) << "\">" << (run->passed ? "PASS" : "FAIL") << "</td>";
        }
        o << "<td>";
        for (std::size_t k = 0; k < row.numbers.size(); ++k) {
            o << (k == 0 ? "" : "<br>") << escapeHtml(row.numbers[k]);
        }
        o << "</td></tr>\n";
    }
    o << "</table>\n";
}

void summarySection(std::ostringstream& o, const Report& r) {
    const std::vector<std::string> families = engineFamilies(r);
    const auto table = summaryTable(r);
    o << "<h2 id=\"summary\">Summary</h2>\n";
    hardCaseTableHtml(o, r);
    o << "<p class=\"note\">Baseline runs. Each cell: PASS/FAIL and the largest check error as a "
         "fraction of its tolerance (1 = at the limit). <span style=\"background:#e53935;color:#fff"
         "\">&nbsp;red&nbsp;</span>: e2d does worse than Box2D on that scenario.</p>\n";
    o << "<table class=\"summary\">\n<tr><th>scenario</th><th>family</th><th>measures</th>";
    for (const std::string& f : families) {
        o << "<th>" << escapeHtml(f) << "</th>";
    }
    o << "</tr>\n";
    for (std::size_t i = 0; i < r.scenarios.size(); ++i) {
        const Scenario& s = r.scenarios[i];
        o << "<tr><td>" << escapeHtml(s.name) << "</td><td>" << escapeHtml(s.family) << "</td><td>"
          << escapeHtml(s.measures) << "</td>";
        for (const std::string& f : families) {
            auto it = table[i].find(f);
            if (it == table[i].end() || it->second.run == nullptr) {
                o << "<td>-</td>";
                continue;
            }
            const RunResult& run = *it->second.run;
            const char* cls = it->second.worseThanReference ? "worse"
                              : run.passed                  ? "pass"
                                                            : "fail";
            std::string tip;
            for (const CheckResult& c : run.checks) {
                tip += c.kind + ": " + fmt(c.measured) + " vs " + fmt(c.expected) + " (" +
                       (c.passed ? "ok" : "FAIL") + ") ";
            }
            if (!run.failure.empty()) {
                tip = run.failure;
            }
            o << "<td class=\"" << cls << "\" title=\"" << escapeHtml(tip) << "\">"
              << (run.passed ? "PASS" : "FAIL") << " " << fmt(run.normalizedError, 2) << "</td>";
        }
        o << "</tr>\n";
    }
    o << "</table>\n";
}

void checksSection(std::ostringstream& o, const Report& r) {
    const std::vector<std::string> families = engineFamilies(r);
    const auto table = summaryTable(r);
    o << "<h2>Checks</h2>\n<p class=\"note\">Every check of every baseline run: the analytic or "
         "limit value, then each engine's measurement.</p>\n<table>\n<tr><th>scenario</th>"
         "<th>check</th><th>quantity</th><th>expected / limit</th><th>tolerance</th>";
    for (const std::string& f : families) {
        o << "<th>" << escapeHtml(f) << "</th>";
    }
    o << "</tr>\n";
    for (std::size_t i = 0; i < r.scenarios.size(); ++i) {
        const Scenario& s = r.scenarios[i];
        for (std::size_t c = 0; c < s.checks.size(); ++c) {
            const CheckResult* first = nullptr;
            for (const std::string& f : families) {
                auto it = table[i].find(f);
                if (it != table[i].end() && it->second.run != nullptr &&
                    c < it->second.run->checks.size()) {
                    first = &it->second.run->checks[c];
                    break;
                }
            }
            if (first == nullptr) {
                continue;
            }
            o << "<tr><td>" << escapeHtml(s.name) << "</td><td>" << escapeHtml(first->kind)
              << (first->body.empty() ? "" : " (" + escapeHtml(first->body) + ")") << "</td><td>"
              << escapeHtml(first->quantity) << "</td><td class=\"num\">" << fmt(first->expected, 4)
              << "</td><td class=\"num\">" << fmt(first->tolerance, 3) << "</td>";
            for (const std::string& f : families) {
                auto it = table[i].find(f);
                if (it == table[i].end() || it->second.run == nullptr ||
                    c >= it->second.run->checks.size()) {
                    o << "<td>-</td>";
                    continue;
                }
                const CheckResult& cr = it->second.run->checks[c];
                o << "<td class=\"num " << (cr.passed ? "pass" : "fail") << "\" title=\""
                  << escapeHtml(cr.detail) << "\">" << fmt(cr.measured, 4) << "</td>";
            }
            o << "</tr>\n";
        }
    }
    o << "</table>\n";
}

void familySections(std::ostringstream& o, const Report& r) {
    const std::vector<std::string> families = engineFamilies(r);
    const auto curves = sweepCurves(r);
    const auto costs = featureCosts(r);
    std::vector<std::string> order{"stacking",     "friction", "restitution",
                                   "conservation", "joints",   "hard"};
    o << "<h2>Speed against error, per family</h2>\n<p class=\"note\">Each point sums the median "
         "ms/step over the family's swept scenarios (x) and averages their error as a fraction of "
         "tolerance (y; 1 = at the limit, lower is better); points are the sweep of solver effort "
         "of one engine and mode, the dashed line of the same colour is its Pareto front. Points "
         "with zero error are drawn at 0.001. Sweep runs have sleeping off, so that the cost is "
         "the solver's and not how soon the scene falls asleep.</p>\n<div class=\"plots\">\n";
    for (const std::string& family : order) {
        auto it = curves.find(family);
        if (it == curves.end()) {
            continue;
        }
        Plot plot;
        plot.title = family + ": speed against error";
        plot.xLabel = "ms per step, summed over scenarios";
        plot.yLabel = "mean error / tolerance";
        plot.logX = true;
        plot.logY = true;
        plot.hLines.emplace_back(1.0, "tolerance");
        int scenarios = 0;
        for (const auto& [engine, curve] : it->second) {
            const std::string name = curveLabel(family, engine);
            PlotSeries s{name, colorOf(engine, families), {}, false, true, {}};
            std::vector<std::pair<double, double>> pts;
            for (const SweepPoint& p : curve) {
                const std::pair<double, double> xy{p.ms, std::max(p.error, 1e-3)};
                s.points.push_back(xy);
                pts.push_back(xy);
                s.labels.push_back(name + " " + p.label + ": " + fmt(p.ms) + " ms, error " +
                                   fmt(p.error) + ", " + std::to_string(p.failed) + "/" +
                                   std::to_string(p.scenarios) + " failed");
                scenarios = p.scenarios;
            }
            // Sweep points joined in order of cost.
            plot.series.push_back(s);
            PlotSeries front{name + " Pareto front",
                             colorOf(engine, families),
                             paretoFront(pts),
                             true,
                             false,
                             {}};
            plot.series.push_back(front);
        }
        plot.title += " (" + std::to_string(scenarios) + " scenarios)";
        o << renderSvg(plot);
    }
    o << "</div>\n";
    o << "<details><summary>Sweep points as a table (click to "
         "open)</summary>\n<table>\n<tr><th>family</th><th>engine</th><th>effort</th>"
         "<th>ms/step (sum)</th><th>mean error / tol</th><th>scenarios failed</th></tr>\n";
    for (const std::string& family : order) {
        auto it = curves.find(family);
        if (it == curves.end()) {
            continue;
        }
        for (const auto& [engine, curve] : it->second) {
            for (const SweepPoint& p : curve) {
                o << "<tr><td>" << family << "</td><td>" << escapeHtml(engine) << "</td><td>"
                  << escapeHtml(p.label) << "</td><td class=\"num\">" << fmt(p.ms, 4)
                  << "</td><td class=\"num\">" << fmt(p.error, 3) << "</td><td class=\"num "
                  << (p.failed > 0 ? "fail" : "pass") << "\">" << p.failed << "/" << p.scenarios
                  << "</td></tr>\n";
            }
        }
    }
    o << "</table>\n</details>\n";

    o << "<h2>What each feature costs</h2>\n<p class=\"note\">One option switched against the "
         "reference run (the engine's default effort with sleeping off), on every swept scenario "
         "of the family: change in summed ms/step and in mean error / tolerance, and how many "
         "scenarios fail. \"sleep on\" is the baseline run (sleeping on) against that reference. "
         "Switch a feature off when the time saved matters more than the error it adds for your "
         "scene.</p>\n<table>\n<tr>"
         "<th>family</th><th>engine</th><th>feature</th><th>ms/step: reference &rarr; with</th>"
         "<th>time</th><th>error/tol: reference &rarr; with</th><th>failed: reference &rarr; "
         "with</th></tr>\n";
    for (const std::string& family : order) {
        auto it = costs.find(family);
        if (it == costs.end()) {
            continue;
        }
        for (const auto& [engine, list] : it->second) {
            for (const FeatureCost& c : list) {
                const double change =
                    c.baselineMs > 0.0 ? 100.0 * (c.ms / c.baselineMs - 1.0) : 0.0;
                const bool worse = c.failed > c.baselineFailed;
                o << "<tr><td>" << family << "</td><td>" << escapeHtml(engine) << "</td><td>"
                  << escapeHtml(c.feature) << "</td><td class=\"num\">" << fmt(c.baselineMs, 3)
                  << " &rarr; " << fmt(c.ms, 3) << "</td><td class=\"num\">"
                  << (change >= 0 ? "+" : "") << fmt(change, 2) << " %</td><td class=\"num\">"
                  << fmt(c.baselineError, 3) << " &rarr; " << fmt(c.error, 3)
                  << "</td><td class=\"num" << (worse ? " fail" : "") << "\">" << c.baselineFailed
                  << " &rarr; " << c.failed << " of " << c.scenarios << "</td></tr>\n";
            }
        }
    }
    o << "</table>\n";
}

void seriesSection(std::ostringstream& o, const Report& r) {
    const std::vector<std::string> families = engineFamilies(r);
    o << "<h2>Time series</h2>\n<p class=\"note\">Baseline runs: the quantity each check is "
         "about, per engine (solid), against the analytic curve or the tolerance (dashed, "
         "black).</p>\n<div class=\"plots\">\n";
    for (std::size_t i = 0; i < r.scenarios.size(); ++i) {
        // Series index -> plot; all engines' runs of the scenario share the plot.
        std::vector<Plot> plots;
        for (const RunResult& run : r.runs) {
            if (run.spec.scenario != static_cast<int>(i) || run.spec.role != RunRole::Baseline) {
                continue;
            }
            for (std::size_t k = 0; k < run.series.size(); ++k) {
                const Series& s = run.series[k];
                if (plots.size() <= k) {
                    Plot p;
                    p.title = r.scenarios[i].name;
                    p.xLabel = "t, s";
                    p.yLabel = s.name.substr(0, s.name.find(';')) + ", " + s.unit;
                    p.width = 440.0;
                    p.height = 280.0;
                    PlotSeries expected{
                        s.name.substr(s.name.find(';') + 2), "#000", {}, true, false, {}};
                    for (std::size_t j = 0; j < s.t.size() && j < s.expected.size(); ++j) {
                        expected.points.emplace_back(s.t[j], s.expected[j]);
                    }
                    p.series.push_back(expected);
                    plots.push_back(p);
                }
                PlotSeries measured{run.spec.config.family(),
                                    colorOf(run.spec.config.family(), families),
                                    {},
                                    false,
                                    false,
                                    {}};
                for (std::size_t j = 0; j < s.t.size(); ++j) {
                    measured.points.emplace_back(s.t[j], s.measured[j]);
                }
                plots[k].series.push_back(measured);
            }
        }
        for (const Plot& p : plots) {
            o << renderSvg(p);
        }
    }
    o << "</div>\n";
}

void scalingSection(std::ostringstream& o, const Report& r) {
    const std::vector<std::string> families = engineFamilies(r);
    // The reference run (default effort, sleeping off) measures the solver; the baseline
    // (sleeping on) only when there is none, e.g. without a sweep.
    std::map<std::pair<int, std::string>, const RunResult*> chosen;
    for (const RunResult& run : r.runs) {
        const Scenario& s = r.scenarios[static_cast<std::size_t>(run.spec.scenario)];
        if (s.scaling.empty() || !run.failure.empty()) {
            continue;
        }
        const std::pair<int, std::string> key{run.spec.scenario, run.spec.config.family()};
        if (run.spec.role == RunRole::Baseline && !chosen.contains(key)) {
            chosen[key] = &run;
        }
        if (run.spec.role == RunRole::Sweep && !run.spec.config.sleeping) {
            for (const RunResult& b : r.runs) {
                if (b.spec.role == RunRole::Baseline && b.spec.scenario == run.spec.scenario &&
                    b.spec.config.family() == key.second &&
                    effortLabel(b.spec.config) == effortLabel(run.spec.config)) {
                    chosen[key] = &run;
                }
            }
        }
    }
    std::map<std::string, PlotSeries> series;
    for (const auto& [key, chosenRun] : chosen) {
        const RunResult& run = *chosenRun;
        const Scenario& s = r.scenarios[static_cast<std::size_t>(run.spec.scenario)];
        const std::string engine = run.spec.config.family();
        PlotSeries& ps = series[s.scaling + ": " + engine];
        ps.name = s.scaling + ": " + engine;
        ps.color = colorOf(engine, families);
        ps.markers = true;
        ps.points.emplace_back(run.bodies, run.metrics.msMedian);
        ps.labels.push_back(s.name + ": " + fmt(run.metrics.msMedian) + " ms (p95 " +
                            fmt(run.metrics.msP95) + "), sleeping " +
                            (run.spec.config.sleeping ? "on" : "off"));
    }
    if (series.empty()) {
        return;
    }
    Plot plot;
    plot.title = "Scaling: median ms per step against body count";
    plot.xLabel = "bodies";
    plot.yLabel = "ms per step";
    plot.logX = true;
    plot.logY = true;
    plot.width = 720.0;
    plot.height = 400.0;
    for (auto& entry : series) {
        // Not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
        const PlotSeries& ps = entry.second;
        std::vector<std::size_t> idx(ps.points.size());
        for (std::size_t i = 0; i < idx.size(); ++i) {
            idx[i] = i;
        }
        std::sort(idx.begin(), idx.end(),
                  [&](std::size_t a, std::size_t b) { return ps.points[a] < ps.points[b]; });
        PlotSeries sorted = ps;
        for (std::size_t i = 0; i < idx.size(); ++i) {
            sorted.points[i] = ps.points[idx[i]];
            sorted.labels[i] = ps.labels[idx[i]];
        }
        plot.series.push_back(sorted);
    }
    o << "<h2>Scaling</h2>\n<p class=\"note\">Median ms/step after settling at each engine's "
         "default effort with sleeping off (the sweep's reference run; a run with sleeping on "
         "where there is none), against the number of bodies.</p>\n"
      << renderSvg(plot);
}

void runsSection(std::ostringstream& o, const Report& r) {
    o << "<h2>All runs</h2>\n<details><summary>" << r.runs.size()
      << " runs (click to open)</summary>\n<table>\n<tr><th>scenario</th><th>engine</th>"
         "<th>role</th><th>settings</th><th>bodies</th><th>ms median</th><th>ms p95</th>"
         "<th>max penetration, m</th><th>max speed, m/s</th><th>final KE, J</th>"
         "<th>top drift, m</th><th>standing</th><th>sleep at, s</th><th>error/tol</th>"
         "<th>result</th></tr>\n";
    for (const RunResult& run : r.runs) {
        const Metrics& m = run.metrics;
        o << "<tr><td>" << escapeHtml(r.scenarios[static_cast<std::size_t>(run.spec.scenario)].name)
          << "</td><td>" << escapeHtml(run.spec.config.family()) << "</td><td>"
          << runRoleName(run.spec.role) << "</td><td>" << escapeHtml(run.spec.config.describe())
          << "</td><td class=\"num\">" << run.bodies << "</td><td class=\"num\">"
          << fmt(m.msMedian, 3) << "</td><td class=\"num\">" << fmt(m.msP95, 3)
          << "</td><td class=\"num\">" << fmt(m.maxPenetration, 3) << "</td><td class=\"num\">"
          << fmt(m.maxSpeed, 3) << "</td><td class=\"num\">" << fmt(m.finalKineticEnergy, 3)
          << "</td><td class=\"num\">" << (m.topDrift ? fmt(*m.topDrift, 3) : "-") << "</td><td>"
          << (m.standing ? (*m.standing ? "yes" : "no") : "-") << "</td><td class=\"num\">"
          << (m.timeToSleep ? fmt(*m.timeToSleep, 3) : "-") << "</td><td class=\"num\">"
          << fmt(run.normalizedError, 3) << "</td><td class=\"" << (run.passed ? "pass" : "fail")
          << "\">"
          << (run.failure.empty() ? (run.passed ? "pass" : "fail") : escapeHtml(run.failure))
          << "</td></tr>\n";
    }
    o << "</table>\n</details>\n";
}

} // namespace

std::string reportToHtml(const Report& r) {
    std::ostringstream o;
    int failed = 0;
    int baselines = 0;
    for (const RunResult& run : r.runs) {
        if (run.spec.role == RunRole::Baseline) {
            ++baselines;
            failed += run.passed ? 0 : 1;
        }
    }
    o << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<title>e2d physics validation report</title>\n<style>"
      << kStyle << "</style>\n</head>\n<body>\n";
    o << "<h1>e2d physics validation: e2d and Box2D side by side</h1>\n";
    o << "<p><b>"
      << (failed == 0 ? "All " + std::to_string(baselines) + " baseline runs passed."
                      : std::to_string(failed) + " of " + std::to_string(baselines) +
                            " baseline runs failed a check.")
      << "</b> " << r.scenarios.size() << " scenarios, " << r.runs.size() << " runs.</p>\n";
    environmentSection(o, r);
    summarySection(o, r);
    enginesSection(o, r);
    checksSection(o, r);
    familySections(o, r);
    seriesSection(o, r);
    scalingSection(o, r);
    runsSection(o, r);
    o << "</body>\n</html>\n";
    return o.str();
}

std::string reportSummary(const Report& r) {
    std::ostringstream o;
    for (const HardCaseRow& row : hardCaseTable(r)) {
        o << "HARD  " << r.scenarios[row.scenario].name << ":";
        for (const auto& [family, run] : row.runs) {
            if (run != nullptr) {
                o << " " << family << " " << (run->passed ? "PASS" : "FAIL") << ";";
            }
        }
        for (const std::string& n : row.numbers) {
            o << "  " << n << ";";
        }
        o << "\n";
    }
    const std::vector<std::string> families = engineFamilies(r);
    const auto table = summaryTable(r);
    int failed = 0;
    int worse = 0;
    int baselines = 0;
    for (std::size_t i = 0; i < table.size(); ++i) {
        for (const auto& [family, cell] : table[i]) {
            if (cell.run == nullptr) {
                continue;
            }
            ++baselines;
            if (!cell.run->passed) {
                ++failed;
                o << "FAIL  " << r.scenarios[i].name << " [" << family << "]";
                for (const CheckResult& c : cell.run->checks) {
                    if (!c.passed) {
                        o << "  " << c.kind << (c.body.empty() ? "" : "(" + c.body + ")") << ": "
                          << c.quantity << " measured " << fmt(c.measured, 4) << ", expected "
                          << fmt(c.expected, 4) << ", error " << fmt(c.error, 3) << " vs "
                          << fmt(c.tolerance, 3) << (c.detail.empty() ? "" : " (" + c.detail + ")")
                          << ";";
                    }
                }
                if (!cell.run->failure.empty()) {
                    o << "  " << cell.run->failure;
                }
                o << "\n";
            }
            if (cell.worseThanReference) {
                ++worse;
                o << "WORSE " << r.scenarios[i].name << " [" << family << "] than Box2D\n";
            }
        }
    }
    o << baselines - failed << "/" << baselines << " baseline runs passed";
    if (worse > 0) {
        o << ", e2d worse than Box2D in " << worse;
    }
    o << " (" << r.scenarios.size() << " scenarios, " << r.runs.size() << " runs, "
      << fmt(r.env.wallSeconds, 3) << " s)\n";
    return o.str();
}

} // namespace e2d::validation
