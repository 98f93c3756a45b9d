// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
#include <e2d/core/scene_registry.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using e2d::core::Error;
using e2d::core::Scene;
using e2d::core::SceneRegistry;
using testing::ElementsAre;
using testing::ThrowsMessage;

namespace {

class MenuScene : public Scene {};
class LevelScene : public Scene {
public:
    LevelScene() { ++constructed; }
    static inline int constructed = 0;
};

} // namespace

TEST(SceneRegistry, CreatesAFreshSceneOfTheRegisteredType) {
    SceneRegistry registry;
    registry.add<LevelScene>("Level");
    const int before = LevelScene::constructed;
    auto a = registry.create("Level");
    auto b = registry.create("Level");
    ASSERT_NE(a, nullptr);
    ASSERT_NE(b, nullptr);
    EXPECT_NE(a.get(), b.get());
    EXPECT_NE(dynamic_cast<LevelScene*>(a.get()), nullptr);
    EXPECT_EQ(LevelScene::constructed, before + 2);
}

TEST(SceneRegistry, UnknownNameGivesNull) {
    SceneRegistry registry;
    registry.add<MenuScene>("Menu");
    EXPECT_EQ(registry.create("menu"), nullptr); // names are case-sensitive
    EXPECT_EQ(registry.create(""), nullptr);
    EXPECT_FALSE(registry.contains("Level"));
    EXPECT_TRUE(registry.contains("Menu"));
}

TEST(SceneRegistry, MacroRegistersUnderTheClassName) {
    SceneRegistry registry;
    E2D_REGISTER_SCENE(registry, MenuScene);
    E2D_REGISTER_SCENE(registry, LevelScene);
    EXPECT_THAT(registry.names(), ElementsAre("LevelScene", "MenuScene"));
    EXPECT_NE(dynamic_cast<MenuScene*>(registry.create("MenuScene").get()), nullptr);
}

TEST(SceneRegistry, CustomFactory) {
    SceneRegistry registry;
    int calls = 0;
    registry.add("Custom", [&calls] {
        ++calls;
        return std::make_unique<MenuScene>();
    });
    EXPECT_NE(registry.create("Custom"), nullptr);
    EXPECT_EQ(calls, 1);
}

TEST(SceneRegistry, RejectsDuplicateEmptyAndNull) {
    SceneRegistry registry;
    registry.add<MenuScene>("Menu");
    EXPECT_THAT([&] { registry.add<LevelScene>("Menu"); },
                ThrowsMessage<Error>(
                    "core::SceneRegistry::add(): a scene named 'Menu' is already registered"));
    EXPECT_THAT([&] { registry.add<MenuScene>(""); },
                ThrowsMessage<Error>("core::SceneRegistry::add(): scene name must not be empty"));
    EXPECT_THAT(
        [&] { registry.add("Null", SceneRegistry::Factory{}); },
        ThrowsMessage<Error>("core::SceneRegistry::add(): factory for scene 'Null' is empty"));
    EXPECT_THAT(registry.names(), ElementsAre("Menu"));
}

TEST(SceneRegistry, FunctionScenesRunTheirFunctionsAtTheirEvents) {
    SceneRegistry registry;
    std::vector<std::string> seen;
    registry.add(
        "Functions",
        e2d::core::SceneFunctions{
            .initialize =
                [&](Scene& s) {
                    seen.push_back(s.createGameObject().isInitialized() ? "init?" : "init");
                },
            .update = [&](Scene&, double dt) { seen.push_back("update " + std::to_string(dt)); },
            .fixedUpdate = [&](Scene&,
                               double step) { seen.push_back("fixed " + std::to_string(step)); },
            .terminate = [&](Scene&) { seen.push_back("terminate"); },
        });
    registry.add("Empty", e2d::core::SceneFunctions{});
    for (int round = 0; round < 2; ++round) {
        std::unique_ptr<Scene> scene = registry.create("Functions");
        ASSERT_NE(scene, nullptr);
        scene->dispatchInitialize();
        EXPECT_EQ(scene->gameObjects().size(), 1u)
            << "the object created in initialize joined the scene";
        scene->dispatchFixedUpdate(0.5);
        scene->dispatchUpdate(0.25);
        scene->dispatchTerminate();
    }
    EXPECT_THAT(seen, ElementsAre("init", "fixed 0.500000", "update 0.250000", "terminate", "init",
                                  "fixed 0.500000", "update 0.250000", "terminate"));
    std::unique_ptr<Scene> empty = registry.create("Empty");
    empty->dispatchInitialize();
    empty->dispatchUpdate(0.25);
    empty->dispatchTerminate();
    EXPECT_THAT([&] { registry.add("Functions", e2d::core::SceneFunctions{}); },
                ThrowsMessage<Error>(
                    "core::SceneRegistry::add(): a scene named 'Functions' is already registered"));
}
