// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/component.hpp>
#include <e2d/core/game_object_id.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>

namespace e2d::core {

class Logger;
class Scene;

/// Something that exists in a scene: a transform, a place in a hierarchy and components.
///
/// Created and owned by a Scene (`Scene::createGameObject()`); refer to it across frames by
/// its GameObjectId. Its behaviour is the sum of its components.
///
/// Transform: `position()` (x, y in world units; z orders drawing, as the renderer defines),
/// `scale()` and `orientation()` are relative to the parent (to the world for a root
/// object). Orientation is in radians, counter-clockwise positive with y pointing up. The local matrix is T(position) * R(orientation) * S(scale); the world
/// matrix is parent world * local, cached and recomputed only after something on the path to
/// the root changed.
///
/// Hierarchy: children follow their parent's transform. Reparenting keeps the local transform
/// (so the world transform follows the new parent). Destroying an object destroys its
/// children. Cycles and cross-scene links are refused with core::Error.
///
/// Components: `addComponent` and `removeComponent` are deferred to the start of the next
/// frame (`Scene::beginFrame()`), so they are safe from inside any event, including while the
/// component list is being iterated. The getters see only attached components.
class GameObject {
public:
    GameObject(const GameObject&) = delete;
    GameObject& operator=(const GameObject&) = delete;
    ~GameObject();

    [[nodiscard]] GameObjectId id() const noexcept { return id_; }
    [[nodiscard]] Scene& scene() const noexcept { return *scene_; }
    /// The logger of the scene's host, or nullptr when the scene runs without a host.
    [[nodiscard]] Logger* logger() const noexcept;
    /// True once the object joined its scene and received onInitialize.
    [[nodiscard]] bool isInitialized() const noexcept { return initialized_; }
    /// True after `Scene::destroyGameObject()` until the object is actually destroyed.
    [[nodiscard]] bool isPendingDestroy() const noexcept { return pendingDestroy_; }

    // Name, tag, active ---------------------------------------------------------------------

    /// What the object is called, for `Scene::findByName()`; need not be unique. Default "".
    [[nodiscard]] const std::string& name() const noexcept { return name_; }
    void setName(std::string name) { name_ = std::move(name); }
    /// A category shared by several objects ("enemy", "coin"), for `Scene::findByTag()`.
    /// Default "".
    [[nodiscard]] const std::string& tag() const noexcept { return tag_; }
    void setTag(std::string tag) { tag_ = std::move(tag); }
    /// The object's own active flag. Default true.
    [[nodiscard]] bool isActive() const noexcept { return active_; }
    /// Deactivating an object pauses it and its descendants: their components receive no
    /// update, fixedUpdate or input events (the scene's broadcasts skip them) and renderers
    /// hide them; they stay in the scene, keep their components and still receive onInitialize
    /// and onTerminate. Takes effect at once.
    void setActive(bool active) noexcept { active_ = active; }
    /// Active, and so is every ancestor.
    [[nodiscard]] bool isActiveInHierarchy() const noexcept;

    // Transform ---------------------------------------------------------------------------

    // The setters refuse NaN and infinite values with core::Error naming the object (its
    // name, else its tag, else its index), the setter and the value, so a bad value fails
    // where it is made instead of later in the renderer or physics. The object is unchanged.

    /// Position relative to the parent; z is the draw order. Default (0, 0, 0).
    [[nodiscard]] glm::vec3 position() const noexcept { return position_; }
    void setPosition(glm::vec3 position);
    /// Sets x and y, keeps z.
    void setPosition(glm::vec2 position);
    /// Adds `delta` to x and y.
    void translate(glm::vec2 delta);

    /// Scale relative to the parent. Default (1, 1). Zero and negative scales are allowed
    /// (negative mirrors).
    [[nodiscard]] glm::vec2 scale() const noexcept { return scale_; }
    void setScale(glm::vec2 scale);
    void setScale(float uniform) { setScale(glm::vec2(uniform)); }

    /// Radians, counter-clockwise positive, relative to the parent. Default 0.
    [[nodiscard]] float orientation() const noexcept { return orientation_; }
    void setOrientation(float radians);
    void rotate(float radians);

    /// T(position) * R(orientation) * S(scale).
    [[nodiscard]] const glm::mat4& localTransform() const;
    /// Parent's world transform * local transform (cached).
    [[nodiscard]] const glm::mat4& worldTransform() const;
    /// Translation column of the world transform.
    [[nodiscard]] glm::vec3 worldPosition() const;
    /// Angle of the world x axis in radians, in (-pi, pi], counter-clockwise from +x. Equals
    /// the sum of the orientations up to the root when no object on the way has a negative
    /// or non-uniform scale.
    [[nodiscard]] float worldOrientation() const;
    /// True when the cached world transform is out of date (it is rebuilt on the next read).
    [[nodiscard]] bool isTransformDirty() const noexcept { return worldDirty_; }

    // Where the object is drawn ----------------------------------------------------------

    /// The world transform to draw this frame: what renderers, cameras, labels and debug lines
    /// use, so everything drawn for an object and its children agrees. Changes made during the
    /// scene's fixed steps (fixedUpdate, physics) are drawn between the pose the last step
    /// started from and the current one, at Scene::frameAlpha() (rendering runs between two
    /// steps); changes made anywhere else (update, input events, creation) show at once.
    /// Composed through the parents' render transforms. Equals worldTransform() when nothing
    /// on the way to the root moved during the last step, or with frameAlpha() 1.
    [[nodiscard]] glm::mat4 renderTransform() const;
    /// Translation column of renderTransform().
    [[nodiscard]] glm::vec3 renderPosition() const;
    /// Angle of renderTransform()'s x axis, as worldOrientation().
    [[nodiscard]] float renderOrientation() const;
    /// Draws the object where it is from now on, without the in-between pose of the last step
    /// (for a teleport made inside fixedUpdate; changes outside the steps do this already).
    void snapRenderPose() noexcept;

    // Hierarchy ---------------------------------------------------------------------------

    [[nodiscard]] GameObject* parent() const noexcept { return parent_; }
    [[nodiscard]] const std::vector<GameObject*>& children() const noexcept { return children_; }
    /// Makes `child` a child of this object, taking it from its previous parent. Throws
    /// core::Error if `child` is this object or one of its ancestors, or is in another scene.
    void addChild(GameObject& child);
    /// Makes `child` a root object. Throws core::Error if it is not a child of this object.
    void removeChild(GameObject& child);
    /// `addChild` on `parent`, or detaches from the current parent when `parent` is nullptr.
    void setParent(GameObject* parent);
    /// True if `other` is below this object in the hierarchy (not counting itself).
    [[nodiscard]] bool isAncestorOf(const GameObject& other) const noexcept;

    /// "object 'name'", else "object tagged 'tag'", else "object <index>": how messages
    /// about this object name it.
    [[nodiscard]] std::string describe() const;

    // Components --------------------------------------------------------------------------

    /// Constructs a T from `args` and queues it; it is attached at the start of the next
    /// frame. Returns it (owned by this object), or nullptr when uniqueness forbids it (see
    /// Component; a warning is logged if there is a logger, and a refused component that
    /// had to be constructed for the check is destroyed at once).
    template <class T, class... Args>
    T* addComponent(Args&&... args);

    /// Queues `component` for removal at the start of the next frame (it still receives the
    /// events of the current frame). Removing a component that is still queued for adding
    /// cancels it. Throws core::Error if the component does not belong to this object.
    void removeComponent(Component* component);

    /// First attached component that is a T, or nullptr.
    template <class T>
    [[nodiscard]] T* getComponent() const;
    /// Every attached component that is a T, in attachment order.
    template <class T>
    [[nodiscard]] std::vector<T*> getComponents() const;
    /// First T in the descendants (depth first, children in order; this object excluded).
    template <class T>
    [[nodiscard]] T* getComponentInChildren() const;
    /// Every T in the descendants (depth first; this object excluded).
    template <class T>
    [[nodiscard]] std::vector<T*> getComponentsInChildren() const;

    /// Number of attached components (queued ones not counted).
    [[nodiscard]] std::size_t componentCount() const noexcept { return components_.size(); }

    // Events -----------------------------------------------------------------------------

    /// Delivers `event` to this object's attached components that handle its type (derive
    /// from `Handles<Event>`), in attachment order, active or not: how a library sends an
    /// object its own events (physics: collisions and triggers). See Scene::dispatch() for
    /// scene-wide events.
    template <class Event>
    void dispatch(const Event& event);

private:
    friend class Scene;

    GameObject(Scene& scene, GameObjectId id, std::uint32_t serial);

    // True if an attached (not leaving) or queued (not cancelled) component satisfies it.
    template <class Predicate>
    bool hasConflict(Predicate&& conflicts) const;
    void warnRefusedUnique(const std::type_info& type) const;
    template <class T>
    void collectInChildren(std::vector<T*>& out) const;

    // Tells the scene this object has queued component changes, so beginFrame() visits
    // only such objects.
    void queueComponentChange();
    [[noreturn]] void refuseNonFinite(const char* function, const char* what,
                                      const std::string& value) const;
    void markWorldDirty() const noexcept;
    void notePoseChange() noexcept;
    [[nodiscard]] bool isInterpolated() const noexcept;
    static glm::mat4 composeLocal(glm::vec3 position, float orientation, glm::vec2 scale) noexcept;
    void detachFromParent() noexcept;

    // Called by Scene at the start of a frame and for lifecycle events.
    void applyPendingComponents();
    void initialize();
    void terminate();
    template <class F>
    void forEachComponent(F&& f) {
        for (const auto& component : components_) {
            f(*component);
        }
    }

    Scene* scene_;
    GameObjectId id_;
    std::uint32_t serial_; // creation order in the scene, for the order events are delivered in
    GameObject* parent_ = nullptr;
    std::vector<GameObject*> children_;

    glm::vec3 position_{0.0f};
    glm::vec2 scale_{1.0f};
    float orientation_ = 0.0f;
    mutable glm::mat4 local_{1.0f};
    mutable glm::mat4 world_{1.0f};
    mutable bool localDirty_ = false;
    mutable bool worldDirty_ = false;
    // The local pose when the scene's fixed step number stepStamp_ started, kept by the first
    // change in that step: what renderTransform() draws from.
    glm::vec3 stepStartPosition_{0.0f};
    glm::vec2 stepStartScale_{1.0f};
    float stepStartOrientation_ = 0.0f;
    std::uint64_t stepStamp_ = 0;

    bool initialized_ = false;
    bool pendingDestroy_ = false;
    bool active_ = true;
    std::string name_;
    std::string tag_;
    bool beingDestroyed_ = false; // set by Scene while it destroys a batch
    bool componentChangeQueued_ = false;

    std::vector<std::unique_ptr<Component>> pendingAdd_;
    std::vector<Component*> pendingRemove_;
    // Last member: destroyed first, while the rest of the object is still intact.
    std::vector<std::unique_ptr<Component>> components_;
};

template <class T, class... Args>
T* GameObject::addComponent(Args&&... args) {
    static_assert(std::is_base_of_v<Component, T>,
                  "addComponent<T>: T must derive from core::Component");
    // The common refusal (a T already there) is decided before constructing anything.
    if constexpr (T::kUnique) {
        if (hasConflict([](const Component& c) { return dynamic_cast<const T*>(&c) != nullptr; })) {
            warnRefusedUnique(typeid(T));
            return nullptr;
        }
    }
    auto component = std::make_unique<T>(std::forward<Args>(args)...);
    // A T that is also a subclass of an already-present unique type is only detectable on
    // the object itself.
    const Component& candidate = *component;
    if (hasConflict([&candidate](const Component& c) {
            return c.isSameUniqueKind_ != nullptr && c.isSameUniqueKind_(candidate);
        })) {
        warnRefusedUnique(typeid(T));
        return nullptr;
    }
    T* raw = component.get();
    auto* base = static_cast<Component*>(raw);
    base->gameObject_ = this;
    if constexpr (T::kUnique) {
        base->isSameUniqueKind_ = [](const Component& c) {
            return dynamic_cast<const T*>(&c) != nullptr;
        };
    }
    // &T::update names Component::update unless a class on the way to T declares its own.
    base->hasUpdate_ = !std::is_same_v<decltype(&T::update), void (Component::*)(double)>;
    base->hasFixedUpdate_ = !std::is_same_v<decltype(&T::fixedUpdate), void (Component::*)(double)>;
    pendingAdd_.push_back(std::move(component));
    queueComponentChange();
    return raw;
}

template <class Event>
void GameObject::dispatch(const Event& event) {
    // Indexed: a handler may queue components (attached next frame), never attach them now.
    for (std::size_t i = 0; i < components_.size(); ++i) {
        if (Handler<Event>* handler = components_[i]->template handlerOf<Event>()) {
            handler->on(event);
        }
    }
}

template <class Predicate>
bool GameObject::hasConflict(Predicate&& conflicts) const {
    const auto leaving = [this](const Component* c) {
        return std::find(pendingRemove_.begin(), pendingRemove_.end(), c) != pendingRemove_.end();
    };
    for (const auto& component : components_) {
        if (!leaving(component.get()) && conflicts(*component)) {
            return true;
        }
    }
    for (const auto& component : pendingAdd_) {
        if (!leaving(component.get()) && conflicts(*component)) {
            return true;
        }
    }
    return false;
}

template <class T>
T* GameObject::getComponent() const {
    for (const auto& component : components_) {
        if (auto* found = dynamic_cast<T*>(component.get())) {
            return found;
        }
    }
    return nullptr;
}

template <class T>
std::vector<T*> GameObject::getComponents() const {
    std::vector<T*> found;
    for (const auto& component : components_) {
        if (auto* typed = dynamic_cast<T*>(component.get())) {
            found.push_back(typed);
        }
    }
    return found;
}

template <class T>
T* GameObject::getComponentInChildren() const {
    for (const GameObject* child : children_) {
        if (T* found = child->getComponent<T>()) {
            return found;
        }
        if (T* found = child->getComponentInChildren<T>()) {
            return found;
        }
    }
    return nullptr;
}

template <class T>
void GameObject::collectInChildren(std::vector<T*>& out) const {
    for (const GameObject* child : children_) {
        for (const auto& component : child->components_) {
            if (auto* typed = dynamic_cast<T*>(component.get())) {
                out.push_back(typed);
            }
        }
        child->collectInChildren(out);
    }
}

template <class T>
std::vector<T*> GameObject::getComponentsInChildren() const {
    std::vector<T*> found;
    collectInChildren(found);
    return found;
}

} // namespace e2d::core
