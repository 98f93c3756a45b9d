// SPDX-License-Identifier: MIT
#include "report.hpp"

#include <cmath>

namespace e2d::validation {
namespace {

using nlohmann::json;

// JSON has no NaN or infinity; a metric that is not finite is written as null.
json number(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

const char* shapeKindName(scenes::ShapeKind kind) {
    switch (kind) {
    case scenes::ShapeKind::Box:
        return "box";
    case scenes::ShapeKind::Polygon:
        return "polygon";
    case scenes::ShapeKind::Circle:
        return "circle";
    case scenes::ShapeKind::Capsule:
        return "capsule";
    case scenes::ShapeKind::Segment:
        return "segment";
    case scenes::ShapeKind::Chain:
        return "chain";
    }
    return "?";
}

json configJson(const EngineConfig& c) {
    json j{{"engine", c.engine},       {"family", c.family()},
           {"settings", c.describe()}, {"continuous", c.continuous},
           {"sleeping", c.sleeping},   {"warmStarting", c.warmStarting}};
    if (c.engine == "e2d") {
        j["solver"] = c.solver;
        j["collision"] = c.collision;
        j["speculativeDistance"] = c.speculativeDistance;
        if (c.solver == "soft") {
            j["subSteps"] = c.subSteps;
            j["relaxIterations"] = c.relaxIterations;
            j["jointSolver"] = c.jointSolver;
        }
    }
    if (c.engine == "box2d" || c.solver == "classic") {
        j["velocityIterations"] = c.velocityIterations;
        j["positionIterations"] = c.positionIterations;
    }
    return j;
}

json scenarioJson(const Scenario& s) {
    std::map<std::string, int> shapes;
    int dynamic = 0;
    for (const scenes::BodyDesc& b : s.scene.bodies) {
        dynamic += b.kind == scenes::BodyKind::Dynamic ? 1 : 0;
        for (const scenes::ShapeDesc& shape : b.shapes) {
            shapes[shapeKindName(shape.kind)] += 1;
        }
    }
    json checks = json::array();
    for (const Check& c : s.checks) {
        checks.push_back({{"type", checkKindName(c.kind)}, {"body", c.body}});
    }
    json joints = json::object();
    for (const scenes::JointDesc& j : s.scene.joints) {
        const std::string kind = scenes::jointKindName(j.kind);
        joints[kind] = joints.value(kind, 0) + 1;
    }
    return {{"name", s.name},
            {"family", s.family},
            {"description", s.description},
            {"measures", s.measures},
            {"file", s.file},
            {"duration", s.duration},
            {"settle", s.settle},
            {"timeStep", s.scene.timeStep},
            {"gravity", {s.scene.gravity.x, s.scene.gravity.y}},
            {"bodies", s.scene.bodies.size()},
            {"dynamicBodies", dynamic},
            {"shapes", shapes},
            {"joints", joints},
            {"quick", s.quick},
            {"sweep", s.sweep},
            {"hardCase", s.hardCase},
            {"checks", checks}};
}

json runJson(const Report& report, const RunResult& r) {
    const Metrics& m = r.metrics;
    json metrics{{"msMedian", number(m.msMedian)},
                 {"msP95", number(m.msP95)},
                 {"maxPenetration", number(m.maxPenetration)},
                 {"maxSpeed", number(m.maxSpeed)},
                 {"finalKineticEnergy", number(m.finalKineticEnergy)},
                 {"topDrift", m.topDrift ? number(*m.topDrift) : json(nullptr)},
                 {"standing", m.standing ? json(*m.standing) : json(nullptr)},
                 {"timeToSleep", m.timeToSleep ? number(*m.timeToSleep) : json(nullptr)}};
    json checks = json::array();
    for (const CheckResult& c : r.checks) {
        checks.push_back({{"type", c.kind},
                          {"body", c.body},
                          {"quantity", c.quantity},
                          {"expected", number(c.expected)},
                          {"measured", number(c.measured)},
                          {"error", number(c.error)},
                          {"tolerance", number(c.tolerance)},
                          {"passed", c.passed},
                          {"detail", c.detail}});
    }
    json series = json::array();
    for (const Series& s : r.series) {
        json e = s.expected.empty() ? json(nullptr) : json(s.expected);
        series.push_back({{"name", s.name},
                          {"unit", s.unit},
                          {"t", s.t},
                          {"measured", s.measured},
                          {"expected", e}});
    }
    json j{{"scenario", report.scenarios[static_cast<std::size_t>(r.spec.scenario)].name},
           {"role", runRoleName(r.spec.role)},
           {"variant", r.spec.variant},
           {"config", configJson(r.spec.config)},
           {"bodies", r.bodies},
           {"steps", r.steps},
           {"seconds", number(r.seconds)},
           {"passed", r.passed},
           {"normalizedError", number(r.normalizedError)},
           {"metrics", metrics},
           {"checks", checks}};
    if (!series.empty()) {
        j["series"] = series;
    }
    if (!r.failure.empty()) {
        j["failure"] = r.failure;
    }
    return j;
}

} // namespace

json reportToJson(const Report& report) {
    const Environment& e = report.env;
    json env{{"e2dVersion", e.e2dVersion},
             {"box2dVersion", e.box2dVersion},
             {"compiler", e.compiler},
             {"buildType", e.buildType},
             {"flags", e.flags},
             {"cpu", e.cpu},
             {"cores", e.cores},
             {"threads", e.threads},
             {"date", e.date},
             {"command", e.command},
             {"sweep", e.sweep},
             {"wallSeconds", number(e.wallSeconds)}};
    json engines = json::array();
    for (const RunResult& r : report.runs) {
        if (r.spec.role != RunRole::Baseline || r.spec.scenario != 0) {
            continue;
        }
        json c = configJson(r.spec.config);
        c["translation"] = translationNotes(r.spec.config);
        engines.push_back(c);
    }
    json scenarios = json::array();
    for (const Scenario& s : report.scenarios) {
        scenarios.push_back(scenarioJson(s));
    }
    json runs = json::array();
    for (const RunResult& r : report.runs) {
        runs.push_back(runJson(report, r));
    }
    json summary = json::array();
    const auto table = summaryTable(report);
    for (std::size_t i = 0; i < table.size(); ++i) {
        json row{{"scenario", report.scenarios[i].name}, {"family", report.scenarios[i].family}};
        for (const auto& [family, cell] : table[i]) {
            if (cell.run != nullptr) {
                row["engines"][family] = {{"passed", cell.run->passed},
                                          {"normalizedError", number(cell.run->normalizedError)},
                                          {"msMedian", number(cell.run->metrics.msMedian)},
                                          {"worseThanBox2D", cell.worseThanReference}};
            }
        }
        summary.push_back(row);
    }
    json hardCases = json::array();
    for (const HardCaseRow& row : hardCaseTable(report)) {
        json passed = json::object();
        for (const auto& [family, run] : row.runs) {
            if (run != nullptr) {
                passed[family] = run->passed;
            }
        }
        hardCases.push_back({{"scenario", report.scenarios[row.scenario].name},
                             {"passed", passed},
                             {"numbers", row.numbers}});
    }
    json sweeps = json::object();
    for (const auto& [family, engineCurves] : sweepCurves(report)) {
        for (const auto& [engine, curve] : engineCurves) {
            json points = json::array();
            for (const SweepPoint& p : curve) {
                points.push_back({{"label", p.label},
                                  {"ms", number(p.ms)},
                                  {"error", number(p.error)},
                                  {"failed", p.failed},
                                  {"scenarios", p.scenarios}});
            }
            sweeps[family][engine] = points;
        }
    }
    json features = json::object();
    for (const auto& [family, engineCosts] : featureCosts(report)) {
        for (const auto& [engine, costs] : engineCosts) {
            json list = json::array();
            for (const FeatureCost& c : costs) {
                list.push_back({{"feature", c.feature},
                                {"baselineMs", number(c.baselineMs)},
                                {"ms", number(c.ms)},
                                {"baselineError", number(c.baselineError)},
                                {"error", number(c.error)},
                                {"baselineFailed", c.baselineFailed},
                                {"failed", c.failed},
                                {"scenarios", c.scenarios}});
            }
            features[family][engine] = list;
        }
    }
    return {{"tool", "e2d-validate"}, {"environment", env},
            {"engines", engines},     {"passed", exitStatus(report) == 0},
            {"hardCases", hardCases}, {"summary", summary},
            {"sweeps", sweeps},       {"features", features},
            {"scenarios", scenarios}, {"runs", runs}};
}

} // namespace e2d::validation
