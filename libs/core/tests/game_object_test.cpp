// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>

#include "test_support.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/vec4.hpp>

#include <cmath>
#include <limits>
#include <numbers>

using e2d::core::Component;
using e2d::core::Error;
using e2d::core::GameObject;
using e2d::core::LogLevel;
using e2d::core::Scene;
using e2d::core::test::EventLog;
using e2d::core::test::Recorder;
using e2d::core::test::TestHost;
using testing::ElementsAre;
using testing::HasSubstr;
using testing::ThrowsMessage;

namespace {

constexpr float kHalfPi = std::numbers::pi_v<float> / 2.0f;
constexpr float kEps = 1e-5f;

// World position of a point given in the object's local space.
glm::vec2 toWorld(const GameObject& object, glm::vec2 local) {
    const glm::vec4 p = object.worldTransform() * glm::vec4(local, 0.0f, 1.0f);
    return {p.x, p.y};
}

void expectNear(glm::vec2 actual, glm::vec2 expected) {
    EXPECT_NEAR(actual.x, expected.x, kEps);
    EXPECT_NEAR(actual.y, expected.y, kEps);
}

void expectNear(glm::vec3 actual, glm::vec3 expected) {
    EXPECT_NEAR(actual.x, expected.x, kEps);
    EXPECT_NEAR(actual.y, expected.y, kEps);
    EXPECT_NEAR(actual.z, expected.z, kEps);
}

class Body : public Component {
public:
    static constexpr bool kUnique = true;
};
class SpecialBody : public Body {};
class Tag : public Component {
public:
    explicit Tag(int v) : value(v) {}
    int value;
};

} // namespace

// Transform ------------------------------------------------------------------------------

TEST(GameObjectTransform, DefaultsToIdentity) {
    Scene scene;
    const GameObject& o = scene.createGameObject();
    EXPECT_EQ(o.position(), glm::vec3(0.0f));
    EXPECT_EQ(o.scale(), glm::vec2(1.0f));
    EXPECT_EQ(o.orientation(), 0.0f);
    EXPECT_EQ(o.worldTransform(), glm::mat4(1.0f));
    EXPECT_FALSE(o.isTransformDirty());
}

TEST(GameObjectTransform, RotationIsCounterClockwise) {
    Scene scene;
    GameObject& o = scene.createGameObject();
    o.setOrientation(kHalfPi);
    // +x rotated a quarter turn counter-clockwise (y up) is +y.
    expectNear(toWorld(o, {1.0f, 0.0f}), {0.0f, 1.0f});
    expectNear(toWorld(o, {0.0f, 1.0f}), {-1.0f, 0.0f});
}

TEST(GameObjectTransform, ScaleThenRotateThenTranslate) {
    Scene scene;
    GameObject& o = scene.createGameObject();
    o.setPosition(glm::vec3(10.0f, 20.0f, 3.0f));
    o.setScale(glm::vec2(2.0f, 3.0f));
    o.setOrientation(kHalfPi);
    // (1, 1) scaled -> (2, 3), rotated -> (-3, 2), translated -> (7, 22).
    expectNear(toWorld(o, {1.0f, 1.0f}), {7.0f, 22.0f});
    expectNear(o.worldPosition(), {10.0f, 20.0f, 3.0f});
}

TEST(GameObjectTransform, SettersAndHelpers) {
    Scene scene;
    GameObject& o = scene.createGameObject();
    o.setPosition(glm::vec3(1.0f, 2.0f, 5.0f));
    o.setPosition(glm::vec2(3.0f, 4.0f));
    EXPECT_EQ(o.position(), glm::vec3(3.0f, 4.0f, 5.0f));
    o.translate({1.0f, -1.0f});
    EXPECT_EQ(o.position(), glm::vec3(4.0f, 3.0f, 5.0f));
    o.setScale(2.0f);
    EXPECT_EQ(o.scale(), glm::vec2(2.0f));
    o.setOrientation(0.5f);
    o.rotate(0.25f);
    EXPECT_FLOAT_EQ(o.orientation(), 0.75f);
}

TEST(GameObjectTransform, ChildFollowsParent) {
    Scene scene;
    GameObject& parent = scene.createGameObject();
    GameObject& child = scene.createGameObject();
    parent.addChild(child);
    parent.setPosition(glm::vec2(10.0f, 0.0f));
    parent.setOrientation(kHalfPi);
    parent.setScale(2.0f);
    child.setPosition(glm::vec2(1.0f, 0.0f));
    // Child origin: (1, 0) scaled by 2 -> (2, 0), rotated -> (0, 2), moved -> (10, 2).
    expectNear(glm::vec2(child.worldPosition()), {10.0f, 2.0f});
    // The child's own +x axis is the parent's +y, stretched by 2.
    expectNear(toWorld(child, {1.0f, 0.0f}), {10.0f, 4.0f});
}

TEST(GameObjectTransform, ThreeLevelsComposeAndDirtyPropagates) {
    Scene scene;
    GameObject& a = scene.createGameObject();
    GameObject& b = scene.createGameObject();
    GameObject& c = scene.createGameObject();
    a.addChild(b);
    b.addChild(c);
    a.setPosition(glm::vec3(1.0f, 2.0f, 1.0f));
    a.setScale(2.0f);
    b.setPosition(glm::vec3(3.0f, 0.0f, 0.5f));
    b.setOrientation(kHalfPi);
    c.setPosition(glm::vec3(1.0f, 0.0f, 0.25f));
    // In b: (1, 0) rotated -> (0, 1), + (3, 0) = (3, 1). In a: * 2 = (6, 2), + (1, 2) = (7, 4).
    // z is not scaled (the scale is 2D): 1 + 0.5 + 0.25.
    expectNear(c.worldPosition(), {7.0f, 4.0f, 1.75f});
    EXPECT_FALSE(c.isTransformDirty());

    a.setPosition(glm::vec3(0.0f, 0.0f, 0.0f));
    EXPECT_TRUE(a.isTransformDirty());
    EXPECT_TRUE(b.isTransformDirty());
    EXPECT_TRUE(c.isTransformDirty());
    expectNear(c.worldPosition(), {6.0f, 2.0f, 0.75f});

    // Changing the middle level leaves the top clean.
    b.setOrientation(0.0f);
    EXPECT_FALSE(a.isTransformDirty());
    EXPECT_TRUE(c.isTransformDirty());
    // In b: (1, 0) + (3, 0) = (4, 0); in a: * 2 = (8, 0).
    expectNear(glm::vec2(c.worldPosition()), {8.0f, 0.0f});
}

TEST(GameObjectTransform, WorldOrientationAddsUpTheChain) {
    Scene scene;
    GameObject& a = scene.createGameObject();
    GameObject& b = scene.createGameObject();
    a.addChild(b);
    a.setOrientation(0.5f);
    a.setScale(3.0f);
    b.setOrientation(0.25f);
    EXPECT_NEAR(b.worldOrientation(), 0.75f, kEps);
    // Past a half turn the angle wraps into (-pi, pi]: 2 + 2 = 4 rad is 4 - 2 pi.
    a.setOrientation(2.0f);
    b.setOrientation(2.0f);
    EXPECT_NEAR(b.worldOrientation(), 4.0f - 2.0f * std::numbers::pi_v<float>, kEps);
}

TEST(GameObjectTransform, DirtyReachesGrandchildrenAfterAPartialRead) {
    Scene scene;
    GameObject& a = scene.createGameObject();
    GameObject& b = scene.createGameObject();
    GameObject& c = scene.createGameObject();
    a.addChild(b);
    b.addChild(c);
    c.setPosition(glm::vec2(1.0f, 0.0f));
    expectNear(glm::vec2(c.worldPosition()), {1.0f, 0.0f});
    a.translate({5.0f, 0.0f});
    (void)b.worldTransform(); // b clean again, c must still be dirty
    a.translate({5.0f, 0.0f});
    expectNear(glm::vec2(c.worldPosition()), {11.0f, 0.0f});
}

TEST(GameObjectTransform, ReparentingKeepsTheLocalTransform) {
    Scene scene;
    GameObject& first = scene.createGameObject();
    GameObject& second = scene.createGameObject();
    GameObject& child = scene.createGameObject();
    first.setPosition(glm::vec2(10.0f, 0.0f));
    second.setPosition(glm::vec2(0.0f, 100.0f));
    second.setOrientation(kHalfPi);
    child.setPosition(glm::vec2(1.0f, 0.0f));

    first.addChild(child);
    expectNear(glm::vec2(child.worldPosition()), {11.0f, 0.0f});

    child.setParent(&second); // taken from `first`
    EXPECT_EQ(child.parent(), &second);
    EXPECT_TRUE(first.children().empty());
    EXPECT_THAT(second.children(), ElementsAre(&child));
    expectNear(glm::vec2(child.worldPosition()), {0.0f, 101.0f});

    second.removeChild(child);
    EXPECT_EQ(child.parent(), nullptr);
    expectNear(glm::vec2(child.worldPosition()), {1.0f, 0.0f});

    first.addChild(child);
    child.setParent(nullptr);
    expectNear(glm::vec2(child.worldPosition()), {1.0f, 0.0f});
}

TEST(GameObjectTransform, NonFiniteValuesAreRefusedAtTheSetterNamingTheObject) {
    constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
    constexpr float kInf = std::numeric_limits<float>::infinity();
    Scene scene;
    GameObject& crate = scene.createGameObject();
    crate.setName("crate");
    crate.setPosition(glm::vec3(1.0f, 2.0f, 3.0f));
    crate.setScale(glm::vec2(2.0f, 0.5f));
    crate.setOrientation(0.25f);

    EXPECT_THAT([&] { crate.setPosition(glm::vec2(kNan, 0.0f)); },
                ThrowsMessage<Error>(
                    "core::GameObject::setPosition(): object 'crate' got position (nan, 0); "
                    "it must be finite"));
    EXPECT_THAT([&] { crate.setPosition(glm::vec3(0.0f, 0.0f, -kInf)); },
                ThrowsMessage<Error>(
                    "core::GameObject::setPosition(): object 'crate' got position (0, 0, -inf); "
                    "it must be finite"));
    EXPECT_THAT(
        [&] {
            crate.translate({kInf, 1.0f});
        },
        ThrowsMessage<Error>("core::GameObject::translate(): object 'crate' got delta (inf, 1) "
                             "(new position (inf, 3)); it must be finite"));
    // A scale is reported as a scale, not as a bad rotation further down.
    EXPECT_THAT(
        [&] { crate.setScale(kNan); },
        ThrowsMessage<Error>("core::GameObject::setScale(): object 'crate' got scale (nan, nan); "
                             "it must be finite"));
    EXPECT_THAT([&] { crate.setOrientation(kInf); },
                ThrowsMessage<Error>(
                    "core::GameObject::setOrientation(): object 'crate' got orientation inf; "
                    "it must be finite"));
    EXPECT_THAT([&] { crate.rotate(kNan); },
                ThrowsMessage<Error>(
                    "core::GameObject::rotate(): object 'crate' got angle nan; it must be finite"));
    // Nothing changed.
    expectNear(crate.position(), {1.0f, 2.0f, 3.0f});
    expectNear(crate.scale(), {2.0f, 0.5f});
    EXPECT_FLOAT_EQ(crate.orientation(), 0.25f);
    EXPECT_TRUE(std::isfinite(crate.worldTransform()[3][0]));

    // Without a name the tag names the object, without either its index.
    GameObject& coin = scene.createGameObject();
    coin.setTag("coin");
    EXPECT_THAT(
        [&] {
            coin.setScale({1.0f, kInf});
        },
        ThrowsMessage<Error>(
            HasSubstr("core::GameObject::setScale(): object tagged 'coin' got scale (1, inf)")));
    GameObject& plain = scene.createGameObject();
    EXPECT_THAT([&] { plain.setPosition(glm::vec2(kNan)); },
                ThrowsMessage<Error>(HasSubstr(
                    "core::GameObject::setPosition(): object 2 got position (nan, nan)")));
}

TEST(GameObjectRenderPose, ChangesDuringFixedStepsAreDrawnBetweenStatesAndChildrenFollow) {
    // Moves its object 10 units per fixed step, as a body's write-back does.
    struct Mover : Component {
        void fixedUpdate(double) override { gameObject()->translate({10.0f, 0.0f}); }
    };
    Scene scene;
    GameObject& body = scene.createGameObject();
    body.addComponent<Mover>();
    GameObject& label = scene.createGameObject();
    label.setPosition(glm::vec2{0.0f, 5.0f});
    body.addChild(label);
    GameObject& still = scene.createGameObject();
    still.setPosition(glm::vec2{-3.0f, 0.0f});
    scene.beginFrame();

    scene.dispatchFixedUpdate(0.1); // body 0 -> 10
    scene.setFrameAlpha(0.25);
    expectNear(body.renderPosition(), {2.5f, 0.0f, 0.0f});
    expectNear(label.renderPosition(), {2.5f, 5.0f, 0.0f}); // the child from the same pose
    expectNear(still.renderPosition(), {-3.0f, 0.0f, 0.0f});
    expectNear(body.worldPosition(),
               {10.0f, 0.0f, 0.0f}); // the object itself is where the step put it

    scene.dispatchUpdate(0.1);
    scene.dispatchFixedUpdate(0.1); // 10 -> 20
    scene.dispatchFixedUpdate(0.1); // 20 -> 30: between the last two states only
    scene.setFrameAlpha(0.5);
    expectNear(label.renderPosition(), {25.0f, 5.0f, 0.0f});

    // A frame without a step keeps interpolating the same two states.
    scene.dispatchUpdate(0.1);
    scene.setFrameAlpha(0.75);
    expectNear(body.renderPosition(), {27.5f, 0.0f, 0.0f});

    // Moved outside the steps (update, input): shown at once, children too.
    body.setPosition(glm::vec2{100.0f, 0.0f});
    expectNear(body.renderPosition(), {100.0f, 0.0f, 0.0f});
    expectNear(label.renderPosition(), {100.0f, 5.0f, 0.0f});

    // A step in which it does not move: drawn where it is.
    body.removeComponent(body.getComponent<Mover>());
    scene.beginFrame();
    scene.dispatchFixedUpdate(0.1);
    scene.setFrameAlpha(0.5);
    expectNear(body.renderPosition(), {100.0f, 0.0f, 0.0f});
}

TEST(GameObjectRenderPose, RotationTakesTheShortWayAndAlphaOneIsTheWorldTransform) {
    struct Turner : Component {
        void fixedUpdate(double) override { gameObject()->setOrientation(-3.0f); }
    };
    Scene scene;
    GameObject& o = scene.createGameObject();
    o.setOrientation(3.0f);
    o.addComponent<Turner>();
    scene.beginFrame();
    scene.dispatchFixedUpdate(0.1); // 3 -> -3: 0.28 rad through pi, not 6 rad back
    scene.setFrameAlpha(0.5);
    EXPECT_NEAR(std::abs(o.renderOrientation()), std::numbers::pi_v<float>, 1e-4f);
    scene.setFrameAlpha(1.0);
    EXPECT_EQ(o.renderTransform(), o.worldTransform());
    o.snapRenderPose();
    scene.setFrameAlpha(0.0);
    EXPECT_EQ(o.renderTransform(), o.worldTransform());
}

// Hierarchy ------------------------------------------------------------------------------

TEST(GameObjectHierarchy, RefusesCyclesAndSelf) {
    Scene scene;
    GameObject& a = scene.createGameObject();
    GameObject& b = scene.createGameObject();
    GameObject& c = scene.createGameObject();
    a.addChild(b);
    b.addChild(c);
    EXPECT_TRUE(a.isAncestorOf(c));
    EXPECT_FALSE(c.isAncestorOf(a));
    EXPECT_THAT(
        [&] { c.addChild(a); },
        ThrowsMessage<Error>("core::GameObject::addChild(): object 0 is an ancestor of object 2, "
                             "this would make a cycle"));
    EXPECT_THAT(
        [&] { a.addChild(a); },
        ThrowsMessage<Error>("core::GameObject::addChild(): object 0 cannot be its own child"));
    // Unchanged.
    EXPECT_EQ(a.parent(), nullptr);
    EXPECT_THAT(c.children(), testing::IsEmpty());
    a.addChild(b); // already a child: no-op, no duplicate
    EXPECT_THAT(a.children(), ElementsAre(&b));
}

TEST(GameObjectHierarchy, RefusesOtherScenesAndStrangers) {
    Scene one;
    Scene two;
    GameObject& a = one.createGameObject();
    GameObject& b = one.createGameObject();
    GameObject& stranger = two.createGameObject();
    EXPECT_THAT([&] { a.addChild(stranger); },
                ThrowsMessage<Error>(HasSubstr("belongs to another scene")));
    EXPECT_THAT([&] { a.removeChild(b); },
                ThrowsMessage<Error>(
                    "core::GameObject::removeChild(): object 1 is not a child of object 0"));
}

// Components -----------------------------------------------------------------------------

TEST(GameObjectComponents, AddIsDeferredToTheNextFrame) {
    EventLog log;
    Scene scene;
    GameObject& o = scene.createGameObject();
    auto* r = o.addComponent<Recorder>(log, "r");
    ASSERT_NE(r, nullptr);
    EXPECT_EQ(r->gameObject(), &o);
    EXPECT_EQ(r->scene(), &scene);
    EXPECT_EQ(o.componentCount(), 0u);
    EXPECT_EQ(o.getComponent<Recorder>(), nullptr);
    EXPECT_TRUE(log.events.empty());

    scene.beginFrame();
    EXPECT_EQ(o.getComponent<Recorder>(), r);
    EXPECT_THAT(log.events, ElementsAre("r:added", "r:init"));
}

TEST(GameObjectComponents, GettersFilterByType) {
    Scene scene;
    GameObject& o = scene.createGameObject();
    Tag* one = o.addComponent<Tag>(1);
    Body* body = o.addComponent<Body>();
    Tag* two = o.addComponent<Tag>(2);
    scene.beginFrame();
    EXPECT_EQ(o.getComponent<Tag>(), one);
    EXPECT_THAT(o.getComponents<Tag>(), ElementsAre(one, two));
    EXPECT_THAT(o.getComponents<Component>(), ElementsAre(one, body, two));
    EXPECT_EQ(o.getComponent<SpecialBody>(), nullptr);
    EXPECT_THAT(o.getComponents<SpecialBody>(), testing::IsEmpty());
}

TEST(GameObjectComponents, InChildrenSearchesDescendantsOnly) {
    Scene scene;
    GameObject& root = scene.createGameObject();
    GameObject& child = scene.createGameObject();
    GameObject& grandchild = scene.createGameObject();
    GameObject& child2 = scene.createGameObject();
    root.addChild(child);
    child.addChild(grandchild);
    root.addChild(child2);
    Tag* onRoot = root.addComponent<Tag>(0);
    Tag* onGrandchild = grandchild.addComponent<Tag>(2);
    Tag* onChild2 = child2.addComponent<Tag>(3);
    scene.beginFrame();
    EXPECT_EQ(root.getComponent<Tag>(), onRoot);
    EXPECT_EQ(root.getComponentInChildren<Tag>(), onGrandchild); // depth first
    EXPECT_THAT(root.getComponentsInChildren<Tag>(), ElementsAre(onGrandchild, onChild2));
    EXPECT_EQ(grandchild.getComponentInChildren<Tag>(), nullptr);
}

TEST(GameObjectComponents, UniqueComponentRefusedEvenWhilePending) {
    TestHost host;
    Scene scene;
    scene.attachHost(&host);
    GameObject& o = scene.createGameObject();
    Body* first = o.addComponent<Body>();
    ASSERT_NE(first, nullptr);
    EXPECT_EQ(o.addComponent<Body>(), nullptr);        // first one still pending
    EXPECT_EQ(o.addComponent<SpecialBody>(), nullptr); // a SpecialBody is a Body
    ASSERT_EQ(host.messages.size(), 2u);
    EXPECT_EQ(host.messages[0].first, LogLevel::Warning);
    EXPECT_THAT(host.messages[0].second,
                HasSubstr("core::GameObject::addComponent(): object 0 already has a "
                          "unique component"));
    scene.beginFrame();
    EXPECT_EQ(o.addComponent<Body>(), nullptr); // now attached
    EXPECT_EQ(o.getComponents<Body>().size(), 1u);
    // Non-unique types can repeat.
    EXPECT_NE(o.addComponent<Tag>(1), nullptr);
    EXPECT_NE(o.addComponent<Tag>(2), nullptr);
}

TEST(GameObjectComponents, UniquenessHoldsAcrossSubclassesInBothOrders) {
    Scene scene;
    GameObject& a = scene.createGameObject();
    ASSERT_NE(a.addComponent<SpecialBody>(), nullptr);
    EXPECT_EQ(a.addComponent<Body>(), nullptr); // the SpecialBody is a Body

    GameObject& b = scene.createGameObject();
    ASSERT_NE(b.addComponent<Body>(), nullptr);
    EXPECT_EQ(b.addComponent<SpecialBody>(), nullptr); // would be a second Body
    scene.beginFrame();
    EXPECT_EQ(a.getComponents<Body>().size(), 1u);
    EXPECT_EQ(b.getComponents<Body>().size(), 1u);
}

TEST(GameObjectComponents, UniqueRefusalWithoutALoggerIsSilent) {
    Scene scene; // no host, no logger
    GameObject& o = scene.createGameObject();
    ASSERT_NE(o.addComponent<Body>(), nullptr);
    EXPECT_EQ(o.addComponent<Body>(), nullptr);
}

TEST(GameObjectComponents, UniqueSlotFreedByAPendingRemoval) {
    Scene scene;
    GameObject& o = scene.createGameObject();
    Body* first = o.addComponent<Body>();
    scene.beginFrame();
    o.removeComponent(first);
    Body* second = o.addComponent<Body>();
    ASSERT_NE(second, nullptr);
    scene.beginFrame();
    EXPECT_THAT(o.getComponents<Body>(), ElementsAre(second));
}

TEST(GameObjectComponents, RemoveIsDeferredAndSendsTerminateThenRemoved) {
    EventLog log;
    Scene scene;
    GameObject& o = scene.createGameObject();
    auto* r = o.addComponent<Recorder>(log, "r");
    scene.beginFrame();
    log.clear();

    o.removeComponent(r);
    o.removeComponent(r); // a second request is harmless
    EXPECT_EQ(o.getComponent<Recorder>(), r);
    scene.dispatchUpdate(0.0); // still receives this frame's events
    scene.beginFrame();
    EXPECT_EQ(o.getComponent<Recorder>(), nullptr);
    EXPECT_THAT(log.events, ElementsAre("r:update", "r:term", "r:removed", "r:destroyed"));
}

TEST(GameObjectComponents, RemovingAPendingComponentCancelsIt) {
    EventLog log;
    Scene scene;
    GameObject& o = scene.createGameObject();
    auto* r = o.addComponent<Recorder>(log, "r");
    o.removeComponent(r);
    scene.beginFrame();
    EXPECT_EQ(o.componentCount(), 0u);
    EXPECT_THAT(log.events, ElementsAre("r:destroyed"));
}

TEST(GameObjectComponents, RemoveRejectsForeignOrNullComponents) {
    Scene scene;
    GameObject& a = scene.createGameObject();
    GameObject& b = scene.createGameObject();
    Tag* onB = b.addComponent<Tag>(1);
    EXPECT_THAT(
        [&] { a.removeComponent(onB); },
        ThrowsMessage<Error>(
            "core::GameObject::removeComponent(): the component does not belong to object 0"));
    EXPECT_THAT([&] { a.removeComponent(nullptr); },
                ThrowsMessage<Error>("core::GameObject::removeComponent(): component is null"));
}

namespace {

// Adds a Recorder to its own object and removes `victim` from inside update().
class Mutator : public Component {
public:
    Mutator(EventLog& log, Component* victim) : log_(log), victim_(victim) {}
    void update(double) override {
        ++updates;
        if (updates == 1) {
            gameObject()->addComponent<Recorder>(log_, "late");
            if (victim_ != nullptr) {
                gameObject()->removeComponent(victim_);
            }
        }
    }
    int updates = 0;

private:
    EventLog& log_;
    Component* victim_;
};

} // namespace

TEST(GameObjectComponents, AddAndRemoveFromInsideUpdateAreSafe) {
    EventLog log;
    Scene scene;
    GameObject& o = scene.createGameObject();
    auto* victim = o.addComponent<Recorder>(log, "victim");
    auto* mutator = o.addComponent<Mutator>(log, victim);
    o.addComponent<Recorder>(log, "after");
    scene.beginFrame();
    log.clear();

    scene.dispatchUpdate(0.1);
    // The list did not change during iteration: victim and "after" both updated, "late" not yet.
    EXPECT_THAT(log.events, ElementsAre("victim:update", "after:update"));
    log.clear();

    scene.beginFrame();
    EXPECT_THAT(log.events, ElementsAre("victim:term", "victim:removed", "victim:destroyed",
                                        "late:added", "late:init"));
    log.clear();

    scene.dispatchUpdate(0.1);
    EXPECT_THAT(log.events, ElementsAre("after:update", "late:update"));
    EXPECT_EQ(mutator->updates, 2);
}
