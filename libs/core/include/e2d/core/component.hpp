// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/contact_info.hpp>

#include <glm/vec2.hpp>

namespace e2d::core {

class GameObject;
class Scene;

/// Base class of every behaviour attached to a GameObject; override the events you need.
///
/// Events reach components from their GameObject, which gets them from its Scene (scene
/// first, then objects in creation order, then components in the order they were attached).
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
class Component {
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
    /// Once per frame; `dt` is the scaled frame time in seconds.
    virtual void update(double dt) { static_cast<void>(dt); }
    /// Once per fixed step; `step` is the fixed timestep in seconds.
    virtual void fixedUpdate(double step) { static_cast<void>(step); }

    /// A keyboard key was pressed / released (`key` is the input library's key code).
    virtual void onButtonDown(int key) { static_cast<void>(key); }
    virtual void onButtonUp(int key) { static_cast<void>(key); }
    /// A gamepad button was pressed / released.
    virtual void onControllerButtonDown(int controller, int button) {
        static_cast<void>(controller);
        static_cast<void>(button);
    }
    virtual void onControllerButtonUp(int controller, int button) {
        static_cast<void>(controller);
        static_cast<void>(button);
    }
    /// A mouse button was pressed / released at `screen` (pixels) / `world` (world units).
    virtual void onMouseButtonDown(int button, glm::vec2 screen, glm::vec2 world) {
        static_cast<void>(button);
        static_cast<void>(screen);
        static_cast<void>(world);
    }
    virtual void onMouseButtonUp(int button, glm::vec2 screen, glm::vec2 world) {
        static_cast<void>(button);
        static_cast<void>(screen);
        static_cast<void>(world);
    }
    /// The mouse moved to `screen` (pixels) / `world` (world units).
    virtual void onMouseMove(glm::vec2 screen, glm::vec2 world) {
        static_cast<void>(screen);
        static_cast<void>(world);
    }

    /// A key was pressed / released / auto-repeated with modifier bits `mods` (the input
    /// library's, GLFW's: shift 1, control 2, alt 4, super 8, caps lock 16, num lock 32).
    /// A press or release arrives as onButtonDown/onButtonUp(key) first, then as this event.
    virtual void onKeyDown(int key, int mods) {
        static_cast<void>(key);
        static_cast<void>(mods);
    }
    virtual void onKeyUp(int key, int mods) {
        static_cast<void>(key);
        static_cast<void>(mods);
    }
    virtual void onKeyRepeat(int key, int mods) {
        static_cast<void>(key);
        static_cast<void>(mods);
    }
    /// Text was typed: one Unicode code point (UTF-32), after keyboard layout and modifiers.
    virtual void onTextInput(char32_t codepoint) { static_cast<void>(codepoint); }
    /// The mouse wheel (or touchpad) scrolled by `offset` (x horizontal, y vertical; positive y
    /// is away from the user), with the cursor at `screen` (pixels) / `world` (world units).
    virtual void onScroll(glm::vec2 offset, glm::vec2 screen, glm::vec2 world) {
        static_cast<void>(offset);
        static_cast<void>(screen);
        static_cast<void>(world);
    }
    /// The window gained / lost keyboard focus (on loss, every held key and button has
    /// already been released with the usual up events).
    virtual void onFocusChanged(bool focused) { static_cast<void>(focused); }
    /// A gamepad was connected / disconnected (`controller` is its slot, 0-based).
    virtual void onControllerConnected(int controller) { static_cast<void>(controller); }
    virtual void onControllerDisconnected(int controller) { static_cast<void>(controller); }
    /// A gamepad axis changed to `value` (sticks in [-1, 1] after the dead zone, triggers in
    /// [0, 1]).
    virtual void onControllerAxis(int controller, int axis, float value) {
        static_cast<void>(controller);
        static_cast<void>(axis);
        static_cast<void>(value);
    }

    /// The owning object started / stopped touching another collider.
    virtual void onCollisionEnter(const ContactInfo& contact) { static_cast<void>(contact); }
    virtual void onCollisionExit(const ContactInfo& contact) { static_cast<void>(contact); }
    /// Same, when one of the two colliders is a trigger (sensor).
    virtual void onTriggerEnter(const ContactInfo& contact) { static_cast<void>(contact); }
    virtual void onTriggerExit(const ContactInfo& contact) { static_cast<void>(contact); }

    /// Called by the owning object when the component joins / leaves it.
    virtual void onAddedToGameObject() {}
    virtual void onRemovedFromGameObject() {}

private:
    friend class GameObject;
    GameObject* gameObject_ = nullptr;
    // For a component added as a unique type U: tells whether another component is a U.
    bool (*isSameUniqueKind_)(const Component&) = nullptr;
    bool initialized_ = false;
};

} // namespace e2d::core
