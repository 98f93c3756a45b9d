// SPDX-License-Identifier: MIT
// CharacterMover against a real World: walking, walls, slopes, corners, fast moves, landing,
// ceilings, moving platforms, overlaps, one-way platforms, and its def's errors.
#include <e2d/physics/character_mover.hpp>
#include <e2d/physics/world.hpp>

#include "world_test_util.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace e2d::physics {
namespace {

using test::errorOf;

constexpr float kDt = 1.0f / 60.0f;
// The default test mover: capsule centres 0.5 above and below its position, radius 0.3, skin
// 0.01. Resting on a surface its position is this far above it.
constexpr float kRest = 0.5f + 0.3f + 0.01f;
// Casts stop within kShapeCastTolerance of contact; positions are good to about a millimetre.
constexpr float kTol = 2e-3f;

CharacterMoverDef moverAt(Vec2 position) {
    CharacterMoverDef def;
    def.capsule = {{0.0f, -0.5f}, {0.0f, 0.5f}, 0.3f};
    def.skin = 0.01f;
    def.position = position;
    return def;
}

BodyId addBody(World& world, Vec2 position, const ShapeGeometry& geometry,
               BodyType type = BodyType::Static, Vec2 velocity = {0.0f, 0.0f}) {
    BodyDef bd;
    bd.type = type;
    bd.position = position;
    bd.linearVelocity = velocity;
    const BodyId body = world.createBody(bd);
    world.createShape(body, {}, geometry);
    return body;
}

// A floor whose top is y = 0 from x = -50 to 50.
BodyId addFloor(World& world) { return addBody(world, {0.0f, -0.5f}, makeBox(50.0f, 0.5f)); }

// A ramp rising to the right from (0, 0) at `degrees`, 10 m wide.
void addRamp(World& world, float degrees) {
    const float rise = 10.0f * std::tan(degrees * 3.14159265f / 180.0f);
    const std::array<Vec2, 3> points{Vec2{0.0f, 0.0f}, Vec2{10.0f, 0.0f}, Vec2{10.0f, rise}};
    addBody(world, {0.0f, 0.0f}, makePolygon(points));
}

TEST(CharacterMover, WalksOnFlatGroundAtFullSpeedAndStaysGrounded) {
    World world;
    const BodyId floor = addFloor(world);
    CharacterMover mover(moverAt({0.0f, kRest}));
    for (int i = 0; i < 60; ++i) {
        const MoveResult r = mover.move(world, {0.1f, -0.01f});
        ASSERT_TRUE(r.grounded) << "move " << i;
        EXPECT_NEAR(r.translation.x, 0.1f, 1e-4f);
    }
    EXPECT_NEAR(mover.position().x, 6.0f, 1e-3f);
    EXPECT_NEAR(mover.position().y, kRest, kTol);
    const MoveResult& r = mover.lastMove();
    EXPECT_EQ(r.groundBody, floor);
    EXPECT_NEAR(r.groundNormal.y, 1.0f, 1e-4f);
    EXPECT_NEAR(r.groundPoint.y, 0.0f, 1e-4f);
    EXPECT_FALSE(r.touchingWall);
    EXPECT_FALSE(r.touchingCeiling);
    EXPECT_EQ(r.groundVelocity, Vec2(0.0f, 0.0f));
}

TEST(CharacterMover, StopsAtAWallAndKeepsItsSkin) {
    World world;
    addFloor(world);
    addBody(world, {3.0f, 2.0f}, makeBox(0.5f, 2.0f)); // face at x = 2.5
    CharacterMover mover(moverAt({0.0f, kRest}));
    for (int i = 0; i < 30; ++i) {
        mover.move(world, {0.2f, -0.01f});
    }
    EXPECT_NEAR(mover.position().x, 2.5f - 0.31f, kTol);
    EXPECT_NEAR(mover.position().y, kRest, kTol);
    const MoveResult& r = mover.lastMove();
    EXPECT_TRUE(r.grounded);
    ASSERT_TRUE(r.touchingWall);
    EXPECT_NEAR(r.wallNormal.x, -1.0f, 1e-4f);
    // Pushing on keeps it there and the velocity loses the part into the wall.
    const Vec2 v = mover.clipVelocity({5.0f, -3.0f});
    EXPECT_NEAR(v.x, 0.0f, 1e-5f);
    EXPECT_NEAR(v.y, 0.0f, 1e-5f);
}

TEST(CharacterMover, SlidesAlongATiltedWallWithTheTangentialPart) {
    World world; // no floor: only the wall, tilted 30 degrees from vertical
    const float tilt = 30.0f * 3.14159265f / 180.0f;
    addBody(world, {0.0f, 0.0f}, makeOffsetBox(0.5f, 20.0f, {4.0f, 0.0f}, tilt));
    const Vec2 normal{-std::cos(tilt), -std::sin(tilt)}; // the face the mover meets
    CharacterMoverDef def = moverAt({0.0f, 0.0f});
    def.capsule = {{0.0f, 0.0f}, {0.0f, 0.0f}, 0.3f}; // a disc: its contact is one point
    CharacterMover mover(def);
    // Bring it against the wall, then push diagonally into it.
    for (int i = 0; i < 40; ++i) {
        mover.move(world, {0.2f, 0.0f});
    }
    ASSERT_TRUE(mover.lastMove().touchingWall);
    const Vec2 push{0.3f, -0.1f};
    const MoveResult r = mover.move(world, push);
    const Vec2 tangential = push - dot(push, normal) * normal;
    EXPECT_NEAR(r.translation.x, tangential.x, kTol);
    EXPECT_NEAR(r.translation.y, tangential.y, kTol);
    EXPECT_GT(length(tangential), 0.1f); // the slide is not nothing
    EXPECT_NEAR(r.wallNormal.x, normal.x, 1e-3f);
    EXPECT_NEAR(r.wallNormal.y, normal.y, 1e-3f);
}

TEST(CharacterMover, WalksUpASlopeBelowTheLimitKeepingItsHorizontalSpeed) {
    World world;
    addFloor(world);
    addRamp(world, 30.0f);
    CharacterMover mover(moverAt({-2.0f, kRest}));
    for (int i = 0; i < 40; ++i) {
        mover.move(world, {0.1f, -0.02f});
    }
    // Up the slope to x = 2: the capsule's lower centre sits (r + skin) from the slope's line.
    const float angle = 30.0f * 3.14159265f / 180.0f;
    EXPECT_NEAR(mover.position().x, 2.0f, kTol);
    EXPECT_NEAR(mover.position().y, 0.5f + 2.0f * std::tan(angle) + 0.31f / std::cos(angle), kTol);
    const MoveResult& r = mover.lastMove();
    ASSERT_TRUE(r.grounded);
    EXPECT_NEAR(r.groundNormal.x, -std::sin(angle), 1e-3f);
    EXPECT_NEAR(r.groundNormal.y, std::cos(angle), 1e-3f);
}

TEST(CharacterMover, StandsStillOnAWalkableSlopeUnderGravity) {
    World world;
    addRamp(world, 30.0f);
    const float angle = 30.0f * 3.14159265f / 180.0f;
    // Resting on the slope at x = 5.
    CharacterMover mover(moverAt({5.0f, 0.5f + 5.0f * std::tan(angle) + 0.31f / std::cos(angle)}));
    const Vec2 start = mover.position();
    for (int i = 0; i < 60; ++i) {
        ASSERT_TRUE(mover.move(world, {0.0f, -0.05f}).grounded) << "move " << i;
    }
    EXPECT_NEAR(mover.position().x, start.x, 1e-4f);
    EXPECT_NEAR(mover.position().y, start.y, kTol);
}

TEST(CharacterMover, FollowsASlopeDownWithGroundSnapping) {
    World world;
    addRamp(world, 30.0f);
    const float angle = 30.0f * 3.14159265f / 180.0f;
    const Vec2 top{9.0f, 0.5f + 9.0f * std::tan(angle) + 0.31f / std::cos(angle)};
    // Walking down at 0.1 m per move with a little gravity: the slope drops 5.8 cm per move.
    const auto groundedMoves = [&](float snap) {
        CharacterMoverDef def = moverAt(top);
        def.groundSnapDistance = snap;
        CharacterMover mover(def);
        mover.move(world, {0.0f, -0.01f});
        int count = 0;
        for (int i = 0; i < 50; ++i) {
            count += mover.move(world, {-0.1f, -0.01f}).grounded ? 1 : 0;
        }
        return count;
    };
    EXPECT_EQ(groundedMoves(0.1f), 50);
    EXPECT_LT(groundedMoves(0.0f), 30); // without it the feet leave the slope every other move
}

TEST(CharacterMover, DoesNotWalkUpASlopeAboveTheLimitAndSlidesDownIt) {
    World world;
    addFloor(world);
    addRamp(world, 60.0f);
    CharacterMover mover(moverAt({-2.0f, kRest}));
    float highest = mover.position().y;
    for (int i = 0; i < 60; ++i) {
        mover.move(world, {0.1f, -0.02f});
        highest = std::max(highest, mover.position().y);
    }
    EXPECT_LT(highest, kRest + 1e-3f);
    EXPECT_LT(mover.position().x, 0.0f); // held at the foot of the slope
    EXPECT_TRUE(mover.lastMove().touchingWall);
    EXPECT_TRUE(mover.lastMove().grounded); // on the floor, not on the slope

    // Dropped onto the steep slope it slides down (and is not grounded on the way).
    CharacterMover slider(moverAt({6.0f, 13.0f}));
    int groundedMoves = 0;
    for (int i = 0; i < 40; ++i) {
        groundedMoves += slider.move(world, {0.0f, -0.1f}).grounded ? 1 : 0;
    }
    EXPECT_LT(slider.position().x, 5.0f);
    EXPECT_LT(slider.position().y, 9.0f);
    EXPECT_EQ(groundedMoves, 0);
}

TEST(CharacterMover, WalksOverALowStepAndNotOverAHighOne) {
    // Steps up at x = 1: 0.05 m is below radius * (1 - cos 45) = 0.088 m, 0.15 m is above.
    const auto walk = [](float height) {
        World world;
        addFloor(world);
        addBody(world, {6.0f, 0.5f * height}, makeBox(5.0f, 0.5f * height));
        CharacterMover mover(moverAt({0.0f, kRest}));
        for (int i = 0; i < 30; ++i) {
            mover.move(world, {0.1f, -0.02f});
        }
        return mover.position();
    };
    const Vec2 low = walk(0.05f);
    EXPECT_GT(low.x, 2.9f);
    EXPECT_NEAR(low.y, 0.05f + kRest, kTol);
    const Vec2 high = walk(0.15f);
    EXPECT_LT(high.x, 1.0f);
    EXPECT_NEAR(high.y, kRest, kTol);
}

TEST(CharacterMover, RestsInACornerWithoutJitter) {
    World world;
    addFloor(world);
    addBody(world, {3.0f, 2.0f}, makeBox(0.5f, 2.0f));
    CharacterMover mover(moverAt({0.0f, kRest + 1.0f}));
    std::vector<Vec2> trail;
    for (int i = 0; i < 60; ++i) {
        trail.push_back(mover.move(world, {0.3f, -0.3f}).position);
    }
    EXPECT_NEAR(mover.position().x, 2.5f - 0.31f, kTol);
    EXPECT_NEAR(mover.position().y, kRest, kTol);
    for (std::size_t i = 30; i < trail.size(); ++i) {
        EXPECT_NEAR(trail[i].x, trail.back().x, 1e-5f) << "move " << i;
        EXPECT_NEAR(trail[i].y, trail.back().y, 1e-5f) << "move " << i;
    }
}

TEST(CharacterMover, SettlesInAVBetweenTwoSteepWallsWithoutJitter) {
    World world;
    // Two segments 70 degrees from horizontal meeting at the origin.
    const Vec2 side{std::cos(70.0f * 3.14159265f / 180.0f), std::sin(70.0f * 3.14159265f / 180.0f)};
    addBody(world, {0.0f, 0.0f}, Segment{{0.0f, 0.0f}, Vec2(-side.x, side.y) * 6.0f});
    addBody(world, {0.0f, 0.0f}, Segment{{0.0f, 0.0f}, side * 6.0f});
    CharacterMoverDef def = moverAt({0.2f, 3.0f});
    CharacterMover mover(def);
    std::vector<Vec2> trail;
    for (int i = 0; i < 90; ++i) {
        trail.push_back(mover.move(world, {0.0f, -0.1f}).position);
    }
    // The lower cap (centre 0.5 below the position) wedged between the walls, above the apex.
    const float capCentreHeight = 0.31f / std::cos(70.0f * 3.14159265f / 180.0f);
    EXPECT_NEAR(mover.position().x, 0.0f, kTol);
    EXPECT_NEAR(mover.position().y - 0.5f, capCentreHeight, 5e-3f);
    for (std::size_t i = 60; i < trail.size(); ++i) {
        EXPECT_NEAR(trail[i].x, trail.back().x, 1e-5f) << "move " << i;
        EXPECT_NEAR(trail[i].y, trail.back().y, 1e-5f) << "move " << i;
    }
}

TEST(CharacterMover, NeverTunnelsThroughAThinSegmentAtAnySpeed) {
    World world;
    addBody(world, {0.0f, 0.0f}, Segment{{5.0f, -5.0f}, {5.0f, 5.0f}});
    CharacterMover mover(moverAt({0.0f, 0.0f}));
    const MoveResult r = mover.move(world, {200.0f, 0.0f}); // 12 km/s at 60 Hz
    EXPECT_NEAR(r.position.x, 5.0f - 0.31f, kTol);
    EXPECT_NEAR(r.position.y, 0.0f, kTol);
    EXPECT_TRUE(r.touchingWall);

    // Diagonally and fast into the corner of two thin segments: stops inside it.
    World corner;
    addBody(corner, {0.0f, 0.0f}, Segment{{-5.0f, 0.0f}, {5.0f, 0.0f}});
    addBody(corner, {0.0f, 0.0f}, Segment{{5.0f, 0.0f}, {5.0f, 10.0f}});
    CharacterMover fast(moverAt({0.0f, 5.0f}));
    for (int i = 0; i < 3; ++i) {
        fast.move(corner, {150.0f, -150.0f});
    }
    EXPECT_NEAR(fast.position().x, 5.0f - 0.31f, kTol);
    EXPECT_NEAR(fast.position().y, kRest, kTol);
    EXPECT_TRUE(fast.lastMove().grounded);
    EXPECT_TRUE(fast.lastMove().touchingWall);
}

TEST(CharacterMover, WalksAChainTerrainSmoothlyAndPassesThroughItsBack) {
    World world;
    // A floor of 1 m chain segments (listed right to left: solid from above), top at y = 0.
    ChainDef chain;
    for (int x = 20; x >= -20; --x) {
        chain.points.push_back({static_cast<float>(x), 0.0f});
    }
    const BodyId ground = world.createBody({});
    world.createChain(ground, chain);
    CharacterMover mover(moverAt({-10.0f, kRest}));
    for (int i = 0; i < 150; ++i) {
        const MoveResult r = mover.move(world, {0.13f, -0.01f});
        ASSERT_TRUE(r.grounded) << "move " << i;
        ASSERT_NEAR(r.translation.x, 0.13f, 1e-4f) << "move " << i; // no catching on the seams
        ASSERT_NEAR(r.position.y, kRest, kTol) << "move " << i;
    }
    // From below, the chain's back side lets it through.
    CharacterMover below(moverAt({0.3f, -2.0f}));
    for (int i = 0; i < 10; ++i) {
        below.move(world, {0.0f, 0.5f});
    }
    EXPECT_NEAR(below.position().y, 3.0f, kTol);
}

TEST(CharacterMover, LandsFromAFallGroundedWithoutSinking) {
    World world;
    const BodyId floor = addFloor(world);
    CharacterMover mover(moverAt({0.0f, 6.0f}));
    Vec2 velocity{1.0f, 0.0f};
    float lowest = mover.position().y;
    int landedAt = -1;
    for (int i = 0; i < 120; ++i) {
        velocity.y -= 10.0f * kDt;
        const MoveResult r = mover.move(world, velocity * kDt);
        velocity = mover.clipVelocity(velocity);
        lowest = std::min(lowest, r.position.y);
        if (r.grounded && landedAt < 0) {
            landedAt = i;
        }
    }
    // From 6 - kRest = 5.19 m at g = 10: about 1.02 s, so around move 61.
    ASSERT_GE(landedAt, 0);
    EXPECT_NEAR(landedAt, 61, 2);
    EXPECT_TRUE(mover.grounded());
    EXPECT_EQ(mover.lastMove().groundBody, floor);
    EXPECT_NEAR(mover.position().y, kRest, kTol);
    EXPECT_GT(lowest, kRest - kTol);
    EXPECT_NEAR(velocity.y, 0.0f, 1e-4f); // the fall speed was clipped on landing
    EXPECT_NEAR(velocity.x, 1.0f, 1e-4f); // the run was not
}

TEST(CharacterMover, BumpsItsHeadOnACeiling) {
    World world;
    addFloor(world);
    addBody(world, {0.0f, 3.0f}, makeBox(5.0f, 0.5f)); // underside at y = 2.5
    CharacterMover mover(moverAt({0.0f, kRest}));
    Vec2 velocity{0.0f, 8.0f};
    float highest = 0.0f;
    bool bumped = false;
    for (int i = 0; i < 30; ++i) {
        velocity.y -= 10.0f * kDt;
        const MoveResult r = mover.move(world, velocity * kDt);
        highest = std::max(highest, r.position.y);
        if (r.touchingCeiling && !bumped) {
            bumped = true;
            EXPECT_NEAR(r.ceilingNormal.y, -1.0f, 1e-4f);
            EXPECT_GT(velocity.y, 0.0f);
            velocity = mover.clipVelocity(velocity);
            EXPECT_NEAR(velocity.y, 0.0f, 1e-5f); // the rise stops at the bump
        }
    }
    EXPECT_TRUE(bumped);
    // The head (upper centre + radius) stays a skin below the ceiling.
    EXPECT_NEAR(highest, 2.5f - kRest, kTol);
}

TEST(CharacterMover, RidesAKinematicPlatformWithItsGroundVelocity) {
    World world;
    const Vec2 platformVelocity{1.0f, 0.5f};
    const BodyId platform =
        addBody(world, {0.0f, 0.0f}, makeBox(1.5f, 0.2f), BodyType::Kinematic, platformVelocity);
    CharacterMover rider(moverAt({0.0f, 0.2f + kRest}));
    CharacterMover passenger(moverAt({0.0f, 0.2f + kRest})); // does not add the ground velocity
    rider.move(world, {0.0f, 0.0f});
    passenger.move(world, {0.0f, 0.0f});
    for (int i = 0; i < 60; ++i) {
        world.step(kDt);
        const Vec2 gravity{0.0f, -0.01f};
        const MoveResult r = rider.move(world, rider.groundVelocity() * kDt + gravity);
        passenger.move(world, gravity);
        ASSERT_TRUE(r.grounded) << "step " << i;
        EXPECT_EQ(r.groundBody, platform);
    }
    const Vec2 p = world.transform(platform).p;
    EXPECT_NEAR(p.x, 1.0f, 1e-4f);
    EXPECT_NEAR(rider.position().x, p.x, kTol);
    EXPECT_NEAR(rider.position().y, p.y + 0.2f + kRest, kTol);
    EXPECT_NEAR(rider.groundVelocity().x, platformVelocity.x, 1e-4f);
    EXPECT_NEAR(rider.groundVelocity().y, platformVelocity.y, 1e-4f);
    // Without the ground velocity the platform slides away under it (it is only lifted).
    EXPECT_LT(passenger.position().x, 0.1f);
}

TEST(CharacterMover, LeavesAnOverlapGentlyWithoutLaunching) {
    World world;
    addFloor(world);
    CharacterMoverDef def = moverAt({0.0f, kRest - 0.25f}); // 0.25 m into the floor
    def.maxPushOut = 0.1f;
    CharacterMover mover(def);
    std::vector<float> heights;
    for (int i = 0; i < 10; ++i) {
        const MoveResult r = mover.move(world, {0.0f, -0.01f});
        EXPECT_LE(r.translation.y, def.maxPushOut + 1e-5f) << "move " << i;
        heights.push_back(r.position.y);
    }
    EXPECT_NEAR(heights[0], kRest - 0.15f, 1e-4f);
    EXPECT_NEAR(heights[1], kRest - 0.05f, 1e-4f);
    for (std::size_t i = 2; i < heights.size(); ++i) {
        EXPECT_NEAR(heights[i], kRest, kTol) << "move " << i; // out, and no higher
    }
    EXPECT_TRUE(mover.grounded());

    // Buried so deep that the capsule's core is inside the floor: out the same way, upwards.
    CharacterMover buried(moverAt({0.0f, -0.2f}));
    for (int i = 0; i < 12; ++i) {
        const MoveResult r = buried.move(world, {0.0f, 0.0f});
        EXPECT_LE(r.translation.y, 0.1f + 1e-5f) << "move " << i;
        EXPECT_NEAR(r.translation.x, 0.0f, 1e-4f) << "move " << i;
    }
    EXPECT_NEAR(buried.position().y, kRest, kTol);
}

TEST(CharacterMover, SqueezedByAPlatformItStaysAboveTheFloorAndFinite) {
    World world;
    addFloor(world);
    // A kinematic slab coming down at 1 m/s onto the mover's head (head top at 1.61 m).
    const BodyId slab =
        addBody(world, {0.0f, 2.0f}, makeBox(2.0f, 0.2f), BodyType::Kinematic, {0.0f, -1.0f});
    CharacterMover mover(moverAt({0.0f, kRest}));
    for (int i = 0; i < 40; ++i) {
        world.step(kDt);
        const MoveResult r = mover.move(world, {0.0f, -0.01f});
        ASSERT_TRUE(isFinite(r.position)) << "move " << i;
        ASSERT_GT(r.position.y, kRest - kTol) << "move " << i; // never pushed into the floor
        ASSERT_LT(r.position.y, kRest + kTol) << "move " << i; // nor thrown up
        ASSERT_NEAR(r.position.x, 0.0f, 1e-4f) << "move " << i;
    }
    EXPECT_LT(world.transform(slab).p.y, 1.5f); // it did come down into the mover
}

TEST(CharacterMover, AContactFilterMakesAOneWayPlatform) {
    World world;
    addFloor(world);
    const BodyId platform = addBody(world, {0.0f, 3.0f}, makeBox(2.0f, 0.1f)); // top at 3.1
    CharacterMoverDef def = moverAt({0.0f, kRest});
    def.contactFilter = [&](const MoverContact& c) {
        return c.body != platform || (c.surface == MoverSurface::Ground && c.separation > -0.05f);
    };
    CharacterMover mover(def);
    // Jump up through it from below, then fall back onto it.
    Vec2 velocity{0.0f, 11.0f};
    for (int i = 0; i < 120; ++i) {
        velocity.y -= 10.0f * kDt;
        mover.move(world, velocity * kDt);
        velocity = mover.clipVelocity(velocity);
    }
    EXPECT_TRUE(mover.grounded());
    EXPECT_EQ(mover.lastMove().groundBody, platform);
    EXPECT_NEAR(mover.position().y, 3.1f + kRest, kTol);
}

TEST(CharacterMover, IgnoresItsOwnBody) {
    World world;
    addFloor(world);
    const BodyId own = addBody(world, {0.0f, kRest}, Capsule{{0.0f, -0.5f}, {0.0f, 0.5f}, 0.3f},
                               BodyType::Kinematic);
    CharacterMoverDef def = moverAt({0.0f, kRest});
    def.ignoreBody = own;
    CharacterMover mover(def);
    const MoveResult r = mover.move(world, {0.5f, 0.0f});
    EXPECT_NEAR(r.translation.x, 0.5f, 1e-4f);
    EXPECT_NEAR(r.pushedOut, 0.0f, 1e-4f);
}

TEST(CharacterMover, DefErrorsNameTheFieldAndValue) {
    const auto make = [](auto change) {
        return errorOf([&] {
            CharacterMoverDef def;
            change(def);
            CharacterMover mover(def);
        });
    };
    EXPECT_EQ(make([](CharacterMoverDef& d) { d.skin = -1.0f; }),
              "physics::CharacterMover::CharacterMover(): def.skin must be finite and in [0, "
              "capsule.radius = 0.3], got -1");
    EXPECT_EQ(make([](CharacterMoverDef& d) { d.capsule.radius = 0.0f; }),
              "physics::CharacterMover::CharacterMover(): def.capsule.radius must be finite and "
              "> 0, got 0");
    EXPECT_EQ(
        make([](CharacterMoverDef& d) {
            d.up = {0.0f, 2.0f};
        }),
        "physics::CharacterMover::CharacterMover(): def.up must be a unit vector, got (0, 2)");
    EXPECT_EQ(make([](CharacterMoverDef& d) { d.maxSlopeAngle = 2.0f; }),
              "physics::CharacterMover::CharacterMover(): def.maxSlopeAngle must be finite and in "
              "[0, pi/2) radians, got 2");
    EXPECT_EQ(make([](CharacterMoverDef& d) { d.maxPushOut = 0.0f; }),
              "physics::CharacterMover::CharacterMover(): def.maxPushOut must be finite and > 0, "
              "got 0");
    EXPECT_EQ(make([](CharacterMoverDef& d) {
                  d.position = {NAN, 0.0f};
              }),
              "physics::CharacterMover::CharacterMover(): def.position must be finite and within "
              "kHuge, got (nan, 0)");
    World world;
    CharacterMover mover;
    EXPECT_EQ(errorOf([&] {
                  mover.move(world, {INFINITY, 0.0f});
              }),
              "physics::CharacterMover::move(): displacement must be finite and keep the mover "
              "within kHuge, got (inf, 0)");
    EXPECT_EQ(mover.position(), Vec2(0.0f, 0.0f)); // nothing moved
}

} // namespace
} // namespace e2d::physics
