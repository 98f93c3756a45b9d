// SPDX-License-Identifier: MIT
#include <e2d/physics/world.hpp>

#include "world_random_scene.hpp"

#include <set>
#include <utility>

namespace e2d::physics {
namespace {

using test::RandomScene;
using test::ShapeRecord;
using PairSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;

PairSet candidatePairs(const World& world) {
    PairSet pairs;
    world.forEachCandidatePair([&](ShapeId a, ShapeId b) {
        EXPECT_LT(a.index1, b.index1);
        EXPECT_TRUE(world.isValid(a));
        EXPECT_TRUE(world.isValid(b));
        bool inserted = pairs.insert({a.index1, b.index1}).second;
        EXPECT_TRUE(inserted) << "pair listed twice";
    });
    EXPECT_EQ(static_cast<int>(pairs.size()), world.candidatePairCount());
    return pairs;
}

// The rules World::updatePairs() documents, applied to every pair of shapes.
PairSet bruteForcePairs(const RandomScene& scene) {
    PairSet pairs;
    for (std::size_t i = 0; i < scene.shapes.size(); ++i) {
        for (std::size_t j = i + 1; j < scene.shapes.size(); ++j) {
            const ShapeRecord& a = scene.shapes[i];
            const ShapeRecord& b = scene.shapes[j];
            const test::BodyRecord& ba = scene.bodyOf(a);
            const test::BodyRecord& bb = scene.bodyOf(b);
            if (a.body == b.body || !ba.enabled || !bb.enabled ||
                (ba.type != BodyType::Dynamic && bb.type != BodyType::Dynamic) ||
                (a.isSensor && b.isSensor) || !shouldCollide(a.filter, b.filter) ||
                !overlaps(scene.world.shapeFatAabb(a.id), scene.world.shapeFatAabb(b.id))) {
                continue;
            }
            pairs.insert({std::min(a.id.index1, b.id.index1), std::max(a.id.index1, b.id.index1)});
        }
    }
    return pairs;
}

TEST(WorldPairs, FreshWorldFatBoxesHoldTheTightOnes) {
    RandomScene scene(11, 60, 10.0f);
    for (const ShapeRecord& s : scene.shapes) {
        Aabb tight = computeAabb(s.geometry, scene.transformOf(s));
        Aabb fat = scene.world.shapeFatAabb(s.id);
        EXPECT_TRUE(contains(fat, tight));
        // Fattened by at most the margin on every side.
        EXPECT_LE(tight.lower.x - fat.lower.x, kAabbMargin + 1e-5f);
        EXPECT_LE(fat.upper.y - tight.upper.y, kAabbMargin + 1e-5f);
    }
}

TEST(WorldPairs, CandidatePairsMatchBruteForceOverManyFrames) {
    for (std::uint32_t seed : {21u, 22u, 23u}) {
        RandomScene scene(seed, 90, 10.0f);
        test::Random& random = scene.random();
        std::size_t totalPairs = 0;
        for (int frame = 0; frame < 25; ++frame) {
            scene.world.updatePairs();
            scene.index();
            // The fat boxes the brute force uses must hold the shapes where they are now.
            for (const ShapeRecord& shape : scene.shapes) {
                ASSERT_TRUE(contains(scene.world.shapeFatAabb(shape.id),
                                     computeAabb(shape.geometry, scene.transformOf(shape))))
                    << "seed " << seed << " frame " << frame;
            }
            PairSet expected = bruteForcePairs(scene);
            ASSERT_EQ(candidatePairs(scene.world), expected)
                << "seed " << seed << " frame " << frame;
            totalPairs += expected.size();

            for (test::BodyRecord& body : scene.bodies) {
                // Mostly small moves (inside or just out of the fat box), sometimes a teleport.
                int roll = random.below(10);
                if (body.type != BodyType::Static && roll < 6) {
                    Vec2 step{random.uniform(-0.3f, 0.3f), random.uniform(-0.3f, 0.3f)};
                    scene.moveBody(body, body.position + step,
                                   body.angle + random.uniform(-0.2f, 0.2f));
                } else if (roll == 9 && random.below(4) == 0) {
                    Vec2 p{random.uniform(-10.0f, 10.0f), random.uniform(-10.0f, 10.0f)};
                    scene.moveBody(body, p, body.angle);
                }
                if (random.below(40) == 0) {
                    body.enabled = !body.enabled;
                    scene.world.setBodyEnabled(body.id, body.enabled);
                }
            }
            // Churn: destroy and create bodies and shapes, change filters.
            if (!scene.bodies.empty() && random.below(2) == 0) {
                scene.destroyBody(
                    static_cast<std::size_t>(random.below(static_cast<int>(scene.bodies.size()))));
            }
            if (!scene.shapes.empty() && random.below(2) == 0) {
                scene.destroyShape(
                    static_cast<std::size_t>(random.below(static_cast<int>(scene.shapes.size()))));
            }
            if (random.below(2) == 0) {
                scene.addBody();
            }
            if (!scene.shapes.empty()) {
                ShapeRecord& s = scene.shapes[static_cast<std::size_t>(
                    random.below(static_cast<int>(scene.shapes.size())))];
                s.filter.categoryBits = s.filter.categoryBits == 0x1 ? 0x2 : 0x1;
                s.filter.group = 0;
                scene.world.setShapeFilter(s.id, s.filter);
            }
        }
        // The comparison means something only if there were plenty of pairs.
        EXPECT_GT(totalPairs, 500u) << "seed " << seed;
    }
}

TEST(WorldPairs, RulesOnHandBuiltPairs) {
    World world;
    auto body = [&](BodyType type, Vec2 p) {
        BodyDef def;
        def.type = type;
        def.position = p;
        return world.createBody(def);
    };
    Circle circle{{0.0f, 0.0f}, 1.0f};
    // Two static shapes touching, or a static and a kinematic one: never a pair.
    BodyId ground1 = body(BodyType::Static, {0.0f, 0.0f});
    BodyId ground2 = body(BodyType::Static, {1.0f, 0.0f});
    world.createShape(ground1, {}, circle);
    world.createShape(ground2, {}, circle);
    BodyId platform = body(BodyType::Kinematic, {0.5f, -0.5f});
    world.createShape(platform, {}, circle);
    // Two shapes of one dynamic body overlapping each other: never a pair.
    BodyId car = body(BodyType::Dynamic, {20.0f, 0.0f});
    ShapeId car1 = world.createShape(car, {}, circle);
    ShapeId car2 = world.createShape(car, {}, circle);
    world.updatePairs();
    EXPECT_EQ(world.candidatePairCount(), 0);

    // A dynamic ball on the static ground and the kinematic platform: three pairs.
    BodyId ball = body(BodyType::Dynamic, {0.5f, 1.0f});
    ShapeId ballShape = world.createShape(ball, {}, circle);
    world.updatePairs();
    EXPECT_EQ(world.candidatePairCount(), 3);

    // Two sensors do not pair; a sensor pairs with a solid shape.
    ShapeDef sensor;
    sensor.isSensor = true;
    BodyId trigger = body(BodyType::Kinematic, {20.0f, 1.0f});
    ShapeId triggerShape = world.createShape(trigger, sensor, circle);
    BodyId trigger2 = body(BodyType::Dynamic, {20.0f, 1.5f});
    world.createShape(trigger2, sensor, circle);
    world.updatePairs();
    PairSet pairs = candidatePairs(world);
    EXPECT_TRUE(pairs.count({car1.index1, triggerShape.index1}) == 1);
    EXPECT_TRUE(pairs.count({car2.index1, triggerShape.index1}) == 1);
    EXPECT_EQ(world.candidatePairCount(), 3 + 2 + 2); // ball: grounds and platform; car: triggers

    // Masks: the ball stops touching category 1 (ground and platform): those pairs end.
    Filter filter;
    filter.maskBits = ~std::uint64_t{1};
    world.setShapeFilter(ballShape, filter);
    world.updatePairs();
    EXPECT_EQ(world.candidatePairCount(), 4);
    // A shared positive group overrides the masks.
    filter.group = 3;
    world.setShapeFilter(ballShape, filter);
    Filter groundFilter;
    groundFilter.group = 3;
    world.setShapeFilter(world.bodyShapes(ground1)[0], groundFilter);
    world.updatePairs();
    EXPECT_EQ(world.candidatePairCount(), 5);
}

TEST(WorldPairs, PairsFollowSetTransform) {
    World world;
    BodyDef def;
    def.type = BodyType::Dynamic;
    BodyId a = world.createBody(def);
    def.position = {10.0f, 0.0f};
    BodyId b = world.createBody(def);
    ShapeId sa = world.createShape(a, {}, Circle{{0.0f, 0.0f}, 1.0f});
    ShapeId sb = world.createShape(b, {}, Circle{{0.0f, 0.0f}, 1.0f});
    world.updatePairs();
    EXPECT_EQ(world.candidatePairCount(), 0);

    world.setTransform(b, {1.5f, 0.0f}, 0.0f);
    world.updatePairs();
    ASSERT_EQ(world.candidatePairCount(), 1);
    world.forEachCandidatePair([&](ShapeId x, ShapeId y) {
        EXPECT_EQ(x, sa);
        EXPECT_EQ(y, sb);
    });
    // Apart again, beyond both fat boxes: the pair is dropped.
    world.setTransform(b, {5.0f, 0.0f}, 0.0f);
    world.updatePairs();
    EXPECT_EQ(world.candidatePairCount(), 0);
    // Destroying a shape ends its pairs at once.
    world.setTransform(b, {1.0f, 0.0f}, 0.0f);
    world.updatePairs();
    EXPECT_EQ(world.candidatePairCount(), 1);
    world.destroyShape(sb);
    EXPECT_EQ(world.candidatePairCount(), 0);
}

TEST(WorldPairs, DisablingABodyEndsItsPairs) {
    World world;
    BodyDef def;
    def.type = BodyType::Dynamic;
    BodyId a = world.createBody(def);
    BodyId b = world.createBody(def);
    world.createShape(a, {}, Circle{{0.0f, 0.0f}, 1.0f});
    world.createShape(b, {}, Circle{{0.5f, 0.0f}, 1.0f});
    world.updatePairs();
    EXPECT_EQ(world.candidatePairCount(), 1);
    world.setBodyEnabled(b, false);
    EXPECT_FALSE(world.isBodyEnabled(b));
    EXPECT_EQ(world.candidatePairCount(), 0);
    world.setBodyEnabled(b, true);
    world.updatePairs();
    EXPECT_EQ(world.candidatePairCount(), 1);
}

} // namespace
} // namespace e2d::physics

namespace e2d::physics {
namespace {

std::vector<std::pair<std::uint32_t, std::uint32_t>> pairSequence(const World& world) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> sequence;
    world.forEachCandidatePair(
        [&](ShapeId a, ShapeId b) { sequence.emplace_back(a.index1, b.index1); });
    return sequence;
}

TEST(WorldPairs, SameOperationsGiveTheSamePairsInTheSameOrder) {
    // Two worlds side by side, driven by the same seed: determinism includes the order in which
    // pairs are listed (the contacts built from them will be solved in that order).
    test::RandomScene first(41, 80, 8.0f);
    test::RandomScene second(41, 80, 8.0f);
    for (int frame = 0; frame < 10; ++frame) {
        for (test::RandomScene* scene : {&first, &second}) {
            scene->world.updatePairs();
            for (test::BodyRecord& body : scene->bodies) {
                Vec2 step{scene->random().uniform(-0.5f, 0.5f),
                          scene->random().uniform(-0.5f, 0.5f)};
                scene->moveBody(body, body.position + step, body.angle);
            }
        }
        std::vector<std::pair<std::uint32_t, std::uint32_t>> a = pairSequence(first.world);
        EXPECT_FALSE(a.empty());
        EXPECT_EQ(a, pairSequence(second.world)) << "frame " << frame;
    }
}

} // namespace
} // namespace e2d::physics
