// SPDX-License-Identifier: MIT
#include <e2d/render/sprite_renderer.hpp>

#include <e2d/core/error_text.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/render/render_system.hpp>

#include "world_pose.hpp"

#include <cmath>

namespace e2d::render {

namespace {

constexpr const char* kCtor = "render::SpriteRenderer";

SpriteDef toSpriteDef(const SpriteRendererDef& def, TextureId texture) {
    SpriteDef s;
    s.texture = texture;
    s.size = def.size;
    s.pivot = def.pivot;
    s.tint = def.tint;
    s.uv = def.uv;
    s.uvRotated = def.uvRotated;
    s.flipX = def.flipX;
    s.flipY = def.flipY;
    s.parallax = def.parallax;
    s.hud = def.hud;
    s.visible = def.visible;
    return s;
}

void checkSize(const char* function, glm::vec2 size) {
    if (!core::isFinite(size) || size.x < 0.0f || size.y < 0.0f) {
        core::throwError(function, "size must be >= 0 and finite, got " + core::formatVector(size));
    }
}

} // namespace

SpriteRenderer::SpriteRenderer(const SpriteRendererDef& def) : def_(def) {
    // The same checks as the sprite's, before any renderer is involved.
    core::requireFinite(kCtor, "pivot", def.pivot);
    core::requireFinite(kCtor, "zOffset", def.zOffset);
    checkSize(kCtor, def.size);
    if (!std::isfinite(def.parallax) || def.parallax < 0.0f) {
        core::throwError(kCtor, "parallax must be >= 0 and finite, got " +
                                    core::formatNumber(def.parallax));
    }
}

SpriteRenderer::~SpriteRenderer() {
    if (system_ != nullptr) {
        system_->renderer().destroySprite(sprite_);
        system_->remove(*this);
    }
}

void SpriteRenderer::onInitialize() {
    system_ = &scene()->system<RenderSystem>();
    Renderer& renderer = system_->renderer();
    TextureId texture = def_.texture;
    if (!def_.texturePath.empty()) {
        texture = renderer.loadTexture(def_.texturePath, def_.textureDef);
    }
    detail::WorldPose pose = detail::worldPose(*gameObject());
    SpriteDef sprite = toSpriteDef(def_, texture);
    sprite.position = pose.position;
    sprite.z = pose.z + def_.zOffset;
    sprite.rotation = pose.rotation;
    sprite.scale = pose.scale;
    sprite_ = renderer.createSprite(sprite);
    system_->add(*this);
}

void SpriteRenderer::onTerminate() {
    if (system_ != nullptr) {
        system_->renderer().destroySprite(sprite_);
        system_->remove(*this);
    }
    system_ = nullptr;
    sprite_ = {};
}

void SpriteRenderer::syncTransform() {
    if (system_ == nullptr) {
        return;
    }
    detail::WorldPose pose = detail::worldPose(*gameObject());
    system_->renderer().setTransform(sprite_, pose.position, pose.z + def_.zOffset, pose.rotation,
                                     pose.scale);
    // An inactive object (or one under an inactive parent) is not drawn.
    system_->renderer().setVisible(sprite_, def_.visible && gameObject()->isActiveInHierarchy());
}

void SpriteRenderer::setTint(Color tint) {
    def_.tint = tint;
    if (system_ != nullptr) {
        system_->renderer().setTint(sprite_, tint);
    }
}

void SpriteRenderer::setUv(const Rect& uv, bool uvRotated) {
    if (system_ != nullptr) {
        system_->renderer().setUv(sprite_, uv, uvRotated);
    }
    def_.uv = uv;
    def_.uvRotated = uvRotated;
}

void SpriteRenderer::setSize(glm::vec2 size) {
    checkSize("render::SpriteRenderer::setSize()", size);
    if (system_ != nullptr) {
        system_->renderer().setSize(sprite_, size);
    }
    def_.size = size;
}

void SpriteRenderer::setFlip(bool flipX, bool flipY) {
    def_.flipX = flipX;
    def_.flipY = flipY;
    if (system_ != nullptr) {
        system_->renderer().setFlip(sprite_, flipX, flipY);
    }
}

void SpriteRenderer::setVisible(bool visible) {
    def_.visible = visible;
    if (system_ != nullptr) {
        system_->renderer().setVisible(sprite_, visible);
    }
}

void SpriteRenderer::setTexture(TextureId texture) {
    if (system_ != nullptr) {
        system_->renderer().setTexture(sprite_, texture);
    }
    def_.texture = texture;
    def_.texturePath.clear();
}

CameraComponent::CameraComponent(const CameraComponentDef& def)
    : camera_(CameraDef{{0.0f, 0.0f}, 0.0f, def.zoom, def.referenceSize, def.fit}) {}

CameraComponent::~CameraComponent() {
    if (system_ != nullptr) {
        system_->remove(*this);
    }
}

void CameraComponent::onInitialize() {
    system_ = &scene()->system<RenderSystem>();
    system_->add(*this);
    syncTransform();
}

void CameraComponent::onTerminate() {
    if (system_ != nullptr) {
        system_->remove(*this);
    }
    system_ = nullptr;
}

void CameraComponent::syncTransform() {
    if (gameObject() == nullptr) {
        return;
    }
    // Drawn from the same pose as the sprites, so a camera on a moving body keeps it still.
    const detail::WorldPose pose = detail::worldPose(*gameObject());
    camera_.setPosition(pose.position);
    camera_.setRotation(pose.rotation);
}

} // namespace e2d::render
