// SPDX-License-Identifier: MIT
#include <e2d/core/scene.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/scene_host.hpp>

#include "format.hpp"

#include <algorithm>
#include <string>

namespace e2d::core {

// Marks the scene as busy dispatching, so beginFrame()/dispatchTerminate() cannot run from
// inside an event and change the lists being iterated.
class Scene::DispatchGuard {
public:
    explicit DispatchGuard(Scene& scene) : scene_(scene) { ++scene_.dispatchDepth_; }
    ~DispatchGuard() { --scene_.dispatchDepth_; }
    DispatchGuard(const DispatchGuard&) = delete;
    DispatchGuard& operator=(const DispatchGuard&) = delete;

private:
    Scene& scene_;
};

Scene::Scene() = default;

Scene::~Scene() = default;

// Game objects ---------------------------------------------------------------------------

GameObject& Scene::createGameObject() {
    std::uint32_t index = 0;
    if (!freeSlots_.empty()) {
        index = freeSlots_.back();
        freeSlots_.pop_back();
    } else {
        index = static_cast<std::uint32_t>(slots_.size());
        slots_.emplace_back();
    }
    Slot& slot = slots_[index];
    slot.object.reset(new GameObject(*this, GameObjectId{index, slot.generation}));
    pendingAdd_.push_back(slot.object.get());
    return *slot.object;
}

void Scene::destroyGameObject(GameObject& object) {
    if (object.scene_ != this) {
        throw Error("core::Scene::destroyGameObject(): object " + std::to_string(object.id().index) +
                    " belongs to another scene");
    }
    if (!object.pendingDestroy_) {
        object.pendingDestroy_ = true;
        pendingDestroy_.push_back(&object);
    }
}

bool Scene::destroyGameObject(GameObjectId id) {
    GameObject* object = find(id);
    if (object == nullptr) {
        return false;
    }
    destroyGameObject(*object);
    return true;
}

GameObject* Scene::find(GameObjectId id) const noexcept {
    if (id.isNull() || id.index >= slots_.size()) {
        return nullptr;
    }
    const Slot& slot = slots_[id.index];
    return slot.generation == id.generation ? slot.object.get() : nullptr;
}

namespace {

// Joined objects, then those waiting to join, skipping those waiting to be destroyed.
template <class F>
void forEachLive(const std::vector<GameObject*>& joined, const std::vector<GameObject*>& pending, F&& f) {
    for (const auto* list : {&joined, &pending}) {
        for (GameObject* o : *list) {
            if (!o->isPendingDestroy() && !f(*o)) {
                return;
            }
        }
    }
}

} // namespace

GameObject* Scene::findByName(std::string_view name) const noexcept {
    GameObject* found = nullptr;
    forEachLive(objects_, pendingAdd_, [&](GameObject& o) {
        if (o.name() == name) {
            found = &o;
            return false;
        }
        return true;
    });
    return found;
}

std::vector<GameObject*> Scene::findByTag(std::string_view tag) const {
    std::vector<GameObject*> found;
    forEachLive(objects_, pendingAdd_, [&](GameObject& o) {
        if (o.tag() == tag) {
            found.push_back(&o);
        }
        return true;
    });
    return found;
}

GameObject* Scene::findFirstByTag(std::string_view tag) const noexcept {
    GameObject* found = nullptr;
    forEachLive(objects_, pendingAdd_, [&](GameObject& o) {
        if (o.tag() == tag) {
            found = &o;
            return false;
        }
        return true;
    });
    return found;
}

void Scene::freeSlot(GameObject& object) {
    Slot& slot = slots_[object.id().index];
    // Generation 0 is reserved for the null id.
    slot.generation = slot.generation == UINT32_MAX ? 1 : slot.generation + 1;
    freeSlots_.push_back(object.id().index);
    slot.object.reset();
}

// Host services --------------------------------------------------------------------------

void Scene::attachHost(SceneHost* host, std::string name) {
    host_ = host;
    name_ = std::move(name);
}

Logger* Scene::logger() const noexcept {
    return host_ != nullptr ? &host_->logger() : nullptr;
}

SceneHost& Scene::requireHost(const char* function) const {
    if (host_ == nullptr) {
        throw Error(std::string("core::Scene::") + function + "(): the scene has no host attached");
    }
    return *host_;
}

void Scene::throwNoSystem(const std::type_info& type) const {
    if (host_ == nullptr) {
        throw Error("core::Scene::system(): the scene has no host yet to look up " + detail::demangledName(type) +
                    " in (a scene's constructor runs before its host attaches: look systems up in onInitialize() "
                    "or later)");
    }
    throw Error(std::string("core::Scene::system(): no system of type ") + detail::demangledName(type) +
                " is registered with the scene's host");
}

void Scene::changeToScene(std::string_view name) {
    requireHost("changeToScene").changeToScene(name);
}

void Scene::terminateGame() {
    requireHost("terminateGame").terminateGame();
}

int Scene::windowWidth() const {
    return requireHost("windowWidth").windowSize().x;
}

int Scene::windowHeight() const {
    return requireHost("windowHeight").windowSize().y;
}

int Scene::referenceWindowWidth() const {
    return requireHost("referenceWindowWidth").referenceWindowSize().x;
}

int Scene::referenceWindowHeight() const {
    return requireHost("referenceWindowHeight").referenceWindowSize().y;
}

// Driving --------------------------------------------------------------------------------

void Scene::dispatchInitialize() {
    {
        DispatchGuard guard(*this);
        onInitialize();
    }
    beginFrame();
}

void Scene::destroyPending() {
    std::vector<GameObject*> requested;
    requested.swap(pendingDestroy_);
    if (requested.empty()) {
        return;
    }

    // Every requested object and its descendants, parents first, each once.
    std::vector<GameObject*> batch;
    for (GameObject* root : requested) {
        if (root->beingDestroyed_) {
            continue;
        }
        const std::size_t first = batch.size();
        root->beingDestroyed_ = true;
        batch.push_back(root);
        for (std::size_t i = first; i < batch.size(); ++i) {
            for (GameObject* child : batch[i]->children_) {
                if (!child->beingDestroyed_) {
                    child->beingDestroyed_ = true;
                    child->pendingDestroy_ = true;
                    batch.push_back(child);
                }
            }
        }
    }

    // All onTerminate calls happen while every object of the batch is still intact.
    for (GameObject* object : batch) {
        object->terminate();
    }

    const auto dying = [](const GameObject* o) { return o->beingDestroyed_; };
    objects_.erase(std::remove_if(objects_.begin(), objects_.end(), dying), objects_.end());
    pendingAdd_.erase(std::remove_if(pendingAdd_.begin(), pendingAdd_.end(), dying), pendingAdd_.end());
    componentChanges_.erase(std::remove_if(componentChanges_.begin(), componentChanges_.end(), dying),
                            componentChanges_.end());
    for (GameObject* object : batch) {
        if (object->parent_ != nullptr && !object->parent_->beingDestroyed_) {
            object->detachFromParent();
        }
        // A child attached by an onTerminate handler above is not in the batch: it survives
        // as a root object instead of keeping a dangling parent.
        for (GameObject* child : object->children_) {
            if (!child->beingDestroyed_) {
                child->parent_ = nullptr;
                child->markWorldDirty();
            }
        }
    }
    for (GameObject* object : batch) {
        freeSlot(*object);
    }
}

void Scene::beginFrame() {
    if (dispatchDepth_ > 0) {
        throw Error("core::Scene::beginFrame(): called from inside an event of scene '" + name_ + "'");
    }
    DispatchGuard guard(*this);

    destroyPending();

    // Objects still waiting to join are in this list too; applying their components here
    // instead of when they join sends the same events in the same order.
    std::vector<GameObject*> changed;
    changed.swap(componentChanges_);
    for (GameObject* object : changed) {
        object->applyPendingComponents();
    }

    std::vector<GameObject*> joining;
    joining.swap(pendingAdd_);
    // Join first, initialise after, so onInitialize sees every object of the batch in the scene.
    for (GameObject* object : joining) {
        objects_.push_back(object);
        object->applyPendingComponents();
    }
    for (GameObject* object : joining) {
        object->initialize();
    }
}

template <class SceneHandler, class ComponentHandler>
void Scene::broadcast(SceneHandler&& sceneHandler, ComponentHandler&& componentHandler) {
    DispatchGuard guard(*this);
    sceneHandler();
    for (GameObject* object : objects_) {
        if (object->isActiveInHierarchy()) {
            object->forEachComponent(componentHandler);
        }
    }
}

void Scene::dispatchFixedUpdate(double step) {
    broadcast([&] { fixedUpdate(step); }, [&](Component& c) { c.fixedUpdate(step); });
}

void Scene::dispatchUpdate(double dt) {
    broadcast([&] { update(dt); }, [&](Component& c) { c.update(dt); });
}

void Scene::dispatchButtonDown(int key) {
    broadcast([&] { onButtonDown(key); }, [&](Component& c) { c.onButtonDown(key); });
}

void Scene::dispatchButtonUp(int key) {
    broadcast([&] { onButtonUp(key); }, [&](Component& c) { c.onButtonUp(key); });
}

void Scene::dispatchControllerButtonDown(int controller, int button) {
    broadcast([&] { onControllerButtonDown(controller, button); },
              [&](Component& c) { c.onControllerButtonDown(controller, button); });
}

void Scene::dispatchControllerButtonUp(int controller, int button) {
    broadcast([&] { onControllerButtonUp(controller, button); },
              [&](Component& c) { c.onControllerButtonUp(controller, button); });
}

void Scene::dispatchMouseButtonDown(int button, glm::vec2 screen, glm::vec2 world) {
    broadcast([&] { onMouseButtonDown(button, screen, world); },
              [&](Component& c) { c.onMouseButtonDown(button, screen, world); });
}

void Scene::dispatchMouseButtonUp(int button, glm::vec2 screen, glm::vec2 world) {
    broadcast([&] { onMouseButtonUp(button, screen, world); },
              [&](Component& c) { c.onMouseButtonUp(button, screen, world); });
}

void Scene::dispatchMouseMove(glm::vec2 screen, glm::vec2 world) {
    broadcast([&] { onMouseMove(screen, world); }, [&](Component& c) { c.onMouseMove(screen, world); });
}

void Scene::dispatchKeyDown(int key, int mods) {
    broadcast([&] { onKeyDown(key, mods); }, [&](Component& c) { c.onKeyDown(key, mods); });
}

void Scene::dispatchKeyUp(int key, int mods) {
    broadcast([&] { onKeyUp(key, mods); }, [&](Component& c) { c.onKeyUp(key, mods); });
}

void Scene::dispatchKeyRepeat(int key, int mods) {
    broadcast([&] { onKeyRepeat(key, mods); }, [&](Component& c) { c.onKeyRepeat(key, mods); });
}

void Scene::dispatchTextInput(char32_t codepoint) {
    broadcast([&] { onTextInput(codepoint); }, [&](Component& c) { c.onTextInput(codepoint); });
}

void Scene::dispatchScroll(glm::vec2 offset, glm::vec2 screen, glm::vec2 world) {
    broadcast([&] { onScroll(offset, screen, world); },
              [&](Component& c) { c.onScroll(offset, screen, world); });
}

void Scene::dispatchFocusChanged(bool focused) {
    broadcast([&] { onFocusChanged(focused); }, [&](Component& c) { c.onFocusChanged(focused); });
}

void Scene::dispatchControllerConnected(int controller) {
    broadcast([&] { onControllerConnected(controller); },
              [&](Component& c) { c.onControllerConnected(controller); });
}

void Scene::dispatchControllerDisconnected(int controller) {
    broadcast([&] { onControllerDisconnected(controller); },
              [&](Component& c) { c.onControllerDisconnected(controller); });
}

void Scene::dispatchControllerAxis(int controller, int axis, float value) {
    broadcast([&] { onControllerAxis(controller, axis, value); },
              [&](Component& c) { c.onControllerAxis(controller, axis, value); });
}

void Scene::dispatchTerminate() {
    if (dispatchDepth_ > 0) {
        throw Error("core::Scene::dispatchTerminate(): called from inside an event of scene '" + name_ + "'");
    }
    {
        DispatchGuard guard(*this);
        onTerminate();
        for (GameObject* object : objects_) {
            object->terminate();
        }
    }
    objects_.clear();
    pendingAdd_.clear();
    pendingDestroy_.clear();
    componentChanges_.clear();
    for (Slot& slot : slots_) {
        if (slot.object) {
            freeSlot(*slot.object);
        }
    }
}

} // namespace e2d::core
