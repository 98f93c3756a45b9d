// SPDX-License-Identifier: MIT
#include <e2d/physics/world.hpp>

#include "world_random_scene.hpp"

#include <algorithm>
#include <functional>
#include <string>
#include <utility>

namespace e2d::physics {
namespace {

using test::RandomScene;
using test::ShapeRecord;

std::vector<ShapeId> bruteForceBox(const RandomScene& scene, const Aabb& box,
                                   const QueryFilter& filter) {
    std::vector<ShapeId> result;
    for (const ShapeRecord& s : scene.shapes) {
        if (scene.bodyOf(s).enabled && test::seenBy(s, filter) &&
            overlaps(computeAabb(s.geometry, scene.transformOf(s)), box)) {
            result.push_back(s.id);
        }
    }
    return test::sortedIds(result);
}

std::vector<ShapeId> bruteForcePoint(const RandomScene& scene, Vec2 point,
                                     const QueryFilter& filter) {
    std::vector<ShapeId> result;
    for (const ShapeRecord& s : scene.shapes) {
        if (scene.bodyOf(s).enabled && test::seenBy(s, filter) &&
            testPoint(s.geometry, invTransformPoint(scene.transformOf(s), point))) {
            result.push_back(s.id);
        }
    }
    return test::sortedIds(result);
}

QueryFilter randomFilter(test::Random& random) {
    QueryFilter filter;
    static constexpr std::uint64_t kMasks[] = {~std::uint64_t{0}, 0x1, 0x6};
    filter.maskBits = kMasks[random.below(3)];
    filter.categoryBits = random.below(2) == 0 ? 0x1 : 0x2;
    filter.includeSensors = random.below(2) == 0;
    return filter;
}

TEST(WorldOverlap, AabbAndPointQueriesMatchBruteForce) {
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        RandomScene scene(seed, 120, 15.0f);
        test::Random& random = scene.random();
        int nonEmptyBoxes = 0;
        int nonEmptyPoints = 0;
        for (int frame = 0; frame < 6; ++frame) {
            for (int q = 0; q < 40; ++q) {
                QueryFilter filter = randomFilter(random);
                Vec2 c{random.uniform(-16.0f, 16.0f), random.uniform(-16.0f, 16.0f)};
                Vec2 h{random.uniform(0.0f, 4.0f), random.uniform(0.0f, 4.0f)};
                Aabb box{c - h, c + h};
                std::vector<ShapeId> expected = bruteForceBox(scene, box, filter);
                EXPECT_EQ(scene.world.overlapAabb(box, filter), expected) << "seed " << seed;
                nonEmptyBoxes += expected.empty() ? 0 : 1;

                std::vector<ShapeId> inside = bruteForcePoint(scene, c, filter);
                EXPECT_EQ(scene.world.overlapPoint(c, filter), inside) << "seed " << seed;
                nonEmptyPoints += inside.empty() ? 0 : 1;
            }
            // Move some bodies (any type: a teleported static body moves too), disable a few.
            for (test::BodyRecord& body : scene.bodies) {
                if (random.below(3) == 0) {
                    Vec2 p = body.position +
                             Vec2(random.uniform(-3.0f, 3.0f), random.uniform(-3.0f, 3.0f));
                    scene.moveBody(body, p, random.uniform(-3.0f, 3.0f));
                }
                if (random.below(20) == 0) {
                    body.enabled = !body.enabled;
                    scene.world.setBodyEnabled(body.id, body.enabled);
                }
            }
        }
        // The comparison means something only if many queries found shapes.
        EXPECT_GT(nonEmptyBoxes, 60);
        EXPECT_GT(nonEmptyPoints, 10);
    }
}

TEST(WorldOverlap, CallbackCanStopEarly) {
    RandomScene scene(7, 50, 3.0f);
    int calls = 0;
    scene.world.overlapAabb({{-10.0f, -10.0f}, {10.0f, 10.0f}}, {}, [&](ShapeId) {
        ++calls;
        return calls < 3;
    });
    EXPECT_EQ(calls, 3);
}

TEST(WorldOverlap, SetTransformMovesTheShapeInTheTree) {
    World world;
    BodyDef def;
    def.type = BodyType::Dynamic;
    BodyId body = world.createBody(def);
    ShapeId box = world.createShape(body, {}, makeBox(0.5f, 0.5f));
    EXPECT_EQ(world.overlapPoint({0.0f, 0.0f}), std::vector<ShapeId>{box});

    world.setTransform(body, {20.0f, -7.0f}, 0.3f);
    EXPECT_TRUE(world.overlapPoint({0.0f, 0.0f}).empty());
    EXPECT_TRUE(world.overlapAabb({{-1.0f, -1.0f}, {1.0f, 1.0f}}).empty());
    EXPECT_FALSE(world.castRayClosest({-5.0f, 0.0f}, {10.0f, 0.0f}).has_value());
    EXPECT_EQ(world.overlapPoint({20.0f, -7.0f}), std::vector<ShapeId>{box});
    EXPECT_EQ(world.overlapAabb({{19.0f, -8.0f}, {19.5f, -7.5f}}), std::vector<ShapeId>{box});
    std::optional<RayResult> hit = world.castRayClosest({15.0f, -7.0f}, {10.0f, 0.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, box);

    // A small move that stays inside the fat box is still seen exactly by the queries.
    world.setTransform(body, {20.05f, -7.0f}, 0.0f);
    EXPECT_TRUE(world.overlapPoint({19.52f, -7.0f}).empty());
    EXPECT_EQ(world.overlapPoint({20.54f, -7.0f}), std::vector<ShapeId>{box});
    EXPECT_TRUE(contains(world.shapeFatAabb(box), world.shapeAabb(box)));
}

// New shapes enter the broad-phase tree in bulk when it is next needed; queries made before any
// step must still see every shape created so far, whether the tree is built from nothing (many
// new shapes) or takes a few more one by one, and whatever moved or went meanwhile.
TEST(WorldOverlap, QueriesSeeShapesCreatedSinceTheLastStep) {
    World world;
    constexpr int kSide = 40; // 1600 boxes of 1 m, 2 m apart: (2i, 2j)
    std::vector<ShapeId> shapes;
    std::vector<BodyId> bodies;
    for (int j = 0; j < kSide; ++j) {
        for (int i = 0; i < kSide; ++i) {
            BodyDef def;
            def.type = j % 2 == 0 ? BodyType::Dynamic : BodyType::Static;
            def.position = {2.0f * static_cast<float>(i), 2.0f * static_cast<float>(j)};
            bodies.push_back(world.createBody(def));
            shapes.push_back(world.createShape(bodies.back(), {}, makeBox(0.5f, 0.5f)));
        }
    }
    auto at = [&](int i, int j) { return shapes[static_cast<std::size_t>(j * kSide + i)]; };

    // A ray along row 3 from the left hits its first box at x = -0.5 and all 40 of them.
    std::optional<RayResult> hit = world.castRayClosest({-10.0f, 6.0f}, {100.0f, 0.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, at(0, 3));
    EXPECT_NEAR(hit->point.x, -0.5f, 1e-4f);
    EXPECT_EQ(world.castRayAll({-10.0f, 6.0f}, {100.0f, 0.0f}).size(), std::size_t{kSide});
    // Every box contains its centre; a box query over columns 5..7 of rows 10..11 finds six.
    for (int j = 0; j < kSide; j += 7) {
        for (int i = 0; i < kSide; i += 3) {
            EXPECT_EQ(
                world.overlapPoint({2.0f * static_cast<float>(i), 2.0f * static_cast<float>(j)}),
                std::vector<ShapeId>{at(i, j)});
        }
    }
    std::vector<ShapeId> expected{at(5, 10), at(6, 10), at(7, 10), at(5, 11), at(6, 11), at(7, 11)};
    std::sort(expected.begin(), expected.end(),
              [](ShapeId a, ShapeId b) { return a.index1 < b.index1; });
    EXPECT_EQ(world.overlapAabb({{9.8f, 19.8f}, {14.2f, 22.2f}}), expected);

    // A few more after the tree exists, one moved and one destroyed before any query.
    std::vector<ShapeId> late;
    for (int k = 0; k < 5; ++k) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {-20.0f - 3.0f * static_cast<float>(k), 0.0f};
        const BodyId body = world.createBody(def);
        late.push_back(world.createShape(body, {}, Circle{{0.0f, 0.0f}, 0.5f}));
        if (k == 1) {
            world.setTransform(body, {-20.0f, 50.0f}, 0.0f);
        }
        if (k == 2) {
            world.destroyBody(body);
        }
    }
    hit = world.castRayClosest({-40.0f, 0.0f}, {100.0f, 0.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, late[4]); // at x = -32, the leftmost of the late ones
    EXPECT_TRUE(world.overlapPoint({-26.0f, 0.0f}).empty()); // destroyed
    EXPECT_TRUE(world.overlapPoint({-23.0f, 0.0f}).empty()); // moved away
    EXPECT_EQ(world.overlapPoint({-20.0f, 50.0f}), std::vector<ShapeId>{late[1]});
    EXPECT_EQ(world.overlapAabb({{-35.0f, -1.0f}, {-18.0f, 1.0f}}).size(), 3u);

    // A shape created overlapping another touches it after the next step (its pair is found).
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {2.5f, 0.0f};
    def.gravityScale = 0.0f;
    const ShapeId overlapping = world.createShape(world.createBody(def), {}, makeBox(0.5f, 0.5f));
    EXPECT_EQ(world.overlapPoint({2.2f, 0.0f}).size(), 2u);
    world.step(1.0f / 60.0f);
    EXPECT_EQ(world.candidatePairCount(), 1);
    EXPECT_EQ(world.contactCount(), 1);
    EXPECT_TRUE(world.isValid(overlapping));
}

// A row of ten dynamic balls around the origin, for the callback tests.
std::vector<BodyId> addRowOfBalls(World& world) {
    std::vector<BodyId> balls;
    for (int i = 0; i < 10; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {static_cast<float>(i) - 4.5f, 0.0f};
        balls.push_back(world.createBody(def));
        world.createShape(balls.back(), {}, Circle{{0.0f, 0.0f}, 0.25f});
    }
    return balls;
}

TEST(WorldOverlap, ChangingTheShapesInsideAnOverlapCallbackIsAnErrorAtThatCall) {
    // Destroying inside the walk used to skip results and pass stale ids; creating visited the
    // new shapes. Each such call now throws, naming itself and the query, and changes nothing.
    World world;
    std::vector<BodyId> balls = addRowOfBalls(world);
    const Aabb all{{-10.0f, -1.0f}, {10.0f, 1.0f}};
    BodyId spare = world.createBody({.position = {50.0f, 0.0f}});
    ShapeId spareShape = world.createShape(spare, {}, Circle{{0.0f, 0.0f}, 0.25f});
    const std::vector<std::pair<std::string, std::function<void(ShapeId)>>> calls = {
        {"destroyBody", [&](ShapeId s) { world.destroyBody(world.shapeBody(s)); }},
        {"destroyShape", [&](ShapeId s) { world.destroyShape(s); }},
        {"createBody", [&](ShapeId) { (void)world.createBody({}); }},
        {"createShape",
         [&](ShapeId s) {
             world.createShape(world.shapeBody(s), {}, Circle{{}, 1.0f});
         }},
        {"setTransform",
         [&](ShapeId) {
             world.setTransform(spare, {60.0f, 0.0f}, 0.0f);
         }},
        {"setBodyEnabled", [&](ShapeId) { world.setBodyEnabled(spare, false); }},
        {"setShapeFilter", [&](ShapeId) { world.setShapeFilter(spareShape, {}); }},
        {"updatePairs", [&](ShapeId) { world.updatePairs(); }},
        {"step", [&](ShapeId) { world.step(1.0f / 60.0f); }},
    };
    for (const auto& [name, call] : calls) {
        SCOPED_TRACE(name);
        int visited = 0;
        std::string error = test::errorOf([&] {
            world.overlapAabb(all, {}, [&](ShapeId s) {
                ++visited;
                EXPECT_TRUE(world.isValid(s));
                call(s);
                return true;
            });
        });
        EXPECT_EQ(error,
                  "physics::World::" + name +
                      "(): cannot run inside the callback of "
                      "overlapAabb() (it would change what the callback is walking); collect "
                      "the ids and call it after overlapAabb() returns");
        EXPECT_EQ(visited, 1);
        EXPECT_EQ(world.bodyCount(), 11);
        EXPECT_EQ(world.shapeCount(), 11);
        EXPECT_EQ(world.transform(spare).p, Vec2(50.0f, 0.0f));
        EXPECT_TRUE(world.isBodyEnabled(spare));
        // The lock is gone once the query returned (by the exception here).
        EXPECT_EQ(world.overlapAabb(all).size(), 10u);
    }
}

TEST(WorldOverlap, AnOverlapCallbackMayPushWakeAndReadBodies) {
    // An explosion: impulses, velocities, sleep and nested queries are allowed in the walk;
    // destroying what was found happens after it, from the collected ids.
    World world{WorldDef{.gravity = {0.0f, 0.0f}}};
    std::vector<BodyId> balls = addRowOfBalls(world);
    const Aabb all{{-10.0f, -1.0f}, {10.0f, 1.0f}};
    std::vector<ShapeId> found;
    world.overlapAabb(all, {}, [&](ShapeId s) {
        BodyId b = world.shapeBody(s);
        world.applyLinearImpulseToCenter(b, {0.0f, 1.0f});
        world.setAngularVelocity(b, 2.0f);
        world.setBodyUserData(b, 5);
        EXPECT_FALSE(world.overlapPoint(world.transform(b).p).empty());
        found.push_back(s);
        return true;
    });
    ASSERT_EQ(found.size(), 10u);
    for (BodyId b : balls) {
        EXPECT_GT(world.linearVelocity(b).y, 0.0f);
        EXPECT_EQ(world.angularVelocity(b), 2.0f);
    }
    for (ShapeId s : found) {
        world.destroyBody(world.shapeBody(s));
    }
    EXPECT_EQ(world.bodyCount(), 0);
}

TEST(WorldOverlap, PairAndContactWalksLockTheWorldToo) {
    World world;
    std::vector<BodyId> balls = addRowOfBalls(world);
    world.createShape(world.createBody({}), {}, makeOffsetBox(10.0f, 0.5f, {0.0f, -0.7f}, 0.0f));
    world.step(1.0f / 60.0f);
    ASSERT_GT(world.candidatePairCount(), 0);
    E2D_EXPECT_ERROR(
        world.forEachCandidatePair([&](ShapeId, ShapeId) { world.destroyBody(balls[0]); }),
        "physics::World::destroyBody(): cannot run inside the callback of "
        "forEachCandidatePair()");
    int touching = 0;
    world.forEachTouchingContact([&](const ContactData&) { ++touching; });
    ASSERT_GT(touching, 0);
    E2D_EXPECT_ERROR(world.forEachTouchingContact([&](const ContactData&) { world.step(0.0f); }),
                     "physics::World::step(): cannot run inside the callback of "
                     "forEachTouchingContact()");
    EXPECT_TRUE(world.isValid(balls[0]));
}

} // namespace
} // namespace e2d::physics
