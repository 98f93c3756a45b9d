// SPDX-License-Identifier: MIT
#include "runner.hpp"

#include "engine.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <numeric>
#include <thread>

namespace e2d::validation {

RunResult runOne(const Scenario& scenario, const RunSpec& spec, const StepProgress& stepProgress,
                 double progressSeconds) {
    using Clock = std::chrono::steady_clock;
    RunResult result;
    result.spec = spec;
    result.bodies = static_cast<int>(scenario.scene.bodies.size());
    const auto start = Clock::now();
    auto lastReport = start;
    const int steps =
        std::max(1, static_cast<int>(std::lround(scenario.duration / scenario.scene.timeStep)));
    auto report = [&](int done, Clock::time_point now) {
        if (stepProgress &&
            std::chrono::duration<double>(now - lastReport).count() >= progressSeconds) {
            lastReport = now;
            stepProgress(spec, done, steps, std::chrono::duration<double>(now - start).count());
        }
    };
    try {
        std::unique_ptr<Engine> engine = makeEngine(scenario.scene, spec.config);
        report(0, Clock::now());
        Recorder recorder(scenario.scene, scenario.settle);
        recorder.record(*engine, 0.0);
        for (int i = 0; i < steps; ++i) {
            const auto t0 = Clock::now();
            engine->step();
            const auto t1 = Clock::now();
            recorder.record(*engine, std::chrono::duration<double, std::milli>(t1 - t0).count());
            report(i + 1, t1);
        }
        result.steps = steps;
        const Recording rec = recorder.take();
        result.metrics = summarize(rec, scenario.scene);
        const float g = std::sqrt(scenario.scene.gravity.x * scenario.scene.gravity.x +
                                  scenario.scene.gravity.y * scenario.scene.gravity.y);
        result.passed = true;
        for (const Check& check : scenario.checks) {
            CheckResult c = evaluate(check, rec, g);
            result.passed = result.passed && c.passed;
            double ratio = c.tolerance > 0.0 ? c.error / c.tolerance : (c.passed ? 0.0 : 1.0);
            if (!std::isfinite(ratio)) {
                ratio = kNonFiniteError;
            }
            // A failed check counts at least as "at the limit" even when its measure is small
            // (a fallen stack with little drift, a tunnelled ball).
            result.normalizedError =
                std::max({result.normalizedError, ratio, c.passed ? 0.0 : 1.0});
            result.checks.push_back(std::move(c));
        }
        if (spec.role == RunRole::Baseline) {
            // About 300 points per curve whatever the duration.
            const int stride = std::max(1, rec.instants() / 300);
            for (const Check& check : scenario.checks) {
                Series s = seriesFor(check, rec, g, stride);
                if (!s.name.empty()) {
                    result.series.push_back(std::move(s));
                }
            }
        }
    } catch (const std::exception& e) {
        result.failure = e.what();
        result.passed = false;
        result.normalizedError = std::max(result.normalizedError, 1.0);
    }
    result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return result;
}

std::vector<RunResult> runPlan(const std::vector<Scenario>& scenarios,
                               const std::vector<RunSpec>& plan, int threads,
                               const Progress& progress, const StepProgress& stepProgress) {
    std::vector<RunResult> results(plan.size());
    // Longest first so that one big pyramid does not start last and run alone.
    std::vector<std::size_t> order(plan.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    auto cost = [&](std::size_t i) {
        const Scenario& s = scenarios[static_cast<std::size_t>(plan[i].scenario)];
        const EngineConfig& c = plan[i].config;
        const double effort = c.engine == "e2d" && c.solver == "soft"
                                  ? c.subSteps
                                  : 0.25 * (c.velocityIterations + c.positionIterations);
        return static_cast<double>(s.scene.bodies.size()) * s.duration / s.scene.timeStep *
               (1.0 + effort);
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return cost(a) > cost(b); });

    std::atomic<std::size_t> next{0};
    std::mutex mutex;
    int done = 0;
    auto worker = [&] {
        for (std::size_t n = next++; n < order.size(); n = next++) {
            const std::size_t i = order[n];
            RunResult r = runOne(scenarios[static_cast<std::size_t>(plan[i].scenario)], plan[i],
                                 stepProgress);
            std::lock_guard lock(mutex);
            results[i] = std::move(r);
            ++done;
            if (progress) {
                progress(done, static_cast<int>(plan.size()), results[i]);
            }
        }
    };
    const int count = std::max(1, std::min<int>(threads, static_cast<int>(plan.size())));
    std::vector<std::jthread> pool;
    for (int t = 1; t < count; ++t) {
        pool.emplace_back(worker);
    }
    worker();
    pool.clear();
    return results;
}

} // namespace e2d::validation
