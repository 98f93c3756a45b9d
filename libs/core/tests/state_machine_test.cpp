// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/core/state_machine.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

using e2d::core::Error;
using e2d::core::Scene;
using e2d::core::State;
using e2d::core::StateMachine;
using e2d::core::StateMachineComponent;
using testing::ElementsAre;
using testing::IsEmpty;
using testing::ThrowsMessage;

namespace {

class Traced : public State {
public:
    Traced(std::vector<std::string>& log, std::string name) : log_(log), name_(std::move(name)) {}
    void onEnter() override { log_.push_back(name_ + ".enter"); }
    void update(double dt) override {
        log_.push_back(name_ + ".update");
        time += dt;
    }
    void onExit() override { log_.push_back(name_ + ".exit"); }
    double time = 0.0;

private:
    std::vector<std::string>& log_;
    std::string name_;
};

} // namespace

TEST(StateMachine, StartEntersTheInitialState) {
    std::vector<std::string> log;
    StateMachine machine;
    auto& idle = machine.addState<Traced>(log, "idle");
    EXPECT_EQ(machine.current(), nullptr);
    machine.update(1.0); // not started: nothing happens
    EXPECT_THAT(log, IsEmpty());
    machine.start(idle);
    EXPECT_EQ(machine.current(), &idle);
    EXPECT_THAT(log, ElementsAre("idle.enter"));
}

TEST(StateMachine, TransitionFiresAfterUpdateWithExitBeforeEnter) {
    std::vector<std::string> log;
    StateMachine machine;
    auto& idle = machine.addState<Traced>(log, "idle");
    auto& run = machine.addState<Traced>(log, "run");
    bool moving = false;
    machine.addTransition(idle, run, [&] { return moving; });
    machine.addTransition(run, idle, [&] { return !moving; });
    machine.start(idle);
    log.clear();

    machine.update(0.5);
    EXPECT_EQ(machine.current(), &idle);
    moving = true;
    machine.update(0.5);
    EXPECT_EQ(machine.current(), &run);
    EXPECT_THAT(log, ElementsAre("idle.update", "idle.update", "idle.exit", "run.enter"));
    EXPECT_EQ(idle.time, 1.0);
    log.clear();

    moving = false;
    machine.update(0.25);
    EXPECT_THAT(log, ElementsAre("run.update", "run.exit", "idle.enter"));
}

TEST(StateMachine, FirstTrueConditionInInsertionOrderWinsAndOnlyOneFires) {
    std::vector<std::string> log;
    StateMachine machine;
    auto& a = machine.addState<Traced>(log, "a");
    auto& b = machine.addState<Traced>(log, "b");
    auto& c = machine.addState<Traced>(log, "c");
    std::vector<std::string> checked;
    machine.addTransition(a, c, [&] {
        checked.push_back("a->c");
        return false;
    });
    machine.addTransition(a, b, [&] {
        checked.push_back("a->b");
        return true;
    });
    machine.addTransition(a, c, [&] {
        checked.push_back("a->c again");
        return true;
    });
    machine.addTransition(b, c, [&] {
        checked.push_back("b->c");
        return true;
    });
    machine.start(a);
    machine.update(0.0);
    EXPECT_EQ(machine.current(), &b);
    // b's transition is not looked at in the same update.
    EXPECT_THAT(checked, ElementsAre("a->c", "a->b"));
}

TEST(StateMachine, SelfTransitionReenters) {
    std::vector<std::string> log;
    StateMachine machine;
    auto& s = machine.addState<Traced>(log, "s");
    machine.addTransition(s, s, [] { return true; });
    machine.start(s);
    machine.update(0.0);
    EXPECT_THAT(log, ElementsAre("s.enter", "s.update", "s.exit", "s.enter"));
}

TEST(StateMachine, ChangeStateAndStop) {
    std::vector<std::string> log;
    StateMachine machine;
    auto& a = machine.addState<Traced>(log, "a");
    auto& b = machine.addState<Traced>(log, "b");
    machine.start(a);
    machine.changeState(b);
    machine.stop();
    EXPECT_EQ(machine.current(), nullptr);
    machine.stop(); // nothing to exit
    EXPECT_THAT(log, ElementsAre("a.enter", "a.exit", "b.enter", "b.exit"));
    machine.start(a); // restartable
    EXPECT_EQ(machine.current(), &a);
}

TEST(StateMachine, ChangeFromInsideUpdateSkipsTransitions) {
    std::vector<std::string> log;
    StateMachine machine;
    struct Jumper : State {
        StateMachine* machine = nullptr;
        State* target = nullptr;
        void update(double) override { machine->changeState(*target); }
    };
    auto& jumper = machine.addState<Jumper>();
    auto& target = machine.addState<Traced>(log, "target");
    auto& other = machine.addState<Traced>(log, "other");
    jumper.machine = &machine;
    jumper.target = &target;
    machine.addTransition(jumper, other, [] { return true; });
    machine.start(jumper);
    machine.update(0.0);
    EXPECT_EQ(machine.current(), &target);
    EXPECT_THAT(log, ElementsAre("target.enter"));
}

TEST(StateMachine, RejectsForeignStatesAndEmptyConditions) {
    std::vector<std::string> log;
    StateMachine machine;
    StateMachine other;
    auto& mine = machine.addState<Traced>(log, "mine");
    auto& theirs = other.addState<Traced>(log, "theirs");
    EXPECT_THAT(
        [&] { machine.addTransition(mine, theirs, [] { return true; }); },
        ThrowsMessage<Error>(
            "core::StateMachine::addTransition(): the 'to' state does not belong to this machine"));
    EXPECT_THAT([&] { machine.addTransition(theirs, mine, [] { return true; }); },
                ThrowsMessage<Error>("core::StateMachine::addTransition(): the 'from' state does "
                                     "not belong to this machine"));
    EXPECT_THAT([&] { machine.addTransition(mine, mine, {}); },
                ThrowsMessage<Error>("core::StateMachine::addTransition(): condition is empty"));
    EXPECT_THAT(
        [&] { machine.start(theirs); },
        ThrowsMessage<Error>(
            "core::StateMachine::start(): the initial state does not belong to this machine"));
    EXPECT_THAT([&] { machine.changeState(theirs); },
                ThrowsMessage<Error>(testing::HasSubstr("changeState()")));
    EXPECT_THAT([&] { machine.addState(std::unique_ptr<State>()); },
                ThrowsMessage<Error>("core::StateMachine::addState(): state is null"));
    EXPECT_EQ(machine.current(), nullptr);
    EXPECT_EQ(machine.stateCount(), 1u);
}

TEST(StateMachineComponent, RunsWithItsObjectAndExitsOnTerminate) {
    std::vector<std::string> log;
    Scene scene;
    auto* component = scene.createGameObject().addComponent<StateMachineComponent>();
    StateMachine& machine = component->machine();
    auto& walk = machine.addState<Traced>(log, "walk");
    auto& jump = machine.addState<Traced>(log, "jump");
    machine.addTransition(walk, jump, [&walk] { return walk.time >= 0.5; });
    machine.start(walk);
    scene.beginFrame();

    scene.dispatchUpdate(0.25);
    scene.dispatchUpdate(0.25);
    EXPECT_EQ(machine.current(), &jump);
    scene.dispatchTerminate();
    EXPECT_THAT(log, ElementsAre("walk.enter", "walk.update", "walk.update", "walk.exit",
                                 "jump.enter", "jump.exit"));
}
