// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/component.hpp>

#include <functional>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace e2d::core {

/// One state of a StateMachine; override what you need (all no-ops by default).
class State {
public:
    State() = default;
    virtual ~State() = default;
    State(const State&) = delete;
    State& operator=(const State&) = delete;

    /// The machine entered this state.
    virtual void onEnter() {}
    /// Once per machine update while this state is current; `dt` in seconds.
    virtual void update(double dt) { static_cast<void>(dt); }
    /// The machine is leaving this state (called before the next state's onEnter).
    virtual void onExit() {}
};

/// A finite state machine that owns its states, with guarded transitions.
///
/// `update(dt)` updates the current state, then checks the current state's transitions in
/// the order they were added; the first whose condition returns true fires: current
/// `onExit()`, then target `onEnter()`. At most one transition fires per update.
class StateMachine {
public:
    /// A transition guard: true means "take this transition now".
    using Condition = std::function<bool()>;

    StateMachine() = default;
    StateMachine(const StateMachine&) = delete;
    StateMachine& operator=(const StateMachine&) = delete;

    /// Constructs a T from `args` and returns it (owned by the machine).
    template <class T, class... Args>
    T& addState(Args&&... args) {
        static_assert(std::is_base_of_v<State, T>, "addState<T>: T must derive from core::State");
        auto state = std::make_unique<T>(std::forward<Args>(args)...);
        T& ref = *state;
        addState(std::move(state));
        return ref;
    }
    /// Takes ownership of `state` (not null, else core::Error) and returns it.
    State& addState(std::unique_ptr<State> state);

    /// Adds a transition from `from` to `to` taken when `condition` returns true. Both states
    /// must belong to this machine and the condition must not be empty (else core::Error).
    /// `from == to` is allowed and re-enters the state (onExit then onEnter).
    void addTransition(State& from, State& to, Condition condition);

    /// Enters `initial` (owned by this machine, else core::Error), exiting the current state
    /// first if there is one.
    void start(State& initial);
    /// Forces a change to `state` (exit current, enter `state`), ignoring conditions.
    void changeState(State& state);
    /// Exits the current state; afterwards there is none and `update()` does nothing.
    void stop();

    /// Updates the current state, then fires the first transition whose condition holds.
    /// Does nothing before `start()`.
    void update(double dt);

    /// The current state, or nullptr before `start()` / after `stop()`.
    [[nodiscard]] State* current() const noexcept { return current_; }
    [[nodiscard]] std::size_t stateCount() const noexcept { return states_.size(); }

private:
    struct Transition {
        State* from;
        State* to;
        Condition condition;
    };

    bool owns(const State& state) const noexcept;
    void enter(State& state);

    std::vector<std::unique_ptr<State>> states_;
    std::vector<Transition> transitions_;
    State* current_ = nullptr;
};

/// A StateMachine attached to a GameObject: it is
/// updated with the object's update event and exits its current state on onTerminate.
/// Build the machine with `machine()` and call `machine().start(...)`.
class StateMachineComponent : public Component {
public:
    [[nodiscard]] StateMachine& machine() noexcept { return machine_; }
    [[nodiscard]] const StateMachine& machine() const noexcept { return machine_; }

    void update(double dt) override { machine_.update(dt); }
    void onTerminate() override { machine_.stop(); }

private:
    StateMachine machine_;
};

} // namespace e2d::core
