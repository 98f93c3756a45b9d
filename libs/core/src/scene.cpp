// SPDX-License-Identifier: MIT
#include <e2d/core/scene.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/scene_host.hpp>

#include "type_name.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>

namespace e2d::core {

Scene::Scene() {
    // Only needs to differ from the tag of the scene that ran before in the same place.
    const auto address = reinterpret_cast<std::uintptr_t>(this);
    tag_ = static_cast<std::uint32_t>((address >> 4) ^ (address >> 36)) | 0x80000000u;
}

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
    slot.object.reset(new GameObject(*this, GameObjectId::forSlot(index, slot.generation, tag_),
                                     objectsCreated_++));
    pendingAdd_.push_back(slot.object.get());
    return *slot.object;
}

void Scene::destroyGameObject(GameObject& object) {
    if (object.scene_ != this) {
        throw Error("core::Scene::destroyGameObject(): object " +
                    std::to_string(object.id().index()) + " belongs to another scene");
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
    // A free slot's generation is already the next object's; its object is null.
    const std::optional<std::uint32_t> index = findSlot(
        id, slots_.size(), [this](std::uint32_t i) { return slots_[i].generation; }, tag_);
    return index ? slots_[*index].object.get() : nullptr;
}

namespace {

// Joined objects, then those waiting to join, skipping those waiting to be destroyed.
template <class F>
void forEachLive(const std::vector<GameObject*>& joined, const std::vector<GameObject*>& pending,
                 F&& f) {
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
    Slot& slot = slots_[object.id().index()];
    slot.generation = nextGeneration(slot.generation);
    freeSlots_.push_back(object.id().index());
    slot.object.reset();
}

// Host services --------------------------------------------------------------------------

void Scene::attachHost(SceneHost* host, std::string name) {
    host_ = host;
    name_ = std::move(name);
    if (host != nullptr) {
        tag_ = host->nextSceneTag();
        for (Slot& slot : slots_) {
            if (slot.object) {
                slot.object->id_.owner = tag_;
            }
        }
    }
}

Logger* Scene::logger() const noexcept { return host_ != nullptr ? &host_->logger() : nullptr; }

SceneHost& Scene::requireHost(const char* function) const {
    if (host_ == nullptr) {
        throw Error(std::string("core::Scene::") + function + "(): the scene has no host attached");
    }
    return *host_;
}

void Scene::throwNoSystem(const std::type_info& type) const {
    if (host_ == nullptr) {
        throw Error("core::Scene::system(): the scene has no host yet to look up " +
                    detail::demangledName(type) +
                    " in (a scene's constructor runs before its host attaches: look systems up in "
                    "onInitialize() "
                    "or later)");
    }
    throw Error(std::string("core::Scene::system(): no system of type ") +
                detail::demangledName(type) + " is registered with the scene's host");
}

void Scene::changeToScene(std::string_view name) {
    requireHost("changeToScene").changeToScene(name);
}

void Scene::terminateGame() { requireHost("terminateGame").terminateGame(); }

int Scene::windowWidth() const { return requireHost("windowWidth").windowSize().x; }

int Scene::windowHeight() const { return requireHost("windowHeight").windowSize().y; }

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
    pendingAdd_.erase(std::remove_if(pendingAdd_.begin(), pendingAdd_.end(), dying),
                      pendingAdd_.end());
    componentChanges_.erase(
        std::remove_if(componentChanges_.begin(), componentChanges_.end(), dying),
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
        for (const auto& component : object->components_) {
            removeReceivers(*component);
        }
        freeSlot(*object);
    }
}

void Scene::beginFrame() {
    if (dispatchDepth_ > 0) {
        throw Error("core::Scene::beginFrame(): called from inside an event of scene '" + name_ +
                    "'");
    }
    DispatchGuard guard(*this);
    inFixedSteps_ = false;

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
    compactChannels();
}

void Scene::dispatchFixedUpdate(double step) {
    ++fixedSteps_;
    inFixedSteps_ = true;
    DispatchGuard guard(*this);
    fixedUpdate(step);
    deliver(fixedUpdates_, [step](const Receiver& r) { r.component->fixedUpdate(step); });
}

void Scene::setFrameAlpha(double alpha) noexcept {
    frameAlpha_ = alpha > 0.0 ? std::min(alpha, 1.0) : 0.0; // NaN: 0
}

void Scene::dispatchUpdate(double dt) {
    inFixedSteps_ = false;
    DispatchGuard guard(*this);
    update(dt);
    deliver(updates_, [dt](const Receiver& r) { r.component->update(dt); });
}

// Receivers ------------------------------------------------------------------------------

const Scene::Channel* Scene::findChannel(std::type_index event) const noexcept {
    for (const Channel& channel : channels_) {
        if (channel.event == event) {
            return &channel;
        }
    }
    return nullptr;
}

namespace {

template <class Channel, class Receiver>
void insertSorted(Channel& channel, const Receiver& receiver) {
    auto& list = channel.receivers;
    // Usually at the end: objects and components are attached in the order they get serials.
    const auto at =
        std::upper_bound(list.begin(), list.end(), receiver.order,
                         [](std::uint64_t order, const Receiver& r) { return order < r.order; });
    list.insert(at, receiver);
}

template <class Channel>
void clearSlot(Channel& channel, std::uint64_t order) {
    auto& list = channel.receivers;
    const auto at = std::lower_bound(list.begin(), list.end(), order,
                                     [](const auto& r, std::uint64_t o) { return r.order < o; });
    if (at != list.end() && at->order == order && at->component != nullptr) {
        at->component = nullptr;
        channel.hasHoles = true;
    }
}

} // namespace

void Scene::addReceivers(Component& component, std::uint32_t objectSerial) {
    component.deliveryOrder_ =
        (static_cast<std::uint64_t>(objectSerial) << 32) | componentsAttached_++;
    const std::uint64_t order = component.deliveryOrder_;
    if (component.hasUpdate_) {
        insertSorted(updates_, Receiver{order, &component, &component});
    }
    if (component.hasFixedUpdate_) {
        insertSorted(fixedUpdates_, Receiver{order, &component, &component});
    }
    for (const HandlerTable::Entry& entry : component.handledEvents()) {
        auto channel = std::find_if(channels_.begin(), channels_.end(),
                                    [&entry](const Channel& c) { return c.event == entry.event; });
        if (channel == channels_.end()) {
            channel = channels_.insert(channels_.end(), Channel{entry.event, {}, false});
        }
        insertSorted(*channel, Receiver{order, &component, entry.handler});
    }
}

void Scene::removeReceivers(Component& component) {
    const std::uint64_t order = component.deliveryOrder_;
    if (component.hasUpdate_) {
        clearSlot(updates_, order);
    }
    if (component.hasFixedUpdate_) {
        clearSlot(fixedUpdates_, order);
    }
    for (const HandlerTable::Entry& entry : component.handledEvents()) {
        for (Channel& channel : channels_) {
            if (channel.event == entry.event) {
                clearSlot(channel, order);
            }
        }
    }
}

void Scene::compactChannels() {
    const auto compact = [](Channel& channel) {
        if (channel.hasHoles) {
            auto& list = channel.receivers;
            list.erase(std::remove_if(list.begin(), list.end(),
                                      [](const Receiver& r) { return r.component == nullptr; }),
                       list.end());
            channel.hasHoles = false;
        }
    };
    compact(updates_);
    compact(fixedUpdates_);
    for (Channel& channel : channels_) {
        compact(channel);
    }
}

void Scene::dispatchTerminate() {
    if (dispatchDepth_ > 0) {
        throw Error("core::Scene::dispatchTerminate(): called from inside an event of scene '" +
                    name_ + "'");
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
    updates_.receivers.clear();
    fixedUpdates_.receivers.clear();
    channels_.clear();
    for (Slot& slot : slots_) {
        if (slot.object) {
            freeSlot(*slot.object);
        }
    }
}

} // namespace e2d::core
