// SPDX-License-Identifier: MIT
#include <e2d/physics/world.hpp>

#include "world_test_util.hpp"

#include <gtest/gtest.h>

#include <string>

namespace e2d::physics {
namespace {

using test::errorOf;

ShapeGeometry unitCircle() { return Circle{{0.0f, 0.0f}, 0.5f}; }

TEST(WorldHandles, NullIdsAreNullAndInvalid) {
    World world;
    EXPECT_TRUE(BodyId{}.isNull());
    EXPECT_TRUE(ShapeId{}.isNull());
    EXPECT_FALSE(world.isValid(BodyId{}));
    EXPECT_FALSE(world.isValid(ShapeId{}));
    EXPECT_EQ(errorOf([&] {
                  world.setTransform(BodyId{}, {0.0f, 0.0f}, 0.0f);
              }),
              "physics::World::setTransform(): stale or null BodyId (index1 0, generation 0, "
              "world 0)");
    E2D_EXPECT_ERROR((void)world.shapeAabb(ShapeId{}),
                     "physics::World::shapeAabb(): stale or null ShapeId");
}

TEST(WorldHandles, CreatedIdsAreValidAndNotNull) {
    World world;
    BodyId body = world.createBody({});
    EXPECT_FALSE(body.isNull());
    EXPECT_TRUE(world.isValid(body));
    ShapeId shape = world.createShape(body, {}, unitCircle());
    EXPECT_FALSE(shape.isNull());
    EXPECT_TRUE(world.isValid(shape));
    EXPECT_EQ(world.shapeBody(shape), body);
    EXPECT_EQ(world.bodyCount(), 1);
    EXPECT_EQ(world.shapeCount(), 1);
}

TEST(WorldHandles, DestroyedBodyIdIsStaleEvenAfterItsSlotIsReused) {
    World world;
    BodyId first = world.createBody({});
    world.destroyBody(first);
    EXPECT_FALSE(world.isValid(first));
    E2D_EXPECT_ERROR((void)world.transform(first),
                     "physics::World::transform(): stale or null BodyId");

    BodyDef def;
    def.position = {3.0f, 4.0f};
    BodyId second = world.createBody(def);
    // The freed slot is reused with a new generation.
    EXPECT_EQ(second.index1, first.index1);
    EXPECT_NE(second.generation, first.generation);
    EXPECT_FALSE(world.isValid(first));
    EXPECT_TRUE(world.isValid(second));
    E2D_EXPECT_ERROR(world.setTransform(first, {1.0f, 1.0f}, 0.0f),
                     "physics::World::setTransform(): stale or null BodyId");
    // The stale call did not move the new occupant of the slot.
    EXPECT_EQ(world.transform(second).p, Vec2(3.0f, 4.0f));
}

TEST(WorldHandles, DestroyedShapeIdIsStaleEvenAfterItsSlotIsReused) {
    World world;
    BodyId body = world.createBody({});
    ShapeId first = world.createShape(body, {}, unitCircle());
    world.destroyShape(first);
    EXPECT_FALSE(world.isValid(first));
    EXPECT_EQ(world.shapeCount(), 0);
    ShapeId second = world.createShape(body, {}, unitCircle());
    EXPECT_EQ(second.index1, first.index1);
    EXPECT_FALSE(world.isValid(first));
    EXPECT_TRUE(world.isValid(second));
    E2D_EXPECT_ERROR(world.destroyShape(first),
                     "physics::World::destroyShape(): stale or null ShapeId");
    EXPECT_TRUE(world.isValid(second));
}

TEST(WorldHandles, DestroyBodyDestroysItsShapesOnly) {
    World world;
    BodyId a = world.createBody({});
    BodyId b = world.createBody({});
    ShapeId a1 = world.createShape(a, {}, unitCircle());
    ShapeId b1 = world.createShape(b, {}, unitCircle());
    ShapeId a2 = world.createShape(a, {}, Capsule{{0.0f, 0.0f}, {1.0f, 0.0f}, 0.25f});
    EXPECT_EQ(world.bodyShapes(a), (std::vector<ShapeId>{a2, a1}));
    world.destroyBody(a);
    EXPECT_FALSE(world.isValid(a1));
    EXPECT_FALSE(world.isValid(a2));
    EXPECT_TRUE(world.isValid(b1));
    EXPECT_EQ(world.bodyCount(), 1);
    EXPECT_EQ(world.shapeCount(), 1);
    EXPECT_EQ(world.bodyShapes(b), std::vector<ShapeId>{b1});
    // Nothing of a is left in the broad phase.
    EXPECT_EQ(world.overlapAabb({{-10.0f, -10.0f}, {10.0f, 10.0f}}), std::vector<ShapeId>{b1});
}

TEST(WorldHandles, DestroyingTheMiddleShapeKeepsTheBodyListIntact) {
    World world;
    BodyId body = world.createBody({});
    ShapeId s1 = world.createShape(body, {}, unitCircle());
    ShapeId s2 = world.createShape(body, {}, unitCircle());
    ShapeId s3 = world.createShape(body, {}, unitCircle());
    world.destroyShape(s2);
    EXPECT_EQ(world.bodyShapes(body), (std::vector<ShapeId>{s3, s1}));
    world.destroyShape(s3);
    EXPECT_EQ(world.bodyShapes(body), std::vector<ShapeId>{s1});
}

TEST(WorldHandles, GettersReturnWhatWasGiven) {
    World world;
    BodyDef def;
    def.type = BodyType::Kinematic;
    def.position = {1.0f, -2.0f};
    def.angle = 0.5f;
    def.linearVelocity = {3.0f, 4.0f};
    def.angularVelocity = -1.5f;
    def.userData = 42;
    BodyId body = world.createBody(def);
    EXPECT_EQ(world.bodyType(body), BodyType::Kinematic);
    Transform xf = world.transform(body);
    EXPECT_EQ(xf.p, Vec2(1.0f, -2.0f));
    EXPECT_FLOAT_EQ(xf.q.c, std::cos(0.5f));
    EXPECT_FLOAT_EQ(xf.q.s, std::sin(0.5f));
    EXPECT_EQ(world.linearVelocity(body), Vec2(3.0f, 4.0f));
    EXPECT_EQ(world.angularVelocity(body), -1.5f);
    EXPECT_EQ(world.bodyUserData(body), 42u);

    ShapeDef sd;
    sd.density = 2.0f;
    sd.friction = 0.25f;
    sd.restitution = 0.5f;
    sd.rollingResistance = 0.125f;
    sd.filter = {0x4, 0x3, -2};
    sd.isSensor = true;
    sd.userData = 7;
    ShapeId shape = world.createShape(body, sd, Circle{{1.0f, 0.0f}, 0.5f});
    EXPECT_EQ(world.shapeType(shape), ShapeType::Circle);
    EXPECT_EQ(std::get<Circle>(world.shapeGeometry(shape)).radius, 0.5f);
    EXPECT_EQ(world.shapeDensity(shape), 2.0f);
    EXPECT_EQ(world.shapeFriction(shape), 0.25f);
    EXPECT_EQ(world.shapeRestitution(shape), 0.5f);
    EXPECT_EQ(world.shapeRollingResistance(shape), 0.125f);
    EXPECT_EQ(world.shapeFilter(shape).categoryBits, 0x4u);
    EXPECT_EQ(world.shapeFilter(shape).maskBits, 0x3u);
    EXPECT_EQ(world.shapeFilter(shape).group, -2);
    EXPECT_TRUE(world.isSensor(shape));
    EXPECT_EQ(world.shapeUserData(shape), 7u);
    world.setShapeUserData(shape, 8);
    EXPECT_EQ(world.shapeUserData(shape), 8u);

    // The circle's centre (1, 0) rotated by 0.5 rad and moved to (1, -2).
    Vec2 c{1.0f + std::cos(0.5f), -2.0f + std::sin(0.5f)};
    Aabb box = world.shapeAabb(shape);
    EXPECT_NEAR(box.lower.x, c.x - 0.5f, 1e-5f);
    EXPECT_NEAR(box.lower.y, c.y - 0.5f, 1e-5f);
    EXPECT_NEAR(box.upper.x, c.x + 0.5f, 1e-5f);
    EXPECT_NEAR(box.upper.y, c.y + 0.5f, 1e-5f);
    Aabb fat = world.shapeFatAabb(shape);
    EXPECT_TRUE(contains(fat, box));
}

TEST(WorldHandles, TwoWorldsAreIndependent) {
    World a;
    World b;
    BodyId bodyA = a.createBody({});
    ShapeId shapeA = a.createShape(bodyA, {}, unitCircle());
    EXPECT_FALSE(b.isValid(bodyA));
    EXPECT_FALSE(b.isValid(shapeA));
    EXPECT_TRUE(b.overlapPoint({0.0f, 0.0f}).empty());
    EXPECT_FALSE(b.castRayClosest({-5.0f, 0.0f}, {10.0f, 0.0f}).has_value());

    BodyDef def;
    def.position = {10.0f, 0.0f};
    BodyId bodyB = b.createBody(def);
    ShapeId shapeB = b.createShape(bodyB, {}, unitCircle());
    // Same slot in each world, different objects: the ids differ by their world's tag.
    EXPECT_EQ(bodyA.index1, bodyB.index1);
    EXPECT_EQ(bodyA.generation, bodyB.generation);
    EXPECT_NE(bodyA, bodyB);
    EXPECT_FALSE(b.isValid(bodyA));
    EXPECT_FALSE(a.isValid(shapeB));
    EXPECT_EQ(a.overlapPoint({0.0f, 0.0f}), std::vector<ShapeId>{shapeA});
    EXPECT_EQ(b.overlapPoint({10.0f, 0.0f}), std::vector<ShapeId>{shapeB});
    EXPECT_TRUE(b.overlapPoint({0.0f, 0.0f}).empty());
    a.setGravity({0.0f, -1.0f});
    EXPECT_EQ(b.gravity(), Vec2(0.0f, -10.0f));
    a.destroyBody(bodyA);
    EXPECT_TRUE(b.isValid(bodyB));
    EXPECT_EQ(b.shapeCount(), 1);
}

TEST(WorldHandles, AnIdFromAnotherWorldIsAnErrorNamingTheFunction) {
    // Two worlds with the same objects in the same slots: a's ids must not name b's objects.
    World a;
    World b;
    ASSERT_NE(a.tag(), b.tag()); // derived from two live worlds' addresses: 1/65535 to clash
    BodyId bodyA = a.createBody({.position = {1.0f, 2.0f}});
    ShapeId shapeA = a.createShape(bodyA, {}, unitCircle());
    BodyId bodyB = b.createBody({.position = {5.0f, 6.0f}});
    ShapeId shapeB = b.createShape(bodyB, {.userData = 9}, unitCircle());
    EXPECT_EQ(bodyA.owner, a.tag());
    EXPECT_EQ(shapeB.owner, b.tag());

    std::string error = errorOf([&] { b.setTransform(bodyA, {0.0f, 0.0f}, 0.0f); });
    EXPECT_EQ(error, "physics::World::setTransform(): BodyId (index1 1, generation 1, world " +
                         std::to_string(a.tag()) +
                         ") belongs to another world (this world's "
                         "tag is " +
                         std::to_string(b.tag()) + ")");
    E2D_EXPECT_ERROR((void)b.shapeUserData(shapeA),
                     "physics::World::shapeUserData(): ShapeId (index1 1, generation 1, world");
    E2D_EXPECT_ERROR(b.destroyBody(bodyA), "physics::World::destroyBody(): BodyId");
    E2D_EXPECT_ERROR(a.createShape(bodyB, {}, unitCircle()),
                     "physics::World::createShape(): BodyId");
    // Nothing of b was touched.
    EXPECT_EQ(b.transform(bodyB).p, Vec2(5.0f, 6.0f));
    EXPECT_EQ(b.shapeUserData(shapeB), 9u);
    EXPECT_EQ(a.shapeCount(), 1);
    EXPECT_EQ(b.bodyCount(), 1);
}

TEST(WorldHandles, ChosenTagsAreWrittenIntoIdsAndZeroIsNeverLive) {
    World a{WorldDef{.tag = 7}};
    World b{WorldDef{.tag = 8}};
    EXPECT_EQ(a.tag(), 7);
    BodyId body = a.createBody({});
    EXPECT_EQ(body.owner, 7);
    EXPECT_EQ(a.createShape(body, {}, unitCircle()).owner, 7);
    EXPECT_FALSE(b.isValid(body));
    // A hand-made id (world 0) never names a body.
    EXPECT_FALSE(a.isValid(BodyId{body.index1, body.generation}));
    World derived;
    EXPECT_NE(derived.tag(), 0);
}

TEST(WorldHandles, MovedWorldKeepsItsObjects) {
    World a;
    BodyId body = a.createBody({});
    ShapeId shape = a.createShape(body, {}, unitCircle());
    std::uint16_t tag = a.tag();
    World b = std::move(a);
    EXPECT_EQ(b.tag(), tag);
    EXPECT_TRUE(b.isValid(body));
    EXPECT_EQ(b.overlapPoint({0.0f, 0.0f}), std::vector<ShapeId>{shape});
}

} // namespace
} // namespace e2d::physics
