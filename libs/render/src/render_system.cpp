// SPDX-License-Identifier: MIT
#include <e2d/render/render_system.hpp>

#include <e2d/render/renderer.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/window.hpp>

#include <algorithm>

namespace e2d::render {

RenderSystem::RenderSystem(Renderer& renderer, Window* window) : renderer_(renderer), window_(window) {}

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
    renderer_.destroyAllSprites();
}

void RenderSystem::add(SpriteRenderer& sprite) { sprites_.push_back(&sprite); }
void RenderSystem::remove(SpriteRenderer& sprite) noexcept { std::erase(sprites_, &sprite); }
void RenderSystem::add(CameraComponent& camera) { cameras_.push_back(&camera); }
void RenderSystem::remove(CameraComponent& camera) noexcept { std::erase(cameras_, &camera); }

} // namespace e2d::render
