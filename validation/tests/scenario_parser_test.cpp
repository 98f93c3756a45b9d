// SPDX-License-Identifier: MIT
#include "scenario_parser.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace e2d::validation {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

// The message of the ScenarioError that parsing `text` throws, or "" if it parses.
std::string errorOf(const std::string& text) {
    try {
        (void)parseScenario(text, "test");
    } catch (const ScenarioError& e) {
        return e.what();
    }
    return "";
}

// A valid scene with four bodies (ground, box, circle, capsule) into which tests splice errors.
std::string scene(const std::string& extraRoot, const std::string& circleShape,
                  const std::string& extraBox = "") {
    return R"({"family": "stacking", "duration": 2)" + extraRoot + R"(,
      "bodies": [
        {"type": "static", "position": [0, -1], "shape": {"type": "box", "halfExtents": [10, 1]}},
        {"position": [0, 0.5], "tag": "top", "shape": {"type": "box")" +
           extraBox + R"(}},
        {"position": [2, 0.5], "shapes": [{"type": "box"}]},
        {"position": [4, 0.5], "shapes": [)" +
           circleShape + R"(]}
      ]})";
}

TEST(ScenarioParser, ParsesAValidScene) {
    const Scenario s =
        parseScenario(scene(R"(, "gravity": [0, -9.8], "quick": true)",
                            R"({"type": "circle", "radius": 0.5, "restitution": 0.5})"),
                      "fallback");
    EXPECT_EQ(s.name, "fallback");
    EXPECT_EQ(s.family, "stacking");
    EXPECT_FLOAT_EQ(s.duration, 2.0f);
    EXPECT_FLOAT_EQ(s.settle, 1.0f); // min(1, duration / 2)
    EXPECT_TRUE(s.quick);
    EXPECT_FLOAT_EQ(s.scene.gravity.y, -9.8f);
    ASSERT_EQ(s.scene.bodies.size(), 4u);
    EXPECT_EQ(s.scene.bodies[0].kind, scenes::BodyKind::Static);
    EXPECT_EQ(s.scene.bodies[1].tag, "top");
    EXPECT_EQ(s.scene.bodies[3].shapes[0].kind, scenes::ShapeKind::Circle);
    EXPECT_FLOAT_EQ(s.scene.bodies[3].shapes[0].restitution, 0.5f);
}

TEST(ScenarioParser, NamesThePathOfANegativeRadius) {
    EXPECT_EQ(errorOf(scene("", R"({"type": "circle", "radius": -1})")),
              "bodies[3].shapes[0].radius: must be > 0, got -1");
}

TEST(ScenarioParser, NamesThePathOfASingleShape) {
    const std::string text = R"({"family": "hard", "bodies": [
        {"shape": {"type": "circle", "radius": 0.5}},
        {"shape": {"type": "circle", "radius": 0}}]})";
    EXPECT_EQ(errorOf(text), "bodies[1].shape.radius: must be > 0, got 0");
}

TEST(ScenarioParser, RejectsUnknownFieldsWithTheirPath) {
    EXPECT_EQ(errorOf(scene("", R"({"type": "circle", "radius": 1, "frction": 0.2})")),
              "bodies[3].shapes[0].frction: unknown field (did you mean \"friction\"?)");
    EXPECT_EQ(errorOf(scene(R"(, "duraton": 3)", R"({"type": "circle", "radius": 1})")),
              "duraton: unknown field (did you mean \"duration\"?)");
    // A field of another shape type is unknown for this one.
    EXPECT_EQ(errorOf(scene("", R"({"type": "circle", "radius": 1, "halfExtents": [1, 1]})")),
              "bodies[3].shapes[0].halfExtents: unknown field");
    // The empty key is valid JSON; the path still names it (the scenario fuzzer found an
    // error message without a place).
    EXPECT_EQ(errorOf(scene(R"(, "": 3)", R"({"type": "circle", "radius": 1})")),
              "\"\": unknown field");
    EXPECT_EQ(errorOf(scene("", R"({"type": "circle", "radius": 1, "": 0.2})")),
              "bodies[3].shapes[0].\"\": unknown field");
}

TEST(ScenarioParser, RejectsWrongTypes) {
    EXPECT_EQ(errorOf(scene(R"(, "timeStep": "fast")", R"({"type": "circle", "radius": 1})")),
              "timeStep: expected a number, got string");
    EXPECT_EQ(errorOf(scene("", R"({"type": "circle", "radius": 1})", R"(, "halfExtents": [1])")),
              "bodies[1].shape.halfExtents: expected [x, y], got an array of 1");
    EXPECT_EQ(
        errorOf(scene("", R"({"type": "circle", "radius": 1})", R"(, "halfExtents": [1, "a"])")),
        "bodies[1].shape.halfExtents[1]: expected a number, got string");
    EXPECT_EQ(errorOf(scene(R"(, "quick": 1)", R"({"type": "circle", "radius": 1})")),
              "quick: expected true or false, got number");
    EXPECT_EQ(errorOf(R"([1, 2])"), "(root): expected an object, got array");
}

TEST(ScenarioParser, RejectsOutOfRangeValues) {
    EXPECT_EQ(
        errorOf(scene("", R"({"type": "circle", "radius": 1})", R"(, "halfExtents": [1, -2])")),
        "bodies[1].shape.halfExtents[1]: must be > 0, got -2");
    EXPECT_EQ(errorOf(scene(R"(, "settle": 3)", R"({"type": "circle", "radius": 1})")),
              "settle: must be < duration (2), got 3");
    EXPECT_EQ(errorOf(scene(
                  "", R"({"type": "capsule", "point1": [0, 0], "point2": [0, 0], "radius": 1})")),
              "bodies[3].shapes[0].point2: must differ from point1");
    EXPECT_EQ(errorOf(scene("", R"({"type": "polygon", "points": [[0, 0], [1, 0], [2, 0]]})")),
              "bodies[3].shapes[0].points: the points enclose no area");
    EXPECT_EQ(
        errorOf(scene("", R"({"type": "cirle"})")),
        "bodies[3].shapes[0].type: expected box, polygon, circle, capsule, segment or chain, got "
        "\"cirle\" (did you mean \"circle\"?)");
    EXPECT_EQ(errorOf(scene("", R"({"type": "triangle"})")),
              "bodies[3].shapes[0].type: expected box, polygon, circle, capsule, segment or chain, "
              "got \"triangle\"");
}

TEST(ScenarioParser, ChecksGeneratorsSettingsAndChecks) {
    EXPECT_EQ(errorOf(R"({"family": "stacking", "generators": [{"type": "pyramid", "base": 0}]})"),
              "generators[0].base: must be in [1, 200], got 0");
    EXPECT_EQ(
        errorOf(
            R"({"family": "stacking", "generators": [{"type": "verticalStack", "count": 2.5}]})"),
        "generators[0].count: expected an integer, got 2.5");
    EXPECT_EQ(errorOf(R"({"family": "stacking", "generators": [{"type": "verticalStack"}],
                          "settings": {"box2d": {"subSteps": 4}}})"),
              "settings.box2d.subSteps: unknown field");
    EXPECT_EQ(errorOf(R"({"family": "stacking", "generators": [{"type": "verticalStack"}],
                          "checks": [{"type": "standing", "body": "apex", "tolerance": 1, "minY": 0}]})"),
              "checks[0].body: no body has tag \"apex\"");
    EXPECT_EQ(errorOf(R"({"family": "stacking", "generators": [{"type": "verticalStack"}],
                          "checks": [{"type": "maxSpeed"}]})"),
              "checks[0].limit: required field is missing");
    // maxSpeed's body is optional; given, it must be a tag of the scene (checks name bodies by
    // tag, not by index: only tagged bodies are recorded).
    const Scenario named = parseScenario(
        scene(R"(, "checks": [{"type": "maxSpeed", "limit": 3}, {"type": "maxSpeed", "limit": 3,
                                                                "body": "top"}])",
              R"({"type": "circle", "radius": 0.5})"),
        "test");
    ASSERT_EQ(named.checks.size(), 2u);
    EXPECT_EQ(named.checks[0].body, "");
    EXPECT_EQ(named.checks[1].body, "top");
    EXPECT_EQ(errorOf(scene(R"(, "checks": [{"type": "maxSpeed", "limit": 3, "body": "tpo"}])",
                            R"({"type": "circle", "radius": 0.5})")),
              "checks[0].body: no body has tag \"tpo\" (did you mean \"top\"?)");
    EXPECT_EQ(errorOf(scene(R"(, "checks": [{"type": "maxSpeed", "limit": 3, "body": 1}])",
                            R"({"type": "circle", "radius": 0.5})")),
              "checks[0].body: expected a string, got number");
    EXPECT_THAT(errorOf(R"({"family": "stacking", "generators": [{"type": "verticalStack"}],
                          "checks": [{"type": "bounce"}]})"),
                StartsWith("checks[0].type: expected standing, maxPenetration"));
    EXPECT_THAT(errorOf(R"({"family": "stacking", "generators": [{"type": "verticalStack"}],
                          "checks": [{"type": "bounce"}]})"),
                HasSubstr("got \"bounce\" (did you mean \"bounceHeight\"?)"));
    EXPECT_EQ(
        errorOf(R"({"family": "friction", "duration": 2, "generators": [{"type": "verticalStack"}],
                          "checks": [{"type": "rollingDistance", "body": "top", "slopeDeg": 20,
                                      "time": 3, "tolerance": 0.1}]})"),
        "checks[0].time: must be <= duration (2), got 3");
}

TEST(ScenarioParser, RejectsBadDocuments) {
    EXPECT_EQ(errorOf("{\"family\": "),
              "line 1, column 12: family: not valid JSON: syntax error while parsing value - "
              "unexpected end of input; expected '[', '{', or a literal");
    EXPECT_EQ(errorOf(R"({"bodies": [{"shape": {"type": "circle", "radius": 1}}]})"),
              "family: required field is missing (one of stacking, friction, restitution, "
              "conservation, joints or hard)");
    EXPECT_EQ(errorOf(R"({"family": "hard"})"),
              "bodies: the scene has no bodies (give bodies or generators)");
    EXPECT_EQ(errorOf(R"({"family": "hard", "bodies": [{"angle": 1, "angleDeg": 2,
                          "shape": {"type": "circle", "radius": 1}}]})"),
              "bodies[0].angleDeg: give either angle (radians) or angleDeg, not both");
}

TEST(ScenarioParser, SyntaxErrorsAndOverflowsNameTheirPathLineAndColumn) {
    // A number no double holds: nlohmann reports it without a place; the parser adds it.
    EXPECT_EQ(errorOf("{\"family\": \"hard\",\n \"bodies\": [{\"shape\": {\"type\": \"circle\",\n"
                      "  \"radius\": 1e999}}]}"),
              "line 3, column 13: bodies[0].shape.radius: not valid JSON: number overflow parsing "
              "'1e999'");
    EXPECT_EQ(
        errorOf(R"({"family": "hard", "bodies": [{}, {"position": [1, 2,]}]})"),
        "line 1, column 54: bodies[1].position[2]: not valid JSON: syntax error while parsing "
        "value - unexpected ']'; expected '[', '{', or a literal");
}

TEST(ScenarioParser, MissingFieldsSayMissing) {
    EXPECT_EQ(errorOf(scene("", R"({"radius": 1})")),
              "bodies[3].shapes[0].type: required field is missing (one of box, polygon, circle, "
              "capsule, segment or chain)");
    EXPECT_EQ(errorOf(R"({"family": "stacking", "generators": [{"count": 3}]})"),
              "generators[0].type: required field is missing (one of verticalStack, pyramid, "
              "dominoes or grid)");
    EXPECT_EQ(errorOf(R"({"family": "stacking", "generators": [{"type": "verticalStack"}],
                          "checks": [{"type": "standing", "tolerance": 1, "minY": 0}]})"),
              "checks[0].body: required field is missing (the tag of the body to check)");
    EXPECT_EQ(errorOf(R"({"family": "stacking", "generators": [{"type": "verticalStack"}],
                          "checks": [{"type": "standing", "body": "tpo", "tolerance": 1, "minY": 0}]})"),
              "checks[0].body: no body has tag \"tpo\" (did you mean \"top\"?)");
}

TEST(ScenarioParser, ValuesBeyondE2dsLimitsNameTheLimit) {
    EXPECT_EQ(errorOf(R"({"family": "hard", "bodies": [{"position": [0, 600000],
                          "shape": {"type": "circle", "radius": 1}}]})"),
              "bodies[0].position[1]: must be within e2d's limit of 500000 (physics::kHuge: metres "
              "for positions and sizes, kg/m^2 for density), got 600000");
    EXPECT_THAT(
        errorOf(scene("", R"({"type": "circle", "radius": 1})", R"(, "halfExtents": [600000, 1])")),
        StartsWith("bodies[1].shape.halfExtents[0]: must be within e2d's limit of 500000"));
    EXPECT_THAT(errorOf(scene("", R"({"type": "circle", "radius": 1, "density": 1e30})")),
                StartsWith("bodies[3].shapes[0].density: must be within e2d's limit of 500000"));
    // Found by fuzz_scenario: e2d refuses a restitution above 1 when the run builds the shape.
    EXPECT_EQ(errorOf(scene("", R"({"type": "circle", "radius": 1, "restitution": 20})")),
              "bodies[3].shapes[0].restitution: must be in [0, 1] (e2d's limit), got 20");
    EXPECT_EQ(
        errorOf(
            R"({"family": "hard", "generators": [{"type": "verticalStack", "restitution": 1.5}]})"),
        "generators[0].restitution: must be in [0, 1] (e2d's limit), got 1.5");
}

TEST(ScenarioParser, PolygonsE2dWouldWeldAreRefused) {
    EXPECT_EQ(
        errorOf(scene(
            "",
            R"({"type": "polygon", "points": [[0, 0], [0.002, 0], [0.002, 0.002], [0, 0.002]]})")),
        "bodies[3].shapes[0].points: e2d welds points closer than physics::kLinearSlop (0.005 m): "
        "1 of 4 "
        "are distinct, a polygon needs 3");
}

TEST(ScenarioParser, BoundsTheNumberOfSteps) {
    EXPECT_EQ(
        errorOf(scene(R"(, "timeStep": 1e-6, "duration": 600, "settle": 1)",
                      R"({"type": "circle", "radius": 1})")),
        "timeStep: duration / timeStep must be at most 360000 steps (600 s at 600 Hz), got 600 s / "
        "1e-06 s = 600000002"); // the float timeStep is not exactly 1e-6
    EXPECT_EQ(errorOf(scene(R"(, "timeStep": 0.001, "duration": 300, "settle": 1)",
                            R"({"type": "circle", "radius": 1})")),
              "");
}

TEST(ScenarioParser, AnglesInDegreesBecomeRadians) {
    const Scenario s = parseScenario(R"({"family": "hard", "bodies": [{"angleDeg": 90,
        "shape": {"type": "box", "angleDeg": 180}}]})",
                                     "x");
    EXPECT_NEAR(s.scene.bodies[0].angle, 1.5707963f, 1e-6f);
    EXPECT_NEAR(s.scene.bodies[0].shapes[0].angle, 3.1415927f, 1e-6f);
}

TEST(ScenarioParser, PushesGravityScaleAndTheNewChecks) {
    const Scenario s = parseScenario(R"({"family": "hard", "duration": 2, "bodies": [
        {"type": "static", "position": [0, -1], "shape": {"type": "box", "halfExtents": [5, 1]}},
        {"tag": "a", "gravityScale": 0.5, "force": [1, 2],
         "impulses": [{"time": 1, "impulse": [3, 4]}, {"time": 0, "impulse": [0, 1]}],
         "shape": {"type": "circle", "radius": 0.5}},
        {"tag": "a", "shape": {"type": "circle", "radius": 0.5}}],
        "checks": [{"type": "turn", "body": "a", "minTurnDeg": 90, "maxTurn": 2},
                   {"type": "moves", "body": "a", "distance": 1, "direction": [3, -4]}]})",
                                     "x");
    const scenes::BodyDesc& a = s.scene.bodies[1];
    EXPECT_FLOAT_EQ(a.gravityScale, 0.5f);
    EXPECT_EQ(a.force, glm::vec2(1.0f, 2.0f));
    ASSERT_EQ(a.impulses.size(), 2u);
    EXPECT_FLOAT_EQ(a.impulses[0].first, 1.0f);
    EXPECT_EQ(a.impulses[0].second, glm::vec2(3.0f, 4.0f));
    EXPECT_FLOAT_EQ(s.scene.bodies[2].gravityScale, 1.0f);
    ASSERT_EQ(s.checks.size(), 2u);
    EXPECT_NEAR(*s.checks[0].minTurn, 1.5707963f, 1e-6f);
    EXPECT_FLOAT_EQ(*s.checks[0].maxTurn, 2.0f);
    EXPECT_NEAR(s.checks[1].direction.x, 0.6f, 1e-6f);
    EXPECT_NEAR(s.checks[1].direction.y, -0.8f, 1e-6f);
}

TEST(ScenarioParser, RejectsBadPushesAndChecks) {
    const std::string ground =
        R"({"type": "static", "position": [0, -1], "shape": {"type": "box", "halfExtents": [5, 1]}})";
    auto withBody = [&](const std::string& body, const std::string& checks = "") {
        return errorOf(R"({"family": "hard", "duration": 2, "bodies": [)" + ground + ", " + body +
                       "]" + (checks.empty() ? "" : R"(, "checks": [)" + checks + "]") + "}");
    };
    const std::string circle = R"("shape": {"type": "circle", "radius": 0.5})";
    EXPECT_EQ(withBody(R"({"type": "static", "force": [1, 0], )" + circle + "}"),
              "bodies[1].force: only a dynamic body can be pushed");
    EXPECT_EQ(withBody(R"({"impulses": [{"time": 3, "impulse": [1, 0]}], )" + circle + "}"),
              "bodies[1].impulses[0].time: must be <= duration (2), got 3");
    EXPECT_EQ(withBody(R"({"impulses": [{"time": 1}], )" + circle + "}"),
              "bodies[1].impulses[0].impulse: required field is missing");
    EXPECT_EQ(
        withBody(R"({"impulses": [{"time": 1, "impulse": [1, 0], "tiem": 2}], )" + circle + "}"),
        "bodies[1].impulses[0].tiem: unknown field (did you mean \"time\"?)");
    EXPECT_EQ(withBody(R"({"gravityScale": 5000, )" + circle + "}"),
              "bodies[1].gravityScale: must be in [-1000, 1000], got 5000");
    const std::string tagged = R"({"tag": "a", )" + circle + "}";
    EXPECT_THAT(withBody(tagged, R"({"type": "turn", "body": "a"})"),
                StartsWith("checks[0].maxTurn: required field is missing"));
    EXPECT_EQ(withBody(tagged, R"({"type": "turn", "body": "a", "maxTurn": -1})"),
              "checks[0].maxTurn: must be > 0, got -1");
    EXPECT_EQ(
        withBody(tagged, R"({"type": "moves", "body": "a", "distance": 1, "direction": [0, 0]})"),
        "checks[0].direction: must not be [0, 0]");
    EXPECT_EQ(withBody(tagged, R"({"type": "moves", "body": "a"})"),
              "checks[0].distance: required field is missing");
}

TEST(ScenarioParser, Joints) {
    const Scenario s =
        parseScenario(R"({"family": "hard", "generators": [{"type": "verticalStack", "count": 2}],
        "bodies": [
          {"type": "static", "position": [0, 10], "shape": {"type": "box", "halfExtents": [0.1, 0.1]}},
          {"position": [1, 10], "tag": "bob", "shape": {"type": "circle", "radius": 0.1}},
          {"position": [3, 10], "shape": {"type": "circle", "radius": 0.1}}],
        "joints": [
          {"type": "revolute", "bodyA": 0, "bodyB": "bob", "anchor": [0, 10], "lowerAngleDeg": -90, "upperAngle": 1,
           "motorSpeed": 2, "maxMotorTorque": 5},
          {"type": "distance", "bodyA": "bob", "bodyB": 2, "anchorA": [1, 10], "anchorB": [3, 10]},
          {"type": "prismatic", "bodyA": "top", "bodyB": 2, "anchor": [3, 10], "axis": [0, 2],
           "lowerTranslation": -1, "upperTranslation": 1},
          {"type": "weld", "bodyA": 1, "bodyB": 2, "anchor": [2, 10], "collideConnected": true}],
        "checks": [{"type": "jointError", "limit": 0.01}, {"type": "period", "body": "bob", "period": 2, "tolerance": 0.1}]})",
                      "joints");
    ASSERT_EQ(s.scene.joints.size(), 4u);
    const scenes::JointDesc& r = s.scene.joints[0];
    EXPECT_EQ(r.kind, scenes::JointKind::Revolute);
    EXPECT_EQ(r.bodyA, 3); // after the two boxes and the ground of the generator
    EXPECT_EQ(r.bodyB, 4);
    EXPECT_TRUE(r.enableLimit);
    EXPECT_NEAR(r.lower, -1.5707963f, 1e-6f);
    EXPECT_FLOAT_EQ(r.upper, 1.0f);
    EXPECT_TRUE(r.enableMotor);
    EXPECT_FLOAT_EQ(r.maxMotor, 5.0f);
    EXPECT_FLOAT_EQ(s.scene.joints[1].length, 2.0f); // the anchors' distance
    EXPECT_FALSE(s.scene.joints[1].enableLimit);
    EXPECT_EQ(s.scene.joints[2].bodyA, 2); // the stack's top box, by tag
    EXPECT_EQ(s.scene.joints[2].axis, glm::vec2(0.0f, 1.0f));
    EXPECT_TRUE(s.scene.joints[3].collideConnected);
    EXPECT_FLOAT_EQ(s.checks[1].period, 2.0f);
}

TEST(ScenarioParser, RejectsBadJoints) {
    auto withJoint = [](const std::string& joint, const std::string& checks = "") {
        return errorOf(R"({"family": "hard", "bodies": [
            {"type": "static", "position": [0, 0], "tag": "post", "shape": {"type": "box", "halfExtents": [0.1, 0.1]}},
            {"type": "static", "position": [2, 0], "tag": "post", "shape": {"type": "box", "halfExtents": [0.1, 0.1]}},
            {"position": [1, 0], "tag": "bob", "shape": {"type": "circle", "radius": 0.1}}],
            "joints": [)" +
                       joint + "]" + (checks.empty() ? "" : R"(, "checks": [)" + checks + "]") +
                       "}");
    };
    EXPECT_EQ(withJoint(R"({"type": "revolute", "bodyA": 2, "bodyB": "bob", "anchor": [1, 0]})"),
              "joints[0].bodyB: must differ from bodyA (both are body 2)");
    EXPECT_EQ(withJoint(R"({"type": "revolute", "bodyA": 0, "bodyB": 1, "anchor": [1, 0]})"),
              "joints[0].bodyB: one of the two bodies must be dynamic");
    EXPECT_EQ(withJoint(R"({"type": "revolute", "bodyA": "post", "bodyB": 2, "anchor": [1, 0]})"),
              "joints[0].bodyA: 2 bodies have tag \"post\"; name one by its index in bodies");
    EXPECT_EQ(withJoint(R"({"type": "revolute", "bodyA": "bbo", "bodyB": 0, "anchor": [1, 0]})"),
              "joints[0].bodyA: no body has tag \"bbo\" (did you mean \"bob\"?)");
    EXPECT_THAT(withJoint(R"({"type": "revolute", "bodyA": 7, "bodyB": 0, "anchor": [1, 0]})"),
                StartsWith("joints[0].bodyA: must be in [0, 2], got 7"));
    EXPECT_EQ(withJoint(R"({"type": "revolute", "bodyA": 0, "bodyB": 2})"),
              "joints[0].anchor: required field is missing");
    EXPECT_THAT(withJoint(R"({"type": "hinge", "bodyA": 0, "bodyB": 2})"),
                StartsWith("joints[0].type: expected revolute, distance, prismatic, weld, wheel, "
                           "motor or mouse, got \"hinge\""));
    EXPECT_EQ(
        withJoint(
            R"({"type": "revolute", "bodyA": 0, "bodyB": 2, "anchor": [0, 0], "lowerAngle": 1, "upperAngle": 0})"),
        "joints[0].upperAngle: must be >= lowerAngle (1), got 0");
    EXPECT_THAT(
        withJoint(
            R"({"type": "revolute", "bodyA": 0, "bodyB": 2, "anchor": [0, 0], "lowerAngle": 1})"),
        StartsWith("joints[0].upperAngle: required field is missing"));
    EXPECT_THAT(
        withJoint(
            R"({"type": "revolute", "bodyA": 0, "bodyB": 2, "anchor": [0, 0], "motorSpeed": 1})"),
        StartsWith("joints[0].maxMotorTorque: required field is missing"));
    EXPECT_EQ(
        withJoint(
            R"({"type": "prismatic", "bodyA": 0, "bodyB": 2, "anchor": [0, 0], "axis": [0, 0]})"),
        "joints[0].axis: must not be [0, 0]");
    EXPECT_THAT(
        withJoint(
            R"({"type": "distance", "bodyA": 0, "bodyB": 2, "anchorA": [1, 0], "anchorB": [1, 0.001]})"),
        StartsWith("joints[0].anchorB: the length must be at least physics::kLinearSlop"));
    EXPECT_THAT(withJoint(R"({"type": "revolute", "bodyA": 0, "bodyB": 2, "anchor": [600000, 0]})"),
                StartsWith("joints[0].anchor[0]: must be within e2d's limit of 500000"));
    EXPECT_EQ(
        withJoint(
            R"({"type": "distance", "bodyA": 0, "bodyB": 2, "anchorA": [0, 0], "anchorB": [1, 0], "hertz": 1})",
            R"({"type": "jointError", "limit": 0.1})"),
        "checks[0].type: the scene has no joint this check measures (revolute, weld, wheel or "
        "rigid distance)");
    EXPECT_EQ(
        withJoint(R"({"type": "weld", "bodyA": 0, "bodyB": 2, "anchor": [0, 0], "lowerAngle": 0})"),
        "joints[0].lowerAngle: unknown field");
}

// The wheel, motor and mouse joints and revolute and prismatic springs: fields, defaults (the
// motor joint's offsets are the pose B has relative to A at the start).
TEST(ScenarioParser, WheelMotorMouseJointsAndSprings) {
    const Scenario s = parseScenario(R"({"family": "hard", "bodies": [
          {"type": "static", "position": [0, 0], "shape": {"type": "box", "halfExtents": [0.1, 0.1]}},
          {"position": [1, 2], "angleDeg": 90, "tag": "car", "shape": {"type": "box"}},
          {"position": [3, 2], "angle": 2, "tag": "wheel", "shape": {"type": "circle", "radius": 0.3}}],
        "joints": [
          {"type": "wheel", "bodyA": "car", "bodyB": "wheel", "anchor": [3, 2], "hertz": 4, "dampingRatio": 0.7,
           "motorSpeed": -10, "maxMotorTorque": 20, "lowerTranslation": -0.1, "upperTranslation": 0.1},
          {"type": "motor", "bodyA": "car", "bodyB": "wheel", "maxForce": 5},
          {"type": "mouse", "bodyA": 0, "bodyB": "wheel", "target": [4, 4]},
          {"type": "revolute", "bodyA": 0, "bodyB": "car", "anchor": [0, 0], "hertz": 2},
          {"type": "prismatic", "bodyA": 0, "bodyB": "car", "anchor": [0, 0], "hertz": 1, "dampingRatio": 0.5},
          {"type": "wheel", "bodyA": 0, "bodyB": "wheel", "anchor": [3, 2], "axis": [2, 0]}],
        "checks": [{"type": "jointError", "limit": 0.01}]})",
                                     "joints");
    ASSERT_EQ(s.scene.joints.size(), 6u);
    const scenes::JointDesc& w = s.scene.joints[0];
    EXPECT_EQ(w.kind, scenes::JointKind::Wheel);
    EXPECT_EQ(w.axis, glm::vec2(0.0f, 1.0f)); // the default axis
    EXPECT_TRUE(w.enableSpring);
    EXPECT_FLOAT_EQ(w.hertz, 4.0f);
    EXPECT_FLOAT_EQ(w.dampingRatio, 0.7f);
    EXPECT_TRUE(w.enableMotor);
    EXPECT_FLOAT_EQ(w.motorSpeed, -10.0f);
    EXPECT_FLOAT_EQ(w.maxMotor, 20.0f);
    EXPECT_TRUE(w.enableLimit);
    EXPECT_FLOAT_EQ(w.lower, -0.1f);
    const scenes::JointDesc& m = s.scene.joints[1];
    EXPECT_EQ(m.kind, scenes::JointKind::Motor);
    // B is 2 m to the right of A, whose x axis points up: in A's frame that is (0, -2).
    EXPECT_NEAR(m.linearOffset.x, 0.0f, 1e-6f);
    EXPECT_NEAR(m.linearOffset.y, -2.0f, 1e-6f);
    EXPECT_NEAR(m.angularOffset, 2.0f - 1.5707963f, 1e-6f);
    EXPECT_FLOAT_EQ(m.maxForce, 5.0f);
    EXPECT_FLOAT_EQ(m.maxTorque, 1.0f);
    EXPECT_FLOAT_EQ(m.correctionFactor, 0.3f);
    const scenes::JointDesc& mouse = s.scene.joints[2];
    EXPECT_EQ(mouse.kind, scenes::JointKind::Mouse);
    EXPECT_EQ(mouse.target, glm::vec2(4.0f, 4.0f));
    EXPECT_EQ(mouse.anchorA, glm::vec2(3.0f, 2.0f)); // body B's origin
    EXPECT_TRUE(mouse.enableSpring);
    EXPECT_FLOAT_EQ(mouse.hertz, 5.0f);
    EXPECT_FLOAT_EQ(mouse.dampingRatio, 0.7f);
    EXPECT_FLOAT_EQ(mouse.maxForce, 1000.0f);
    EXPECT_TRUE(s.scene.joints[3].enableSpring);
    EXPECT_FLOAT_EQ(s.scene.joints[3].hertz, 2.0f);
    EXPECT_FLOAT_EQ(s.scene.joints[3].dampingRatio, 0.0f);
    EXPECT_TRUE(s.scene.joints[4].enableSpring);
    EXPECT_FALSE(s.scene.joints[5].enableSpring);
    EXPECT_EQ(s.scene.joints[5].axis, glm::vec2(1.0f, 0.0f));
}

TEST(ScenarioParser, RejectsBadWheelMotorAndMouseJoints) {
    auto withJoint = [](const std::string& joint) {
        return errorOf(R"({"family": "hard", "bodies": [
            {"type": "static", "position": [0, 0], "shape": {"type": "box", "halfExtents": [0.1, 0.1]}},
            {"position": [1, 0], "tag": "bob", "shape": {"type": "circle", "radius": 0.1}}],
            "joints": [)" +
                       joint + "]}");
    };
    EXPECT_EQ(
        withJoint(
            R"({"type": "wheel", "bodyA": 0, "bodyB": 1, "anchor": [1, 0], "dampingRatio": 1})"),
        "joints[0].hertz: required field is missing (a spring needs hertz; dampingRatio alone does "
        "nothing)");
    EXPECT_EQ(
        withJoint(R"({"type": "wheel", "bodyA": 0, "bodyB": 1, "anchor": [1, 0], "hertz": 0})"),
        "joints[0].hertz: must be > 0, got 0");
    EXPECT_EQ(
        withJoint(R"({"type": "wheel", "bodyA": 0, "bodyB": 1, "anchor": [1, 0], "axis": [0, 0]})"),
        "joints[0].axis: must not be [0, 0]");
    EXPECT_THAT(
        withJoint(
            R"({"type": "wheel", "bodyA": 0, "bodyB": 1, "anchor": [1, 0], "motorSpeed": 3})"),
        StartsWith("joints[0].maxMotorTorque: required field is missing"));
    EXPECT_EQ(withJoint(R"({"type": "motor", "bodyA": 0, "bodyB": 1, "correctionFactor": 2})"),
              "joints[0].correctionFactor: must be in [0, 1], got 2");
    EXPECT_EQ(withJoint(R"({"type": "motor", "bodyA": 0, "bodyB": 1, "maxTorque": -1})"),
              "joints[0].maxTorque: must be >= 0, got -1");
    EXPECT_THAT(withJoint(R"({"type": "motor", "bodyA": 0, "bodyB": 1, "linearOffset": [6e5, 0]})"),
                StartsWith("joints[0].linearOffset[0]: must be within e2d's limit of 500000"));
    EXPECT_EQ(withJoint(R"({"type": "mouse", "bodyA": 0, "bodyB": 1})"),
              "joints[0].target: required field is missing");
    EXPECT_EQ(
        withJoint(R"({"type": "mouse", "bodyA": 0, "bodyB": 1, "target": [1, 1], "hertz": -2})"),
        "joints[0].hertz: must be > 0, got -2");
    EXPECT_EQ(
        withJoint(R"({"type": "mouse", "bodyA": 0, "bodyB": 1, "target": [1, 1], "maxForce": -1})"),
        "joints[0].maxForce: must be >= 0, got -1");
    EXPECT_EQ(
        withJoint(R"({"type": "mouse", "bodyA": 0, "bodyB": 1, "target": [1, 1], "axis": [1, 0]})"),
        "joints[0].axis: unknown field");
    EXPECT_EQ(
        withJoint(R"({"type": "weld", "bodyA": 0, "bodyB": 1, "anchor": [1, 0], "hertz": 1})"),
        "joints[0].hertz: unknown field");
}

// A wheel joint alone is enough for jointError (its error is B's anchor off the axis).
TEST(ScenarioParser, JointErrorMeasuresWheelJoints) {
    const Scenario s = parseScenario(R"({"family": "hard", "bodies": [
          {"type": "static", "position": [0, 0], "shape": {"type": "box", "halfExtents": [0.1, 0.1]}},
          {"position": [1, 0], "shape": {"type": "circle", "radius": 0.1}}],
        "joints": [{"type": "wheel", "bodyA": 0, "bodyB": 1, "anchor": [1, 0]}],
        "checks": [{"type": "jointError", "limit": 0.01}]})",
                                     "wheel");
    EXPECT_EQ(s.checks[0].kind, CheckKind::JointError);
}

TEST(ScenarioParser, ChainShapes) {
    const Scenario s = parseScenario(R"({"family": "hard", "bodies": [
          {"type": "static", "shapes": [
            {"type": "chain", "points": [[2, 0], [1, 0.1], [0, 0]], "ghostBefore": [3, 0], "friction": 0.3,
             "materials": [{"friction": 0.1}, {"restitution": 0.5}]},
            {"type": "chain", "points": [[0, 0], [1, 0], [1, 1]], "loop": true, "materials": [{"friction": 2}]}]},
          {"position": [1, 1], "shape": {"type": "circle", "radius": 0.1}}]})",
                                     "chains");
    const scenes::ShapeDesc& open = s.scene.bodies[0].shapes[0];
    EXPECT_EQ(open.kind, scenes::ShapeKind::Chain);
    EXPECT_FALSE(open.loop);
    ASSERT_EQ(open.points.size(), 3u);
    EXPECT_EQ(open.points[1], glm::vec2(1.0f, 0.1f));
    ASSERT_TRUE(open.ghostBefore.has_value());
    EXPECT_EQ(*open.ghostBefore, glm::vec2(3.0f, 0.0f));
    EXPECT_FALSE(open.ghostAfter.has_value());
    ASSERT_EQ(open.materials.size(), 2u);
    EXPECT_FLOAT_EQ(open.materials[0].friction, 0.1f);
    EXPECT_FLOAT_EQ(open.materials[0].restitution, 0.0f);
    EXPECT_FLOAT_EQ(open.materials[1].friction, 0.3f); // the shape's
    EXPECT_FLOAT_EQ(open.materials[1].restitution, 0.5f);
    const scenes::ShapeDesc& loop = s.scene.bodies[0].shapes[1];
    EXPECT_TRUE(loop.loop);
    ASSERT_EQ(loop.materials.size(), 1u);
    EXPECT_FLOAT_EQ(loop.materials[0].friction, 2.0f);
}

TEST(ScenarioParser, RejectsBadChains) {
    auto withChain = [](const std::string& chain) {
        return errorOf(R"({"family": "hard", "bodies": [{"type": "static", "shape": )" + chain +
                       "}]}");
    };
    EXPECT_EQ(withChain(R"({"type": "chain"})"),
              "bodies[0].shape.points: required field is missing");
    EXPECT_EQ(withChain(R"({"type": "chain", "points": [[0, 0]]})"),
              "bodies[0].shape.points: a chain needs 2 to 10000 points, got 1");
    EXPECT_EQ(withChain(R"({"type": "chain", "points": [[0, 0], [1, 0]], "loop": true})"),
              "bodies[0].shape.points: a loop needs 3 to 10000 points, got 2");
    EXPECT_EQ(withChain(R"({"type": "chain", "points": [[0, 0], [1, 0], [1, 0.001]]})"),
              "bodies[0].shape.points[2]: must be at least physics::kLinearSlop (0.005 m) from "
              "points[1], got 0.001");
    EXPECT_EQ(
        withChain(R"({"type": "chain", "points": [[0, 0], [1, 0], [0.001, 0.001]], "loop": true})"),
        "bodies[0].shape.points[0]: must be at least physics::kLinearSlop (0.005 m) from "
        "points[2], "
        "got 0.0014142137");
    EXPECT_EQ(
        withChain(
            R"({"type": "chain", "points": [[0, 0], [1, 0], [1, 1]], "loop": true, "ghostAfter": [2, 2]})"),
        "bodies[0].shape.ghostAfter: a loop has no ends, so no ghost points");
    EXPECT_EQ(
        withChain(
            R"({"type": "chain", "points": [[0, 0], [1, 0], [2, 0]], "materials": [{}, {}, {}]})"),
        "bodies[0].shape.materials: give one material or one per segment (2), got 3");
    EXPECT_EQ(
        withChain(
            R"({"type": "chain", "points": [[0, 0], [1, 0]], "materials": [{"restitution": 2}]})"),
        "bodies[0].shape.materials[0].restitution: must be in [0, 1] (e2d's limit), got 2");
    EXPECT_EQ(
        withChain(
            R"({"type": "chain", "points": [[0, 0], [1, 0]], "materials": [{"frcition": 1}]})"),
        "bodies[0].shape.materials[0].frcition: unknown field (did you mean \"friction\"?)");
    EXPECT_THAT(withChain(R"({"type": "chain", "points": [[0, 0], [6e5, 0]]})"),
                StartsWith("bodies[0].shape.points[1][0]: must be within e2d's limit of 500000"));
    EXPECT_EQ(withChain(R"({"type": "chain", "points": [[0, 0], [1, 0]], "radius": 1})"),
              "bodies[0].shape.radius: unknown field");
}

TEST(Generators, PyramidHasTheBox2DLayout) {
    // base 3: rows of 3, 2, 1 unit boxes on a ground whose top is y = 0.
    const Scenario s = parseScenario(
        R"({"family": "stacking", "generators": [{"type": "pyramid", "base": 3}]})", "p");
    ASSERT_EQ(s.scene.bodies.size(), 1u + 6u);
    EXPECT_EQ(s.scene.bodies[0].kind, scenes::BodyKind::Static);
    EXPECT_FLOAT_EQ(s.scene.bodies[0].position.y + s.scene.bodies[0].shapes[0].halfExtents.y, 0.0f);
    EXPECT_FLOAT_EQ(s.scene.bodies[1].position.x, -1.0f);
    EXPECT_FLOAT_EQ(s.scene.bodies[1].position.y, 0.5f);
    EXPECT_FLOAT_EQ(s.scene.bodies[3].position.x, 1.0f);
    EXPECT_FLOAT_EQ(s.scene.bodies[4].position.x, -0.5f); // second row, shifted half a box
    EXPECT_FLOAT_EQ(s.scene.bodies[4].position.y, 1.5f);
    EXPECT_FLOAT_EQ(s.scene.bodies[6].position.x, 0.0f); // apex
    EXPECT_FLOAT_EQ(s.scene.bodies[6].position.y, 2.5f);
    EXPECT_EQ(s.scene.bodies[6].tag, "top");
}

TEST(Generators, StackDominoesAndGrid) {
    const Scenario s = parseScenario(R"({"family": "stacking", "generators": [
        {"type": "verticalStack", "count": 4, "half": 0.25, "origin": [10, 2], "tag": "apex"},
        {"type": "dominoes", "count": 5, "spacing": 0.8, "push": -2, "ground": false},
        {"type": "grid", "columns": 3, "rows": 2, "spacing": [1, 2], "origin": [0, 20],
         "shape": {"type": "circle", "radius": 0.3}}]})",
                                     "g");
    ASSERT_EQ(s.scene.bodies.size(), 1u + 4u + 5u + 6u);
    EXPECT_FLOAT_EQ(s.scene.bodies[4].position.x, 10.0f);
    EXPECT_FLOAT_EQ(s.scene.bodies[4].position.y, 2.0f + 0.25f * 7.0f);
    EXPECT_EQ(s.scene.bodies[4].tag, "apex");
    EXPECT_FLOAT_EQ(s.scene.bodies[5].angularVelocity, -2.0f);
    EXPECT_FLOAT_EQ(s.scene.bodies[9].position.x, 4.0f * 0.8f);
    EXPECT_FLOAT_EQ(s.scene.bodies[9].shapes[0].halfExtents.x, 0.125f);
    EXPECT_FLOAT_EQ(s.scene.bodies[15].position.x, 2.0f);
    EXPECT_FLOAT_EQ(s.scene.bodies[15].position.y, 22.0f);
    EXPECT_EQ(s.scene.bodies[15].shapes[0].kind, scenes::ShapeKind::Circle);
}

TEST(ScenarioParser, EveryShippedScenarioParses) {
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(E2D_VALIDATION_SCENARIOS_DIR)) {
        if (entry.path().extension() != ".json") {
            continue;
        }
        SCOPED_TRACE(entry.path().string());
        const Scenario s = loadScenario(entry.path());
        EXPECT_EQ(s.name, entry.path().stem().string());
        EXPECT_FALSE(s.checks.empty());
        EXPECT_FALSE(s.measures.empty());
        ++count;
    }
    EXPECT_GE(count, 25);
}

TEST(ScenarioParser, LoadPrefixesTheFileName) {
    try {
        (void)loadScenario("/nonexistent/x.json");
        FAIL() << "expected a ScenarioError";
    } catch (const ScenarioError& e) {
        EXPECT_STREQ(e.what(), "/nonexistent/x.json: cannot read the file (no such file)");
    }
}

TEST(ScenarioParser, DeepNestingIsRefusedBeforeParsingNamingTheDepth) {
    // 100 000 levels used to overflow the stack (nlohmann copies and prints values recursively).
    const int n = 100000;
    const std::string deep = std::string(n, '[') + std::string(n, ']');
    EXPECT_EQ(
        errorOf(deep),
        "line 1, column 257: arrays and objects nest deeper than 256 levels; a scenario needs 6");
    // In a field the parser never reads, and cut off mid-file.
    EXPECT_THAT(errorOf(scene(R"(, "notes": )" + deep, R"({"type": "circle", "radius": 1})")),
                HasSubstr("line 1, column 303: arrays and objects nest deeper than 256 levels"));
    EXPECT_THAT(errorOf("{\"family\": \"hard\", \"x\": " + deep.substr(0, n / 3)),
                HasSubstr("nest deeper than 256 levels"));
    const auto file = std::filesystem::temp_directory_path() / "e2d_deep_scenario.json";
    {
        std::ofstream out(file);
        out << deep;
    }
    try {
        (void)loadScenario(file);
        FAIL() << "expected a ScenarioError";
    } catch (const ScenarioError& e) {
        EXPECT_EQ(std::string(e.what()),
                  file.string() + ":1:257: arrays and objects nest deeper than 256 levels; "
                                  "a scenario needs 6");
        EXPECT_EQ(e.diagnostic().line, 1);
        EXPECT_EQ(e.diagnostic().column, 257);
    }
}

TEST(ScenarioParser, BytesQuotedFromTheFileAreEscapedWhenNotPrintable) {
    // Ill-formed UTF-8 in a string: nlohmann's reason quotes the raw bytes.
    const std::string bad = errorOf("{\"family\": \"\xFF\xC0\"}");
    EXPECT_THAT(bad, StartsWith("line 1, column 13: family: not valid JSON: "));
    EXPECT_THAT(bad, HasSubstr("\\xff"));
    EXPECT_EQ(bad.find('\xFF'), std::string::npos) << bad;
    // A key JSON escapes a NUL and a control into: named whole, escaped.
    EXPECT_EQ(errorOf(scene(R"(, "a\u0000b\u0007": 1)", R"({"type": "circle", "radius": 1})")),
              "a\\x00b\\x07: unknown field");
}

TEST(ScenarioParser, ADirectoryIsNamedAsOne) {
    const auto dir = std::filesystem::temp_directory_path() / "e2d_scenario_dir.json";
    std::filesystem::create_directories(dir);
    try {
        (void)loadScenario(dir);
        FAIL() << "expected a ScenarioError";
    } catch (const ScenarioError& e) {
        EXPECT_EQ(std::string(e.what()),
                  dir.string() + ": cannot read the file (it is a directory)");
    }
}

} // namespace
} // namespace e2d::validation
