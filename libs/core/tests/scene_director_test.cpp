// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
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

using e2d::core::Logger;
using e2d::core::LogLevel;
using e2d::core::Scene;
using e2d::core::SceneDirector;
using e2d::core::SceneRegistry;
using e2d::core::System;
using e2d::core::test::EventLog;
using e2d::core::test::Recorder;
using testing::ElementsAre;
using testing::HasSubstr;
using testing::IsEmpty;

namespace {

// Each test installs its log here; scenes are default-constructed by the registry.
EventLog* gLog = nullptr;

template <const char* Tag>
class TaggedScene : public Scene {
protected:
    void onInitialize() override {
        gLog->add(Tag, "sceneInit");
        e2d::core::GameObject& object = createGameObject();
        object.addComponent<Recorder>(*gLog, std::string(Tag) + "Object");
    }
    void onTerminate() override { gLog->add(Tag, "sceneTerm"); }
};

constexpr char kMenu[] = "menu";
constexpr char kLevel[] = "level";
using MenuScene = TaggedScene<kMenu>;
using LevelScene = TaggedScene<kLevel>;

class ClearCounter : public System {
public:
    void clear() override { gLog->add("system", "clear"); }
};

class SceneDirectorTest : public testing::Test {
protected:
    SceneDirectorTest()
        : logger(LogLevel::Trace,
                 [this](LogLevel level, std::string_view message) {
                     if (level >= LogLevel::Warning) {
                         problems.emplace_back(message);
                     }
                 }),
          director(registry, logger) {
        gLog = &log;
        registry.add<MenuScene>("Menu");
        registry.add<LevelScene>("Level");
        director.addSystem(system);
    }
    ~SceneDirectorTest() override { gLog = nullptr; }

    EventLog log;
    std::vector<std::string> problems;
    Logger logger;
    SceneRegistry registry;
    ClearCounter system;
    SceneDirector director;
};

} // namespace

TEST_F(SceneDirectorTest, StartCreatesAndInitialisesTheScene) {
    EXPECT_EQ(director.scene(), nullptr);
    EXPECT_TRUE(director.start("Menu"));
    ASSERT_NE(director.scene(), nullptr);
    EXPECT_EQ(director.sceneName(), "Menu");
    EXPECT_EQ(director.scene()->host(), &director);
    // No clear() on the first start: there was no previous scene.
    EXPECT_THAT(log.events, ElementsAre("menu:sceneInit", "menuObject:added", "menuObject:init"));
}

TEST_F(SceneDirectorTest, ChangeHappensOnApplyAndTerminatesTheOldSceneThenClearsSystems) {
    director.start("Menu");
    log.clear();
    director.scene()->changeToScene("Level");
    EXPECT_EQ(director.sceneName(), "Menu"); // not yet
    ASSERT_TRUE(director.pendingChange().has_value());
    EXPECT_EQ(*director.pendingChange(), "Level");

    EXPECT_TRUE(director.applyPendingChange());
    EXPECT_EQ(director.sceneName(), "Level");
    EXPECT_FALSE(director.pendingChange().has_value());
    EXPECT_THAT(log.events, ElementsAre("menu:sceneTerm", "menuObject:term", "menuObject:destroyed",
                                        "system:clear", "level:sceneInit", "levelObject:added",
                                        "levelObject:init"));
    EXPECT_FALSE(director.applyPendingChange()); // nothing pending any more
}

TEST_F(SceneDirectorTest, UnknownSceneIsLoggedAndTheCurrentOneKept) {
    director.start("Menu");
    Scene* menu = director.scene();
    log.clear();
    director.changeToScene("Nowhere");
    EXPECT_FALSE(director.applyPendingChange());
    EXPECT_EQ(director.scene(), menu);
    EXPECT_THAT(log.events, IsEmpty()); // no terminate, no clear
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0], "core::SceneDirector: unknown scene 'Nowhere', keeping scene 'Menu'");
    EXPECT_FALSE(director.pendingChange().has_value());
}

TEST_F(SceneDirectorTest, UnknownFirstSceneFails) {
    EXPECT_FALSE(director.start("Nowhere"));
    EXPECT_EQ(director.scene(), nullptr);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_THAT(problems[0], HasSubstr("unknown scene 'Nowhere', no scene is running"));
}

TEST_F(SceneDirectorTest, LastRequestWinsAndSameNameRestarts) {
    director.start("Menu");
    Scene* first = director.scene();
    director.changeToScene("Level");
    director.changeToScene("Menu");
    log.clear();
    EXPECT_TRUE(director.applyPendingChange());
    EXPECT_EQ(director.sceneName(), "Menu");
    EXPECT_THAT(log.events, ElementsAre("menu:sceneTerm", "menuObject:term", "menuObject:destroyed",
                                        "system:clear", "menu:sceneInit", "menuObject:added",
                                        "menuObject:init"));
    static_cast<void>(first); // the old instance is gone; only its events are checked
}

TEST_F(SceneDirectorTest, StopTerminatesTheScene) {
    director.start("Level");
    log.clear();
    director.stop();
    EXPECT_EQ(director.scene(), nullptr);
    EXPECT_EQ(director.sceneName(), "");
    EXPECT_THAT(log.events,
                ElementsAre("level:sceneTerm", "levelObject:term", "levelObject:destroyed"));
}

TEST_F(SceneDirectorTest, HostServices) {
    director.start("Menu");
    director.setWindowSize({640, 480});
    director.setReferenceWindowSize({320, 240});
    Scene& scene = *director.scene();
    EXPECT_EQ(scene.windowWidth(), 640);
    EXPECT_EQ(scene.referenceWindowHeight(), 240);
    EXPECT_EQ(scene.logger(), &logger);
    EXPECT_FALSE(director.terminateRequested());
    scene.terminateGame();
    EXPECT_TRUE(director.terminateRequested());
}

TEST_F(SceneDirectorTest, SystemsAreRegisteredOnce) {
    EXPECT_THAT(std::vector<System*>(director.systems().begin(), director.systems().end()),
                ElementsAre(&system));
    EXPECT_THROW(director.addSystem(system), e2d::core::Error);
}

namespace {
class OtherSystem : public System {};
} // namespace

TEST_F(SceneDirectorTest, ScenesFindTheirSystemsByType) {
    director.start("Menu");
    Scene& scene = *director.scene();
    EXPECT_EQ(scene.findSystem<ClearCounter>(), &system);
    EXPECT_EQ(&scene.system<ClearCounter>(), &system);
    EXPECT_EQ(scene.findSystem<OtherSystem>(), nullptr);
    try {
        static_cast<void>(scene.system<OtherSystem>());
        FAIL() << "system<OtherSystem>() did not throw";
    } catch (const e2d::core::Error& error) {
        EXPECT_THAT(error.what(), HasSubstr("core::Scene::system(): no system of type"));
        EXPECT_THAT(error.what(), HasSubstr("OtherSystem"));
    }
    Scene hostless;
    EXPECT_EQ(hostless.findSystem<ClearCounter>(), nullptr);
    EXPECT_THROW(static_cast<void>(hostless.system<ClearCounter>()), e2d::core::Error);
}

TEST_F(SceneDirectorTest, IdKeptFromThePreviousSceneIsRefusedByTheNextOne) {
    director.start("Menu");
    ASSERT_EQ(director.scene()->gameObjects().size(), 1u);
    const e2d::core::GameObjectId kept = director.scene()->gameObjects()[0]->id();
    director.changeToScene("Level");
    director.applyPendingChange();
    Scene& level = *director.scene();
    // The level's first object has the same slot and generation as the menu's did...
    ASSERT_EQ(level.gameObjects().size(), 1u);
    const e2d::core::GameObjectId fresh = level.gameObjects()[0]->id();
    EXPECT_EQ(fresh.index(), kept.index());
    EXPECT_EQ(fresh.generation, kept.generation);
    // ...but the old id is refused like a stale one.
    EXPECT_NE(fresh, kept);
    EXPECT_EQ(level.find(kept), nullptr);
    EXPECT_FALSE(level.destroyGameObject(kept));
    EXPECT_FALSE(level.gameObjects()[0]->isPendingDestroy());
    EXPECT_EQ(level.find(fresh), level.gameObjects()[0]);
}

namespace {
// Looks its system up in its constructor, before the director has attached itself as host.
class EagerScene : public Scene {
public:
    EagerScene() { static_cast<void>(system<ClearCounter>()); }
};
} // namespace

TEST_F(SceneDirectorTest, SystemLookupInASceneConstructorBlamesTheMissingHostNotTheSystem) {
    registry.add<EagerScene>("Eager");
    try {
        director.start("Eager");
        FAIL() << "system<ClearCounter>() in the constructor did not throw";
    } catch (const e2d::core::Error& error) {
        // The system is registered: the message must not say it is missing.
        EXPECT_THAT(error.what(), testing::Not(HasSubstr("no system of type")));
        EXPECT_THAT(error.what(), HasSubstr("core::Scene::system(): the scene has no host yet"));
        EXPECT_THAT(error.what(), HasSubstr("ClearCounter"));
        EXPECT_THAT(error.what(), HasSubstr("onInitialize()"));
    }
}
