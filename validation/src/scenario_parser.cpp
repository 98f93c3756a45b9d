// SPDX-License-Identifier: MIT
#include "scenario_parser.hpp"

#include "generators.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>

namespace e2d::validation {
namespace {

using nlohmann::json;

std::string show(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

std::string typeName(const json& value) {
    if (value.is_number()) {
        return "number";
    }
    return value.type_name();
}

[[noreturn]] void fail(const std::string& path, const std::string& message) {
    throw ScenarioError(path + ": " + message);
}

std::string join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
}

// One JSON object being read: every field read is remembered so that the fields nobody read
// (typos, fields of another shape type) are reported by finish().
class Object {
public:
    Object(const json& value, std::string path) : value_(value), path_(std::move(path)) {
        if (!value_.is_object()) {
            fail(path_.empty() ? "(root)" : path_, "expected an object, got " + typeName(value_));
        }
    }

    [[nodiscard]] const std::string& path() const { return path_; }
    [[nodiscard]] std::string at(const std::string& key) const { return join(path_, key); }

    [[nodiscard]] bool has(const std::string& key) const { return value_.contains(key); }

    const json* get(const std::string& key) {
        used_.insert(key);
        auto it = value_.find(key);
        return it == value_.end() ? nullptr : &*it;
    }

    const json& require(const std::string& key) {
        const json* value = get(key);
        if (value == nullptr) {
            fail(at(key), "required field is missing");
        }
        return *value;
    }

    float number(const std::string& key, float fallback) {
        const json* value = get(key);
        return value == nullptr ? fallback : toNumber(*value, at(key));
    }
    float requireNumber(const std::string& key) { return toNumber(require(key), at(key)); }

    // A number with a bound: "> lo" when `strict`, ">= lo" otherwise.
    float numberAbove(const std::string& key, float fallback, float lo, bool strict) {
        const float v = number(key, fallback);
        checkAbove(v, at(key), lo, strict);
        return v;
    }

    int integer(const std::string& key, int fallback, int lo, int hi) {
        const json* value = get(key);
        if (value == nullptr) {
            return fallback;
        }
        if (!value->is_number_integer()) {
            fail(at(key), "expected an integer, got " +
                              (value->is_number() ? show(value->get<double>()) : typeName(*value)));
        }
        const auto v = value->get<long long>();
        if (v < lo || v > hi) {
            fail(at(key), "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                              "], got " + std::to_string(v));
        }
        return static_cast<int>(v);
    }

    bool boolean(const std::string& key, bool fallback) {
        const json* value = get(key);
        if (value == nullptr) {
            return fallback;
        }
        if (!value->is_boolean()) {
            fail(at(key), "expected true or false, got " + typeName(*value));
        }
        return value->get<bool>();
    }

    std::string string(const std::string& key, const std::string& fallback) {
        const json* value = get(key);
        if (value == nullptr) {
            return fallback;
        }
        if (!value->is_string()) {
            fail(at(key), "expected a string, got " + typeName(*value));
        }
        return value->get<std::string>();
    }

    glm::vec2 vec2(const std::string& key, glm::vec2 fallback) {
        const json* value = get(key);
        return value == nullptr ? fallback : toVec2(*value, at(key));
    }

    // An angle given either as "<key>" (radians) or "<key>Deg" (degrees), not both.
    float angle(const std::string& key, float fallback) {
        const std::string degKey = key + "Deg";
        if (has(key) && has(degKey)) {
            fail(at(degKey), "give either " + key + " (radians) or " + degKey + ", not both");
        }
        if (has(degKey)) {
            return number(degKey, 0.0f) * std::numbers::pi_v<float> / 180.0f;
        }
        return number(key, fallback);
    }

    void finish() const {
        for (auto it = value_.begin(); it != value_.end(); ++it) {
            if (!used_.contains(it.key())) {
                fail(at(it.key()), "unknown field");
            }
        }
    }

    static float toNumber(const json& value, const std::string& path) {
        if (!value.is_number()) {
            fail(path, "expected a number, got " + typeName(value));
        }
        const double v = value.get<double>();
        if (!std::isfinite(v) || std::abs(v) > 1.0e30) {
            fail(path, "must be a finite float, got " + show(v));
        }
        return static_cast<float>(v);
    }

    static glm::vec2 toVec2(const json& value, const std::string& path) {
        if (!value.is_array() || value.size() != 2) {
            fail(path, "expected [x, y], got " +
                           (value.is_array() ? "an array of " + std::to_string(value.size())
                                             : typeName(value)));
        }
        return {toNumber(value[0], path + "[0]"), toNumber(value[1], path + "[1]")};
    }

    static void checkAbove(float v, const std::string& path, float lo, bool strict) {
        if (strict ? !(v > lo) : !(v >= lo)) {
            fail(path, std::string("must be ") + (strict ? "> " : ">= ") + show(lo) + ", got " +
                           show(v));
        }
    }

private:
    const json& value_;
    std::string path_;
    std::set<std::string> used_;
};

const json& requireArray(const json& value, const std::string& path) {
    if (!value.is_array()) {
        fail(path, "expected an array, got " + typeName(value));
    }
    return value;
}

std::string indexed(const std::string& path, std::size_t i) {
    return path + "[" + std::to_string(i) + "]";
}

scenes::ShapeDesc parseShape(const json& value, const std::string& path) {
    Object o(value, path);
    scenes::ShapeDesc shape;
    const std::string type = o.string("type", "");
    shape.density = o.numberAbove("density", 1.0f, 0.0f, false);
    shape.friction = o.numberAbove("friction", 0.6f, 0.0f, false);
    shape.restitution = o.numberAbove("restitution", 0.0f, 0.0f, false);
    if (type == "box") {
        shape.kind = scenes::ShapeKind::Box;
        shape.halfExtents = o.vec2("halfExtents", {0.5f, 0.5f});
        Object::checkAbove(shape.halfExtents.x, o.at("halfExtents") + "[0]", 0.0f, true);
        Object::checkAbove(shape.halfExtents.y, o.at("halfExtents") + "[1]", 0.0f, true);
        shape.center = o.vec2("center", {0.0f, 0.0f});
        shape.angle = o.angle("angle", 0.0f);
    } else if (type == "polygon") {
        shape.kind = scenes::ShapeKind::Polygon;
        const json& points = requireArray(o.require("points"), o.at("points"));
        if (points.size() < 3 || points.size() > 8) {
            fail(o.at("points"), "needs 3 to 8 points, got " + std::to_string(points.size()));
        }
        for (std::size_t i = 0; i < points.size(); ++i) {
            shape.points.push_back(Object::toVec2(points[i], indexed(o.at("points"), i)));
        }
        // Twice the signed area: a degenerate (collinear) polygon has none.
        float area2 = 0.0f;
        for (std::size_t i = 0; i < shape.points.size(); ++i) {
            const glm::vec2 a = shape.points[i];
            const glm::vec2 b = shape.points[(i + 1) % shape.points.size()];
            area2 += a.x * b.y - a.y * b.x;
        }
        if (std::abs(area2) < 1.0e-6f) {
            fail(o.at("points"), "the points enclose no area");
        }
        shape.radius = o.numberAbove("radius", 0.0f, 0.0f, false);
    } else if (type == "circle") {
        shape.kind = scenes::ShapeKind::Circle;
        shape.radius = o.requireNumber("radius");
        Object::checkAbove(shape.radius, o.at("radius"), 0.0f, true);
        shape.center = o.vec2("center", {0.0f, 0.0f});
    } else if (type == "capsule" || type == "segment") {
        shape.kind = type == "capsule" ? scenes::ShapeKind::Capsule : scenes::ShapeKind::Segment;
        shape.point1 = Object::toVec2(o.require("point1"), o.at("point1"));
        shape.point2 = Object::toVec2(o.require("point2"), o.at("point2"));
        const glm::vec2 d = shape.point2 - shape.point1;
        if (d.x * d.x + d.y * d.y < 1.0e-8f) {
            fail(o.at("point2"), "must differ from point1");
        }
        if (type == "capsule") {
            shape.radius = o.requireNumber("radius");
            Object::checkAbove(shape.radius, o.at("radius"), 0.0f, true);
        }
    } else {
        fail(o.at("type"), "expected box, polygon, circle, capsule or segment, got \"" + type + "\"");
    }
    o.finish();
    return shape;
}

scenes::BodyKind parseBodyKind(Object& o) {
    const std::string type = o.string("type", "dynamic");
    if (type == "static") {
        return scenes::BodyKind::Static;
    }
    if (type == "kinematic") {
        return scenes::BodyKind::Kinematic;
    }
    if (type == "dynamic") {
        return scenes::BodyKind::Dynamic;
    }
    fail(o.at("type"), "expected static, kinematic or dynamic, got \"" + type + "\"");
}

scenes::BodyDesc parseBody(const json& value, const std::string& path) {
    Object o(value, path);
    scenes::BodyDesc body;
    body.kind = parseBodyKind(o);
    body.position = o.vec2("position", {0.0f, 0.0f});
    body.angle = o.angle("angle", 0.0f);
    body.linearVelocity = o.vec2("linearVelocity", {0.0f, 0.0f});
    body.angularVelocity = o.number("angularVelocity", 0.0f);
    body.bullet = o.boolean("bullet", false);
    body.fixedRotation = o.boolean("fixedRotation", false);
    body.tag = o.string("tag", "");
    if (o.has("shape") && o.has("shapes")) {
        fail(o.at("shapes"), "give either shape or shapes, not both");
    }
    if (o.has("shape")) {
        body.shapes.push_back(parseShape(o.require("shape"), o.at("shape")));
    } else {
        const json& shapes = requireArray(o.require("shapes"), o.at("shapes"));
        if (shapes.empty()) {
            fail(o.at("shapes"), "a body needs at least one shape");
        }
        for (std::size_t i = 0; i < shapes.size(); ++i) {
            body.shapes.push_back(parseShape(shapes[i], indexed(o.at("shapes"), i)));
        }
    }
    o.finish();
    return body;
}

LayoutParams parseLayout(Object& o, const std::string& defaultTag) {
    LayoutParams p;
    p.origin = o.vec2("origin", {0.0f, 0.0f});
    p.half = o.numberAbove("half", 0.5f, 0.0f, true);
    p.friction = o.numberAbove("friction", 0.6f, 0.0f, false);
    p.density = o.numberAbove("density", 1.0f, 0.0f, true);
    p.restitution = o.numberAbove("restitution", 0.0f, 0.0f, false);
    p.ground = o.boolean("ground", true);
    p.tag = o.string("tag", defaultTag);
    return p;
}

void parseGenerator(const json& value, const std::string& path, scenes::SceneDesc& scene) {
    Object o(value, path);
    const std::string type = o.string("type", "");
    if (type == "verticalStack") {
        const int count = o.integer("count", 10, 1, 1000);
        addVerticalStack(scene, count, parseLayout(o, "top"));
    } else if (type == "pyramid") {
        const int base = o.integer("base", 10, 1, 200);
        addPyramid(scene, base, parseLayout(o, "top"));
    } else if (type == "dominoes") {
        const int count = o.integer("count", 10, 1, 1000);
        const float spacing = o.numberAbove("spacing", 0.5f, 0.0f, true);
        const float push = o.number("push", -1.0f);
        addDominoes(scene, count, spacing, push, parseLayout(o, "last"));
    } else if (type == "grid") {
        const int columns = o.integer("columns", 10, 1, 1000);
        const int rows = o.integer("rows", 10, 1, 1000);
        const glm::vec2 spacing = o.vec2("spacing", {1.0f, 1.0f});
        const scenes::ShapeDesc shape = parseShape(o.require("shape"), o.at("shape"));
        LayoutParams p = parseLayout(o, "last");
        p.ground = false;
        addGrid(scene, columns, rows, spacing, shape, p);
    } else {
        fail(o.at("type"),
             "expected verticalStack, pyramid, dominoes or grid, got \"" + type + "\"");
    }
    o.finish();
}

struct CheckName {
    const char* name;
    CheckKind kind;
};
constexpr CheckName kCheckNames[] = {
    {"standing", CheckKind::Standing},
    {"maxPenetration", CheckKind::MaxPenetration},
    {"maxSpeed", CheckKind::MaxSpeed},
    {"bounceHeight", CheckKind::BounceHeight},
    {"slideDistance", CheckKind::SlideDistance},
    {"stoppingDistance", CheckKind::StoppingDistance},
    {"rollingDistance", CheckKind::RollingDistance},
    {"momentum", CheckKind::Momentum},
    {"kineticEnergy", CheckKind::KineticEnergy},
    {"velocity", CheckKind::Velocity},
    {"bounds", CheckKind::Bounds},
    {"sleep", CheckKind::Sleep},
};

Check parseCheck(const json& value, const std::string& path, const Scenario& scenario) {
    Object o(value, path);
    Check c;
    const std::string type = o.string("type", "");
    bool known = false;
    for (const CheckName& n : kCheckNames) {
        if (type == n.name) {
            c.kind = n.kind;
            known = true;
        }
    }
    if (!known) {
        std::string names;
        for (const CheckName& n : kCheckNames) {
            names += names.empty() ? n.name : std::string(", ") + n.name;
        }
        fail(o.at("type"), "expected one of " + names + ", got \"" + type + "\"");
    }
    const bool needsBody = c.kind != CheckKind::MaxPenetration && c.kind != CheckKind::MaxSpeed &&
                           c.kind != CheckKind::Momentum && c.kind != CheckKind::KineticEnergy &&
                           c.kind != CheckKind::Sleep;
    if (needsBody) {
        c.body = o.string("body", "");
        bool found = false;
        for (const scenes::BodyDesc& b : scenario.scene.bodies) {
            found = found || (!c.body.empty() && b.tag == c.body);
        }
        if (!found) {
            fail(o.at("body"), "no body has tag \"" + c.body + "\"");
        }
    }
    auto positive = [&](const char* key) {
        const float v = o.requireNumber(key);
        Object::checkAbove(v, o.at(key), 0.0f, true);
        return v;
    };
    auto tolerance = [&] { c.tolerance = positive("tolerance"); };
    auto timeWithin = [&](const char* key) {
        const float t = positive(key);
        if (t > scenario.duration) {
            fail(o.at(key), "must be <= duration (" + show(scenario.duration) + "), got " + show(t));
        }
        return t;
    };
    switch (c.kind) {
    case CheckKind::Standing:
        tolerance();
        c.minY = o.requireNumber("minY");
        break;
    case CheckKind::MaxPenetration:
    case CheckKind::MaxSpeed:
        c.limit = positive("limit");
        break;
    case CheckKind::BounceHeight:
        tolerance();
        c.height = positive("height");
        c.restY = o.requireNumber("restY");
        c.restitution = o.requireNumber("restitution");
        if (!(c.restitution >= 0.0f && c.restitution <= 1.0f)) {
            fail(o.at("restitution"), "must be in [0, 1], got " + show(c.restitution));
        }
        break;
    case CheckKind::SlideDistance:
    case CheckKind::RollingDistance:
        tolerance();
        c.slopeAngle = o.angle("slope", 0.0f);
        if (!(c.slopeAngle > 0.0f && c.slopeAngle < 0.5f * std::numbers::pi_v<float>)) {
            fail(o.at("slopeDeg"), "the slope must be in (0, 90) degrees, got " +
                                       show(c.slopeAngle * 180.0f / std::numbers::pi_v<float>));
        }
        if (c.kind == CheckKind::SlideDistance) {
            c.friction = o.numberAbove("friction", 0.0f, 0.0f, false);
        }
        c.time = timeWithin("time");
        break;
    case CheckKind::StoppingDistance:
        tolerance();
        c.friction = positive("friction");
        c.speed = positive("speed");
        break;
    case CheckKind::Momentum:
        tolerance();
        break;
    case CheckKind::KineticEnergy:
        tolerance();
        c.ratio = o.numberAbove("ratio", 1.0f, 0.0f, false);
        break;
    case CheckKind::Velocity:
        tolerance();
        c.velocity = Object::toVec2(o.require("velocity"), o.at("velocity"));
        break;
    case CheckKind::Bounds:
        c.lower = Object::toVec2(o.require("lower"), o.at("lower"));
        c.upper = Object::toVec2(o.require("upper"), o.at("upper"));
        if (!(c.lower.x < c.upper.x && c.lower.y < c.upper.y)) {
            fail(o.at("upper"), "must be above and right of lower");
        }
        break;
    case CheckKind::Sleep:
        c.time = timeWithin("time");
        break;
    }
    o.finish();
    return c;
}

void parseSettings(Object& root, Scenario& scenario) {
    const json* settings = root.get("settings");
    if (settings == nullptr) {
        return;
    }
    Object s(*settings, root.at("settings"));
    for (const char* engine : {"box2d", "e2d"}) {
        const json* value = s.get(engine);
        if (value == nullptr) {
            continue;
        }
        Object e(*value, s.at(engine));
        SettingsOverride over;
        auto optInt = [&](const char* key, std::optional<int>& out, int lo, int hi) {
            if (e.has(key)) {
                out = e.integer(key, 0, lo, hi);
            }
        };
        optInt("velocityIterations", over.velocityIterations, 0, 100);
        optInt("positionIterations", over.positionIterations, 0, 100);
        if (std::string(engine) == "e2d") {
            optInt("subSteps", over.subSteps, 1, 64);
            optInt("relaxIterations", over.relaxIterations, 0, 16);
        }
        if (e.has("continuous")) {
            over.continuous = e.boolean("continuous", true);
        }
        if (e.has("sleeping")) {
            over.sleeping = e.boolean("sleeping", true);
        }
        e.finish();
        scenario.settings[engine] = over;
    }
    s.finish();
}

} // namespace

Scenario parseScenario(std::string_view text, const std::string& fallbackName) {
    json document;
    try {
        document = json::parse(text.begin(), text.end());
    } catch (const json::parse_error& e) {
        // nlohmann's message carries line and column.
        fail("(root)", std::string("not valid JSON: ") + e.what());
    }
    Object root(document, "");
    Scenario s;
    s.name = root.string("name", fallbackName);
    if (s.name.empty()) {
        fail("name", "must not be empty");
    }
    s.family = root.string("family", "");
    const std::set<std::string> families{"stacking", "friction", "restitution", "conservation",
                                         "hard"};
    if (!families.contains(s.family)) {
        fail("family", "expected stacking, friction, restitution, conservation or hard, got \"" +
                           s.family + "\"");
    }
    s.description = root.string("description", "");
    s.measures = root.string("measures", "");
    s.duration = root.numberAbove("duration", 5.0f, 0.0f, true);
    if (s.duration > 600.0f) {
        fail("duration", "must be <= 600 s, got " + show(s.duration));
    }
    s.settle = root.numberAbove("settle", std::min(1.0f, 0.5f * s.duration), 0.0f, false);
    if (s.settle >= s.duration) {
        fail("settle", "must be < duration (" + show(s.duration) + "), got " + show(s.settle));
    }
    s.quick = root.boolean("quick", false);
    s.sweep = root.boolean("sweep", true);
    s.scaling = root.string("scaling", "");
    s.scene.name = s.name;
    s.scene.gravity = root.vec2("gravity", {0.0f, -10.0f});
    s.scene.timeStep = root.numberAbove("timeStep", 1.0f / 60.0f, 0.0f, true);
    if (s.scene.timeStep > 0.1f) {
        fail("timeStep", "must be <= 0.1 s, got " + show(s.scene.timeStep));
    }
    parseSettings(root, s);

    if (const json* generators = root.get("generators")) {
        requireArray(*generators, "generators");
        for (std::size_t i = 0; i < generators->size(); ++i) {
            parseGenerator((*generators)[i], indexed("generators", i), s.scene);
        }
    }
    if (const json* bodies = root.get("bodies")) {
        requireArray(*bodies, "bodies");
        for (std::size_t i = 0; i < bodies->size(); ++i) {
            s.scene.bodies.push_back(parseBody((*bodies)[i], indexed("bodies", i)));
        }
    }
    if (s.scene.bodies.empty()) {
        fail("bodies", "the scene has no bodies (give bodies or generators)");
    }
    if (const json* checks = root.get("checks")) {
        requireArray(*checks, "checks");
        for (std::size_t i = 0; i < checks->size(); ++i) {
            s.checks.push_back(parseCheck((*checks)[i], indexed("checks", i), s));
        }
    }
    root.finish();
    return s;
}

Scenario loadScenario(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        throw ScenarioError(file.string() + ": cannot open the file");
    }
    std::stringstream text;
    text << in.rdbuf();
    try {
        Scenario s = parseScenario(text.str(), file.stem().string());
        s.file = file.string();
        return s;
    } catch (const ScenarioError& e) {
        throw ScenarioError(file.string() + ": " + e.what());
    }
}

const char* checkKindName(CheckKind kind) {
    for (const CheckName& n : kCheckNames) {
        if (n.kind == kind) {
            return n.name;
        }
    }
    return "?";
}

} // namespace e2d::validation
