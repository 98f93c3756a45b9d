// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/game_object.hpp>
#include <e2d/core/game_object_id.hpp>
#include <e2d/core/handles.hpp>
#include <e2d/core/scene_host.hpp>
#include <e2d/core/system.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <typeindex>
#include <typeinfo>
#include <vector>

namespace e2d::core {

class Logger;

/// A level, menu or screen: a set of game objects plus the scene's own event handlers.
///
/// Users derive from Scene and override the protected lifecycle methods (all no-ops by
/// default); `onInitialize` is the usual place to create the scene's objects. A scene takes
/// other events as components do, by deriving from `Handles<Event...>` (handles.hpp).
/// Register the type in a SceneRegistry so a SceneDirector can create it by name.
///
/// Whoever runs the scene (SceneDirector, or a test) calls the public `dispatch*` methods;
/// each one runs the scene's own handler first, then reaches the components that take the
/// event, of objects active in the hierarchy (see GameObject::setActive()), in object
/// creation order then attachment order.
///
/// Creation and destruction of game objects are deferred to `beginFrame()`, the start of the
/// next frame, so they are safe from inside any event.
class Scene : public virtual detail::HandlerTable {
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

    /// Set by the runner before `dispatchInitialize()`. `name` is the registry name. Takes a
    /// new tag from the host (SceneHost::nextSceneTag()), also for objects already created.
    void attachHost(SceneHost* host, std::string name = {});
    /// Written into every GameObjectId of this scene; `find()` refuses ids with another tag.
    /// A scene run by a host numbers its scenes 1, 2, 3, ...; a scene without a host has a tag
    /// derived from its address with the top bit set (never 0, no global counter).
    [[nodiscard]] std::uint32_t tag() const noexcept { return tag_; }
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
    /// One fixed step: the scene's fixedUpdate, then the components that override it. Pose
    /// changes from here until the next `dispatchUpdate()` / `beginFrame()` (the systems'
    /// fixed steps included) are drawn interpolated (GameObject::renderTransform()).
    void dispatchFixedUpdate(double step);
    void dispatchUpdate(double dt);
    /// Where between the last two fixed steps this frame is drawn, in [0, 1] (0: the pose the
    /// last step started from, 1: the current one). Set by the loop after the frame's fixed
    /// steps (GameLoop: FixedStepper::alpha()). Default 1: no interpolation.
    void setFrameAlpha(double alpha) noexcept;
    [[nodiscard]] double frameAlpha() const noexcept { return frameAlpha_; }
    /// Delivers `event` (any struct: `input::KeyDown`, a game's own) to the scene if it
    /// handles its type (derives from `Handles<Event>`), then to every attached component that
    /// handles it, of objects active in the hierarchy, in object creation order then
    /// attachment order. Components that do not handle the type are not visited: the scene
    /// lists the receivers of each type when components are attached.
    template <class Event>
    void dispatch(const Event& event);
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

private:
    friend class GameObject;

    struct Slot {
        std::unique_ptr<GameObject> object;
        std::uint32_t generation = 1;
    };
    // Marks the scene as busy dispatching, so beginFrame()/dispatchTerminate() cannot run
    // from inside an event and change the lists being iterated.
    class DispatchGuard {
    public:
        explicit DispatchGuard(Scene& scene) : scene_(scene) { ++scene_.dispatchDepth_; }
        ~DispatchGuard() { --scene_.dispatchDepth_; }
        DispatchGuard(const DispatchGuard&) = delete;
        DispatchGuard& operator=(const DispatchGuard&) = delete;

    private:
        Scene& scene_;
    };
    // The attached components that take one event type (or update / fixedUpdate), sorted by
    // Component::deliveryOrder_. A detached component leaves a null entry until the end of
    // beginFrame(), so nothing moves while a dispatch walks the list.
    struct Receiver {
        std::uint64_t order = 0;
        Component* component = nullptr;
        void* handler = nullptr; // Handler<E>* for the channel's event type
    };
    struct Channel {
        std::type_index event = typeid(void);
        std::vector<Receiver> receivers;
        bool hasHoles = false;
    };

    // Calls `deliver(receiver)` for each live receiver of an object active in the hierarchy.
    template <class Deliver>
    void deliver(const Channel& channel, Deliver&& deliver);
    [[nodiscard]] const Channel* findChannel(std::type_index event) const noexcept;
    // Called by GameObject when a component joins / leaves it.
    void addReceivers(Component& component, std::uint32_t objectSerial);
    void removeReceivers(Component& component);
    void compactChannels();
    SceneHost& requireHost(const char* function) const;
    [[noreturn]] void throwNoSystem(const std::type_info& type) const;
    void destroyPending();
    void freeSlot(GameObject& object);

    SceneHost* host_ = nullptr;
    std::string name_;
    std::uint32_t tag_ = 0;
    std::vector<Slot> slots_;
    std::vector<std::uint32_t> freeSlots_;
    std::vector<GameObject*> objects_;
    std::vector<GameObject*> pendingAdd_;
    std::vector<GameObject*> pendingDestroy_;
    std::vector<GameObject*> componentChanges_; // objects with queued component changes
    int dispatchDepth_ = 0;
    std::uint64_t fixedSteps_ = 1; // number of the current fixed step (GameObject's stamps)
    bool inFixedSteps_ = false;    // between dispatchFixedUpdate() and dispatchUpdate()
    double frameAlpha_ = 1.0;
    std::uint32_t objectsCreated_ = 0;     // the serial of the next object
    std::uint32_t componentsAttached_ = 0; // the serial of the next attached component
    Channel updates_;
    Channel fixedUpdates_;
    std::vector<Channel> channels_; // one per event type some component handles
};

template <class Deliver>
void Scene::deliver(const Channel& channel, Deliver&& deliver) {
    // The list does not change during a dispatch: attachment waits for beginFrame().
    for (const Receiver& receiver : channel.receivers) {
        if (receiver.component != nullptr &&
            receiver.component->gameObject()->isActiveInHierarchy()) {
            deliver(receiver);
        }
    }
}

template <class Event>
void Scene::dispatch(const Event& event) {
    DispatchGuard guard(*this);
    if (Handler<Event>* own = handlerOf<Event>()) {
        own->on(event);
    }
    if (const Channel* channel = findChannel(typeid(Event))) {
        deliver(*channel, [&event](const Receiver& r) {
            static_cast<Handler<Event>*>(r.handler)->on(event);
        });
    }
}

template <class T>
T* Scene::findSystem() const noexcept {
    static_assert(std::is_base_of_v<System, T>,
                  "Scene::findSystem<T>: T must derive from core::System");
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
