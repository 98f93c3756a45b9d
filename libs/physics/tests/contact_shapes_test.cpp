// SPDX-License-Identifier: MIT
// The narrow phase's own path for circle pairs and what a contact copies from its shapes
// (contact.cpp): the manifold a step keeps is the pair routine's to the bit, for circles within
// the speculative distance and for a shape whose geometry changed while it touched. And its
// fat-box test, skipped while no fat box changed: a contact still ends when its boxes part.
#include <e2d/physics/world.hpp>

#include "world_step_util.hpp"
#include "world_test_util.hpp"

#include <gtest/gtest.h>

namespace e2d::physics::test {
namespace {

// No gravity, no sleep: still bodies, so a step's speculative margin is kSpeculativeDistance.
WorldDef stillDef() {
    WorldDef def;
    def.gravity = {0.0f, 0.0f};
    def.solver.enableSleep = false;
    return def;
}

struct TwoBodies {
    World world{stillDef()};
    BodyId a;
    BodyId b;
    ShapeId shapeA;
    ShapeId shapeB;

    TwoBodies(Vec2 positionA, float angleA, const ShapeGeometry& geometryA, Vec2 positionB,
              const ShapeGeometry& geometryB) {
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        bd.position = positionA;
        bd.angle = angleA;
        a = world.createBody(bd);
        shapeA = world.createShape(a, {}, geometryA);
        bd.position = positionB;
        bd.angle = 0.0f;
        b = world.createBody(bd);
        shapeB = world.createShape(b, {}, geometryB);
    }

    // Steps once; expects the step's one touching contact to hold what the pair routine finds
    // at the transforms the step started from, bit for bit (but the solver's impulses).
    // Returns that manifold.
    Manifold stepAndCompare() {
        const Transform xfA = world.transform(a);
        const Transform xfB = world.transform(b);
        world.step(kStep);
        Manifold kept{};
        Manifold fresh{};
        int touching = 0;
        world.forEachTouchingContact([&](const ContactData& c) {
            ++touching;
            kept = *c.manifold;
            const bool aFirst = c.shapeA == shapeA;
            fresh = collide(world.shapeGeometry(c.shapeA), aFirst ? xfA : xfB,
                            world.shapeGeometry(c.shapeB), aFirst ? xfB : xfA,
                            CollisionAlgorithm::Sat, kSpeculativeDistance);
        });
        EXPECT_EQ(touching, 1);
        EXPECT_EQ(kept.pointCount, fresh.pointCount);
        EXPECT_EQ(kept.normal.x, fresh.normal.x);
        EXPECT_EQ(kept.normal.y, fresh.normal.y);
        for (int i = 0; i < fresh.pointCount; ++i) {
            SCOPED_TRACE(i);
            const ManifoldPoint& k = kept.points[i];
            const ManifoldPoint& f = fresh.points[i];
            EXPECT_EQ(k.id, f.id);
            EXPECT_EQ(k.point.x, f.point.x);
            EXPECT_EQ(k.point.y, f.point.y);
            EXPECT_EQ(k.anchorA.x, f.anchorA.x);
            EXPECT_EQ(k.anchorA.y, f.anchorA.y);
            EXPECT_EQ(k.anchorB.x, f.anchorB.x);
            EXPECT_EQ(k.anchorB.y, f.anchorB.y);
            EXPECT_EQ(k.separation, f.separation);
        }
        return kept;
    }
};

// Ball A's centre is off its body's origin and the body turned, so the routine rotates it; ball
// B's surface is 5 mm from A's, within the speculative distance but not touching.
TwoBodies ballsApart() {
    const Circle ballA{{0.1f, 0.05f}, 0.5f};
    const float angleA = 0.3f;
    const Vec2 centreA = rotate(Rot{std::cos(angleA), std::sin(angleA)}, ballA.center);
    return TwoBodies({0.0f, 0.0f}, angleA, ballA, centreA + Vec2{0.5f + 0.4f + 0.005f, 0.0f},
                     Circle{{0.0f, 0.0f}, 0.4f});
}

TEST(ContactShapes, ACirclePairKeepsTheRoutinesManifoldWithinTheMargin) {
    TwoBodies scene = ballsApart();
    const Manifold first = scene.stepAndCompare();
    ASSERT_EQ(first.pointCount, 1);
    EXPECT_GT(first.points[0].separation, 0.0f); // speculative
    EXPECT_FALSE(first.points[0].persisted);
    // The next step finds the same point (circle pairs report id 0) and keeps its impulse.
    const Manifold second = scene.stepAndCompare();
    ASSERT_EQ(second.pointCount, 1);
    EXPECT_TRUE(second.points[0].persisted);
}

TEST(ContactShapes, ACirclePairBeyondTheMarginHasNoPoint) {
    TwoBodies scene = ballsApart();
    scene.world.setTransform(scene.b, scene.world.transform(scene.b).p + Vec2{0.05f, 0.0f}, 0.0f);
    scene.world.step(kStep);
    EXPECT_EQ(scene.world.contactCount(), 1); // the fat boxes still overlap
    int touching = 0;
    scene.world.forEachTouchingContact([&](const ContactData&) { ++touching; });
    EXPECT_EQ(touching, 0);
}

// A ball that becomes a box while it touches another ball: the contact is collided as a
// polygon and a circle from then on.
TEST(ContactShapes, AShapeTurnedFromCircleToBoxIsCollidedAsABox) {
    TwoBodies scene = ballsApart();
    ASSERT_EQ(scene.stepAndCompare().pointCount, 1);
    // Its right face 14 mm from the ball.
    scene.world.setShapeGeometry(scene.shapeA, makeBox(0.55f, 0.55f));
    const Manifold boxBall = scene.stepAndCompare();
    EXPECT_EQ(boxBall.pointCount, 1);
}

// A ball resting on the ground until no proxy has moved for a while (the narrow phase stops
// testing the fat boxes), then moved away by hand: its contact ends that step.
TEST(ContactFatBoxes, AContactEndsWhenItsBoxesPartAfterStepsWithoutMoves) {
    WorldDef def;
    def.solver.enableSleep = false;
    World world{def};
    addGround(world);
    const BodyId ball = addBall(world, {0.0f, 0.25f}, 0.25f);
    int stillSteps = 0;
    for (int i = 0; i < 300 && stillSteps < 10; ++i) {
        world.step(kStep);
        stillSteps = world.stepCounters().proxyMoves == 0 ? stillSteps + 1 : 0;
    }
    ASSERT_EQ(stillSteps, 10);
    ASSERT_EQ(world.contactCount(), 1);
    world.setTransform(ball, {0.0f, 5.0f}, 0.0f);
    world.step(kStep);
    EXPECT_EQ(world.contactCount(), 0);
    EXPECT_EQ(world.contactEndEvents().size(), 1u);
}

} // namespace
} // namespace e2d::physics::test
