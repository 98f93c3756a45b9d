// SPDX-License-Identifier: MIT
#include <e2d/core/state_machine.hpp>

#include <e2d/core/error.hpp>

#include <algorithm>
#include <string>

namespace e2d::core {

State& StateMachine::addState(std::unique_ptr<State> state) {
    if (!state) {
        throw Error("core::StateMachine::addState(): state is null");
    }
    states_.push_back(std::move(state));
    return *states_.back();
}

bool StateMachine::owns(const State& state) const noexcept {
    return std::any_of(states_.begin(), states_.end(),
                       [&state](const std::unique_ptr<State>& s) { return s.get() == &state; });
}

void StateMachine::addTransition(State& from, State& to, Condition condition) {
    if (!owns(from) || !owns(to)) {
        throw Error(std::string("core::StateMachine::addTransition(): the ") +
                    (owns(from) ? "'to'" : "'from'") + " state does not belong to this machine");
    }
    if (!condition) {
        throw Error("core::StateMachine::addTransition(): condition is empty");
    }
    transitions_.push_back(Transition{&from, &to, std::move(condition)});
}

void StateMachine::enter(State& state) {
    if (current_ != nullptr) {
        current_->onExit();
    }
    current_ = &state;
    current_->onEnter();
}

void StateMachine::start(State& initial) {
    if (!owns(initial)) {
        throw Error(
            "core::StateMachine::start(): the initial state does not belong to this machine");
    }
    enter(initial);
}

void StateMachine::changeState(State& state) {
    if (!owns(state)) {
        throw Error("core::StateMachine::changeState(): the state does not belong to this machine");
    }
    enter(state);
}

void StateMachine::stop() {
    if (current_ != nullptr) {
        State* leaving = current_;
        current_ = nullptr;
        leaving->onExit();
    }
}

void StateMachine::update(double dt) {
    if (current_ == nullptr) {
        return;
    }
    State* updated = current_;
    updated->update(dt);
    // The state's update may itself have changed or stopped the machine; then its
    // transitions no longer apply this update.
    if (current_ != updated) {
        return;
    }
    for (const Transition& transition : transitions_) {
        if (transition.from == updated && transition.condition()) {
            enter(*transition.to);
            return;
        }
    }
}

} // namespace e2d::core
