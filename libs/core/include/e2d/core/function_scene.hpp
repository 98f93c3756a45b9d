// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/scene.hpp>

#include <functional>

namespace e2d::core {

/// What a FunctionScene does at its events; an empty function does nothing there.
struct SceneFunctions {
    /// The scene starts (onInitialize): create its objects here.
    std::function<void(Scene&)> initialize{};
    /// Once per frame (update), with the scaled frame time in seconds.
    std::function<void(Scene&, double)> update{};
    /// Once per fixed step (fixedUpdate), with the step in seconds.
    std::function<void(Scene&, double)> fixedUpdate{};
    /// The scene ends (onTerminate), before its objects receive onTerminate.
    std::function<void(Scene&)> terminate{};
};

/// A scene made of functions instead of a subclass, for prototypes, tools and tests:
/// `registry.add("Sandbox", SceneFunctions{.initialize = [](Scene& s) { ... }})`. Each
/// function runs where the matching Scene event would, before the objects get the event.
/// A scene that handles input or keeps state of its own is clearer as a subclass.
class FunctionScene final : public Scene {
public:
    explicit FunctionScene(SceneFunctions functions) : functions_(std::move(functions)) {}

protected:
    void onInitialize() override {
        if (functions_.initialize) {
            functions_.initialize(*this);
        }
    }
    void onTerminate() override {
        if (functions_.terminate) {
            functions_.terminate(*this);
        }
    }
    void update(double dt) override {
        if (functions_.update) {
            functions_.update(*this, dt);
        }
    }
    void fixedUpdate(double step) override {
        if (functions_.fixedUpdate) {
            functions_.fixedUpdate(*this, step);
        }
    }

private:
    SceneFunctions functions_;
};

} // namespace e2d::core
