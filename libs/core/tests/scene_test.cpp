// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>

#include "test_support.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

using e2d::core::Component;
using e2d::core::Error;
using e2d::core::GameObject;
using e2d::core::GameObjectId;
using e2d::core::Scene;
using e2d::core::test::EventLog;
using e2d::core::test::Ping;
using e2d::core::test::Pong;
using e2d::core::test::Recorder;
using e2d::core::test::TestHost;
using testing::ElementsAre;
using testing::HasSubstr;
using testing::IsEmpty;
using testing::ThrowsMessage;

namespace {

// A scene that records its own events, and builds two objects in onInitialize.
class RecordingScene : public Scene, public e2d::core::Handles<Ping> {
public:
    explicit RecordingScene(EventLog& log) : log_(log) {}
    GameObject* first = nullptr;
    GameObject* second = nullptr;

protected:
    void onInitialize() override {
        log_.add("scene", "init");
        first = &createGameObject();
        first->addComponent<Recorder>(log_, "a1");
        first->addComponent<Recorder>(log_, "a2");
        second = &createGameObject();
        second->addComponent<Recorder>(log_, "b1");
    }
    void onTerminate() override { log_.add("scene", "term"); }
    void update(double) override { log_.add("scene", "update"); }
    void fixedUpdate(double) override { log_.add("scene", "fixed"); }
    void on(const Ping&) override { log_.add("scene", "ping"); }

private:
    EventLog& log_;
};

} // namespace

TEST(Scene, ObjectsCreatedInOnInitializeJoinAtOnce) {
    EventLog log;
    RecordingScene scene(log);
    scene.dispatchInitialize();
    EXPECT_THAT(log.events, ElementsAre("scene:init", "a1:added", "a2:added", "b1:added", "a1:init",
                                        "a2:init", "b1:init"));
    EXPECT_THAT(scene.gameObjects(), ElementsAre(scene.first, scene.second));
    EXPECT_TRUE(scene.first->isInitialized());
}

TEST(Scene, EventsGoSceneFirstThenObjectsThenComponentsInOrder) {
    EventLog log;
    RecordingScene scene(log);
    scene.dispatchInitialize();
    log.clear();
    scene.dispatchFixedUpdate(0.01);
    scene.dispatchUpdate(0.02);
    scene.dispatch(Ping{32});
    EXPECT_THAT(log.events, ElementsAre("scene:fixed", "a1:fixed", "a2:fixed", "b1:fixed",     //
                                        "scene:update", "a1:update", "a2:update", "b1:update", //
                                        "scene:ping", "a1:ping", "a2:ping", "b1:ping"));
}

TEST(Scene, AnEventReachesTheSceneThenOnlyTheComponentsThatHandleItsType) {
    struct Both : Component, e2d::core::Handles<Ping, Pong> {
        explicit Both(std::vector<std::string>& s) : seen(s) {}
        std::vector<std::string>& seen;
        void on(const Ping& p) override { seen.push_back("both:ping" + std::to_string(p.value)); }
        void on(const Pong& p) override { seen.push_back("both:pong" + std::to_string(p.value)); }
    };
    // Two Handles bases on one class share one table.
    struct Split : Component, e2d::core::Handles<Pong>, e2d::core::Handles<Ping> {
        explicit Split(std::vector<std::string>& s) : seen(s) {}
        std::vector<std::string>& seen;
        void on(const Ping& p) override { seen.push_back("split:ping" + std::to_string(p.value)); }
        void on(const Pong& p) override { seen.push_back("split:pong" + std::to_string(p.value)); }
    };
    struct PongOnly : Component, e2d::core::Handles<Pong> {
        explicit PongOnly(std::vector<std::string>& s) : seen(s) {}
        std::vector<std::string>& seen;
        void on(const Pong& p) override { seen.push_back("pong:" + std::to_string(p.value)); }
    };
    struct PongScene : Scene, e2d::core::Handles<Pong> {
        explicit PongScene(std::vector<std::string>& s) : seen(s) {}
        std::vector<std::string>& seen;
        void on(const Pong& p) override { seen.push_back("scene:pong" + std::to_string(p.value)); }
    };
    std::vector<std::string> seen;
    PongScene scene(seen);
    GameObject& first = scene.createGameObject();
    first.addComponent<PongOnly>(seen);
    first.addComponent<Component>(); // handles nothing
    GameObject& second = scene.createGameObject();
    second.addComponent<Both>(seen);
    scene.beginFrame();
    // Attached later, but its object came first: delivered in object order, then attachment.
    first.addComponent<Split>(seen);
    scene.beginFrame();

    scene.dispatch(Ping{1});
    scene.dispatch(Pong{2});
    EXPECT_THAT(seen, ElementsAre("split:ping1", "both:ping1", //
                                  "scene:pong2", "pong:2", "split:pong2", "both:pong2"));

    // A removed component and a destroyed object receive nothing any more.
    seen.clear();
    first.removeComponent(first.getComponent<PongOnly>());
    scene.destroyGameObject(second);
    scene.beginFrame();
    scene.dispatch(Pong{3});
    EXPECT_THAT(seen, ElementsAre("scene:pong3", "split:pong3"));
}

TEST(Scene, AnObjectsOwnEventReachesItsHandlingComponentsOnly) {
    struct Counter : Component, e2d::core::Handles<Ping> {
        int pings = 0;
        int last = 0;
        void on(const Ping& p) override {
            ++pings;
            last = p.value;
        }
    };
    Scene scene;
    GameObject& o = scene.createGameObject();
    GameObject& other = scene.createGameObject();
    auto* a = o.addComponent<Counter>();
    o.addComponent<Component>();
    auto* b = o.addComponent<Counter>();
    auto* elsewhere = other.addComponent<Counter>();
    scene.beginFrame();
    o.dispatch(Ping{7});
    o.setActive(false); // an object's own events (collisions) reach it even while inactive
    o.dispatch(Ping{8});
    EXPECT_EQ(a->pings, 2);
    EXPECT_EQ(b->pings, 2);
    EXPECT_EQ(a->last, 8);
    EXPECT_EQ(elsewhere->pings, 0);
}

TEST(Scene, UpdateReachesOverridesInheritedFromAnIntermediateClass) {
    struct Moving : Component {
        int updates = 0;
        int steps = 0;
        void update(double) override { ++updates; }
        void fixedUpdate(double) override { ++steps; }
    };
    struct Ship : Moving {}; // inherits both
    Scene scene;
    auto* ship = scene.createGameObject().addComponent<Ship>();
    scene.createGameObject().addComponent<Component>();
    scene.beginFrame();
    scene.dispatchUpdate(0.1);
    scene.dispatchFixedUpdate(0.1);
    scene.dispatchFixedUpdate(0.1);
    EXPECT_EQ(ship->updates, 1);
    EXPECT_EQ(ship->steps, 2);
}

TEST(Scene, CreatedObjectJoinsAtTheStartOfTheNextFrame) {
    EventLog log;
    Scene scene;
    GameObject& o = scene.createGameObject();
    o.addComponent<Recorder>(log, "r");
    EXPECT_THAT(scene.gameObjects(), IsEmpty());
    EXPECT_EQ(scene.find(o.id()), &o); // findable while waiting
    EXPECT_FALSE(o.isInitialized());
    scene.dispatchUpdate(0.1);
    EXPECT_THAT(log.events, IsEmpty());
    scene.beginFrame();
    EXPECT_THAT(scene.gameObjects(), ElementsAre(&o));
    EXPECT_THAT(log.events, ElementsAre("r:added", "r:init"));
}

namespace {

// From inside update(): spawns an object (with a Recorder) on the first frame and destroys
// its own object on the second.
class Spawner : public Component {
public:
    explicit Spawner(EventLog& log) : log_(log) {}
    void update(double) override {
        ++frame;
        if (frame == 1) {
            GameObject& spawned = scene()->createGameObject();
            spawned.addComponent<Recorder>(log_, "spawned");
            spawnedId = spawned.id();
        } else if (frame == 2) {
            scene()->destroyGameObject(*gameObject());
            scene()->destroyGameObject(*gameObject()); // twice is harmless
        }
    }
    int frame = 0;
    GameObjectId spawnedId;

private:
    EventLog& log_;
};

} // namespace

TEST(Scene, CreateAndDestroyFromInsideUpdateAreDeferred) {
    EventLog log;
    Scene scene;
    GameObject& host = scene.createGameObject();
    auto* spawner = host.addComponent<Spawner>(log);
    host.addComponent<Recorder>(log, "host");
    scene.beginFrame();
    log.clear();

    scene.dispatchUpdate(0.1); // spawns
    EXPECT_EQ(scene.gameObjects().size(), 1u);
    EXPECT_THAT(log.events, ElementsAre("host:update"));
    log.clear();

    scene.beginFrame();
    EXPECT_EQ(scene.gameObjects().size(), 2u);
    EXPECT_THAT(log.events, ElementsAre("spawned:added", "spawned:init"));
    log.clear();

    const GameObjectId hostId = host.id();
    const GameObjectId spawnedId = spawner->spawnedId; // spawner dies with its object
    scene.dispatchUpdate(0.1); // destroys its own object: it still finishes this frame
    EXPECT_THAT(log.events, ElementsAre("host:update", "spawned:update"));
    EXPECT_TRUE(host.isPendingDestroy());
    EXPECT_EQ(scene.find(hostId), &host);
    log.clear();

    scene.beginFrame();
    EXPECT_THAT(log.events, ElementsAre("host:term", "host:destroyed"));
    EXPECT_EQ(scene.find(hostId), nullptr);
    EXPECT_NE(scene.find(spawnedId), nullptr);
    EXPECT_EQ(scene.gameObjects().size(), 1u);
}

TEST(Scene, DestroyingAParentDestroysItsChildrenParentsFirst) {
    EventLog log;
    Scene scene;
    GameObject& root = scene.createGameObject();
    GameObject& child = scene.createGameObject();
    GameObject& grandchild = scene.createGameObject();
    GameObject& bystander = scene.createGameObject();
    GameObject& sibling = scene.createGameObject();
    root.addChild(child);
    child.addChild(grandchild);
    bystander.addChild(sibling);
    root.addComponent<Recorder>(log, "root");
    child.addComponent<Recorder>(log, "child");
    grandchild.addComponent<Recorder>(log, "grandchild");
    bystander.addComponent<Recorder>(log, "bystander");
    scene.beginFrame();
    log.clear();

    const GameObjectId ids[] = {root.id(), child.id(), grandchild.id()};
    scene.destroyGameObject(child); // also covered by the root's destruction
    EXPECT_TRUE(scene.destroyGameObject(root.id()));
    scene.beginFrame();

    // All terminations first (everything still intact), then the destructions.
    EXPECT_THAT(log.events,
                ElementsAre("child:term", "grandchild:term", "root:term", "child:destroyed",
                            "grandchild:destroyed", "root:destroyed"));
    for (const GameObjectId id : ids) {
        EXPECT_EQ(scene.find(id), nullptr);
    }
    EXPECT_THAT(scene.gameObjects(), ElementsAre(&bystander, &sibling));
    EXPECT_THAT(bystander.children(), ElementsAre(&sibling));
}

TEST(Scene, DestroyingAChildDetachesItFromItsParent) {
    Scene scene;
    GameObject& parent = scene.createGameObject();
    GameObject& child = scene.createGameObject();
    parent.addChild(child);
    scene.beginFrame();
    scene.destroyGameObject(child);
    scene.beginFrame();
    EXPECT_THAT(parent.children(), IsEmpty());
    EXPECT_THAT(scene.gameObjects(), ElementsAre(&parent));
}

TEST(Scene, ObjectDestroyedBeforeJoiningGetsNoEvents) {
    EventLog log;
    Scene scene;
    GameObject& o = scene.createGameObject();
    o.addComponent<Recorder>(log, "r");
    const GameObjectId id = o.id();
    scene.destroyGameObject(o);
    scene.beginFrame();
    EXPECT_THAT(log.events, ElementsAre("r:destroyed"));
    EXPECT_EQ(scene.find(id), nullptr);
    EXPECT_THAT(scene.gameObjects(), IsEmpty());
}

TEST(Scene, StaleIdIsDetectedAfterTheSlotIsReused) {
    Scene scene;
    const GameObjectId old = scene.createGameObject().id();
    EXPECT_FALSE(old.isNull());
    scene.beginFrame();
    EXPECT_TRUE(scene.destroyGameObject(old));
    scene.beginFrame();

    GameObject& reuser = scene.createGameObject();
    EXPECT_EQ(reuser.id().index(), old.index());       // same slot...
    EXPECT_NE(reuser.id().generation, old.generation); // ...new generation
    EXPECT_EQ(scene.find(old), nullptr);
    EXPECT_EQ(scene.find(reuser.id()), &reuser);
    EXPECT_FALSE(scene.destroyGameObject(old));
    EXPECT_FALSE(reuser.isPendingDestroy());
}

TEST(Scene, NullAndOutOfRangeIdsFindNothing) {
    Scene scene;
    scene.createGameObject();
    EXPECT_TRUE(GameObjectId{}.isNull());
    EXPECT_EQ(scene.find(GameObjectId{}), nullptr);
    EXPECT_EQ(scene.find(GameObjectId{57, 1, scene.tag()}), nullptr);
    EXPECT_FALSE(scene.destroyGameObject(GameObjectId{}));
}

TEST(Scene, IdOfAnotherSceneIsRefused) {
    TestHost host;
    Scene one;
    one.attachHost(&host, "one");
    const GameObjectId early = one.createGameObject().id(); // created before the next scene's host
    Scene two;
    GameObject& before = two.createGameObject(); // retagged by attachHost
    two.attachHost(&host, "two");
    EXPECT_NE(one.tag(), two.tag());
    EXPECT_EQ(early.index(), before.id().index());
    EXPECT_EQ(early.generation, before.id().generation);
    EXPECT_EQ(two.find(early), nullptr);
    EXPECT_FALSE(two.destroyGameObject(early));
    EXPECT_EQ(two.find(before.id()), &before);
    EXPECT_NE(one.find(early), nullptr);

    Scene bare; // no host: a tag of its own all the same
    EXPECT_NE(bare.tag(), 0u);
    EXPECT_EQ(bare.find(bare.createGameObject().id())->scene().tag(), bare.tag());
    EXPECT_EQ(bare.find(early), nullptr);
}

TEST(Scene, DestroyRejectsObjectsOfAnotherScene) {
    Scene one;
    Scene two;
    GameObject& stranger = two.createGameObject();
    EXPECT_THAT([&] { one.destroyGameObject(stranger); },
                ThrowsMessage<Error>(
                    "core::Scene::destroyGameObject(): object 0 belongs to another scene"));
}

TEST(Scene, TerminateCallsOnTerminateEverywhereAndInvalidatesIds) {
    EventLog log;
    RecordingScene scene(log);
    scene.dispatchInitialize();
    GameObject& late = scene.createGameObject(); // never joined: no onTerminate
    late.addComponent<Recorder>(log, "late");
    const GameObjectId ids[] = {scene.first->id(), scene.second->id(), late.id()};
    log.clear();

    scene.dispatchTerminate();
    EXPECT_THAT(log.events,
                ElementsAre("scene:term", "a1:term", "a2:term", "b1:term", "a1:destroyed",
                            "a2:destroyed", "b1:destroyed", "late:destroyed"));
    for (const GameObjectId id : ids) {
        EXPECT_EQ(scene.find(id), nullptr);
    }
    EXPECT_THAT(scene.gameObjects(), IsEmpty());
}

TEST(Scene, BeginFrameFromInsideAnEventIsRefused) {
    struct Reentrant : Component {
        std::string error;
        void update(double) override {
            try {
                scene()->beginFrame();
            } catch (const Error& e) {
                error = e.what();
            }
        }
    };
    Scene scene;
    scene.attachHost(nullptr, "Level1");
    auto* r = scene.createGameObject().addComponent<Reentrant>();
    scene.beginFrame();
    scene.dispatchUpdate(0.0);
    EXPECT_EQ(r->error, "core::Scene::beginFrame(): called from inside an event of scene 'Level1'");
}

TEST(Scene, HostServices) {
    TestHost host;
    Scene scene;
    scene.attachHost(&host, "Menu");
    EXPECT_EQ(scene.name(), "Menu");
    EXPECT_EQ(scene.host(), &host);
    EXPECT_EQ(scene.logger(), &host.logger());
    EXPECT_EQ(scene.windowWidth(), 800);
    EXPECT_EQ(scene.windowHeight(), 600);
    EXPECT_EQ(scene.referenceWindowWidth(), 1024);
    EXPECT_EQ(scene.referenceWindowHeight(), 624);
    scene.changeToScene("Level2");
    EXPECT_EQ(host.requestedScene, "Level2");
    scene.terminateGame();
    EXPECT_TRUE(host.terminateRequested);
}

TEST(Scene, HostServicesWithoutAHostThrow) {
    Scene scene;
    EXPECT_EQ(scene.logger(), nullptr);
    EXPECT_THAT(
        [&] { scene.changeToScene("X"); },
        ThrowsMessage<Error>("core::Scene::changeToScene(): the scene has no host attached"));
    EXPECT_THAT([&] { scene.terminateGame(); }, ThrowsMessage<Error>(HasSubstr("terminateGame()")));
    EXPECT_THAT([&] { (void)scene.windowWidth(); },
                ThrowsMessage<Error>(HasSubstr("windowWidth()")));
}

TEST(Scene, ComponentsAddedToALiveObjectAreInitialisedOnAttach) {
    EventLog log;
    Scene scene;
    GameObject& o = scene.createGameObject();
    scene.beginFrame();
    o.addComponent<Recorder>(log, "late");
    scene.beginFrame();
    EXPECT_THAT(log.events, ElementsAre("late:added", "late:init"));
}

TEST(Scene, QueuedComponentsOfADestroyedObjectAreDroppedWithIt) {
    EventLog log;
    Scene scene;
    GameObject& o = scene.createGameObject();
    GameObject& other = scene.createGameObject();
    scene.beginFrame();
    o.addComponent<Recorder>(log, "queued");
    other.addComponent<Recorder>(log, "survivor");
    scene.destroyGameObject(o);
    scene.beginFrame();
    EXPECT_THAT(log.events, ElementsAre("queued:destroyed", "survivor:added", "survivor:init"));
    log.clear();
    scene.beginFrame(); // nothing left queued
    EXPECT_THAT(log.events, IsEmpty());
}

TEST(Scene, ComponentAddedToAJoiningObjectDuringInitialisationIsInitialisedWithIt) {
    EventLog log;
    struct Helper : Component {
        EventLog* log = nullptr;
        GameObject* target = nullptr;
        void onInitialize() override { target->addComponent<Recorder>(*log, "gift"); }
    };
    Scene scene;
    GameObject& giver = scene.createGameObject();
    scene.beginFrame();
    GameObject& receiver = scene.createGameObject();
    auto* helper = giver.addComponent<Helper>();
    helper->log = &log;
    helper->target = &receiver;
    scene.beginFrame(); // helper attaches (and initialises) before receiver joins
    EXPECT_THAT(log.events, ElementsAre("gift:added", "gift:init"));
    EXPECT_TRUE(receiver.isInitialized());
}

TEST(Scene, InactiveObjectsAndTheirDescendantsGetNoFrameOrInputEvents) {
    EventLog log;
    RecordingScene scene(log);
    scene.dispatchInitialize();
    GameObject& child = scene.createGameObject();
    child.addComponent<Recorder>(log, "c1");
    scene.first->addChild(child);
    scene.beginFrame();
    log.clear();

    scene.first->setActive(false);
    EXPECT_FALSE(scene.first->isActive());
    EXPECT_FALSE(scene.first->isActiveInHierarchy());
    EXPECT_TRUE(child.isActive());
    EXPECT_FALSE(child.isActiveInHierarchy());
    scene.dispatchUpdate(0.02);
    scene.dispatchFixedUpdate(0.01);
    scene.dispatch(Ping{65});
    EXPECT_THAT(log.events, ElementsAre("scene:update", "b1:update", "scene:fixed", "b1:fixed",
                                        "scene:ping", "b1:ping"));

    log.clear();
    scene.first->setActive(true);
    scene.dispatchUpdate(0.02);
    EXPECT_THAT(log.events,
                ElementsAre("scene:update", "a1:update", "a2:update", "b1:update", "c1:update"));
}

TEST(Scene, ObjectsAreFoundByNameAndTag) {
    EventLog log;
    RecordingScene scene(log);
    scene.dispatchInitialize();
    EXPECT_EQ(scene.first->name(), "");
    EXPECT_EQ(scene.first->tag(), "");
    EXPECT_TRUE(scene.first->isActive());
    scene.first->setName("player");
    scene.first->setTag("hero");
    scene.second->setTag("coin");
    GameObject& later = scene.createGameObject(); // not joined yet: still found
    later.setName("player");
    later.setTag("coin");

    EXPECT_EQ(scene.findByName("player"), scene.first);
    EXPECT_EQ(scene.findByName("nobody"), nullptr);
    EXPECT_THAT(scene.findByTag("coin"), ElementsAre(scene.second, &later));
    EXPECT_EQ(scene.findFirstByTag("coin"), scene.second);
    EXPECT_EQ(scene.findFirstByTag("hero"), scene.first);
    EXPECT_THAT(scene.findByTag("enemy"), IsEmpty());
    EXPECT_EQ(scene.findFirstByTag("enemy"), nullptr);

    // Objects waiting to be destroyed are not found.
    scene.destroyGameObject(*scene.first);
    EXPECT_EQ(scene.findByName("player"), &later);
    EXPECT_EQ(scene.findFirstByTag("hero"), nullptr);
    scene.beginFrame();
    EXPECT_EQ(scene.findByName("player"), &later);
    EXPECT_THAT(scene.findByTag("coin"), ElementsAre(scene.second, &later));
}
