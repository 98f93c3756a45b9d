// SPDX-License-Identifier: MIT
#include <e2d/core/clock.hpp>
#include <e2d/core/error.hpp>
#include <e2d/core/fixed_stepper.hpp>
#include <e2d/core/game_loop.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/log.hpp>
#include <e2d/core/scene_director.hpp>
#include <e2d/core/scene_registry.hpp>
#include <e2d/core/system.hpp>

#include "test_support.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

using e2d::core::Clock;
using e2d::core::Component;
using e2d::core::FixedStepper;
using e2d::core::FrameInfo;
using e2d::core::GameLoop;
using e2d::core::Logger;
using e2d::core::LogLevel;
using e2d::core::Scene;
using e2d::core::SceneDirector;
using e2d::core::SceneRegistry;
using e2d::core::System;
using testing::ElementsAre;

namespace {

std::vector<std::string>* gCalls = nullptr;

void record(std::string call) { gCalls->push_back(std::move(call)); }

class CountingComponent : public Component {
public:
    void fixedUpdate(double) override { record("component.fixed"); }
    void update(double) override { record("component.update"); }
};

class FirstScene : public Scene {
protected:
    void onInitialize() override {
        record("first.init");
        createGameObject().addComponent<CountingComponent>();
    }
    void onTerminate() override { record("first.term"); }
    void fixedUpdate(double) override { record("scene.fixed"); }
    void update(double) override {
        record("scene.update");
        if (leaveOnUpdate) {
            changeToScene("Second");
        }
    }

public:
    static inline bool leaveOnUpdate = false;
};

class SecondScene : public Scene {
protected:
    void onInitialize() override { record("second.init"); }
    void update(double) override {
        record("second.update");
        terminateGame();
    }
};

class TracingSystem : public System {
public:
    explicit TracingSystem(std::string name) : name_(std::move(name)) {}
    void init() override { record(name_ + ".init"); }
    void beginFrame() override { record(name_ + ".begin"); }
    void fixedUpdate(double step) override {
        record(name_ + ".fixed");
        lastStep = step;
    }
    void update(double dt) override {
        record(name_ + ".update");
        lastDt = dt;
    }
    void render(double alpha) override {
        record(name_ + ".render");
        lastAlpha = alpha;
    }
    void clear() override { record(name_ + ".clear"); }
    void shutdown() override { record(name_ + ".shutdown"); }
    double lastStep = -1.0;
    double lastDt = -1.0;
    double lastAlpha = -1.0;

private:
    std::string name_;
};

// A director with the two scenes and a physics-like system, on a manual clock.
class LoopParts : public testing::Test {
protected:
    LoopParts()
        : logger(LogLevel::Off), director(registry, logger), stepper(0.25, 3),
          clock([this] { return now; }) {
        gCalls = &calls;
        FirstScene::leaveOnUpdate = false;
        registry.add<FirstScene>("First");
        registry.add<SecondScene>("Second");
        director.addSystem(physics);
    }
    ~LoopParts() override { gCalls = nullptr; }

    std::vector<std::string> calls;
    double now = 0.0;
    Logger logger;
    SceneRegistry registry;
    SceneDirector director;
    FixedStepper stepper;
    Clock clock;
    TracingSystem physics{"physics"};
};

class GameLoopTest : public LoopParts {
protected:
    GameLoopTest() { director.addSystem(renderer); }

    TracingSystem renderer{"renderer"};
    GameLoop loop{director, stepper, clock, e2d::core::GameLoopDef{.maxFrameTime = 100.0}};
};

} // namespace

TEST_F(GameLoopTest, StartInitialisesSystemsThenTheScene) {
    EXPECT_FALSE(loop.running());
    EXPECT_TRUE(loop.start("First"));
    EXPECT_TRUE(loop.running());
    EXPECT_THAT(calls, ElementsAre("physics.init", "renderer.init", "first.init"));
    EXPECT_THROW(loop.start("First"), e2d::core::Error);
}

TEST_F(GameLoopTest, FrameRunsFixedStepsThenUpdateThenRender) {
    loop.start("First");
    calls.clear();
    now += 0.625; // 2 steps of 0.25, 0.125 left
    const FrameInfo info = loop.frame();
    EXPECT_EQ(info.dt, 0.625);
    EXPECT_EQ(info.fixedSteps, 2);
    EXPECT_EQ(info.alpha, 0.5);
    EXPECT_FALSE(info.sceneChanged);
    EXPECT_THAT(calls,
                ElementsAre("physics.begin", "renderer.begin",                                   //
                            "scene.fixed", "component.fixed", "physics.fixed", "renderer.fixed", //
                            "scene.fixed", "component.fixed", "physics.fixed", "renderer.fixed", //
                            "scene.update", "component.update", "physics.update",
                            "renderer.update", //
                            "physics.render", "renderer.render"));
    EXPECT_EQ(physics.lastStep, 0.25);
    EXPECT_EQ(physics.lastDt, 0.625);
    EXPECT_EQ(renderer.lastAlpha, 0.5);
}

TEST_F(GameLoopTest, TimeScaleSlowsTheFixedSteps) {
    loop.start("First");
    clock.setTimeScale(0.5);
    now += 1.0; // 0.5 s of game time: 2 steps
    const FrameInfo info = loop.frame();
    EXPECT_EQ(info.dt, 0.5);
    EXPECT_EQ(info.fixedSteps, 2);
}

TEST_F(GameLoopTest, LongFramesAreClamped) {
    loop.start("First");
    now += 10.0;
    const FrameInfo info = loop.frame();
    EXPECT_EQ(info.fixedSteps, 3);
    EXPECT_EQ(stepper.droppedTime(), 9.25);
}

TEST_F(GameLoopTest, SceneChangeHappensAtTheStartOfTheNextFrame) {
    loop.start("First");
    FirstScene::leaveOnUpdate = true;
    now += 0.125;
    loop.frame(); // requests the change during update
    EXPECT_EQ(director.sceneName(), "First");
    calls.clear();

    now += 0.125;
    const FrameInfo info = loop.frame();
    EXPECT_TRUE(info.sceneChanged);
    EXPECT_EQ(director.sceneName(), "Second");
    // The 0.125 s left from the first scene are forgotten: 0.125 s is no step yet.
    EXPECT_THAT(calls,
                ElementsAre("first.term", "physics.clear", "renderer.clear", "second.init",
                            "physics.begin", "renderer.begin", "second.update", "physics.update",
                            "renderer.update", "physics.render", "renderer.render"));
    EXPECT_EQ(info.fixedSteps, 0);
    EXPECT_EQ(info.alpha, 0.5);
    // SecondScene asked to end the game.
    EXPECT_FALSE(loop.running());
}

TEST_F(GameLoopTest, ShutdownTerminatesTheSceneThenSystemsInReverse) {
    loop.start("First");
    calls.clear();
    loop.shutdown();
    EXPECT_THAT(calls, ElementsAre("first.term", "renderer.shutdown", "physics.shutdown"));
    EXPECT_EQ(director.scene(), nullptr);
    EXPECT_FALSE(loop.running());
    calls.clear();
    loop.shutdown(); // second call does nothing
    EXPECT_TRUE(calls.empty());
}

TEST_F(GameLoopTest, LoadingTimeIsNotGameTime) {
    now += 5.0; // time before start, e.g. loading assets
    loop.start("First");
    now += 0.25;
    EXPECT_EQ(loop.frame().dt, 0.25);
}

namespace {

// Writes down what the loop tells its observer.
class TracingObserver : public e2d::core::FrameObserver {
public:
    void frameStarted(std::int64_t index) override { record("frame " + std::to_string(index)); }
    void phaseStarted(e2d::core::FramePhase phase) override { record("[" + name(phase)); }
    void phaseEnded(e2d::core::FramePhase phase) override { record(name(phase) + "]"); }
    void systemStarted(e2d::core::FramePhase, const System& system) override {
        record(std::string("(") + (&system == watched ? "watched" : "other"));
    }
    void systemEnded(e2d::core::FramePhase, const System&) override { record(")"); }
    void frameEnded(const FrameInfo& info) override { ended.push_back(info); }

    static std::string name(e2d::core::FramePhase phase) {
        switch (phase) {
        case e2d::core::FramePhase::Begin:
            return "begin";
        case e2d::core::FramePhase::FixedSteps:
            return "fixed";
        case e2d::core::FramePhase::Update:
            return "update";
        case e2d::core::FramePhase::Render:
            return "render";
        }
        return "?";
    }
    const System* watched = nullptr;
    std::vector<FrameInfo> ended;
};

// A loop like an engine's: headless frames, a spike clamp, a frame limit, an observer.
class EngineLoopTest : public LoopParts {
protected:
    EngineLoopTest() { observer.watched = &physics; }

    TracingObserver observer;
};

} // namespace

TEST_F(EngineLoopTest, AFrameLongerThanMaxFrameTimeCountsAsThatLongAndIsASpike) {
    GameLoop loop(director, stepper, clock, {.maxFrameTime = 0.5});
    loop.start("First");
    now += 2.0; // a stall
    const FrameInfo stalled = loop.frame();
    EXPECT_TRUE(stalled.spike);
    EXPECT_EQ(stalled.dt, 0.5);
    EXPECT_EQ(stalled.fixedSteps, 2);
    EXPECT_EQ(physics.lastDt, 0.5);
    now += 0.25;
    const FrameInfo next = loop.frame();
    EXPECT_FALSE(next.spike);
    EXPECT_EQ(next.fixedSteps, 1);
}

TEST_F(EngineLoopTest, FixedFrameTimeAndFrameLimitMakeAHeadlessRun) {
    GameLoop loop(director, stepper, clock, {.fixedFrameTime = 0.25, .frameLimit = 3});
    loop.start("First");
    now += 50.0; // the clock is not read
    loop.run();
    EXPECT_EQ(loop.frames(), 3);
    EXPECT_FALSE(loop.running());
    EXPECT_EQ(std::count(calls.begin(), calls.end(), "physics.fixed"), 3);
    EXPECT_EQ(physics.lastDt, 0.25);
}

TEST_F(EngineLoopTest, TheObserverSeesEveryPhaseAndEverySystemCallInOrder) {
    GameLoop loop(director, stepper, clock, {.fixedFrameTime = 0.3, .observer = &observer});
    loop.start("First");
    calls.clear();
    const FrameInfo info = loop.frame();
    EXPECT_THAT(calls, ElementsAre("frame 0",                                                 //
                                   "[begin", "(watched", "physics.begin", ")", "begin]",      //
                                   "[fixed", "scene.fixed", "component.fixed", "(watched",    //
                                   "physics.fixed", ")", "fixed]",                            //
                                   "[update", "scene.update", "component.update", "(watched", //
                                   "physics.update", ")", "update]",                          //
                                   "[render", "(watched", "physics.render", ")", "render]"));
    ASSERT_EQ(observer.ended.size(), 1u);
    EXPECT_EQ(observer.ended[0].index, 0);
    EXPECT_EQ(observer.ended[0].fixedSteps, info.fixedSteps);
    calls.clear();
    loop.frame();
    EXPECT_EQ(calls.front(), "frame 1");
    EXPECT_EQ(observer.ended.back().index, 1);
}

TEST_F(EngineLoopTest, RenderDrawsTheLastFrameAgainWithItsAlpha) {
    GameLoop loop(director, stepper, clock, {.maxFrameTime = 1.0, .fixedFrameTime = 0.375});
    loop.start("First");
    loop.frame();
    calls.clear();
    loop.render();
    EXPECT_THAT(calls, ElementsAre("physics.render"));
    EXPECT_EQ(physics.lastAlpha, 0.5);
}

TEST_F(EngineLoopTest, BadDefsAreRefusedNamingTheField) {
    const auto errorOf = [&](e2d::core::GameLoopDef def) -> std::string {
        try {
            GameLoop loop(director, stepper, clock, def);
        } catch (const e2d::core::Error& e) {
            return e.what();
        }
        return "(no error)";
    };
    EXPECT_EQ(errorOf({.maxFrameTime = 0.0}),
              "core::GameLoop::GameLoop(): maxFrameTime must be > 0, got 0");
    EXPECT_EQ(errorOf({.fixedFrameTime = -1.0}),
              "core::GameLoop::GameLoop(): fixedFrameTime must be finite and >= 0, got -1");
    EXPECT_EQ(errorOf({.frameLimit = -2}),
              "core::GameLoop::GameLoop(): frameLimit must be >= 0, got -2");
}
