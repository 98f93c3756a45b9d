// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/handles.hpp>

#include <cstdint>

namespace e2d::core {

class GameObject;
class Scene;

/// Base class of every behaviour attached to a GameObject.
///
/// Override `update` / `fixedUpdate` for per-frame / per-step work; only components whose
/// class overrides them are called (decided by `addComponent<T>` from T's type). Other events
/// are small structs declared by the library that sends them (`input::KeyDown`,
/// `physics::CollisionEnter`, ...): derive from `Handles<Event...>` as well and override
/// `on(const Event&)` for each (see handles.hpp). Scene-wide events reach the scene first,
/// then objects in creation order, then components in the order they were attached.
///
/// Lifecycle: onAddedToGameObject when it joins its object (start of the frame after
/// `addComponent`), onInitialize once the object is part of the scene (right after being
/// added if it already is), then update/fixedUpdate/input events, then exactly one
/// onTerminate for every onInitialize received (object destroyed, scene ended, or component
/// removed), and onRemovedFromGameObject when `removeComponent` takes it off.
///
/// Uniqueness: a type that may appear at most once per object declares
/// `static constexpr bool kUnique = true;` (derived types inherit it). `addComponent<T>` then
/// refuses a component that is a T when one is already attached or waiting to be added, and
/// any component that is-a U when a component was added as unique type U (so a subclass of a
/// unique Rigidbody cannot sit next to a plain Rigidbody, in either order).
class Component : public virtual detail::HandlerTable {
public:
    /// Components are not unique unless a derived class says so.
    static constexpr bool kUnique = false;

    Component() = default;
    virtual ~Component() = default;
    Component(const Component&) = delete;
    Component& operator=(const Component&) = delete;

    /// The object this component belongs to: set by `GameObject::addComponent`, so it is
    /// already valid while the component waits to be attached (nullptr only for a component
    /// that was never added).
    [[nodiscard]] GameObject* gameObject() const noexcept { return gameObject_; }
    /// The scene of the owning object (nullptr before the component is attached).
    [[nodiscard]] Scene* scene() const noexcept;

    /// The owning object entered the scene (or this component was attached to an object that
    /// already had).
    virtual void onInitialize() {}
    /// The owning object is being destroyed, the scene ends, or this component is removed.
    virtual void onTerminate() {}
    /// Once per frame; `dt` is the scaled frame time in seconds. Called only on components
    /// whose class (or a base between it and Component) overrides it.
    virtual void update(double dt) { static_cast<void>(dt); }
    /// Once per fixed step; `step` is the fixed timestep in seconds. Called only on components
    /// whose class (or a base between it and Component) overrides it.
    virtual void fixedUpdate(double step) { static_cast<void>(step); }

    /// Called by the owning object when the component joins / leaves it.
    virtual void onAddedToGameObject() {}
    virtual void onRemovedFromGameObject() {}

private:
    friend class GameObject;
    friend class Scene;
    GameObject* gameObject_ = nullptr;
    // For a component added as a unique type U: tells whether another component is a U.
    bool (*isSameUniqueKind_)(const Component&) = nullptr;
    bool initialized_ = false;
    // Set by addComponent<T> from T: whether T overrides update / fixedUpdate.
    bool hasUpdate_ = false;
    bool hasFixedUpdate_ = false;
    // The component's place in the scene's delivery order, given when it is attached.
    std::uint64_t deliveryOrder_ = 0;
};

} // namespace e2d::core
