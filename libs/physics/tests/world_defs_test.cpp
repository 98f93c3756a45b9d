// SPDX-License-Identifier: MIT
#include <e2d/physics/world.hpp>

#include "world_test_util.hpp"

#include <limits>

namespace e2d::physics {
namespace {

using test::errorOf;

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(WorldDefs, DefaultsAreDocumentedValues) {
    WorldDef def;
    EXPECT_EQ(def.gravity, Vec2(0.0f, -10.0f));
    EXPECT_EQ(def.collisionAlgorithm, CollisionAlgorithm::Sat);
    EXPECT_EQ(def.speculativeDistance, kSpeculativeDistance);
    EXPECT_EQ(def.solver.classicAllowedPenetration, kLinearSlop);
    EXPECT_EQ(def.solver.classicPositionBias, 0.2f);
    ShapeDef shape;
    EXPECT_EQ(shape.density, 1.0f);
    EXPECT_EQ(shape.friction, 0.6f);
    EXPECT_EQ(shape.restitution, 0.0f);
    EXPECT_EQ(shape.rollingResistance, 0.0f);
    EXPECT_FALSE(shape.isSensor);
    BodyDef body;
    EXPECT_EQ(body.type, BodyType::Static);
    EXPECT_TRUE(body.enabled);

    World world;
    EXPECT_EQ(world.gravity(), Vec2(0.0f, -10.0f));
    EXPECT_EQ(world.collisionAlgorithm(), CollisionAlgorithm::Sat);
    EXPECT_EQ(world.speculativeDistance(), kSpeculativeDistance);
}

TEST(WorldDefs, WorldDefFieldsAreCheckedByName) {
    WorldDef def;
    def.gravity = {kNan, -10.0f};
    EXPECT_EQ(errorOf([&] { World w(def); }),
              "physics::World::World(): def.gravity must be finite, got (nan, -10)");

    def = {};
    def.collisionAlgorithm = static_cast<CollisionAlgorithm>(7);
    EXPECT_EQ(errorOf([&] { World w(def); }),
              "physics::World::World(): def.collisionAlgorithm must be Sat or GjkEpa, got 7");

    def = {};
    def.speculativeDistance = -0.5f;
    E2D_EXPECT_ERROR(World w(def), "def.speculativeDistance must be finite and in [0, kAabbMargin");
    def.speculativeDistance = 1.0f; // wider than the fattening margin
    E2D_EXPECT_ERROR(World w(def), "got 1");

    def = {};
    def.bodyCapacity = -1;
    EXPECT_EQ(errorOf([&] { World w(def); }),
              "physics::World::World(): def.bodyCapacity must be >= 0, got -1");
    def = {};
    def.shapeCapacity = -3;
    EXPECT_EQ(errorOf([&] { World w(def); }),
              "physics::World::World(): def.shapeCapacity must be >= 0, got -3");

    def = {};
    def.collisionAlgorithm = CollisionAlgorithm::GjkEpa;
    def.bodyCapacity = 10;
    def.shapeCapacity = 20;
    World world(def);
    EXPECT_EQ(world.collisionAlgorithm(), CollisionAlgorithm::GjkEpa);
}

TEST(WorldDefs, ClassicPositionCorrectionFieldsAreCheckedByName) {
    WorldDef def;
    def.solver.classicAllowedPenetration = -0.01f;
    EXPECT_EQ(errorOf([&] { World w(def); }),
              "physics::World::World(): def.solver.classicAllowedPenetration must be finite and in "
              "[0, 0.1], got -0.01");
    def.solver.classicAllowedPenetration = 0.5f;
    EXPECT_EQ(errorOf([&] { World w(def); }),
              "physics::World::World(): def.solver.classicAllowedPenetration must be finite and in "
              "[0, 0.1], got 0.5");
    def.solver.classicAllowedPenetration = kInf;
    E2D_EXPECT_ERROR(World w(def), "def.solver.classicAllowedPenetration must be finite and in "
                                   "[0, 0.1], got inf");

    def = {};
    def.solver.classicPositionBias = 1.5f;
    EXPECT_EQ(errorOf([&] { World w(def); }),
              "physics::World::World(): def.solver.classicPositionBias must be finite and in "
              "[0, 1], got 1.5");
    def.solver.classicPositionBias = -0.2f;
    E2D_EXPECT_ERROR(World w(def), "def.solver.classicPositionBias must be finite and in [0, 1], "
                                   "got -0.2");
    def.solver.classicPositionBias = kNan;
    E2D_EXPECT_ERROR(World w(def), "def.solver.classicPositionBias must be finite and in [0, 1], "
                                   "got nan");

    // The ends of both ranges are valid, in either solver mode.
    for (SolverMode mode : {SolverMode::SoftStep, SolverMode::Classic}) {
        def = {};
        def.solver.mode = mode;
        def.solver.classicAllowedPenetration = 0.0f;
        def.solver.classicPositionBias = 0.0f;
        EXPECT_NO_THROW(World w(def));
        def.solver.classicAllowedPenetration = 0.1f;
        def.solver.classicPositionBias = 1.0f;
        World world(def);
        EXPECT_EQ(world.solverDef().classicAllowedPenetration, 0.1f);
        EXPECT_EQ(world.solverDef().classicPositionBias, 1.0f);
    }
}

TEST(WorldDefs, BodyDefFieldsAreCheckedByNameAndNothingIsCreated) {
    World world;
    BodyDef def;
    def.type = static_cast<BodyType>(3);
    EXPECT_EQ(errorOf([&] { world.createBody(def); }),
              "physics::World::createBody(): def.type must be Static, Kinematic or Dynamic, got 3");
    def = {};
    def.position = {kInf, 0.0f};
    EXPECT_EQ(errorOf([&] { world.createBody(def); }),
              "physics::World::createBody(): def.position must be finite with |x|, |y| <= kHuge "
              "(500000 m), got (inf, 0)");
    def.position = {0.0f, -2.0f * kHuge};
    E2D_EXPECT_ERROR(world.createBody(def), "got (0, -1000000)");
    def = {};
    def.angle = kNan;
    EXPECT_EQ(errorOf([&] { world.createBody(def); }),
              "physics::World::createBody(): def.angle must be finite, got nan");
    def = {};
    def.linearVelocity = {0.0f, -kInf};
    E2D_EXPECT_ERROR(world.createBody(def), "def.linearVelocity must be finite, got (0, -inf)");
    def = {};
    def.angularVelocity = kNan;
    E2D_EXPECT_ERROR(world.createBody(def), "def.angularVelocity must be finite");
    EXPECT_EQ(world.bodyCount(), 0);
    // The failed creations used no slot.
    EXPECT_EQ(world.createBody({}).index1, 1u);
}

TEST(WorldDefs, ShapeDefFieldsAreCheckedByName) {
    World world;
    BodyId body = world.createBody({});
    ShapeGeometry circle = Circle{{0.0f, 0.0f}, 1.0f};
    ShapeDef def;
    def.density = -1.0f;
    EXPECT_EQ(errorOf([&] { world.createShape(body, def, circle); }),
              "physics::World::createShape(): def.density must be finite and >= 0, got -1");
    def = {};
    def.friction = kNan;
    E2D_EXPECT_ERROR(world.createShape(body, def, circle), "def.friction must be finite and >= 0");
    def = {};
    def.restitution = -0.5f;
    E2D_EXPECT_ERROR(world.createShape(body, def, circle),
                     "physics::World::createShape(): def.restitution must be finite and in [0, 1], "
                     "got -0.5");
    // Documented 0..1: a ball with restitution 1.5 dropped from 3 m used to climb to 63 m.
    def.restitution = 1.5f;
    E2D_EXPECT_ERROR(world.createShape(body, def, circle),
                     "physics::World::createShape(): def.restitution must be finite and in [0, 1], "
                     "got 1.5");
    def.restitution = 1.0f;
    EXPECT_NO_THROW(world.createShape(body, def, circle));
    world.destroyShape(world.bodyShapes(body).front());
    def = {};
    def.rollingResistance = kInf;
    E2D_EXPECT_ERROR(world.createShape(body, def, circle),
                     "def.rollingResistance must be finite and >= 0, got inf");
    EXPECT_EQ(world.shapeCount(), 0);
    E2D_EXPECT_ERROR(world.createShape(BodyId{}, {}, circle),
                     "physics::World::createShape(): stale or null BodyId");
}

TEST(WorldDefs, BadGeometryLeavesTheWorldUnchanged) {
    World world;
    BodyId body = world.createBody({});
    ShapeId good = world.createShape(body, {}, Circle{{0.0f, 0.0f}, 1.0f});
    world.updatePairs();

    std::string message = errorOf([&] {
        world.createShape(body, {}, Circle{{0.0f, 0.0f}, -1.0f});
    });
    EXPECT_PRED_FORMAT2(::testing::IsSubstring, "physics::World::createShape()", message);
    EXPECT_PRED_FORMAT2(::testing::IsSubstring, "radius", message);
    E2D_EXPECT_ERROR(world.createShape(body, {}, Capsule{{0.0f, 0.0f}, {kNan, 0.0f}, 0.5f}),
                     "physics::World::createShape()");
    E2D_EXPECT_ERROR(world.createShape(body, {}, Polygon{}), "physics::World::createShape()");

    EXPECT_EQ(world.shapeCount(), 1);
    EXPECT_EQ(world.bodyShapes(body), std::vector<ShapeId>{good});
    EXPECT_EQ(world.overlapAabb({{-5.0f, -5.0f}, {5.0f, 5.0f}}), std::vector<ShapeId>{good});
    // The next shape takes the next slot: nothing was allocated for the failed ones.
    ShapeId next = world.createShape(body, {}, Circle{{0.0f, 0.0f}, 1.0f});
    EXPECT_EQ(next.index1, 2u);
}

TEST(WorldDefs, BadInputToSettersChangesNothing) {
    World world;
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {1.0f, 2.0f};
    BodyId body = world.createBody(def);
    ShapeId shape = world.createShape(body, {}, Circle{{0.0f, 0.0f}, 0.5f});
    Aabb before = world.shapeAabb(shape);

    EXPECT_EQ(errorOf([&] {
                  world.setTransform(body, {kNan, 0.0f}, 0.0f);
              }),
              "physics::World::setTransform(): position must be finite with |x|, |y| <= kHuge "
              "(500000 m), got (nan, 0)");
    EXPECT_EQ(errorOf([&] {
                  world.setTransform(body, {0.0f, 0.0f}, kInf);
              }),
              "physics::World::setTransform(): angle must be finite, got inf");
    EXPECT_EQ(world.transform(body).p, Vec2(1.0f, 2.0f));
    EXPECT_EQ(world.shapeAabb(shape).lower, before.lower);
    EXPECT_EQ(world.overlapPoint({1.0f, 2.0f}), std::vector<ShapeId>{shape});

    E2D_EXPECT_ERROR(
        world.setLinearVelocity(body, {kNan, kNan}),
        "physics::World::setLinearVelocity(): velocity must be finite, got (nan, nan)");
    E2D_EXPECT_ERROR(world.setAngularVelocity(body, kInf),
                     "physics::World::setAngularVelocity(): velocity must be finite, got inf");
    E2D_EXPECT_ERROR(world.setGravity({0.0f, kNan}),
                     "physics::World::setGravity(): gravity must be finite, got (0, nan)");
    EXPECT_EQ(world.linearVelocity(body), Vec2(0.0f, 0.0f));
    EXPECT_EQ(world.angularVelocity(body), 0.0f);
    EXPECT_EQ(world.gravity(), Vec2(0.0f, -10.0f));
}

TEST(WorldDefs, QueryInputIsChecked) {
    World world;
    EXPECT_EQ(
        errorOf([&] {
            (void)world.castRayClosest({0.0f, 0.0f}, {0.0f, 0.0f});
        }),
        "physics::World::castRayClosest(): translation must be finite and non-zero, got (0, 0)");
    E2D_EXPECT_ERROR((void)world.castRayClosest({0.0f, 0.0f}, {3.0e38f, 0.0f}),
                     "physics::World::castRayClosest(): origin + translation must be within kHuge "
                     "(500000 m), got (3e+38, 0)");
    E2D_EXPECT_ERROR((void)world.castRayAll({kNan, 0.0f}, {1.0f, 0.0f}),
                     "physics::World::castRayAll(): origin must be finite");
    E2D_EXPECT_ERROR((void)world.overlapAabb({{1.0f, 0.0f}, {0.0f, 1.0f}}),
                     "physics::World::overlapAabb(): box must be finite with lower <= upper, got "
                     "lower (1, 0), upper (0, 1)");
    E2D_EXPECT_ERROR((void)world.overlapPoint({0.0f, kInf}),
                     "physics::World::overlapPoint(): point must be finite, got (0, inf)");
}

} // namespace
} // namespace e2d::physics
