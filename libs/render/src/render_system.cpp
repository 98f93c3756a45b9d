// SPDX-License-Identifier: MIT
#include <e2d/render/render_system.hpp>

#include <e2d/render/renderer.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/text_renderer.hpp>
#include <e2d/render/window.hpp>

#include <algorithm>

namespace e2d::render {

RenderSystem::RenderSystem(Renderer& renderer, Window* window, core::Logger* logger)
    : renderer_(renderer), window_(window), logger_(logger) {}

TextRenderer& RenderSystem::text() {
    if (!text_) {
        text_ = std::make_unique<TextRenderer>(renderer_, logger_);
    }
    return *text_;
}

void RenderSystem::addHook(RenderHook& hook) { hooks_.push_back(&hook); }
void RenderSystem::removeHook(RenderHook& hook) noexcept { std::erase(hooks_, &hook); }

RenderSystem::~RenderSystem() = default;

Camera& RenderSystem::activeCamera() noexcept {
    for (CameraComponent* camera : cameras_) {
        if (camera->enabled()) {
            return camera->camera();
        }
    }
    return camera_;
}

void RenderSystem::syncTransforms() {
    for (SpriteRenderer* sprite : sprites_) {
        sprite->syncTransform();
    }
    for (CameraComponent* camera : cameras_) {
        camera->syncTransform();
    }
}

void RenderSystem::render(double alpha) {
    static_cast<void>(alpha);
    syncTransforms();
    for (RenderHook* hook : hooks_) {
        hook->beforeRender(renderer_);
    }
    renderer_.render(activeCamera());
    if (window_ != nullptr) {
        window_->swapBuffers();
    }
}

void RenderSystem::clear() {
    // The old scene's components have been terminated (and unregistered) by now; anything
    // else the scene created directly goes too.
    sprites_.clear();
    cameras_.clear();
    hooks_.clear();
    renderer_.destroyAllSprites();
}

void RenderSystem::add(SpriteRenderer& sprite) { sprites_.push_back(&sprite); }
void RenderSystem::remove(SpriteRenderer& sprite) noexcept { std::erase(sprites_, &sprite); }
void RenderSystem::add(CameraComponent& camera) { cameras_.push_back(&camera); }
void RenderSystem::remove(CameraComponent& camera) noexcept { std::erase(cameras_, &camera); }

} // namespace e2d::render
