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
    EXPECT_EQ(errorOf([&] { world.setTransform(BodyId{}, {0.0f, 0.0f}, 0.0f); }),
              "physics::World::setTransform(): stale or null BodyId (index1 0, generation 0)");
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
    // Same slot in each world, different objects.
    EXPECT_EQ(bodyA, bodyB);
    EXPECT_EQ(a.overlapPoint({0.0f, 0.0f}), std::vector<ShapeId>{shapeA});
    EXPECT_EQ(b.overlapPoint({10.0f, 0.0f}), std::vector<ShapeId>{shapeB});
    EXPECT_TRUE(b.overlapPoint({0.0f, 0.0f}).empty());
    a.setGravity({0.0f, -1.0f});
    EXPECT_EQ(b.gravity(), Vec2(0.0f, -10.0f));
    a.destroyBody(bodyA);
    EXPECT_TRUE(b.isValid(bodyB));
    EXPECT_EQ(b.shapeCount(), 1);
}

TEST(WorldHandles, MovedWorldKeepsItsObjects) {
    World a;
    BodyId body = a.createBody({});
    ShapeId shape = a.createShape(body, {}, unitCircle());
    World b = std::move(a);
    EXPECT_TRUE(b.isValid(body));
    EXPECT_EQ(b.overlapPoint({0.0f, 0.0f}), std::vector<ShapeId>{shape});
}

} // namespace
} // namespace e2d::physics
