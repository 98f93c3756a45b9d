// SPDX-License-Identifier: MIT
#include "report.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace e2d::validation {

std::vector<std::string> engineFamilies(const Report& report) {
    std::vector<std::string> out;
    for (const RunResult& r : report.runs) {
        const std::string f = r.spec.config.family();
        if (std::find(out.begin(), out.end(), f) == out.end()) {
            out.push_back(f);
        }
    }
    return out;
}

std::vector<std::map<std::string, SummaryCell>> summaryTable(const Report& report) {
    std::vector<std::map<std::string, SummaryCell>> table(report.scenarios.size());
    for (const RunResult& r : report.runs) {
        if (r.spec.role == RunRole::Baseline) {
            table[static_cast<std::size_t>(r.spec.scenario)][r.spec.config.family()].run = &r;
        }
    }
    for (auto& row : table) {
        auto ref = row.find("box2d");
        if (ref == row.end() || ref->second.run == nullptr) {
            continue;
        }
        const RunResult& b = *ref->second.run;
        for (auto& [family, cell] : row) {
            if (cell.run == nullptr || cell.run->spec.config.engine != "e2d") {
                continue;
            }
            const RunResult& e = *cell.run;
            // Worse: fails where Box2D passes, or (both judged the same) a larger error by more
            // than 10 % of the tolerance.
            cell.worseThanReference =
                (b.passed && !e.passed) ||
                (b.passed == e.passed && e.normalizedError > b.normalizedError + 0.1);
        }
    }
    return table;
}

namespace {

std::string shortNumber(double v) {
    if (std::isnan(v)) {
        return "n/a";
    }
    std::ostringstream out;
    out.precision(3);
    out << v;
    return out.str();
}

} // namespace

std::vector<HardCaseRow> hardCaseTable(const Report& report) {
    // Box2D, then each e2d mode once: SAT, or GJK/EPA where the mode has no SAT run.
    std::vector<std::string> shown;
    const std::vector<std::string> families = engineFamilies(report);
    for (const std::string& f : families) {
        const bool gjk = f.size() > 4 && f.compare(f.size() - 4, 4, " gjk") == 0;
        const std::string sat = gjk ? f.substr(0, f.size() - 4) + " sat" : std::string();
        if (!gjk || std::find(families.begin(), families.end(), sat) == families.end()) {
            shown.push_back(f);
        }
    }
    std::stable_partition(shown.begin(), shown.end(),
                          [](const std::string& f) { return f == "box2d"; });
    const auto table = summaryTable(report);
    std::vector<HardCaseRow> rows;
    for (std::size_t i = 0; i < report.scenarios.size(); ++i) {
        if (!report.scenarios[i].hardCase) {
            continue;
        }
        HardCaseRow row;
        row.scenario = i;
        for (const std::string& f : shown) {
            auto it = table[i].find(f);
            row.runs.emplace_back(f, it == table[i].end() ? nullptr : it->second.run);
        }
        for (std::size_t k = 0; k < report.scenarios[i].checks.size(); ++k) {
            std::string text;
            for (const auto& [family, run] : row.runs) {
                if (run == nullptr || k >= run->checks.size()) {
                    continue;
                }
                const CheckResult& c = run->checks[k];
                if (text.empty()) {
                    text = c.kind + (c.body.empty() ? "" : "(" + c.body + ")") + " [expected " +
                           shortNumber(c.expected) + ", tolerance " + shortNumber(c.tolerance) +
                           "]:";
                } else {
                    text += ",";
                }
                text += " " + family + " " + shortNumber(c.measured) + (c.passed ? "" : " FAIL");
                if (!c.passed && !c.detail.empty()) {
                    text += " (" + c.detail + ")";
                }
            }
            if (!text.empty()) {
                row.numbers.push_back(text);
            }
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

std::string curveLabel(const std::string& family, const std::string& engine) {
    if (family != "joints" || engine.rfind("e2d soft ", 0) != 0) {
        return engine;
    }
    // "e2d soft sat" (the default, Direct) or "e2d soft sat joints <model>".
    const std::string marker = " joints ";
    const std::size_t at = engine.find(marker);
    const std::string model =
        at == std::string::npos ? "direct" : engine.substr(at + marker.size());
    const std::string base = engine.substr(0, at);
    const std::string name = model == "direct"         ? "Direct"
                             : model == "gauss-seidel" ? "GaussSeidel"
                             : model == "soft"         ? "Soft"
                                                       : model;
    return base + ", " + name + " joints";
}

std::map<std::string, std::map<std::string, std::vector<SweepPoint>>>
sweepCurves(const Report& report) {
    // family -> engine -> label -> points; only scenarios that have the whole sweep count, so
    // every point of a curve sums the same scenarios.
    std::map<std::string, std::map<std::string, std::map<std::string, SweepPoint>>> acc;
    for (const RunResult& r : report.runs) {
        const Scenario& s = report.scenarios[static_cast<std::size_t>(r.spec.scenario)];
        // Unswept scenarios may have a reference run (for scaling); it is not a curve point.
        if (r.spec.role != RunRole::Sweep || !s.sweep) {
            continue;
        }
        const std::string engine = r.spec.config.family();
        SweepPoint& p = acc[s.family][engine][effortLabel(r.spec.config)];
        p.label = effortLabel(r.spec.config);
        p.effort = r.spec.config.engine == "e2d" && r.spec.config.solver == "soft"
                       ? r.spec.config.subSteps
                       : r.spec.config.velocityIterations;
        p.ms += r.metrics.msMedian;
        p.error += r.normalizedError;
        p.failed += r.passed ? 0 : 1;
        p.scenarios += 1;
    }
    std::map<std::string, std::map<std::string, std::vector<SweepPoint>>> out;
    for (auto& [family, engines] : acc) {
        for (auto& [engine, points] : engines) {
            int most = 0;
            for (auto& [label, p] : points) {
                most = std::max(most, p.scenarios);
            }
            std::vector<SweepPoint>& curve = out[family][engine];
            for (auto& [label, p] : points) {
                if (p.scenarios == most) {
                    p.error /= p.scenarios;
                    curve.push_back(p);
                }
            }
            std::sort(curve.begin(), curve.end(),
                      [](const SweepPoint& a, const SweepPoint& b) { return a.effort < b.effort; });
        }
    }
    return out;
}

std::map<std::string, std::map<std::string, std::vector<FeatureCost>>>
featureCosts(const Report& report) {
    // Reference of each (scenario, engine family): the sweep point at the baseline's effort.
    std::map<std::pair<int, std::string>, const RunResult*> baselines;
    for (const RunResult& r : report.runs) {
        if (r.spec.role == RunRole::Baseline) {
            baselines[{r.spec.scenario, r.spec.config.family()}] = &r;
        }
    }
    std::map<std::pair<int, std::string>, const RunResult*> reference;
    std::set<std::pair<int, std::string>> featured;
    for (const RunResult& r : report.runs) {
        const std::pair<int, std::string> key{r.spec.scenario, r.spec.config.family()};
        auto b = baselines.find(key);
        if (r.spec.role == RunRole::Sweep && b != baselines.end() &&
            effortLabel(r.spec.config) == effortLabel(b->second->spec.config)) {
            reference[key] = &r;
        }
        if (r.spec.role == RunRole::Feature) {
            featured.insert(key);
        }
    }
    std::map<std::string, std::map<std::string, std::map<std::string, FeatureCost>>> acc;
    std::vector<std::string> order{"sleep on"};
    auto add = [&](const RunResult& r, const std::string& feature) {
        const std::string engine = r.spec.config.family();
        auto it = reference.find({r.spec.scenario, engine});
        if (it == reference.end()) {
            return;
        }
        const RunResult& b = *it->second;
        const Scenario& s = report.scenarios[static_cast<std::size_t>(r.spec.scenario)];
        FeatureCost& c = acc[s.family][engine][feature];
        if (std::find(order.begin(), order.end(), feature) == order.end()) {
            order.push_back(feature);
        }
        c.feature = feature;
        c.baselineMs += b.metrics.msMedian;
        c.ms += r.metrics.msMedian;
        c.baselineError += b.normalizedError;
        c.error += r.normalizedError;
        c.baselineFailed += b.passed ? 0 : 1;
        c.failed += r.passed ? 0 : 1;
        c.scenarios += 1;
    };
    for (const RunResult& r : report.runs) {
        if (r.spec.role == RunRole::Feature) {
            add(r, r.spec.variant);
        } else if (r.spec.role == RunRole::Baseline &&
                   featured.contains({r.spec.scenario, r.spec.config.family()})) {
            // Sleeping is judged by the baseline itself (sleep on) against the reference.
            add(r, "sleep on");
        }
    }
    std::map<std::string, std::map<std::string, std::vector<FeatureCost>>> out;
    for (auto& [family, engines] : acc) {
        for (auto& [engine, features] : engines) {
            for (const std::string& name : order) {
                auto f = features.find(name);
                if (f == features.end()) {
                    continue;
                }
                FeatureCost c = f->second;
                c.baselineError /= c.scenarios;
                c.error /= c.scenarios;
                out[family][engine].push_back(c);
            }
        }
    }
    return out;
}

int exitStatus(const Report& report) {
    for (const RunResult& r : report.runs) {
        if (r.spec.role == RunRole::Baseline && !r.passed) {
            return 1;
        }
    }
    return 0;
}

} // namespace e2d::validation
