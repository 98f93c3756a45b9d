// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/game_object.hpp>
#include <e2d/core/game_object_id.hpp>
#include <e2d/core/scene_host.hpp>
#include <e2d/core/system.hpp>

#include <glm/vec2.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <typeinfo>
#include <vector>

namespace e2d::core {

class Logger;

/// A level, menu or screen: a set of game objects plus the scene's own event handlers.
///
/// Users derive from Scene and override the protected event methods (all no-ops by default);
/// `onInitialize` is the usual place to create the scene's objects. Register the type in a
/// SceneRegistry so a SceneDirector can create it by name.
///
/// Whoever runs the scene (SceneDirector, or a test) calls the public `dispatch*` methods;
/// each one runs the scene's own handler first, then forwards the event to every game object
/// in creation order (skipping inactive ones, see GameObject::setActive()), which forwards it
/// to its components in attachment order.
///
/// Creation and destruction of game objects are deferred to `beginFrame()`, the start of the
/// next frame, so they are safe from inside any event.
class Scene {
public:
    Scene();
    /// Destroys the remaining objects without sending events; call `dispatchTerminate()`
    /// first for an orderly end.
    virtual ~Scene();
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    // Game objects ------------------------------------------------------------------------

    /// Creates an object owned by this scene. It can be configured and given components at
    /// once; it joins the scene (and receives onInitialize) at the start of the next frame.
    GameObject& createGameObject();
    /// Queues `object` and all its descendants for destruction at the start of the next
    /// frame; each one that was initialised receives onTerminate then. Calling it again is
    /// harmless. Throws core::Error if `object` belongs to another scene.
    void destroyGameObject(GameObject& object);
    /// Same, by id; returns false (and does nothing) for a null or stale id.
    bool destroyGameObject(GameObjectId id);
    /// The object with this id, or nullptr if it was destroyed (or the id is null). Objects
    /// waiting to join or to be destroyed are still found.
    [[nodiscard]] GameObject* find(GameObjectId id) const noexcept;
    /// The first object (in creation order, objects waiting to join included) named `name`,
    /// or nullptr. Objects waiting to be destroyed are skipped.
    [[nodiscard]] GameObject* findByName(std::string_view name) const noexcept;
    /// Every object tagged `tag`, in creation order (objects waiting to join included, those
    /// waiting to be destroyed skipped).
    [[nodiscard]] std::vector<GameObject*> findByTag(std::string_view tag) const;
    /// The first of findByTag(), or nullptr.
    [[nodiscard]] GameObject* findFirstByTag(std::string_view tag) const noexcept;
    /// Objects that joined the scene, in creation order.
    [[nodiscard]] const std::vector<GameObject*>& gameObjects() const noexcept { return objects_; }

    // Host services -----------------------------------------------------------------------

    /// Set by the runner before `dispatchInitialize()`. `name` is the registry name.
    void attachHost(SceneHost* host, std::string name = {});
    [[nodiscard]] SceneHost* host() const noexcept { return host_; }
    [[nodiscard]] const std::string& name() const noexcept { return name_; }
    /// The host's logger, or nullptr without a host.
    [[nodiscard]] Logger* logger() const noexcept;

    /// The first system of the host that is a T (for example `physics::PhysicsSystem`), or
    /// nullptr when there is none or no host. This is how components reach their subsystem:
    /// a component is created with its def alone and looks its system up when it starts.
    template <class T>
    [[nodiscard]] T* findSystem() const noexcept;
    /// Same, but throws core::Error naming the type when there is no such system:
    /// `"core::Scene::system(): no system of type X is registered with the scene's host"`, or
    /// when the scene has no host yet (a scene's constructor runs before its host attaches:
    /// look systems up in onInitialize() or later).
    template <class T>
    [[nodiscard]] T& system() const;

    /// Asks the host to switch to the scene registered as `name` at the start of the next
    /// frame. This and the methods below throw core::Error when no host is attached.
    void changeToScene(std::string_view name);
    /// Asks the host to end the game.
    void terminateGame();
    [[nodiscard]] int windowWidth() const;
    [[nodiscard]] int windowHeight() const;
    [[nodiscard]] int referenceWindowWidth() const;
    [[nodiscard]] int referenceWindowHeight() const;

    // Driving the scene (called by SceneDirector / GameLoop) -------------------------------

    /// Runs onInitialize, then `beginFrame()` so the objects it created join at once.
    void dispatchInitialize();
    /// Applies deferred work, in this order: destroys queued objects (onTerminate on each,
    /// parents before children), attaches and removes queued components of live objects,
    /// then adds queued objects (their components attached, then onInitialize). Work queued
    /// by these events waits for the next call. Throws core::Error if called from inside an
    /// event of this scene.
    void beginFrame();
    void dispatchFixedUpdate(double step);
    void dispatchUpdate(double dt);
    void dispatchButtonDown(int key);
    void dispatchButtonUp(int key);
    void dispatchControllerButtonDown(int controller, int button);
    void dispatchControllerButtonUp(int controller, int button);
    void dispatchMouseButtonDown(int button, glm::vec2 screen, glm::vec2 world);
    void dispatchMouseButtonUp(int button, glm::vec2 screen, glm::vec2 world);
    void dispatchMouseMove(glm::vec2 screen, glm::vec2 world);
    void dispatchKeyDown(int key, int mods);
    void dispatchKeyUp(int key, int mods);
    void dispatchKeyRepeat(int key, int mods);
    void dispatchTextInput(char32_t codepoint);
    void dispatchScroll(glm::vec2 offset, glm::vec2 screen, glm::vec2 world);
    void dispatchFocusChanged(bool focused);
    void dispatchControllerConnected(int controller);
    void dispatchControllerDisconnected(int controller);
    void dispatchControllerAxis(int controller, int axis, float value);
    /// Runs onTerminate on the scene, then on every object (and its components) that was
    /// initialised, then destroys every object: all ids become stale.
    void dispatchTerminate();

protected:
    /// The scene starts: create its objects here.
    virtual void onInitialize() {}
    /// The scene ends (before its objects receive onTerminate).
    virtual void onTerminate() {}
    virtual void update(double dt) { static_cast<void>(dt); }
    virtual void fixedUpdate(double step) { static_cast<void>(step); }
    virtual void onButtonDown(int key) { static_cast<void>(key); }
    virtual void onButtonUp(int key) { static_cast<void>(key); }
    virtual void onControllerButtonDown(int controller, int button) {
        static_cast<void>(controller);
        static_cast<void>(button);
    }
    virtual void onControllerButtonUp(int controller, int button) {
        static_cast<void>(controller);
        static_cast<void>(button);
    }
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
    virtual void onMouseMove(glm::vec2 screen, glm::vec2 world) {
        static_cast<void>(screen);
        static_cast<void>(world);
    }
    /// See the Component events of the same names.
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
    virtual void onTextInput(char32_t codepoint) { static_cast<void>(codepoint); }
    virtual void onScroll(glm::vec2 offset, glm::vec2 screen, glm::vec2 world) {
        static_cast<void>(offset);
        static_cast<void>(screen);
        static_cast<void>(world);
    }
    virtual void onFocusChanged(bool focused) { static_cast<void>(focused); }
    virtual void onControllerConnected(int controller) { static_cast<void>(controller); }
    virtual void onControllerDisconnected(int controller) { static_cast<void>(controller); }
    virtual void onControllerAxis(int controller, int axis, float value) {
        static_cast<void>(controller);
        static_cast<void>(axis);
        static_cast<void>(value);
    }

private:
    friend class GameObject;

    struct Slot {
        std::unique_ptr<GameObject> object;
        std::uint32_t generation = 1;
    };
    class DispatchGuard;

    template <class SceneHandler, class ComponentHandler>
    void broadcast(SceneHandler&& sceneHandler, ComponentHandler&& componentHandler);
    SceneHost& requireHost(const char* function) const;
    [[noreturn]] void throwNoSystem(const std::type_info& type) const;
    void destroyPending();
    void freeSlot(GameObject& object);

    SceneHost* host_ = nullptr;
    std::string name_;
    std::vector<Slot> slots_;
    std::vector<std::uint32_t> freeSlots_;
    std::vector<GameObject*> objects_;
    std::vector<GameObject*> pendingAdd_;
    std::vector<GameObject*> pendingDestroy_;
    std::vector<GameObject*> componentChanges_; // objects with queued component changes
    int dispatchDepth_ = 0;
};

template <class T>
T* Scene::findSystem() const noexcept {
    static_assert(std::is_base_of_v<System, T>, "Scene::findSystem<T>: T must derive from core::System");
    if (host_ == nullptr) {
        return nullptr;
    }
    for (System* system : host_->systems()) {
        if (auto* typed = dynamic_cast<T*>(system)) {
            return typed;
        }
    }
    return nullptr;
}

template <class T>
T& Scene::system() const {
    if (T* found = findSystem<T>()) {
        return *found;
    }
    throwNoSystem(typeid(T));
}

} // namespace e2d::core
