// SPDX-License-Identifier: MIT
// Building a world: N dynamic bodies with one 1 m box each, on a grid 2 m apart (no overlaps),
// created one by one through the public API of e2d and of Box2D 2.4, in one binary. Each
// benchmark iteration builds a fresh world; tearing it down is not timed. Reported: ns per body
// (body + shape) and the ratio e2d / Box2D.
//
// Two groups: "create" times the creation calls alone; "create_step" times them and the first
// step (1/60 s) together. The second is the honest comparison: e2d inserts new shapes into its
// broad-phase tree in bulk when the tree is next needed (the first step, or a query), where
// Box2D 2.4 inserts each one in CreateFixture; both find the new shapes' pairs in the first step.
//
// Extra flag (taken out before Google Benchmark parses the rest):
//   --e2d_table=F   the Markdown table goes to F as well
#include "ratio_reporter.hpp"

#include <e2d/physics/world.hpp>

#include <box2d/box2d.h>

#include <benchmark/benchmark.h>

#include <memory>
#include <string>

namespace {

namespace ph = e2d::physics;

// Grid position of body i of n: rows of ceil(sqrt(n)) bodies, 2 m apart.
struct Grid {
    explicit Grid(int n) {
        while (side * side < n) {
            ++side;
        }
    }
    [[nodiscard]] float x(int i) const { return 2.0f * static_cast<float>(i % side); }
    [[nodiscard]] float y(int i) const { return 2.0f * static_cast<float>(i / side); }
    int side = 1;
};

// range(1): 1 to take the first step inside the timed region too.
void createE2d(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    const bool step = state.range(1) != 0;
    const Grid grid(n);
    const ph::Polygon box = ph::makeBox(0.5f, 0.5f);
    for (auto _ : state) {
        auto world = std::make_unique<ph::World>();
        for (int i = 0; i < n; ++i) {
            ph::BodyDef bd;
            bd.type = ph::BodyType::Dynamic;
            bd.position = {grid.x(i), grid.y(i)};
            const ph::BodyId body = world->createBody(bd);
            world->createShape(body, {}, box);
        }
        if (step) {
            world->step(1.0f / 60.0f);
        }
        benchmark::DoNotOptimize(world->shapeCount());
        state.PauseTiming();
        world.reset();
        state.ResumeTiming();
    }
    state.SetItemsProcessed(state.iterations() * n);
}

void createBox2D(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    const bool step = state.range(1) != 0;
    const Grid grid(n);
    b2PolygonShape box;
    box.SetAsBox(0.5f, 0.5f);
    for (auto _ : state) {
        auto world = std::make_unique<b2World>(b2Vec2(0.0f, -10.0f));
        for (int i = 0; i < n; ++i) {
            b2BodyDef bd;
            bd.type = b2_dynamicBody;
            bd.position.Set(grid.x(i), grid.y(i));
            b2Body* body = world->CreateBody(&bd);
            body->CreateFixture(&box, 1.0f);
        }
        if (step) {
            world->Step(1.0f / 60.0f, 8, 3);
        }
        benchmark::DoNotOptimize(world->GetBodyCount());
        state.PauseTiming();
        world.reset();
        state.ResumeTiming();
    }
    state.SetItemsProcessed(state.iterations() * n);
}

} // namespace

int main(int argc, char** argv) {
    for (const int step : {0, 1}) {
        for (const int n : {1000, 10000, 100000}) {
            const std::string name =
                std::string(step != 0 ? "create_step" : "create") + "/bodies_" + std::to_string(n);
            benchmark::RegisterBenchmark((name + "/box2d").c_str(), createBox2D)
                ->Args({n, step})
                ->Unit(benchmark::kMillisecond);
            benchmark::RegisterBenchmark((name + "/e2d").c_str(), createE2d)
                ->Args({n, step})
                ->Unit(benchmark::kMillisecond);
        }
    }
    return e2d::bench::runWithRatios(argc, argv, "box2d", {"e2d", "box2d"}, "ns per body");
}
