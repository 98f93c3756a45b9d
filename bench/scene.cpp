// SPDX-License-Identifier: MIT
// The cost of a scene's per-step broadcasts with many objects. 50 000 objects whose component
// has no fixedUpdate: a fixed step should cost next to nothing, where the scene used to call
// every component's (empty) fixedUpdate; the peer below does what it did (a virtual call per
// component of an active object), and the same objects with a fixedUpdate that does a little
// work give the price of actually calling them. An event that 10 of the 50 000 components
// handle reaches only those.
#include <e2d/core/component.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/handles.hpp>
#include <e2d/core/scene.hpp>

#include <benchmark/benchmark.h>

#include <vector>

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

struct Ping {
    int value = 0;
};

class Listener : public e2d::core::Component, public e2d::core::Handles<Ping> {
public:
    void on(const Ping& ping) override { sum += ping.value; }
    long sum = 0;
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

void BM_FixedStep_NoFixedUpdate(benchmark::State& state) { fixedStep<Quiet>(state); }
void BM_FixedStep_EveryObjectHasFixedUpdate(benchmark::State& state) { fixedStep<Busy>(state); }

// The peer: the broadcast the scene used to do, every component of every active object.
void BM_FixedStep_NoFixedUpdate_CallingEveryComponent(benchmark::State& state) {
    e2d::core::Scene scene;
    std::vector<e2d::core::Component*> components;
    for (int i = 0; i < kObjects; ++i) {
        components.push_back(scene.createGameObject().addComponent<Quiet>());
    }
    scene.beginFrame();
    for (auto _ : state) {
        for (e2d::core::Component* c : components) {
            if (c->gameObject()->isActiveInHierarchy()) {
                c->fixedUpdate(1.0 / 60.0);
            }
        }
        benchmark::ClobberMemory();
    }
    state.counters["objects"] = kObjects;
}

void BM_Event_TenOf50000Handle(benchmark::State& state) {
    e2d::core::Scene scene;
    for (int i = 0; i < kObjects; ++i) {
        e2d::core::GameObject& o = scene.createGameObject();
        if (i % (kObjects / 10) == 0) {
            o.addComponent<Listener>();
        } else {
            o.addComponent<Quiet>();
        }
    }
    scene.beginFrame();
    for (auto _ : state) {
        scene.dispatch(Ping{1});
    }
    state.counters["objects"] = kObjects;
}

BENCHMARK(BM_FixedStep_NoFixedUpdate)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FixedStep_NoFixedUpdate_CallingEveryComponent)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FixedStep_EveryObjectHasFixedUpdate)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Event_TenOf50000Handle)->Unit(benchmark::kMicrosecond);

} // namespace

BENCHMARK_MAIN();
