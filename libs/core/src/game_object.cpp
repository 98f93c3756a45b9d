// SPDX-License-Identifier: MIT
#include <e2d/core/game_object.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/core/log.hpp>
#include <e2d/core/scene.hpp>

#include "type_name.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace e2d::core {

GameObject::GameObject(Scene& scene, GameObjectId id, std::uint32_t serial)
    : scene_(&scene), id_(id), serial_(serial) {}

GameObject::~GameObject() = default;

Logger* GameObject::logger() const noexcept { return scene_->logger(); }

// Transform ------------------------------------------------------------------------------

std::string GameObject::describe() const {
    if (!name_.empty()) {
        return "object " + quote(name_);
    }
    if (!tag_.empty()) {
        return "object tagged " + quote(tag_);
    }
    return "object " + std::to_string(id_.index());
}

namespace {

bool finite(glm::vec2 v) noexcept { return std::isfinite(v.x) && std::isfinite(v.y); }

} // namespace

void GameObject::refuseNonFinite(const char* function, const char* what,
                                 const std::string& value) const {
    throw Error(std::string("core::GameObject::") + function + "(): " + describe() + " got " +
                what + " " + value + "; it must be finite");
}

void GameObject::setPosition(glm::vec3 position) {
    if (!finite(glm::vec2(position)) || !std::isfinite(position.z)) {
        refuseNonFinite("setPosition", "position", formatVector(position));
    }
    notePoseChange();
    position_ = position;
    localDirty_ = true;
    markWorldDirty();
    if (!scene_->inFixedSteps_) {
        snapRenderPose();
    }
}

void GameObject::setPosition(glm::vec2 position) {
    if (!finite(position)) {
        refuseNonFinite("setPosition", "position", formatVector(position));
    }
    setPosition(glm::vec3(position, position_.z));
}

void GameObject::translate(glm::vec2 delta) {
    const glm::vec2 moved(position_.x + delta.x, position_.y + delta.y);
    if (!finite(moved)) {
        refuseNonFinite("translate", "delta",
                        formatVector(delta) + " (new position " + formatVector(moved) + ")");
    }
    setPosition(glm::vec3(moved, position_.z));
}

void GameObject::setScale(glm::vec2 scale) {
    if (!finite(scale)) {
        refuseNonFinite("setScale", "scale", formatVector(scale));
    }
    notePoseChange();
    scale_ = scale;
    localDirty_ = true;
    markWorldDirty();
    if (!scene_->inFixedSteps_) {
        snapRenderPose();
    }
}

void GameObject::setOrientation(float radians) {
    if (!std::isfinite(radians)) {
        refuseNonFinite("setOrientation", "orientation", formatNumber(radians));
    }
    notePoseChange();
    orientation_ = radians;
    localDirty_ = true;
    markWorldDirty();
    // A change outside the fixed steps shows at once: nothing to draw in between.
    if (!scene_->inFixedSteps_) {
        snapRenderPose();
    }
}

void GameObject::rotate(float radians) {
    if (!std::isfinite(orientation_ + radians)) {
        refuseNonFinite("rotate", "angle", formatNumber(radians));
    }
    setOrientation(orientation_ + radians);
}

// Drawing between fixed steps --------------------------------------------------------------

void GameObject::notePoseChange() noexcept {
    // The first change in a step keeps the pose the step started from.
    if (stepStamp_ != scene_->fixedSteps_) {
        stepStamp_ = scene_->fixedSteps_;
        stepStartPosition_ = position_;
        stepStartScale_ = scale_;
        stepStartOrientation_ = orientation_;
    }
}

void GameObject::snapRenderPose() noexcept {
    stepStamp_ = scene_->fixedSteps_;
    stepStartPosition_ = position_;
    stepStartScale_ = scale_;
    stepStartOrientation_ = orientation_;
}

bool GameObject::isInterpolated() const noexcept {
    return stepStamp_ == scene_->fixedSteps_ && scene_->frameAlpha_ < 1.0 &&
           (stepStartPosition_ != position_ || stepStartScale_ != scale_ ||
            stepStartOrientation_ != orientation_);
}

glm::mat4 GameObject::renderTransform() const {
    bool anyInterpolated = false;
    for (const GameObject* o = this; o != nullptr && !anyInterpolated; o = o->parent_) {
        anyInterpolated = o->isInterpolated();
    }
    if (!anyInterpolated) {
        return worldTransform();
    }
    glm::mat4 local = localTransform();
    if (isInterpolated()) {
        const float a = static_cast<float>(scene_->frameAlpha_);
        const glm::vec3 position = stepStartPosition_ + (position_ - stepStartPosition_) * a;
        const glm::vec2 scale = stepStartScale_ + (scale_ - stepStartScale_) * a;
        // The short way round: a body turning through +-pi does not spin back the long way.
        const float turn =
            std::remainder(orientation_ - stepStartOrientation_, 2.0f * std::numbers::pi_v<float>);
        local = composeLocal(position, stepStartOrientation_ + turn * a, scale);
    }
    return parent_ != nullptr ? parent_->renderTransform() * local : local;
}

glm::mat4 GameObject::composeLocal(glm::vec3 position, float orientation,
                                   glm::vec2 scale) noexcept {
    const float c = std::cos(orientation);
    const float s = std::sin(orientation);
    glm::mat4 m(1.0f);
    m[0] = glm::vec4(c * scale.x, s * scale.x, 0.0f, 0.0f);
    m[1] = glm::vec4(-s * scale.y, c * scale.y, 0.0f, 0.0f);
    m[3] = glm::vec4(position, 1.0f);
    return m;
}

glm::vec3 GameObject::renderPosition() const { return glm::vec3(renderTransform()[3]); }

float GameObject::renderOrientation() const {
    const glm::mat4 m = renderTransform();
    return std::atan2(m[0][1], m[0][0]);
}

void GameObject::markWorldDirty() const noexcept {
    // A dirty object always has dirty descendants (a world matrix is only rebuilt after its
    // parent's), so the walk can stop at the first object that is already dirty.
    if (worldDirty_) {
        return;
    }
    worldDirty_ = true;
    for (const GameObject* child : children_) {
        child->markWorldDirty();
    }
}

const glm::mat4& GameObject::localTransform() const {
    if (localDirty_) {
        local_ = composeLocal(position_, orientation_, scale_);
        localDirty_ = false;
    }
    return local_;
}

const glm::mat4& GameObject::worldTransform() const {
    if (worldDirty_) {
        world_ =
            parent_ != nullptr ? parent_->worldTransform() * localTransform() : localTransform();
        worldDirty_ = false;
    }
    return world_;
}

glm::vec3 GameObject::worldPosition() const { return glm::vec3(worldTransform()[3]); }

float GameObject::worldOrientation() const {
    const glm::mat4& world = worldTransform();
    return std::atan2(world[0][1], world[0][0]);
}

// Hierarchy ------------------------------------------------------------------------------

bool GameObject::isAncestorOf(const GameObject& other) const noexcept {
    for (const GameObject* p = other.parent_; p != nullptr; p = p->parent_) {
        if (p == this) {
            return true;
        }
    }
    return false;
}

void GameObject::addChild(GameObject& child) {
    if (&child == this) {
        throw Error("core::GameObject::addChild(): " + describe() + " cannot be its own child");
    }
    if (child.scene_ != scene_) {
        throw Error("core::GameObject::addChild(): object " + std::to_string(child.id_.index()) +
                    " belongs to another scene");
    }
    if (child.isAncestorOf(*this)) {
        throw Error("core::GameObject::addChild(): object " + std::to_string(child.id_.index()) +
                    " is an ancestor of object " + std::to_string(id_.index()) +
                    ", this would make a cycle");
    }
    if (child.parent_ == this) {
        return;
    }
    child.detachFromParent();
    child.parent_ = this;
    children_.push_back(&child);
    child.markWorldDirty();
}

void GameObject::removeChild(GameObject& child) {
    if (child.parent_ != this) {
        throw Error("core::GameObject::removeChild(): object " + std::to_string(child.id_.index()) +
                    " is not a child of object " + std::to_string(id_.index()));
    }
    child.detachFromParent();
}

void GameObject::setParent(GameObject* parent) {
    if (parent != nullptr) {
        parent->addChild(*this);
    } else {
        detachFromParent();
    }
}

void GameObject::detachFromParent() noexcept {
    if (parent_ == nullptr) {
        return;
    }
    auto& siblings = parent_->children_;
    siblings.erase(std::find(siblings.begin(), siblings.end(), this));
    parent_ = nullptr;
    markWorldDirty();
}

// Components -----------------------------------------------------------------------------

void GameObject::warnRefusedUnique(const std::type_info& type) const {
    if (Logger* log = logger()) {
        log->warning(std::string("core::GameObject::addComponent(): object ") +
                     std::to_string(id_.index()) + " already has a unique component of type " +
                     detail::demangledName(type) + ", the new one is refused");
    }
}

void GameObject::removeComponent(Component* component) {
    if (component == nullptr) {
        throw Error("core::GameObject::removeComponent(): component is null");
    }
    const auto owns = [component](const std::unique_ptr<Component>& c) {
        return c.get() == component;
    };
    if (std::none_of(components_.begin(), components_.end(), owns) &&
        std::none_of(pendingAdd_.begin(), pendingAdd_.end(), owns)) {
        throw Error(
            "core::GameObject::removeComponent(): the component does not belong to object " +
            std::to_string(id_.index()));
    }
    if (std::find(pendingRemove_.begin(), pendingRemove_.end(), component) ==
        pendingRemove_.end()) {
        pendingRemove_.push_back(component);
        queueComponentChange();
    }
}

void GameObject::queueComponentChange() {
    if (!componentChangeQueued_) {
        componentChangeQueued_ = true;
        scene_->componentChanges_.push_back(this);
    }
}

void GameObject::applyPendingComponents() {
    componentChangeQueued_ = false;
    // Swapped out first: events below may queue more work, which waits for the next frame.
    std::vector<Component*> removals;
    removals.swap(pendingRemove_);
    std::vector<std::unique_ptr<Component>> additions;
    additions.swap(pendingAdd_);

    for (Component* component : removals) {
        const auto owns = [component](const std::unique_ptr<Component>& c) {
            return c.get() == component;
        };
        if (auto queued = std::find_if(additions.begin(), additions.end(), owns);
            queued != additions.end()) {
            additions.erase(queued); // never attached: no events
            continue;
        }
        if (component->initialized_) {
            component->initialized_ = false;
            component->onTerminate();
        }
        scene_->removeReceivers(*component);
        component->onRemovedFromGameObject();
        components_.erase(std::find_if(components_.begin(), components_.end(), owns));
    }

    for (auto& owned : additions) {
        Component* component = owned.get();
        components_.push_back(std::move(owned));
        scene_->addReceivers(*component, serial_);
        component->onAddedToGameObject();
        if (initialized_) {
            component->initialized_ = true;
            component->onInitialize();
        }
    }
}

void GameObject::initialize() {
    initialized_ = true;
    snapRenderPose(); // a new object appears where it was put

    for (const auto& component : components_) {
        if (!component->initialized_) {
            component->initialized_ = true;
            component->onInitialize();
        }
    }
}

void GameObject::terminate() {
    if (!initialized_) {
        return;
    }
    initialized_ = false;
    for (const auto& component : components_) {
        if (component->initialized_) {
            component->initialized_ = false;
            component->onTerminate();
        }
    }
}

bool GameObject::isActiveInHierarchy() const noexcept {
    for (const GameObject* o = this; o != nullptr; o = o->parent_) {
        if (!o->active_) {
            return false;
        }
    }
    return true;
}

} // namespace e2d::core
