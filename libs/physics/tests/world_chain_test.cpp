// SPDX-License-Identifier: MIT
// Chain shapes: one-sided segments that know their neighbours. A box sliding over a floor of
// collinear chain segments glides; the same floor of separate segments or boxes catches it.
#include <e2d/physics/world.hpp>

#include "world_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace e2d::physics {
namespace {

using test::errorOf;

constexpr float kDt = 1.0f / 60.0f;
constexpr int kSegments = 100;

// Floor points at y = 0 from x = +50 to x = -50 (right to left: the front side is up).
std::vector<Vec2> floorPoints() {
    std::vector<Vec2> points;
    for (int i = 0; i <= kSegments; ++i) {
        points.push_back({50.0f - static_cast<float>(i), 0.0f});
    }
    return points;
}

enum class FloorKind { Chain, Segments, Boxes };

void buildFloor(World& world, FloorKind kind) {
    BodyId ground = world.createBody({});
    ShapeDef sd;
    sd.friction = 0.0f;
    if (kind == FloorKind::Chain) {
        ChainDef def;
        def.points = floorPoints();
        def.shape = sd;
        world.createChain(ground, def);
        return;
    }
    for (int i = 0; i < kSegments; ++i) {
        float x = -50.0f + static_cast<float>(i);
        if (kind == FloorKind::Segments) {
            world.createShape(ground, sd, Segment{{x, 0.0f}, {x + 1.0f, 0.0f}});
        } else {
            world.createShape(ground, sd, makeOffsetBox(0.5f, 0.5f, {x + 0.5f, -0.5f}, 0.0f));
        }
    }
}

struct Slide {
    float maxVerticalSpeed = 0.0f; // after the box settled
    float distance = 0.0f;         // along x
    float finalSpeed = 0.0f;
};

// A frictionless box pushed along the floor at 4 m/s for 8 s (32 joints), or a capsule.
Slide slideAcross(FloorKind kind, const ShapeGeometry& body, float restHeight) {
    World world;
    buildFloor(world, kind);
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = {-45.3f, restHeight};
    bd.enableSleep = false;
    BodyId box = world.createBody(bd);
    ShapeDef sd;
    sd.friction = 0.0f;
    world.createShape(box, sd, body);
    for (int i = 0; i < 30; ++i) { // settle onto the floor
        world.step(kDt);
    }
    world.setLinearVelocity(box, {4.0f, world.linearVelocity(box).y});
    const float x0 = world.transform(box).p.x;
    Slide slide;
    for (int i = 0; i < 480; ++i) {
        world.step(kDt);
        slide.maxVerticalSpeed =
            std::max(slide.maxVerticalSpeed, std::abs(world.linearVelocity(box).y));
    }
    slide.distance = world.transform(box).p.x - x0;
    slide.finalSpeed = world.linearVelocity(box).x;
    return slide;
}

TEST(WorldChain, BoxSlidesOverAChainFloorWithoutABump) {
    Slide chain = slideAcross(FloorKind::Chain, makeBox(0.5f, 0.5f), 0.5f);
    EXPECT_LT(chain.maxVerticalSpeed, 0.01f);
    // Frictionless: it keeps its speed over all the joints it crosses (32 m at 4 m/s).
    EXPECT_NEAR(chain.distance, 32.0f, 0.1f);
    EXPECT_NEAR(chain.finalSpeed, 4.0f, 1e-3f);
}

TEST(WorldChain, TheSameFloorOfSeparateSegmentsOrBoxesCatches) {
    // The test above only shows what the chain does if these catch.
    for (FloorKind kind : {FloorKind::Segments, FloorKind::Boxes}) {
        Slide s = slideAcross(kind, makeBox(0.5f, 0.5f), 0.5f);
        SCOPED_TRACE(kind == FloorKind::Segments ? "segments" : "boxes");
        // A bump (the criterion the chain passes) and a stop: the box hits a joint.
        EXPECT_GE(s.maxVerticalSpeed, 0.01f);
        EXPECT_LT(s.finalSpeed, 3.0f);
    }
}

TEST(WorldChain, CapsuleAndRoundedBoxAlsoGlide) {
    Capsule capsule{{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f};
    Slide c = slideAcross(FloorKind::Chain, capsule, 0.25f);
    EXPECT_LT(c.maxVerticalSpeed, 0.01f);
    EXPECT_NEAR(c.finalSpeed, 4.0f, 1e-3f);
    Slide r = slideAcross(FloorKind::Chain, makeRoundedBox(0.4f, 0.4f, 0.1f), 0.5f);
    EXPECT_LT(r.maxVerticalSpeed, 0.01f);
    EXPECT_NEAR(r.finalSpeed, 4.0f, 1e-3f);
}

BodyId dropBox(World& world, Vec2 position, Vec2 velocity = {0.0f, 0.0f}, float half = 0.5f) {
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = position;
    bd.linearVelocity = velocity;
    BodyId id = world.createBody(bd);
    world.createShape(id, {}, makeBox(half, half));
    return id;
}

void run(World& world, float seconds) {
    for (int i = 0; i < static_cast<int>(seconds / kDt); ++i) {
        world.step(kDt);
    }
}

TEST(WorldChain, AJointDropsTheCornerNormalThatASegmentReports) {
    // A box sunk 4 mm into the floor, its right face 1 mm short of a segment's left end: the
    // plain segment reports the box's side (a horizontal normal: it would stop the box); the
    // chain segment, knowing the floor continues to its left, reports nothing.
    const Segment seg{{1.0f, 0.0f}, {0.0f, 0.0f}};
    const Polygon box = makeBox(0.5f, 0.5f);
    const Transform xfBox{{-0.501f, 0.496f}, {}};
    Manifold plain = collide(seg, {}, box, xfBox, CollisionAlgorithm::Sat, 0.02f);
    ASSERT_GT(plain.pointCount, 0);
    EXPECT_NEAR(std::abs(plain.normal.x), 1.0f, 1e-4f);
    ChainSegment chain{seg, {2.0f, 0.0f}, {-1.0f, 0.0f}, true, true};
    EXPECT_EQ(collide(chain, {}, box, xfBox, CollisionAlgorithm::Sat, 0.02f).pointCount, 0);
    // A free end behaves like the segment.
    chain.hasGhost2 = false;
    Manifold free = collide(chain, {}, box, xfBox, CollisionAlgorithm::Sat, 0.02f);
    EXPECT_EQ(free.pointCount, plain.pointCount);
    // Over the segment's middle it is the face contact, normal up, in either argument order.
    const Transform xfMiddle{{0.5f, 0.496f}, {}};
    Manifold face = collide(chain, {}, box, xfMiddle, CollisionAlgorithm::Sat, 0.02f);
    ASSERT_EQ(face.pointCount, 2);
    EXPECT_NEAR(face.normal.y, 1.0f, 1e-6f);
    EXPECT_NEAR(face.points[0].separation, -0.004f, 1e-5f);
    Manifold swapped = collide(box, xfMiddle, chain, {}, CollisionAlgorithm::GjkEpa, 0.02f);
    ASSERT_EQ(swapped.pointCount, 2);
    EXPECT_NEAR(swapped.normal.y, -1.0f, 1e-6f);
    // From behind (centre below the line) there is no contact at all.
    const Transform xfBelow{{0.5f, -0.49f}, {}};
    EXPECT_GT(collide(seg, {}, box, xfBelow, CollisionAlgorithm::Sat, 0.02f).pointCount, 0);
    EXPECT_EQ(collide(chain, {}, box, xfBelow, CollisionAlgorithm::Sat, 0.02f).pointCount, 0);
}

TEST(WorldChain, ChainSegmentsAreShapesThatQueriesAndDebugDataSee) {
    World world;
    BodyId ground = world.createBody({});
    ChainDef def;
    def.points = {{2.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}};
    std::vector<ShapeId> ids = world.createChain(ground, def);
    ASSERT_EQ(ids.size(), 2u);
    EXPECT_EQ(world.shapeCount(), 2);
    EXPECT_EQ(world.shapeType(ids[0]), ShapeType::ChainSegment);
    const auto& g0 = std::get<ChainSegment>(world.shapeGeometry(ids[0]));
    EXPECT_EQ(g0.segment.point1, Vec2(2.0f, 0.0f));
    EXPECT_FALSE(g0.hasGhost1); // a free end
    EXPECT_TRUE(g0.hasGhost2);
    EXPECT_EQ(g0.ghost2, Vec2(0.0f, 0.0f));
    const auto& g1 = std::get<ChainSegment>(world.shapeGeometry(ids[1]));
    EXPECT_TRUE(g1.hasGhost1);
    EXPECT_EQ(g1.ghost1, Vec2(2.0f, 0.0f));
    EXPECT_FALSE(g1.hasGhost2);
    EXPECT_EQ(world.shapeAabb(ids[1]).lower, Vec2(0.0f, 0.0f));
    EXPECT_EQ(world.shapeAabb(ids[1]).upper, Vec2(1.0f, 0.0f));
    EXPECT_EQ(world.overlapAabb({{0.5f, -0.1f}, {1.5f, 0.1f}}).size(), 2u);
    EXPECT_FLOAT_EQ(world.massData(ground).mass, 0.0f);

    // Ghost points given for the ends of an open chain.
    ChainDef ghosts = def;
    ghosts.ghostBefore = Vec2{3.0f, 1.0f};
    ghosts.ghostAfter = Vec2{-1.0f, 1.0f};
    std::vector<ShapeId> g = world.createChain(ground, ghosts);
    const auto& first = std::get<ChainSegment>(world.shapeGeometry(g.front()));
    const auto& last = std::get<ChainSegment>(world.shapeGeometry(g.back()));
    EXPECT_TRUE(first.hasGhost1);
    EXPECT_EQ(first.ghost1, Vec2(3.0f, 1.0f));
    EXPECT_TRUE(last.hasGhost2);
    EXPECT_EQ(last.ghost2, Vec2(-1.0f, 1.0f));

    // A box resting on the chain shows up in the touching contacts (debug drawing).
    dropBox(world, {1.0f, 0.6f});
    run(world, 0.5f);
    int touching = 0;
    world.forEachTouchingContact([&](const ContactData& c) {
        ++touching;
        EXPECT_NEAR(c.manifold->normal.y *
                        (world.shapeType(c.shapeA) == ShapeType::ChainSegment ? 1.0f : -1.0f),
                    1.0f, 1e-4f);
    });
    EXPECT_GE(touching, 1);
}

TEST(WorldChain, OpenChainsAreOneSided) {
    World world;
    BodyId ground = world.createBody({});
    ChainDef def;
    def.points = floorPoints(); // right to left: solid from above
    world.createChain(ground, def);
    BodyId above = dropBox(world, {0.0f, 2.0f});
    BodyId below = dropBox(world, {3.0f, -2.0f}, {0.0f, 8.0f}); // comes up through the back
    run(world, 2.0f);
    EXPECT_NEAR(world.transform(above).p.y, 0.5f, 0.02f);
    // Rose through (8 m/s reaches 1.2 m above the floor... then lands on its front).
    EXPECT_NEAR(world.transform(below).p.y, 0.5f, 0.02f);

    // The same floor listed left to right faces down: a box from above falls through.
    World flipped;
    BodyId g2 = flipped.createBody({});
    def.points = floorPoints();
    std::reverse(def.points.begin(), def.points.end());
    flipped.createChain(g2, def);
    BodyId falls = dropBox(flipped, {0.0f, 2.0f});
    run(flipped, 2.0f);
    EXPECT_LT(flipped.transform(falls).p.y, -5.0f);
}

TEST(WorldChain, CounterClockwiseLoopIsSolidFromOutside) {
    World world;
    BodyId ground = world.createBody({});
    ChainDef def;
    def.points = {{-2.0f, -2.0f}, {2.0f, -2.0f}, {2.0f, 2.0f}, {-2.0f, 2.0f}};
    def.isLoop = true;
    std::vector<ShapeId> ids = world.createChain(ground, def);
    ASSERT_EQ(ids.size(), 4u);
    for (ShapeId id : ids) {
        const auto& g = std::get<ChainSegment>(world.shapeGeometry(id));
        EXPECT_TRUE(g.hasGhost1 && g.hasGhost2);
    }
    BodyId onTop = dropBox(world, {0.5f, 4.0f});
    BodyId inside = dropBox(world, {0.0f, 0.0f}); // starts inside: falls out of the bottom
    // Sliding off the top's corner: a box pushed along the top keeps going over the edge.
    BodyId slider = dropBox(world, {-1.0f, 2.5f}, {0.0f, 0.0f}, 0.25f);
    run(world, 0.3f);
    world.setLinearVelocity(slider, {-6.0f, 0.0f}); // friction would stop it after 3 m
    run(world, 1.7f);
    EXPECT_NEAR(world.transform(onTop).p.y, 2.5f, 0.02f);
    EXPECT_LT(world.transform(inside).p.y, -4.0f);
    EXPECT_LT(world.transform(slider).p.x, -2.5f);
}

TEST(WorldChain, ConcaveValleyHoldsABox) {
    World world;
    BodyId ground = world.createBody({});
    ChainDef def;
    // Right to left: down into a V and up again (a concave corner at the bottom).
    def.points = {{6.0f, 6.0f}, {0.0f, 0.0f}, {-6.0f, 6.0f}};
    world.createChain(ground, def);
    BodyId box = dropBox(world, {0.3f, 3.0f}, {0.0f, 0.0f}, 0.3f);
    run(world, 4.0f);
    // The box wedged into the V: its lowest point cannot be below the corner.
    Vec2 p = world.transform(box).p;
    EXPECT_NEAR(p.x, 0.0f, 0.05f);
    EXPECT_GT(p.y, 0.3f);
    EXPECT_LT(p.y, 0.6f);
    EXPECT_LT(length(world.linearVelocity(box)), 0.05f);
}

TEST(WorldChain, RaysAndShapeCastsHitOnlyTheFront) {
    World world;
    BodyId ground = world.createBody({});
    ChainDef def;
    def.points = floorPoints();
    std::vector<ShapeId> ids = world.createChain(ground, def);
    std::optional<RayResult> down = world.castRayClosest({0.3f, 5.0f}, {0.0f, -10.0f});
    ASSERT_TRUE(down.has_value());
    EXPECT_NEAR(down->point.y, 0.0f, 1e-5f);
    EXPECT_NEAR(down->normal.y, 1.0f, 1e-6f);
    EXPECT_NEAR(down->fraction, 0.5f, 1e-5f);
    EXPECT_FALSE(world.castRayClosest({0.3f, -5.0f}, {0.0f, 10.0f}).has_value());
    QueryFilter backFaces;
    backFaces.ignoreBackFaces = false;
    EXPECT_TRUE(world.castRayAll({0.3f, -5.0f}, {0.0f, 10.0f}, backFaces).empty());
    // A slanted ray from above hits the segment under its crossing point.
    std::optional<RayResult> slanted = world.castRayClosest({-3.0f, 4.0f}, {8.0f, -8.0f});
    ASSERT_TRUE(slanted.has_value());
    EXPECT_NEAR(slanted->point.x, 1.0f, 1e-4f);

    Circle ball{{0.0f, 0.0f}, 0.5f};
    std::optional<RayResult> fromAbove = world.castShape(ball, {{0.3f, 3.0f}, {}}, {0.0f, -5.0f});
    ASSERT_TRUE(fromAbove.has_value());
    EXPECT_NEAR(fromAbove->fraction, 2.5f / 5.0f, 0.01f);
    EXPECT_FALSE(world.castShape(ball, {{0.3f, -3.0f}, {}}, {0.0f, 5.0f}).has_value());
    // rayCastShape() on one segment follows the same rule.
    const int under = 49; // segment from x = 1 to x = 0
    EXPECT_TRUE(world.rayCastShape(ids[under], {0.5f, 1.0f}, {0.0f, -2.0f}).has_value());
    EXPECT_FALSE(world.rayCastShape(ids[under], {0.5f, -1.0f}, {0.0f, 2.0f}).has_value());
}

TEST(WorldChain, EachSegmentHasItsOwnMaterial) {
    World world;
    BodyId ground = world.createBody({});
    ChainDef def;
    def.points = {{20.0f, 0.0f}, {0.0f, 0.0f}, {-20.0f, 0.0f}};
    SurfaceMaterial ice;
    ice.friction = 0.0f;
    ice.userData = 7;
    SurfaceMaterial rubber;
    rubber.friction = 1.0f;
    rubber.restitution = 0.8f;
    def.materials = {ice, rubber};
    std::vector<ShapeId> ids = world.createChain(ground, def);
    EXPECT_FLOAT_EQ(world.shapeFriction(ids[0]), 0.0f);
    EXPECT_EQ(world.shapeUserData(ids[0]), 7u);
    EXPECT_FLOAT_EQ(world.shapeFriction(ids[1]), 1.0f);
    EXPECT_FLOAT_EQ(world.shapeRestitution(ids[1]), 0.8f);

    BodyId onIce = dropBox(world, {10.0f, 0.5f});
    BodyId onRubber = dropBox(world, {-15.0f, 0.5f});
    run(world, 0.2f);
    world.setLinearVelocity(onIce, {3.0f, 0.0f});
    world.setLinearVelocity(onRubber, {3.0f, 0.0f});
    run(world, 1.0f);
    EXPECT_NEAR(world.linearVelocity(onIce).x, 3.0f, 1e-3f); // no friction at all
    // Friction sqrt(0.6 * 1) stops it within v^2 / (2 mu g) = 0.58 m.
    EXPECT_NEAR(world.linearVelocity(onRubber).x, 0.0f, 1e-3f);
    EXPECT_LT(world.transform(onRubber).p.x, -15.0f + 0.7f);

    // Restitution: a ball dropped from 2 m bounces on rubber, not on ice.
    auto bounce = [&](float x) {
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        bd.position = {x, 2.25f};
        BodyId ball = world.createBody(bd);
        world.createShape(ball, {}, Circle{{0.0f, 0.0f}, 0.25f}); // restitution 0
        float peak = 0.0f;
        bool fell = false;
        for (int i = 0; i < 120; ++i) {
            world.step(kDt);
            float y = world.transform(ball).p.y;
            fell = fell || world.linearVelocity(ball).y > 0.0f;
            if (fell) {
                peak = std::max(peak, y);
            }
        }
        return peak;
    };
    float rubberPeak = bounce(-5.0f);
    float icePeak = bounce(5.0f);
    // Restitution 0.8 (the larger of the two) returns 0.64 of the 2 m drop.
    EXPECT_GT(rubberPeak, 0.25f + 0.5f * 0.64f * 2.0f);
    EXPECT_LT(icePeak, 0.25f + 0.05f);
}

TEST(WorldChain, BadDefsAreRejectedAndCreateNothing) {
    World world;
    BodyId ground = world.createBody({});
    ChainDef def;
    def.points = {{0.0f, 0.0f}};
    E2D_EXPECT_ERROR(
        world.createChain(ground, def),
        "physics::World::createChain(): def.points must hold at least 2 points, got 1");
    def.points = {{0.0f, 0.0f}, {1.0f, 0.0f}};
    def.isLoop = true;
    E2D_EXPECT_ERROR(world.createChain(ground, def), "at least 3 points for a loop, got 2");
    def.isLoop = false;
    def.points = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 0.0f}};
    E2D_EXPECT_ERROR(world.createChain(ground, def),
                     "def.points[1] and def.points[2] must be at least kLinearSlop");
    def.points = {{0.0f, 0.0f}, {1.0f, NAN}};
    E2D_EXPECT_ERROR(world.createChain(ground, def), "def.points[1] must be finite");
    def.points = {{0.0f, 0.0f}, {1.0f, 0.0f}, {2.0f, 0.0f}};
    def.materials = {SurfaceMaterial{}, SurfaceMaterial{}, SurfaceMaterial{}};
    E2D_EXPECT_ERROR(world.createChain(ground, def),
                     "def.materials must hold 0, 1 or one per segment (2) materials, got 3");
    def.materials = {SurfaceMaterial{-1.0f}};
    E2D_EXPECT_ERROR(world.createChain(ground, def),
                     "def.materials[0].friction must be finite and >= 0, got -1");
    def.materials.clear();
    def.isLoop = true;
    def.ghostAfter = Vec2{3.0f, 0.0f};
    E2D_EXPECT_ERROR(world.createChain(ground, def), "a loop has no ends");
    E2D_EXPECT_ERROR(world.createChain(BodyId{}, ChainDef{}),
                     "createChain(): stale or null BodyId");
    EXPECT_EQ(world.shapeCount(), 0);
}

} // namespace
} // namespace e2d::physics
