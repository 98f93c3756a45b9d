// SPDX-License-Identifier: MIT
// The callback rules of World for the hooks (pre-solve, pair filter) and the game API (chains,
// setters, views): the world is locked while a hook runs, ids carry their world everywhere.
#include <e2d/physics/world.hpp>

#include "world_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace e2d::physics {
namespace {

using test::errorOf;

constexpr float kDt = 1.0f / 60.0f;

// A dynamic box resting on a static ground, touching after one step.
struct Resting {
    World world;
    BodyId ground;
    BodyId box;
    BodyId spare;
    Resting() {
        ground = world.createBody({});
        world.createShape(ground, {}, makeOffsetBox(10.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
        box = world.createBody({.type = BodyType::Dynamic, .position = {0.0f, 0.5f}});
        world.createShape(box, {}, makeBox(0.5f, 0.5f));
        spare = world.createBody({.type = BodyType::Dynamic, .position = {50.0f, 0.5f}});
        world.createShape(spare, {}, makeBox(0.5f, 0.5f));
    }
};

std::string lockedMessage(const std::string& function, const char* hook, const char* by) {
    return "physics::World::" + function + "(): cannot run inside the " + hook + " callback of " +
           by +
           "() (it would change what the callback is walking); collect the ids and call it "
           "after " +
           by + "() returns";
}

TEST(WorldCallbackRules, ThePreSolveCallbackLocksTheWorld) {
    struct Call {
        std::string name;
        std::function<void(Resting&)> call;
    };
    const std::vector<Call> calls = {
        {"createBody", [](Resting& r) { r.world.createBody({}); }},
        {"destroyBody", [](Resting& r) { r.world.destroyBody(r.spare); }},
        {"createShape",
         [](Resting& r) {
             r.world.createShape(r.spare, {}, Circle{{0, 0}, 1});
         }},
        {"createChain",
         [](Resting& r) {
             r.world.createChain(r.ground, {.points = {{1, 0}, {0, 0}}});
         }},
        {"destroyShape",
         [](Resting& r) { r.world.destroyShape(r.world.bodyShapes(r.spare).front()); }},
        {"setTransform",
         [](Resting& r) {
             r.world.setTransform(r.spare, {60, 0}, 0);
         }},
        {"setBodyEnabled", [](Resting& r) { r.world.setBodyEnabled(r.spare, false); }},
        {"setBodyType", [](Resting& r) { r.world.setBodyType(r.spare, BodyType::Static); }},
        {"setShapeSensor",
         [](Resting& r) { r.world.setShapeSensor(r.world.bodyShapes(r.spare).front(), true); }},
        {"setShapeGeometry",
         [](Resting& r) {
             r.world.setShapeGeometry(r.world.bodyShapes(r.spare).front(), Circle{{0, 0}, 1});
         }},
        {"setShapeFilter",
         [](Resting& r) { r.world.setShapeFilter(r.world.bodyShapes(r.spare).front(), {}); }},
        {"setPreSolveCallback", [](Resting& r) { r.world.setPreSolveCallback({}); }},
        {"setPairFilterCallback", [](Resting& r) { r.world.setPairFilterCallback({}); }},
        {"updatePairs", [](Resting& r) { r.world.updatePairs(); }},
        {"step", [](Resting& r) { r.world.step(kDt); }},
    };
    for (const Call& c : calls) {
        SCOPED_TRACE(c.name);
        Resting r;
        int called = 0;
        r.world.setPreSolveCallback([&](ShapeId, ShapeId, const Manifold&) {
            ++called;
            c.call(r);
            return true;
        });
        const std::string error = errorOf([&] { r.world.step(kDt); });
        EXPECT_EQ(error, lockedMessage(c.name, "pre-solve", "step"));
        EXPECT_EQ(called, 1);
        // Nothing the call would have done happened, and the world steps on without the hook.
        EXPECT_EQ(r.world.bodyCount(), 3);
        EXPECT_EQ(r.world.shapeCount(), 3);
        EXPECT_EQ(r.world.transform(r.spare).p, Vec2(50.0f, 0.5f));
        EXPECT_EQ(r.world.bodyType(r.spare), BodyType::Dynamic);
        EXPECT_TRUE(r.world.isBodyEnabled(r.spare));
        r.world.setPreSolveCallback({});
        for (int i = 0; i < 30; ++i) {
            r.world.step(kDt);
        }
        EXPECT_NEAR(r.world.transform(r.box).p.y, 0.5f, 0.02f); // still resting on the ground
    }
}

TEST(WorldCallbackRules, ThePreSolveCallbackMayPushReadAndChangeMaterials) {
    Resting r;
    ShapeId boxShape = r.world.bodyShapes(r.box).front();
    int called = 0;
    r.world.setPreSolveCallback([&](ShapeId a, ShapeId b, const Manifold&) {
        ++called;
        BodyId other = r.world.shapeBody(a) == r.box ? r.world.shapeBody(b) : r.world.shapeBody(a);
        EXPECT_EQ(other, r.ground);
        EXPECT_FALSE(r.world.overlapPoint({0.0f, 0.5f}).empty());
        r.world.setShapeFriction(boxShape, 0.1f);
        r.world.setShapeDensity(boxShape, 2.0f);
        r.world.applyLinearImpulseToCenter(r.spare, {0.0f, 1.0f});
        r.world.setBodyUserData(r.box, 9);
        return true;
    });
    r.world.step(kDt);
    EXPECT_EQ(called, 1);
    EXPECT_FLOAT_EQ(r.world.shapeFriction(boxShape), 0.1f);
    EXPECT_FLOAT_EQ(r.world.massData(r.box).mass, 2.0f); // 1 m^2 at 2 kg/m^2
    EXPECT_GT(r.world.linearVelocity(r.spare).y, 0.0f);
    EXPECT_EQ(r.world.bodyUserData(r.box), 9u);
}

TEST(WorldCallbackRules, ThePairFilterCallbackLocksTheWorldInUpdatePairsAndInStep) {
    for (bool inStep : {false, true}) {
        SCOPED_TRACE(inStep ? "step" : "updatePairs");
        Resting r;
        int called = 0;
        r.world.setPairFilterCallback([&](ShapeId, ShapeId) {
            ++called;
            r.world.destroyBody(r.spare);
            return true;
        });
        const std::string error =
            errorOf([&] { inStep ? r.world.step(kDt) : r.world.updatePairs(); });
        EXPECT_EQ(error,
                  lockedMessage("destroyBody", "pair filter", inStep ? "step" : "updatePairs"));
        EXPECT_EQ(called, 1);
        EXPECT_TRUE(r.world.isValid(r.spare));
        // Outside the callback the world is unlocked again.
        r.world.setPairFilterCallback({});
        r.world.destroyBody(r.spare);
        r.world.step(kDt);
        EXPECT_EQ(r.world.bodyCount(), 2);
    }
}

TEST(WorldCallbackRules, AQueryCallbackCannotCreateAChainOrChangeABodysType) {
    Resting r;
    const Aabb all{{-20.0f, -2.0f}, {60.0f, 2.0f}};
    E2D_EXPECT_ERROR(
        r.world.overlapAabb(all, {},
                            [&](ShapeId) {
                                r.world.createChain(r.ground, {.points = {{1, 0}, {0, 0}}});
                                return true;
                            }),
        "physics::World::createChain(): cannot run inside the callback of overlapAabb()");
    E2D_EXPECT_ERROR(
        r.world.overlapAabb(all, {},
                            [&](ShapeId) {
                                r.world.setBodyType(r.box, BodyType::Kinematic);
                                return true;
                            }),
        "physics::World::setBodyType(): cannot run inside the callback of overlapAabb()");
    EXPECT_EQ(r.world.shapeCount(), 3);
    EXPECT_EQ(r.world.bodyType(r.box), BodyType::Dynamic);
    // An explosion in a walk pushes (impulses are allowed).
    r.world.overlapAabb(all, {}, [&](ShapeId) {
        r.world.explode({.position = {50.0f, -1.0f}, .radius = 1.0f, .falloff = 1.0f});
        return false;
    });
    EXPECT_GT(r.world.linearVelocity(r.spare).y, 0.0f);
}

TEST(WorldCallbackRules, ChainIdsAndViewsCarryTheirWorld) {
    World a{WorldDef{.tag = 11}};
    World b{WorldDef{.tag = 12}};
    BodyId groundA = a.createBody({});
    BodyId groundB = b.createBody({});
    ASSERT_EQ(groundA.index1, groundB.index1); // same slot in each world
    const ChainDef chain{.points = {{2.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}}};
    std::vector<ShapeId> ids = a.createChain(groundA, chain);
    ASSERT_EQ(ids.size(), 2u);
    for (ShapeId id : ids) {
        EXPECT_EQ(id.owner, 11);
        EXPECT_EQ(a.shapeBody(id), groundA);
    }
    // b's body named with a's id: rejected, naming createChain and both tags; nothing created.
    BodyId wrong = groundB;
    wrong.owner = a.tag();
    EXPECT_EQ(errorOf([&] { b.createChain(wrong, chain); }),
              "physics::World::createChain(): BodyId (index1 1, generation 1, world 11) belongs "
              "to another world (this world's tag is 12)");
    EXPECT_EQ(b.shapeCount(), 0);
    // A view over the wrong world checks like the world does.
    Shape seg = b.shape(ids[0]);
    EXPECT_FALSE(seg.isValid());
    E2D_EXPECT_ERROR(seg.setFriction(0.1f), "belongs to another world (this world's tag is 12)");
    Body ground = a.body(groundA);
    std::vector<ShapeId> shapes = ground.shapes();
    EXPECT_TRUE(std::is_permutation(shapes.begin(), shapes.end(), ids.begin(), ids.end()));
    EXPECT_EQ(ground.createShape({}, makeBox(1.0f, 1.0f)).id().owner, 11);
}

TEST(WorldCallbackRules, RestitutionAboveOneIsRejectedBySettersAndChains) {
    World world;
    BodyId body = world.createBody({});
    ShapeId shape = world.createShape(body, {}, makeBox(1.0f, 1.0f));
    EXPECT_EQ(errorOf([&] { world.setShapeRestitution(shape, 1.5f); }),
              "physics::World::setShapeRestitution(): restitution must be finite and in [0, 1], "
              "got 1.5");
    EXPECT_FLOAT_EQ(world.shapeRestitution(shape), 0.0f);
    ChainDef chain{.points = {{1.0f, 0.0f}, {0.0f, 0.0f}}};
    chain.materials = {SurfaceMaterial{.restitution = 2.0f}};
    EXPECT_EQ(errorOf([&] { world.createChain(body, chain); }),
              "physics::World::createChain(): def.materials[0].restitution must be finite and in "
              "[0, 1], got 2");
    chain.materials.clear();
    chain.shape.restitution = -0.5f;
    EXPECT_EQ(errorOf([&] { world.createChain(body, chain); }),
              "physics::World::createChain(): def.shape.restitution must be finite and in [0, 1], "
              "got -0.5");
    EXPECT_EQ(world.shapeCount(), 1);
}

} // namespace
} // namespace e2d::physics
