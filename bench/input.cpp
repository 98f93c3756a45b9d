// SPDX-License-Identifier: MIT
// One frame of input: 1 000 window events queued through the callback entry points, 16 pads
// polled (every stick and trigger moving, a button changing per pad), delivery, then 100
// actions (key, key pair, any-pad button and any-pad axis bindings) evaluated. Guards against
// accidental quadratic work; expected to take microseconds.
#include <e2d/input/actions.hpp>
#include <e2d/input/input.hpp>

#include <GLFW/glfw3.h>
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

namespace {

using namespace e2d::input;

void setupActions(ActionMap& actions) {
    for (int i = 0; i < 100; ++i) {
        const ActionId id = actions.add("action_" + std::to_string(i));
        // Key's values are GLFW's: A..Z, 0..9 and F1..F25 are consecutive.
        actions.bind(id, Binding::key(Key(static_cast<int>(Key::A) + i % 26)));
        actions.bind(id, Binding::keyAxis(Key(static_cast<int>(Key::Num0) + i % 10),
                                          Key(static_cast<int>(Key::F1) + i % 12)));
        actions.bind(id, Binding::gamepadButton(GamepadButton(i % kGamepadButtonCount)));
        actions.bind(id, Binding::gamepadAxis(GamepadAxis(i % kGamepadAxisCount), i % 2 == 1));
    }
}

void queueEvents(Input& input, int frame, int count) {
    for (int i = 0; i < count; i += 5) {
        const int key = GLFW_KEY_A + (frame + i) % 26;
        input.handleKey(key, 38, GLFW_PRESS, 0);
        input.handleChar(static_cast<char32_t>('a' + (frame + i) % 26));
        input.handleCursorPos(100.0 + i % 200, 50.0 + (frame + i) % 100);
        input.handleMouseButton(i % 3, i % 2 == 0 ? GLFW_PRESS : GLFW_RELEASE, 0);
        input.handleKey(key, 38, GLFW_RELEASE, 0);
    }
}

void feedPads(Input& input, int frame) {
    for (int slot = 0; slot < kMaxGamepads; ++slot) {
        JoystickSnapshot s;
        s.present = true;
        s.gamepad = true;
        s.guid = "030000005e0400008e02000010010000";
        s.name = "Bench Pad";
        const float t = static_cast<float>(frame) * 0.1f + static_cast<float>(slot);
        s.axes = {std::sin(t),        std::cos(t), std::sin(2.0f * t),
                  std::cos(2.0f * t), std::sin(t), std::cos(t)};
        s.buttons[static_cast<std::size_t>((frame + slot) % 15)] = GLFW_PRESS;
        input.handleJoystick(slot, s);
    }
}

void BM_InputFrame(benchmark::State& state) {
    const int events = static_cast<int>(state.range(0));
    InputDef def;
    def.screenToWorld = [](glm::vec2 s) { return s * 0.01f; };
    def.maxQueuedEvents = 1u << 20;
    Input input(def);
    ActionMap actions;
    setupActions(actions);
    int frame = 0;
    for (auto _ : state) {
        queueEvents(input, frame, events);
        feedPads(input, frame);
        input.beginFrame();
        actions.update(input);
        benchmark::DoNotOptimize(actions.value(ActionId{1}));
        benchmark::DoNotOptimize(input.events().data());
        ++frame;
    }
    state.counters["events"] = static_cast<double>(input.events().size());
    state.SetItemsProcessed(state.iterations() * events);
}
BENCHMARK(BM_InputFrame)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

// Action evaluation alone, with nothing queued (the cost every frame pays).
void BM_ActionsUpdate(benchmark::State& state) {
    Input input;
    ActionMap actions;
    setupActions(actions);
    feedPads(input, 0);
    input.beginFrame();
    for (auto _ : state) {
        actions.update(input);
        benchmark::DoNotOptimize(actions.value(ActionId{1}));
    }
}
BENCHMARK(BM_ActionsUpdate)->Unit(benchmark::kMicrosecond);

} // namespace

BENCHMARK_MAIN();
