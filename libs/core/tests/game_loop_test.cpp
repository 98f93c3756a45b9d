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

void record(std::string call) {
    gCalls->push_back(std::move(call));
}

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

class GameLoopTest : public testing::Test {
protected:
    GameLoopTest()
        : logger(LogLevel::Off), director(registry, logger), stepper(0.25, 3), clock([this] { return now; }),
          loop(director, stepper, clock) {
        gCalls = &calls;
        FirstScene::leaveOnUpdate = false;
        registry.add<FirstScene>("First");
        registry.add<SecondScene>("Second");
        director.addSystem(physics);
        director.addSystem(renderer);
    }
    ~GameLoopTest() override { gCalls = nullptr; }

    std::vector<std::string> calls;
    double now = 0.0;
    Logger logger;
    SceneRegistry registry;
    SceneDirector director;
    FixedStepper stepper;
    Clock clock;
    TracingSystem physics{"physics"};
    TracingSystem renderer{"renderer"};
    GameLoop loop;
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
    EXPECT_THAT(calls, ElementsAre("physics.begin", "renderer.begin",                                       //
                                   "scene.fixed", "component.fixed", "physics.fixed", "renderer.fixed",     //
                                   "scene.fixed", "component.fixed", "physics.fixed", "renderer.fixed",     //
                                   "scene.update", "component.update", "physics.update", "renderer.update", //
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
    EXPECT_THAT(calls, ElementsAre("first.term", "physics.clear", "renderer.clear", "second.init", "physics.begin",
                                   "renderer.begin", "physics.fixed", "renderer.fixed", "second.update",
                                   "physics.update", "renderer.update", "physics.render", "renderer.render"));
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
