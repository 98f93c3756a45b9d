// SPDX-License-Identifier: MIT
#include "report.hpp"

#include <algorithm>
#include <set>

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
            cell.worseThanReference = (b.passed && !e.passed) ||
                                      (b.passed == e.passed &&
                                       e.normalizedError > b.normalizedError + 0.1);
        }
    }
    return table;
}

std::string effortLabel(const EngineConfig& c) {
    if (c.engine == "e2d" && c.solver == "soft") {
        return "sub-steps " + std::to_string(c.subSteps);
    }
    return "vel " + std::to_string(c.velocityIterations) + ", pos " +
           std::to_string(c.positionIterations);
}

namespace {

// The baseline configuration of a family, with default features: only runs that differ from
// it in effort belong on the sweep curve.
bool sameFeatures(const EngineConfig& a, const EngineConfig& b) {
    return a.continuous == b.continuous && a.sleeping == b.sleeping &&
           a.warmStarting == b.warmStarting && a.relaxIterations == b.relaxIterations &&
           a.speculativeDistance == b.speculativeDistance;
}

} // namespace

std::map<std::string, std::map<std::string, std::vector<SweepPoint>>> sweepCurves(
    const Report& report) {
    // family -> engine -> label -> points; only scenarios that have the whole sweep count, so
    // every point of a curve sums the same scenarios.
    std::map<std::string, std::map<std::string, std::map<std::string, SweepPoint>>> acc;
    std::map<std::string, const EngineConfig*> baselines;
    for (const RunResult& r : report.runs) {
        if (r.spec.role == RunRole::Baseline) {
            baselines.emplace(r.spec.config.family(), &r.spec.config);
        }
    }
    for (const RunResult& r : report.runs) {
        const Scenario& s = report.scenarios[static_cast<std::size_t>(r.spec.scenario)];
        if (!s.sweep || r.spec.role == RunRole::Feature) {
            continue;
        }
        const std::string engine = r.spec.config.family();
        if (!sameFeatures(r.spec.config, *baselines[engine])) {
            continue;
        }
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

std::map<std::string, std::map<std::string, std::vector<FeatureCost>>> featureCosts(
    const Report& report) {
    // Baseline of each (scenario, engine family).
    std::map<std::pair<int, std::string>, const RunResult*> base;
    for (const RunResult& r : report.runs) {
        if (r.spec.role == RunRole::Baseline) {
            base[{r.spec.scenario, r.spec.config.family()}] = &r;
        }
    }
    std::map<std::string, std::map<std::string, std::map<std::string, FeatureCost>>> acc;
    std::vector<std::string> order;
    for (const RunResult& r : report.runs) {
        if (r.spec.role != RunRole::Feature) {
            continue;
        }
        const std::string engine = r.spec.config.family();
        auto it = base.find({r.spec.scenario, engine});
        if (it == base.end()) {
            continue;
        }
        const RunResult& b = *it->second;
        const Scenario& s = report.scenarios[static_cast<std::size_t>(r.spec.scenario)];
        FeatureCost& c = acc[s.family][engine][r.spec.variant];
        if (std::find(order.begin(), order.end(), r.spec.variant) == order.end()) {
            order.push_back(r.spec.variant);
        }
        c.feature = r.spec.variant;
        c.baselineMs += b.metrics.msMedian;
        c.ms += r.metrics.msMedian;
        c.baselineError += b.normalizedError;
        c.error += r.normalizedError;
        c.baselineFailed += b.passed ? 0 : 1;
        c.failed += r.passed ? 0 : 1;
        c.scenarios += 1;
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
