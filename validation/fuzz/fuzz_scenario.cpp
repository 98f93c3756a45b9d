// SPDX-License-Identifier: MIT
// Scenario files as raw bytes, through the harness as a user's file goes: parseScenario, then,
// for scenes small enough to step in a fuzzer (at most kMaxFuzzBodies bodies and kMaxFuzzSteps steps),
// one baseline run on Box2D and on each e2d mode, the checks evaluated and both reports written.
// What must hold, else abort:
// - the reader throws ScenarioError and nothing else, with a printable message that names a place;
// - a scene the reader accepts is one e2d builds and steps: an e2d run never fails (the schema
//   refuses what e2d would refuse, naming the limit), and a Box2D run fails only with the
//   harness's own "cannot build" reason, never by an abort inside Box2D;
// - no check passes on a non-finite measurement, and a passed run has every check passed;
// - the JSON report serialises (non-finite numbers as null) and the HTML report is produced.
#include "plan.hpp"
#include "report.hpp"
#include "runner.hpp"
#include "scenario_parser.hpp"

#include <e2d/core/printable.hpp>
#include <e2d/core/utf8.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

using namespace e2d::validation;

constexpr std::size_t kMaxFuzzBodies = 48;
constexpr double kMaxFuzzSteps = 300.0;

// Aborts naming the failed check's line and what was seen.
void check(bool condition, const std::string& what, int line = __builtin_LINE()) {
    if (!condition) {
        std::fprintf(stderr, "fuzz_scenario.cpp:%d: check failed: %s\n", line, what.c_str());
        std::abort();
    }
}

RunSpec spec(const std::string& engine, const std::string& solver) {
    RunSpec s;
    s.config.engine = engine;
    s.config.solver = solver;
    return s;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    Scenario scenario;
    try {
        scenario = parseScenario(text, "fuzz");
    } catch (const ScenarioError& e) {
        const std::string message = e.what();
        check(!message.empty() && message.find(": ") != std::string::npos,
              "unplaced error: " + message);
        check(e2d::core::isPrintable(message),
              "unescaped bytes in: " + e2d::core::printable(message));
        return 0;
    }
    // Anything else thrown escapes and libFuzzer reports it.
    check(std::isfinite(scenario.duration) && scenario.duration > 0.0f, "duration");
    check(std::isfinite(scenario.scene.timeStep) && scenario.scene.timeStep > 0.0f, "timeStep");
    check(!scenario.scene.bodies.empty(), "no bodies");
    if (scenario.scene.bodies.size() > kMaxFuzzBodies ||
        double(scenario.duration) / double(scenario.scene.timeStep) > kMaxFuzzSteps) {
        return 0;
    }
    Report report;
    report.scenarios = {scenario};
    for (const RunSpec& s : {spec("box2d", "soft"), spec("e2d", "soft"), spec("e2d", "classic")}) {
        const RunResult r = runOne(scenario, s);
        if (s.config.engine == "e2d") {
            check(r.failure.empty(), "e2d run failed on an accepted scene: " + r.failure);
        } else {
            check(r.failure.empty() || r.failure.rfind("Box2D 2.4 cannot build this scene", 0) == 0,
                  "Box2D run failed: " + r.failure);
        }
        check(std::isfinite(r.normalizedError), "normalizedError");
        bool all = r.failure.empty();
        for (const CheckResult& c : r.checks) {
            all = all && c.passed;
            if (c.passed) {
                check(std::isfinite(c.measured) && std::isfinite(c.error),
                      c.kind + " passed on a non-finite measurement");
            }
        }
        check(r.passed == all, "run passed with a failed check");
        report.runs.push_back(r);
    }
    (void)reportToJson(report).dump();
    (void)reportToHtml(report);
    (void)reportSummary(report);
    return 0;
}
