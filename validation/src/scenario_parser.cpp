// SPDX-License-Identifier: MIT
#include "scenario_parser.hpp"

#include "generators.hpp"

#include <e2d/core/error_text.hpp>
#include <e2d/core/json_scan.hpp>
#include <e2d/core/printable.hpp>
#include <e2d/core/text_file.hpp>
#include <e2d/physics/constants.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <vector>

namespace e2d::validation {
namespace {

using nlohmann::json;

std::string typeName(const json& value) {
    if (value.is_number()) {
        return "number";
    }
    return value.type_name();
}

// Keys and strings quoted from the file may hold any character JSON can escape (a NUL would
// cut what() short): the message is made printable here, once.
// `at` places a problem of the text itself (malformed JSON); the others are placed by `path`.
[[noreturn]] void fail(const std::string& path, const std::string& message,
                       core::TextPosition at = {0, 0}) {
    throw ScenarioError(core::Diagnostic{core::Severity::Error,
                                         {},
                                         at.line,
                                         at.column,
                                         core::printable(path),
                                         core::printable(message)});
}

// A key as the path names it: the empty key (valid JSON) as "", so the message still says where.
std::string join(const std::string& path, const std::string& key) {
    const std::string name = key.empty() ? "\"\"" : key;
    return path.empty() ? name : path + "." + name;
}

// Edit distance (insertions, deletions, substitutions, each 1), for "did you mean".
std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) {
        row[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                              std::tolower(static_cast<unsigned char>(b[j - 1]));
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

// The candidate nearest to `word`, if it is near enough to be a typo of it; a candidate that
// the word begins (a name cut short: "bounce" for "bounceHeight") comes first.
std::string nearest(const std::string& word, const std::vector<std::string>& candidates) {
    for (const std::string& c : candidates) {
        if (word.size() >= 3 && c.size() > word.size() && c.compare(0, word.size(), word) == 0) {
            return c;
        }
    }
    std::string best;
    std::size_t bestDistance = std::max<std::size_t>(2, word.size() / 3) + 1;
    for (const std::string& c : candidates) {
        const std::size_t d = editDistance(word, c);
        if (d < bestDistance) {
            best = c;
            bestDistance = d;
        }
    }
    return best;
}

std::string suggestion(const std::string& word, const std::vector<std::string>& candidates) {
    const std::string near = nearest(word, candidates);
    return near.empty() ? "" : " (did you mean \"" + near + "\"?)";
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
                              (value->is_number() ? core::formatNumber(value->get<double>())
                                                  : typeName(*value)));
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

    // A required string naming a kind: missing, wrong type and unknown values each say so,
    // an unknown value with the nearest valid one.
    std::string choice(const std::string& key, const std::vector<std::string>& valid) {
        const json* value = get(key);
        std::string list;
        for (std::size_t i = 0; i < valid.size(); ++i) {
            list += (i == 0 ? "" : i + 1 == valid.size() ? " or " : ", ") + valid[i];
        }
        if (value == nullptr) {
            fail(at(key), "required field is missing (one of " + list + ")");
        }
        if (!value->is_string()) {
            fail(at(key), "expected a string, got " + typeName(*value));
        }
        const std::string got = value->get<std::string>();
        if (std::find(valid.begin(), valid.end(), got) == valid.end()) {
            fail(at(key), "expected " + list + ", got \"" + got + "\"" + suggestion(got, valid));
        }
        return got;
    }

    // Every field must have been read: the others are typos or fields of another kind of
    // object; the message suggests the nearest field this object has.
    void finish() const {
        const std::vector<std::string> known(used_.begin(), used_.end());
        for (auto it = value_.begin(); it != value_.end(); ++it) {
            if (!used_.contains(it.key())) {
                fail(at(it.key()), "unknown field" + suggestion(it.key(), known));
            }
        }
    }

    static float toNumber(const json& value, const std::string& path) {
        if (!value.is_number()) {
            fail(path, "expected a number, got " + typeName(value));
        }
        const double v = value.get<double>();
        if (!std::isfinite(v) || std::abs(v) > 1.0e30) {
            fail(path, "must be a finite float, got " + core::formatNumber(v));
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

    // e2d refuses coordinates, sizes and densities beyond physics::kHuge; saying so here names
    // the real limit instead of a confusing error from inside a run.
    static void checkWithinE2d(float v, const std::string& path) {
        if (std::abs(v) > physics::kHuge) {
            fail(path, "must be within e2d's limit of " + core::formatNumber(physics::kHuge) +
                           " (physics::kHuge: metres for positions and sizes, kg/m^2 for "
                           "density), got " +
                           core::formatNumber(v));
        }
    }
    static void checkWithinE2d(glm::vec2 v, const std::string& path) {
        checkWithinE2d(v.x, path + "[0]");
        checkWithinE2d(v.y, path + "[1]");
    }

    static void checkAbove(float v, const std::string& path, float lo, bool strict) {
        if (strict ? !(v > lo) : !(v >= lo)) {
            fail(path, std::string("must be ") + (strict ? "> " : ">= ") + core::formatNumber(lo) +
                           ", got " + core::formatNumber(v));
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

// A chain's points, loop, ghost points and per-segment materials, with e2d's createChain()
// rules (consecutive points at least kLinearSlop apart, a loop has no ghosts) said here.
void parseChain(Object& o, scenes::ShapeDesc& shape) {
    constexpr std::size_t kMaxChainPoints = 10000;
    shape.kind = scenes::ShapeKind::Chain;
    shape.loop = o.boolean("loop", false);
    const json& points = requireArray(o.require("points"), o.at("points"));
    const std::size_t minimum = shape.loop ? 3 : 2;
    if (points.size() < minimum || points.size() > kMaxChainPoints) {
        fail(o.at("points"), std::string(shape.loop ? "a loop" : "a chain") + " needs " +
                                 std::to_string(minimum) + " to " +
                                 std::to_string(kMaxChainPoints) + " points, got " +
                                 std::to_string(points.size()));
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::vec2 p = Object::toVec2(points[i], indexed(o.at("points"), i));
        Object::checkWithinE2d(p, indexed(o.at("points"), i));
        shape.points.push_back(p);
    }
    const std::size_t n = shape.points.size();
    const std::size_t segments = shape.loop ? n : n - 1;
    for (std::size_t i = 0; i < segments; ++i) {
        const std::size_t next = (i + 1) % n;
        const glm::vec2 d = shape.points[next] - shape.points[i];
        const float gap = std::sqrt(d.x * d.x + d.y * d.y);
        if (!(gap >= physics::kLinearSlop)) {
            fail(indexed(o.at("points"), next), "must be at least physics::kLinearSlop (" +
                                                    core::formatNumber(physics::kLinearSlop) +
                                                    " m) from points[" + std::to_string(i) +
                                                    "], got " + core::formatNumber(gap));
        }
    }
    for (const char* key : {"ghostBefore", "ghostAfter"}) {
        if (!o.has(key)) {
            continue;
        }
        if (shape.loop) {
            fail(o.at(key), "a loop has no ends, so no ghost points");
        }
        const glm::vec2 ghost = Object::toVec2(*o.get(key), o.at(key));
        Object::checkWithinE2d(ghost, o.at(key));
        (std::string(key) == "ghostBefore" ? shape.ghostBefore : shape.ghostAfter) = ghost;
    }
    if (const json* materials = o.get("materials")) {
        requireArray(*materials, o.at("materials"));
        if (materials->size() != 1 && materials->size() != segments) {
            fail(o.at("materials"), "give one material or one per segment (" +
                                        std::to_string(segments) + "), got " +
                                        std::to_string(materials->size()));
        }
        for (std::size_t i = 0; i < materials->size(); ++i) {
            Object m((*materials)[i], indexed(o.at("materials"), i));
            scenes::ChainMaterial material;
            material.friction = m.numberAbove("friction", shape.friction, 0.0f, false);
            material.restitution = m.numberAbove("restitution", shape.restitution, 0.0f, false);
            if (material.restitution > 1.0f) {
                fail(m.at("restitution"), "must be in [0, 1] (e2d's limit), got " +
                                              core::formatNumber(material.restitution));
            }
            m.finish();
            shape.materials.push_back(material);
        }
    }
}

scenes::ShapeDesc parseShape(const json& value, const std::string& path) {
    Object o(value, path);
    scenes::ShapeDesc shape;
    const std::string type =
        o.choice("type", {"box", "polygon", "circle", "capsule", "segment", "chain"});
    shape.density = o.numberAbove("density", 1.0f, 0.0f, false);
    shape.friction = o.numberAbove("friction", 0.6f, 0.0f, false);
    shape.restitution = o.numberAbove("restitution", 0.0f, 0.0f, false);
    if (shape.restitution > 1.0f) {
        fail(o.at("restitution"),
             "must be in [0, 1] (e2d's limit), got " + core::formatNumber(shape.restitution));
    }
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
        // e2d welds points closer than kLinearSlop; say so here rather than in a failed run.
        std::vector<glm::vec2> distinct;
        for (glm::vec2 p : shape.points) {
            const bool near = std::any_of(distinct.begin(), distinct.end(), [&](glm::vec2 q) {
                const glm::vec2 d = p - q;
                return d.x * d.x + d.y * d.y < physics::kLinearSlop * physics::kLinearSlop;
            });
            if (!near) {
                distinct.push_back(p);
            }
        }
        if (distinct.size() < 3) {
            fail(o.at("points"), "e2d welds points closer than physics::kLinearSlop (" +
                                     core::formatNumber(physics::kLinearSlop) +
                                     " m): " + std::to_string(distinct.size()) + " of " +
                                     std::to_string(shape.points.size()) +
                                     " are distinct, a polygon needs 3");
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
    } else if (type == "chain") {
        parseChain(o, shape);
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
    }
    Object::checkWithinE2d(shape.density, o.at("density"));
    Object::checkWithinE2d(shape.radius, o.at("radius"));
    if (shape.kind == scenes::ShapeKind::Box) {
        Object::checkWithinE2d(shape.halfExtents, o.at("halfExtents"));
    }
    Object::checkWithinE2d(shape.center, o.at("center"));
    Object::checkWithinE2d(shape.point1, o.at("point1"));
    Object::checkWithinE2d(shape.point2, o.at("point2"));
    for (std::size_t i = 0; i < shape.points.size(); ++i) {
        Object::checkWithinE2d(shape.points[i], indexed(o.at("points"), i));
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
    fail(o.at("type"), "expected static, kinematic or dynamic, got \"" + type + "\"" +
                           suggestion(type, {"static", "kinematic", "dynamic"}));
}

scenes::BodyDesc parseBody(const json& value, const std::string& path, float duration) {
    Object o(value, path);
    scenes::BodyDesc body;
    body.kind = parseBodyKind(o);
    body.position = o.vec2("position", {0.0f, 0.0f});
    Object::checkWithinE2d(body.position, o.at("position"));
    body.angle = o.angle("angle", 0.0f);
    body.linearVelocity = o.vec2("linearVelocity", {0.0f, 0.0f});
    body.angularVelocity = o.number("angularVelocity", 0.0f);
    body.bullet = o.boolean("bullet", false);
    body.fixedRotation = o.boolean("fixedRotation", false);
    body.tag = o.string("tag", "");
    body.gravityScale = o.number("gravityScale", 1.0f);
    if (std::abs(body.gravityScale) > 1000.0f) {
        fail(o.at("gravityScale"),
             "must be in [-1000, 1000], got " + core::formatNumber(body.gravityScale));
    }
    body.force = o.vec2("force", {0.0f, 0.0f});
    if (const json* impulses = o.get("impulses")) {
        requireArray(*impulses, o.at("impulses"));
        for (std::size_t i = 0; i < impulses->size(); ++i) {
            Object im((*impulses)[i], indexed(o.at("impulses"), i));
            const float time = im.numberAbove("time", 0.0f, 0.0f, false);
            if (time > duration) {
                fail(im.at("time"), "must be <= duration (" + core::formatNumber(duration) +
                                        "), got " + core::formatNumber(time));
            }
            body.impulses.emplace_back(time,
                                       Object::toVec2(im.require("impulse"), im.at("impulse")));
            im.finish();
        }
    }
    if (body.kind != scenes::BodyKind::Dynamic &&
        (body.force != glm::vec2(0.0f) || !body.impulses.empty())) {
        fail(o.at(body.force != glm::vec2(0.0f) ? "force" : "impulses"),
             "only a dynamic body can be pushed");
    }
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
    Object::checkWithinE2d(p.origin, o.at("origin"));
    Object::checkWithinE2d(p.half, o.at("half"));
    Object::checkWithinE2d(p.density, o.at("density"));
    p.restitution = o.numberAbove("restitution", 0.0f, 0.0f, false);
    if (p.restitution > 1.0f) {
        fail(o.at("restitution"),
             "must be in [0, 1] (e2d's limit), got " + core::formatNumber(p.restitution));
    }
    p.ground = o.boolean("ground", true);
    p.tag = o.string("tag", defaultTag);
    return p;
}

void parseGenerator(const json& value, const std::string& path, scenes::SceneDesc& scene) {
    Object o(value, path);
    const std::string type = o.choice("type", {"verticalStack", "pyramid", "dominoes", "grid"});
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
    {"turn", CheckKind::Turn},
    {"moves", CheckKind::Moves},
    {"jointError", CheckKind::JointError},
    {"period", CheckKind::Period},
};

Check parseCheck(const json& value, const std::string& path, const Scenario& scenario) {
    Object o(value, path);
    Check c;
    std::vector<std::string> names;
    for (const CheckName& n : kCheckNames) {
        names.emplace_back(n.name);
    }
    const std::string type = o.choice("type", names);
    for (const CheckName& n : kCheckNames) {
        if (type == n.name) {
            c.kind = n.kind;
        }
    }
    const bool needsBody = c.kind != CheckKind::MaxPenetration && c.kind != CheckKind::MaxSpeed &&
                           c.kind != CheckKind::Momentum && c.kind != CheckKind::KineticEnergy &&
                           c.kind != CheckKind::Sleep && c.kind != CheckKind::JointError;
    // maxSpeed judges every dynamic body, or the tagged ones when it names a body.
    const bool optionalBody = c.kind == CheckKind::MaxSpeed && o.has("body");
    if (needsBody || optionalBody) {
        if (!o.has("body")) {
            fail(o.at("body"), "required field is missing (the tag of the body to check)");
        }
        c.body = o.string("body", "");
        std::vector<std::string> tags;
        for (const scenes::BodyDesc& b : scenario.scene.bodies) {
            if (!b.tag.empty() && std::find(tags.begin(), tags.end(), b.tag) == tags.end()) {
                tags.push_back(b.tag);
            }
        }
        if (std::find(tags.begin(), tags.end(), c.body) == tags.end()) {
            fail(o.at("body"), "no body has tag \"" + c.body + "\"" + suggestion(c.body, tags));
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
            fail(o.at(key), "must be <= duration (" + core::formatNumber(scenario.duration) +
                                "), got " + core::formatNumber(t));
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
            fail(o.at("restitution"),
                 "must be in [0, 1], got " + core::formatNumber(c.restitution));
        }
        break;
    case CheckKind::SlideDistance:
    case CheckKind::RollingDistance:
        tolerance();
        c.slopeAngle = o.angle("slope", 0.0f);
        if (!(c.slopeAngle > 0.0f && c.slopeAngle < 0.5f * std::numbers::pi_v<float>)) {
            fail(o.at("slopeDeg"),
                 "the slope must be in (0, 90) degrees, got " +
                     core::formatNumber(c.slopeAngle * 180.0f / std::numbers::pi_v<float>));
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
    case CheckKind::Turn: {
        if (o.has("minTurn") || o.has("minTurnDeg")) {
            c.minTurn = o.angle("minTurn", 0.0f);
            Object::checkAbove(*c.minTurn, o.at("minTurn"), 0.0f, true);
        }
        if (o.has("maxTurn") || o.has("maxTurnDeg")) {
            c.maxTurn = o.angle("maxTurn", 0.0f);
            Object::checkAbove(*c.maxTurn, o.at("maxTurn"), 0.0f, true);
        }
        if (!c.minTurn && !c.maxTurn) {
            fail(o.at("maxTurn"), "required field is missing (give minTurn, maxTurn or both, in "
                                  "radians, or minTurnDeg / maxTurnDeg)");
        }
        break;
    }
    case CheckKind::JointError: {
        c.limit = positive("limit");
        const bool measured = std::any_of(
            scenario.scene.joints.begin(), scenario.scene.joints.end(),
            [](const scenes::JointDesc& j) {
                return j.kind == scenes::JointKind::Revolute || j.kind == scenes::JointKind::Weld ||
                       j.kind == scenes::JointKind::Wheel ||
                       (j.kind == scenes::JointKind::Distance && !j.enableSpring && !j.enableLimit);
            });
        if (!measured) {
            fail(o.at("type"), "the scene has no joint this check measures (revolute, weld, wheel "
                               "or rigid distance)");
        }
        break;
    }
    case CheckKind::Period:
        c.period = positive("period");
        tolerance();
        break;
    case CheckKind::Moves: {
        c.distance = positive("distance");
        if (const json* direction = o.get("direction")) {
            const glm::vec2 d = Object::toVec2(*direction, o.at("direction"));
            const float length = std::sqrt(d.x * d.x + d.y * d.y);
            if (!(length > 0.0f)) {
                fail(o.at("direction"), "must not be [0, 0]");
            }
            c.direction = d / length;
        }
        break;
    }
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

// Follows the parse as a SAX handler to tell where a document that nlohmann rejects went
// wrong: the JSON path being read (`bodies[2].position[0]`) and the line and column.
class ErrorLocator final : public nlohmann::json_sax<json> {
public:
    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override {
        levels_.push_back({false, 0, {}});
        return true;
    }
    bool key(string_t& name) override {
        levels_.back().key = name;
        return true;
    }
    bool end_object() override {
        levels_.pop_back();
        return value();
    }
    bool start_array(std::size_t) override {
        levels_.push_back({true, 0, {}});
        return true;
    }
    bool end_array() override {
        levels_.pop_back();
        return value();
    }
    bool parse_error(std::size_t position, const std::string& token,
                     const nlohmann::detail::exception& error) override {
        // `position` counts the characters read: just past the offending character of a
        // syntax error, just past the whole literal of a number out of range.
        const std::size_t back =
            dynamic_cast<const json::out_of_range*>(&error) != nullptr ? token.size() : 1;
        position_ = position >= back ? position - back : 0;
        message_ = error.what();
        // "[json.exception.parse_error.101] parse error at line 1, column 9: ..." -> the reason.
        if (const auto bracket = message_.find("] "); bracket != std::string::npos) {
            message_ = message_.substr(bracket + 2);
        }
        return false;
    }

    [[nodiscard]] std::string path() const {
        std::string out;
        for (const Level& level : levels_) {
            if (level.array) {
                out += "[" + std::to_string(level.index) + "]";
            } else if (!level.key.empty()) {
                out += (out.empty() ? "" : ".") + level.key;
            }
        }
        return out.empty() ? "(root)" : out;
    }
    [[nodiscard]] std::size_t position() const { return position_; }
    [[nodiscard]] const std::string& message() const { return message_; }

private:
    struct Level {
        bool array;
        std::size_t index; // arrays: elements finished so far, so the one being read
        std::string key;   // objects: the key being read
    };
    bool value() {
        if (!levels_.empty() && levels_.back().array) {
            ++levels_.back().index;
        }
        return true;
    }
    std::vector<Level> levels_;
    std::size_t position_ = 0;
    std::string message_;
};

[[noreturn]] void failJson(std::string_view text) {
    ErrorLocator locator;
    static_cast<void>(json::sax_parse(text.begin(), text.end(), &locator));
    const core::TextPosition at = core::positionOf(text, locator.position());
    std::string reason = locator.message();
    // nlohmann's parse errors repeat the place; out-of-range numbers do not have one.
    const std::string lead = "parse error at line ";
    if (reason.rfind(lead, 0) == 0) {
        if (const auto colon = reason.find(": "); colon != std::string::npos) {
            reason = reason.substr(colon + 2);
        }
    }
    // The reason ends quoting the bytes nlohmann read, which need not be text (fail() escapes).
    fail(locator.path(), "not valid JSON: " + reason, at);
}

} // namespace

// A joint's body: an index into the file's `bodies` array (after the generators' bodies in the
// scene), or a tag that exactly one body carries.
int jointBody(Object& o, const std::string& key, const scenes::SceneDesc& scene,
              std::size_t generated) {
    const json& v = o.require(key);
    if (v.is_string()) {
        const std::string tag = v.get<std::string>();
        int found = -1;
        int count = 0;
        std::vector<std::string> tags;
        for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
            if (scene.bodies[i].tag == tag) {
                found = static_cast<int>(i);
                ++count;
            }
            if (!scene.bodies[i].tag.empty()) {
                tags.push_back(scene.bodies[i].tag);
            }
        }
        if (count == 0) {
            fail(o.at(key), "no body has tag \"" + tag + "\"" + suggestion(tag, tags));
        }
        if (count > 1) {
            fail(o.at(key), std::to_string(count) + " bodies have tag \"" + tag +
                                "\"; name one by its index in bodies");
        }
        return found;
    }
    const std::size_t own = scene.bodies.size() - generated;
    if (own == 0) {
        fail(o.at(key),
             "the file has no bodies to join by index (generators' bodies are named by tag)");
    }
    const int index = o.integer(key, 0, 0, static_cast<int>(own) - 1);
    return static_cast<int>(generated) + index;
}

scenes::JointDesc parseJoint(const json& value, const std::string& path,
                             const scenes::SceneDesc& scene, std::size_t generated) {
    Object o(value, path);
    scenes::JointDesc j;
    const std::string type =
        o.choice("type", {"revolute", "distance", "prismatic", "weld", "wheel", "motor", "mouse"});
    j.kind = type == "revolute"    ? scenes::JointKind::Revolute
             : type == "distance"  ? scenes::JointKind::Distance
             : type == "prismatic" ? scenes::JointKind::Prismatic
             : type == "wheel"     ? scenes::JointKind::Wheel
             : type == "motor"     ? scenes::JointKind::Motor
             : type == "mouse"     ? scenes::JointKind::Mouse
                                   : scenes::JointKind::Weld;
    j.bodyA = jointBody(o, "bodyA", scene, generated);
    j.bodyB = jointBody(o, "bodyB", scene, generated);
    if (j.bodyA == j.bodyB) {
        fail(o.at("bodyB"),
             "must differ from bodyA (both are body " + std::to_string(j.bodyA) + ")");
    }
    if (scene.bodies[std::size_t(j.bodyA)].kind != scenes::BodyKind::Dynamic &&
        scene.bodies[std::size_t(j.bodyB)].kind != scenes::BodyKind::Dynamic) {
        fail(o.at("bodyB"), "one of the two bodies must be dynamic");
    }
    j.collideConnected = o.boolean("collideConnected", false);
    auto point = [&](const char* key) {
        const glm::vec2 p = Object::toVec2(o.require(key), o.at(key));
        Object::checkWithinE2d(p, o.at(key));
        return p;
    };
    // Both ends of a range or neither; lower <= upper.
    auto range = [&](const std::string& lowKey, const std::string& highKey, bool angle) {
        const bool low = o.has(lowKey) || (angle && o.has(lowKey + "Deg"));
        const bool high = o.has(highKey) || (angle && o.has(highKey + "Deg"));
        if (low != high) {
            fail(o.at(low ? highKey : lowKey),
                 "required field is missing (a limit needs " + lowKey + " and " + highKey + ")");
        }
        if (!low) {
            return;
        }
        j.enableLimit = true;
        j.lower = angle ? o.angle(lowKey, 0.0f) : o.requireNumber(lowKey);
        j.upper = angle ? o.angle(highKey, 0.0f) : o.requireNumber(highKey);
        Object::checkWithinE2d(j.lower, o.at(lowKey));
        Object::checkWithinE2d(j.upper, o.at(highKey));
        if (!(j.lower <= j.upper)) {
            fail(o.at(highKey), "must be >= " + lowKey + " (" + core::formatNumber(j.lower) +
                                    "), got " + core::formatNumber(j.upper));
        }
    };
    auto motor = [&](const char* maxKey) {
        if (!o.has(maxKey)) {
            if (o.has("motorSpeed")) {
                fail(o.at(maxKey),
                     std::string("required field is missing (a motor needs motorSpeed and ") +
                         maxKey + ")");
            }
            return;
        }
        j.enableMotor = true;
        j.maxMotor = o.numberAbove(maxKey, 0.0f, 0.0f, false);
        j.motorSpeed = o.number("motorSpeed", 0.0f);
        Object::checkWithinE2d(j.maxMotor, o.at(maxKey));
        Object::checkWithinE2d(j.motorSpeed, o.at("motorSpeed"));
    };
    // A spring of `hertz` (> 0) and `dampingRatio` (>= 0), both at most 1000; `required`: the
    // joint always has one (mouse), with these defaults.
    auto spring = [&](bool required, float defaultHertz, float defaultRatio) {
        if (!required && !o.has("hertz")) {
            if (o.has("dampingRatio")) {
                fail(o.at("hertz"), "required field is missing (a spring needs hertz; dampingRatio "
                                    "alone does nothing)");
            }
            return;
        }
        j.enableSpring = true;
        j.hertz = o.numberAbove("hertz", defaultHertz, 0.0f, true);
        j.dampingRatio = o.numberAbove("dampingRatio", defaultRatio, 0.0f, false);
        if (j.hertz > 1000.0f || j.dampingRatio > 1000.0f) {
            fail(o.at(j.hertz > 1000.0f ? "hertz" : "dampingRatio"), "must be <= 1000");
        }
    };
    auto axis = [&](glm::vec2 fallback) {
        const glm::vec2 a = o.vec2("axis", fallback);
        const float length = std::sqrt(a.x * a.x + a.y * a.y);
        if (!(length > 1.0e-6f)) {
            fail(o.at("axis"), "must not be [0, 0]");
        }
        j.axis = a / length;
    };
    const scenes::BodyDesc& bodyA = scene.bodies[std::size_t(j.bodyA)];
    const scenes::BodyDesc& bodyB = scene.bodies[std::size_t(j.bodyB)];
    switch (j.kind) {
    case scenes::JointKind::Revolute:
        j.anchorA = point("anchor");
        range("lowerAngle", "upperAngle", true);
        motor("maxMotorTorque");
        spring(false, 0.0f, 0.0f);
        break;
    case scenes::JointKind::Prismatic: {
        j.anchorA = point("anchor");
        axis({1.0f, 0.0f});
        range("lowerTranslation", "upperTranslation", false);
        motor("maxMotorForce");
        spring(false, 0.0f, 0.0f);
        break;
    }
    case scenes::JointKind::Wheel:
        j.anchorA = point("anchor");
        axis({0.0f, 1.0f});
        range("lowerTranslation", "upperTranslation", false);
        motor("maxMotorTorque");
        spring(false, 0.0f, 0.0f);
        break;
    case scenes::JointKind::Motor: {
        // Defaults: the pose B has relative to A at the start (what Box2D's Initialize() takes).
        const float c = std::cos(bodyA.angle);
        const float sn = std::sin(bodyA.angle);
        const glm::vec2 d = bodyB.position - bodyA.position;
        j.linearOffset = o.vec2("linearOffset", {c * d.x + sn * d.y, -sn * d.x + c * d.y});
        Object::checkWithinE2d(j.linearOffset, o.at("linearOffset"));
        j.angularOffset = o.angle("angularOffset", bodyB.angle - bodyA.angle);
        Object::checkWithinE2d(j.angularOffset, o.at("angularOffset"));
        j.maxForce = o.numberAbove("maxForce", 1.0f, 0.0f, false);
        j.maxTorque = o.numberAbove("maxTorque", 1.0f, 0.0f, false);
        j.correctionFactor = o.numberAbove("correctionFactor", 0.3f, 0.0f, false);
        if (j.correctionFactor > 1.0f) {
            fail(o.at("correctionFactor"),
                 "must be in [0, 1], got " + core::formatNumber(j.correctionFactor));
        }
        break;
    }
    case scenes::JointKind::Mouse:
        j.target = point("target");
        j.anchorA = o.has("anchor") ? point("anchor") : bodyB.position;
        j.maxForce = o.numberAbove("maxForce", 1000.0f, 0.0f, false);
        spring(true, 5.0f, 0.7f);
        break;
    case scenes::JointKind::Weld:
        j.anchorA = point("anchor");
        break;
    case scenes::JointKind::Distance: {
        j.anchorA = point("anchorA");
        j.anchorB = point("anchorB");
        const glm::vec2 d = j.anchorB - j.anchorA;
        j.length = o.numberAbove("length", std::sqrt(d.x * d.x + d.y * d.y), 0.0f, false);
        Object::checkWithinE2d(j.length, o.at("length"));
        // e2d and Box2D both hold lengths below the linear slop at the slop.
        if (j.length < physics::kLinearSlop) {
            fail(o.at(o.has("length") ? "length" : "anchorB"),
                 "the length must be at least physics::kLinearSlop (" +
                     core::formatNumber(physics::kLinearSlop) + " m), got " +
                     core::formatNumber(j.length));
        }
        range("minLength", "maxLength", false);
        if (j.enableLimit && j.lower < 0.0f) {
            fail(o.at("minLength"), "must be >= 0, got " + core::formatNumber(j.lower));
        }
        spring(false, 0.0f, 0.0f);
        break;
    }
    }
    o.finish();
    return j;
}

Scenario parseScenario(std::string_view text, const std::string& fallbackName) {
    // Printing or copying a value recurses once per level: bound the depth before parsing.
    if (const auto deep = core::findJsonNestingBeyond(text)) {
        const core::TextPosition at = core::positionOf(text, *deep);
        fail("",
             "arrays and objects nest deeper than " + std::to_string(core::kMaxJsonDepth) +
                 " levels; a scenario needs 6",
             at);
    }
    json document;
    try {
        document = json::parse(text.begin(), text.end());
    } catch (const json::exception&) {
        // Syntax errors and numbers no double can hold (1e999) alike.
        failJson(text);
    }
    Object root(document, "");
    Scenario s;
    s.name = root.string("name", fallbackName);
    if (s.name.empty()) {
        fail("name", "must not be empty");
    }
    s.family = root.choice(
        "family", {"stacking", "friction", "restitution", "conservation", "joints", "hard"});
    s.description = root.string("description", "");
    s.measures = root.string("measures", "");
    s.duration = root.numberAbove("duration", 5.0f, 0.0f, true);
    if (s.duration > 600.0f) {
        fail("duration", "must be <= 600 s, got " + core::formatNumber(s.duration));
    }
    s.settle = root.numberAbove("settle", std::min(1.0f, 0.5f * s.duration), 0.0f, false);
    if (s.settle >= s.duration) {
        fail("settle", "must be < duration (" + core::formatNumber(s.duration) + "), got " +
                           core::formatNumber(s.settle));
    }
    s.quick = root.boolean("quick", false);
    s.sweep = root.boolean("sweep", true);
    s.hardCase = root.boolean("hardCase", false);
    s.scaling = root.string("scaling", "");
    s.scene.name = s.name;
    s.scene.gravity = root.vec2("gravity", {0.0f, -10.0f});
    s.scene.timeStep = root.numberAbove("timeStep", 1.0f / 60.0f, 0.0f, true);
    if (s.scene.timeStep > 0.1f) {
        fail("timeStep", "must be <= 0.1 s, got " + core::formatNumber(s.scene.timeStep));
    }
    // Every step is recorded (a few dozen bytes per tagged body and instant) and runs in every
    // configuration of the sweep: bound the count so a scenario cannot run for days or out of
    // memory.
    if (const double steps = std::round(double(s.duration) / s.scene.timeStep); steps > kMaxSteps) {
        fail("timeStep", "duration / timeStep must be at most " + core::formatNumber(kMaxSteps) +
                             " steps (600 s at 600 Hz), got " + core::formatNumber(s.duration) +
                             " s / " + core::formatNumber(s.scene.timeStep) +
                             " s = " + core::formatNumber(steps));
    }
    parseSettings(root, s);

    if (const json* generators = root.get("generators")) {
        requireArray(*generators, "generators");
        for (std::size_t i = 0; i < generators->size(); ++i) {
            parseGenerator((*generators)[i], indexed("generators", i), s.scene);
        }
    }
    const std::size_t generated = s.scene.bodies.size();
    if (const json* bodies = root.get("bodies")) {
        requireArray(*bodies, "bodies");
        for (std::size_t i = 0; i < bodies->size(); ++i) {
            s.scene.bodies.push_back(parseBody((*bodies)[i], indexed("bodies", i), s.duration));
        }
    }
    if (s.scene.bodies.empty()) {
        fail("bodies", "the scene has no bodies (give bodies or generators)");
    }
    if (const json* joints = root.get("joints")) {
        requireArray(*joints, "joints");
        for (std::size_t i = 0; i < joints->size(); ++i) {
            s.scene.joints.push_back(
                parseJoint((*joints)[i], indexed("joints", i), s.scene, generated));
        }
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
    const core::TextFile text = core::readTextFile(file);
    if (!text.ok()) {
        throw ScenarioError(core::Diagnostic{core::Severity::Error,
                                             core::printable(file.string()),
                                             0,
                                             0,
                                             {},
                                             "cannot read the file (" + text.error + ")"});
    }
    try {
        Scenario s = parseScenario(text.text, file.stem().string());
        s.file = file.string();
        return s;
    } catch (const ScenarioError& e) {
        core::Diagnostic placed = e.diagnostic();
        placed.file = core::printable(file.string());
        throw ScenarioError(std::move(placed));
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
