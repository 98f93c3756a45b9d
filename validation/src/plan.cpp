// SPDX-License-Identifier: MIT
#include "plan.hpp"

#include <algorithm>

namespace e2d::validation {

const char* runRoleName(RunRole role) {
    switch (role) {
    case RunRole::Baseline:
        return "baseline";
    case RunRole::Sweep:
        return "sweep";
    case RunRole::Feature:
        return "feature";
    }
    return "?";
}

std::vector<EngineConfig> baselineConfigs(const std::vector<std::string>& engines) {
    std::vector<EngineConfig> out;
    for (const std::string& engine : engines) {
        if (engine == "box2d") {
            EngineConfig c;
            c.engine = "box2d";
            out.push_back(c);
        } else if (engine == "e2d") {
            for (const char* solver : {"soft", "classic"}) {
                for (const char* collision : {"sat", "gjk"}) {
                    EngineConfig c;
                    c.engine = "e2d";
                    c.solver = solver;
                    c.collision = collision;
                    out.push_back(c);
                }
            }
        }
    }
    return out;
}

std::vector<std::pair<std::string, EngineConfig>> sweepPoints(const EngineConfig& baseline,
                                                              SweepLevel level) {
    std::vector<std::pair<std::string, EngineConfig>> out;
    if (level == SweepLevel::None) {
        return out;
    }
    // Sleeping off: a scene that falls asleep steps for free, which would credit the cost
    // axis with how soon it sleeps instead of what the solver costs.
    EngineConfig awake = baseline;
    awake.sleeping = false;
    const bool subSteps = baseline.engine == "e2d" && baseline.solver == "soft";
    if (subSteps) {
        const std::vector<int> full{1, 2, 4, 8, 16};
        const std::vector<int> quick{1, 4};
        for (int n : level == SweepLevel::Full ? full : quick) {
            EngineConfig c = awake;
            c.subSteps = n;
            out.emplace_back(effortLabel(c), c);
        }
    } else {
        // Velocity iterations do most of the work; position iterations grow slowly with them.
        const std::vector<std::pair<int, int>> full{{1, 1}, {2, 1},  {4, 2},
                                                    {8, 3}, {16, 6}, {32, 10}};
        const std::vector<std::pair<int, int>> quick{{2, 1}, {8, 3}};
        for (auto [v, p] : level == SweepLevel::Full ? full : quick) {
            EngineConfig c = awake;
            c.velocityIterations = v;
            c.positionIterations = p;
            out.emplace_back(effortLabel(c), c);
        }
    }
    return out;
}

std::vector<std::pair<std::string, EngineConfig>> featureVariants(const EngineConfig& baseline) {
    std::vector<std::pair<std::string, EngineConfig>> out;
    // Against the sleep-off reference at the baseline's effort (a sweep point), for the same
    // reason as the sweep; sleeping itself is judged by the baseline run.
    EngineConfig awake = baseline;
    awake.sleeping = false;
    auto add = [&](const std::string& label, auto&& change) {
        EngineConfig c = awake;
        change(c);
        out.emplace_back(label, c);
    };
    add("ccd off", [](EngineConfig& c) { c.continuous = false; });
    if (baseline.engine == "box2d") {
        // e2d always warm starts; Box2D 2.4 can switch it off.
        add("warm start off", [](EngineConfig& c) { c.warmStarting = false; });
    }
    if (baseline.engine == "e2d") {
        if (baseline.solver == "soft") {
            add("extra relax 1", [](EngineConfig& c) { c.relaxIterations = 1; });
            add("extra relax 2", [](EngineConfig& c) { c.relaxIterations = 2; });
        }
        add("speculative 0", [](EngineConfig& c) { c.speculativeDistance = 0.0f; });
        add("speculative 0.04", [](EngineConfig& c) { c.speculativeDistance = 0.04f; });
    }
    return out;
}

std::string effortLabel(const EngineConfig& c) {
    if (c.engine == "e2d" && c.solver == "soft") {
        return "sub-steps " + std::to_string(c.subSteps);
    }
    return "vel " + std::to_string(c.velocityIterations) + ", pos " +
           std::to_string(c.positionIterations);
}

std::vector<RunSpec> makePlan(const std::vector<Scenario>& scenarios,
                              const std::vector<std::string>& engines, SweepLevel level,
                              bool features) {
    std::vector<RunSpec> plan;
    for (int i = 0; i < static_cast<int>(scenarios.size()); ++i) {
        const Scenario& s = scenarios[static_cast<std::size_t>(i)];
        for (EngineConfig base : baselineConfigs(engines)) {
            if (auto it = s.settings.find(base.engine); it != s.settings.end()) {
                it->second.applyTo(base);
            }
            plan.push_back({i, RunRole::Baseline, base, "baseline"});
            if (!s.sweep) {
                // A scaling point still needs its cost with sleeping off: the reference run.
                if (!s.scaling.empty() && level != SweepLevel::None) {
                    EngineConfig awake = base;
                    awake.sleeping = false;
                    plan.push_back({i, RunRole::Sweep, awake, effortLabel(awake)});
                }
                continue;
            }
            for (auto& [label, config] : sweepPoints(base, level)) {
                plan.push_back({i, RunRole::Sweep, config, label});
            }
            // The joints family sweeps each joint model of the soft step (one collision
            // algorithm: they differ in joints only): the error-against-cost curves of the
            // report's joints plot.
            if (s.family == "joints" && base.engine == "e2d" && base.solver == "soft" &&
                base.collision == "sat") {
                for (const char* model : {"gauss-seidel", "soft"}) {
                    EngineConfig other = base;
                    other.jointSolver = model;
                    for (auto& [label, config] : sweepPoints(other, level)) {
                        plan.push_back({i, RunRole::Sweep, config, label});
                    }
                }
            }
            // Feature switches on one collision algorithm per mode: SAT against GJK is already
            // its own curve.
            if (features && base.collision != "gjk") {
                for (auto& [label, config] : featureVariants(base)) {
                    plan.push_back({i, RunRole::Feature, config, label});
                }
            }
        }
    }
    return plan;
}

} // namespace e2d::validation
