// SPDX-License-Identifier: MIT
// The cost of a scene's per-step broadcasts with many objects: 50 000 objects whose component
// has no fixedUpdate (a quiet step: should cost next to nothing), against the same objects
// with a fixedUpdate that does a little work (the peer: the price of actually calling them).
#include <e2d/core/component.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>

#include <benchmark/benchmark.h>

namespace {

constexpr int kObjects = 50'000;

// Draws itself in a real game; here it only has the per-frame update a renderer would have.
class Quiet : public e2d::core::Component {
public:
    void update(double dt) override { elapsed += dt; }
    double elapsed = 0.0;
};

class Busy : public e2d::core::Component {
public:
    void fixedUpdate(double step) override { elapsed += step; }
    double elapsed = 0.0;
};

template <class C>
void fixedStep(benchmark::State& state) {
    e2d::core::Scene scene;
    for (int i = 0; i < kObjects; ++i) {
        scene.createGameObject().addComponent<C>();
    }
    scene.beginFrame();
    for (auto _ : state) {
        scene.dispatchFixedUpdate(1.0 / 60.0);
    }
    state.counters["objects"] = kObjects;
}

void BM_FixedStep_NoFixedUpdate(benchmark::State& state) {
    fixedStep<Quiet>(state);
}
void BM_FixedStep_EveryObjectHasFixedUpdate(benchmark::State& state) {
    fixedStep<Busy>(state);
}

BENCHMARK(BM_FixedStep_NoFixedUpdate)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FixedStep_EveryObjectHasFixedUpdate)->Unit(benchmark::kMicrosecond);

} // namespace

BENCHMARK_MAIN();
