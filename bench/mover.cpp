// SPDX-License-Identifier: MIT
// What a character's ground handling costs per fixed step on a small level: e2d's
// CharacterMover::move() (collide, solve the planes, cast the capsule, look for ground) against
// the three downward ray casts a game without a mover uses to ground its player (the
// platformer's old probe), in e2d and in Box2D 2.4, in one binary. The rays only answer
// "grounded?"; the mover also moves the character, slides it and reports walls and ceilings.
//
// The level (the same shapes in both worlds): a 100 m floor, a 30 degree ramp, a wall, a low
// ceiling block and 300 1 m boxes stacked out of reach above (so the trees are not trivial).
// Cases: walking on the flat, walking up the ramp, pushing into the corner of floor and wall.
// Each iteration starts the character at the same place and moves it once (1/60 s at 6 m/s).
//
// Extra flag (taken out before Google Benchmark parses the rest):
//   --e2d_table=F   the Markdown table goes to F as well
#include "ratio_reporter.hpp"

#include <e2d/physics/character_mover.hpp>
#include <e2d/physics/world.hpp>

#include <box2d/box2d.h>

#include <benchmark/benchmark.h>

#include <array>
#include <string>
#include <vector>

namespace {

namespace ph = e2d::physics;

struct Block {
    ph::Vec2 center;
    ph::Vec2 half;
};

std::vector<Block> blocks() {
    std::vector<Block> out{{{0.0f, -0.5f}, {50.0f, 0.5f}},  // floor, top at y = 0
                           {{-10.0f, 2.0f}, {0.5f, 2.0f}},  // wall, face at x = -9.5
                           {{-20.0f, 3.0f}, {3.0f, 0.5f}}}; // ceiling block, underside y = 2.5
    for (int i = 0; i < 300; ++i) {
        out.push_back({{-30.0f + 2.0f * static_cast<float>(i % 30),
                        20.0f + 2.0f * static_cast<float>(i / 30)},
                       {0.5f, 0.5f}});
    }
    return out;
}

// The ramp: rises to the right from (10, 0) at 30 degrees, 10 m wide.
const std::array<ph::Vec2, 3> kRamp{ph::Vec2{10.0f, 0.0f}, ph::Vec2{20.0f, 0.0f},
                                    ph::Vec2{20.0f, 5.7735f}};

// Capsule centres 0.5 m above and below the position, radius 0.3, skin 0.01.
constexpr float kRest = 0.81f;
constexpr float kStep = 6.0f / 60.0f;

struct Case {
    const char* name;
    ph::Vec2 start;
    ph::Vec2 displacement;
};
const std::array<Case, 3> kCases{
    Case{"flat", {0.0f, kRest}, {kStep, -0.01f}},
    Case{"slope", {14.0f, 4.0f * 0.57735f + 0.5f + 0.358f}, {kStep, -0.01f}},
    Case{"corner", {-9.5f - 0.31f, kRest}, {-kStep, -0.01f}}};

ph::World makeE2dWorld() {
    ph::World world;
    const ph::BodyId ground = world.createBody({});
    for (const Block& b : blocks()) {
        world.createShape(ground, {}, ph::makeOffsetBox(b.half.x, b.half.y, b.center, 0.0f));
    }
    world.createShape(ground, {}, ph::makePolygon(kRamp));
    return world;
}

void moverE2d(benchmark::State& state) {
    const Case& c = kCases[static_cast<std::size_t>(state.range(0))];
    const ph::World world = makeE2dWorld();
    ph::CharacterMoverDef def;
    def.position = c.start;
    ph::CharacterMover mover(def);
    for (auto _ : state) {
        mover.setPosition(c.start);
        benchmark::DoNotOptimize(mover.move(world, c.displacement));
    }
    state.SetItemsProcessed(state.iterations());
}

void raysE2d(benchmark::State& state) {
    const Case& c = kCases[static_cast<std::size_t>(state.range(0))];
    const ph::World world = makeE2dWorld();
    for (auto _ : state) {
        bool grounded = false;
        for (const float dx : {-0.25f, 0.0f, 0.25f}) {
            const ph::Vec2 feet = c.start + ph::Vec2(dx, -0.5f);
            grounded = world.castRayClosest(feet, {0.0f, -0.4f}).has_value() || grounded;
        }
        benchmark::DoNotOptimize(grounded);
    }
    state.SetItemsProcessed(state.iterations());
}

class ClosestHit : public b2RayCastCallback {
public:
    float ReportFixture(b2Fixture*, const b2Vec2&, const b2Vec2&, float fraction) override {
        hit = true;
        return fraction;
    }
    bool hit = false;
};

void raysBox2D(benchmark::State& state) {
    const Case& c = kCases[static_cast<std::size_t>(state.range(0))];
    b2World world(b2Vec2(0.0f, -10.0f));
    b2BodyDef bd;
    b2Body* ground = world.CreateBody(&bd);
    for (const Block& b : blocks()) {
        b2PolygonShape box;
        box.SetAsBox(b.half.x, b.half.y, b2Vec2(b.center.x, b.center.y), 0.0f);
        ground->CreateFixture(&box, 0.0f);
    }
    std::array<b2Vec2, 3> ramp;
    for (std::size_t i = 0; i < ramp.size(); ++i) {
        ramp[i].Set(kRamp[i].x, kRamp[i].y);
    }
    b2PolygonShape rampShape;
    rampShape.Set(ramp.data(), 3);
    ground->CreateFixture(&rampShape, 0.0f);
    for (auto _ : state) {
        bool grounded = false;
        for (const float dx : {-0.25f, 0.0f, 0.25f}) {
            ClosestHit hit;
            const b2Vec2 feet(c.start.x + dx, c.start.y - 0.5f);
            world.RayCast(&hit, feet, feet + b2Vec2(0.0f, -0.4f));
            grounded = hit.hit || grounded;
        }
        benchmark::DoNotOptimize(grounded);
    }
    state.SetItemsProcessed(state.iterations());
}

} // namespace

int main(int argc, char** argv) {
    for (std::size_t i = 0; i < kCases.size(); ++i) {
        const std::string name = std::string("ground/") + kCases[i].name;
        const auto arg = static_cast<std::int64_t>(i);
        benchmark::RegisterBenchmark((name + "/box2d_rays").c_str(), raysBox2D)->Arg(arg);
        benchmark::RegisterBenchmark((name + "/e2d_rays").c_str(), raysE2d)->Arg(arg);
        benchmark::RegisterBenchmark((name + "/e2d_mover").c_str(), moverE2d)->Arg(arg);
    }
    return e2d::bench::runWithRatios(argc, argv, "box2d_rays",
                                     {"box2d_rays", "e2d_rays", "e2d_mover"}, "ns per character");
}
