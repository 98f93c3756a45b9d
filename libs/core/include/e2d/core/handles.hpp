// SPDX-License-Identifier: MIT
#pragma once

#include <typeindex>
#include <typeinfo>
#include <vector>

namespace e2d::core {

/// Receives events of type `Event`, any small struct a library declares (`input::KeyDown`,
/// `physics::CollisionEnter`, or a game's own). Not used alone: derive from Handles.
template <class Event>
class Handler {
public:
    /// Called once per event, during the dispatch; the event is valid only during the call.
    virtual void on(const Event& event) = 0;

protected:
    Handler() = default;
    ~Handler() = default;
    Handler(const Handler&) = default;
    Handler& operator=(const Handler&) = default;
};

namespace detail {

/// The event types an object handles, with the Handler<E> that takes each. Component and Scene
/// have one (a virtual base, shared with every Handles<...> base of the same class), so the
/// scene reads it once when a component is attached instead of asking every component about
/// every event.
class HandlerTable {
public:
    struct Entry {
        std::type_index event;
        void* handler; // a Handler<E>* for the E of `event`
    };

    [[nodiscard]] const std::vector<Entry>& handledEvents() const noexcept { return handled_; }
    /// The Handler<E> of this object, or nullptr if it does not handle E.
    template <class E>
    [[nodiscard]] Handler<E>* handlerOf() const noexcept {
        for (const Entry& entry : handled_) {
            if (entry.event == typeid(E)) {
                return static_cast<Handler<E>*>(entry.handler);
            }
        }
        return nullptr;
    }

protected:
    HandlerTable() = default;
    ~HandlerTable() = default;
    HandlerTable(const HandlerTable&) = delete;
    HandlerTable& operator=(const HandlerTable&) = delete;

    template <class E>
    void addHandler(Handler<E>* handler) {
        handled_.push_back({typeid(E), handler});
    }

private:
    std::vector<Entry> handled_;
};

} // namespace detail

/// Declares the events a Component (or a Scene) takes, each with one `on` overload:
///
///     class Player : public core::Component, public core::Handles<input::KeyDown, physics::CollisionEnter> {
///         void on(const input::KeyDown& key) override;
///         void on(const physics::CollisionEnter& contact) override;
///     };
///
/// The library that owns an event type delivers it with `Scene::dispatch(event)` (the scene,
/// then every component of an active object that handles it) or `GameObject::dispatch(event)`
/// (that object's components). Only those that handle the type are called: the scene notes the
/// receivers when a component is attached, so an event costs nothing for the others. A class
/// may derive from several Handles; listing the same event twice does not compile.
template <class... Events>
class Handles : public virtual detail::HandlerTable, public Handler<Events>... {
public:
    using Handler<Events>::on...;

protected:
    Handles() { (addHandler<Events>(this), ...); }
    ~Handles() = default;
};

} // namespace e2d::core
