// SPDX-License-Identifier: MIT
#include <e2d/render/render_system.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/log.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/sprite_sheet.hpp>
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

const SpriteSheet* RenderSystem::sheet(const std::filesystem::path& path) {
    const std::string key = path.string();
    if (auto it = sheets_.find(key); it != sheets_.end()) {
        return it->second.get();
    }
    std::unique_ptr<SpriteSheet> loaded;
    try {
        loaded = std::make_unique<SpriteSheet>(SpriteSheet::fromFile(path));
    } catch (const core::Error& e) {
        sheetErrors_[key] = e.what();
        if (logger_ != nullptr) {
            logger_->error(e.what());
        }
    }
    return sheets_.emplace(key, std::move(loaded)).first->second.get();
}

std::string RenderSystem::sheetError(const std::filesystem::path& path) const {
    auto it = sheetErrors_.find(path.string());
    return it == sheetErrors_.end() ? std::string{} : it->second;
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

int RenderSystem::releaseUnusedTextures() {
    text_.reset();
    return renderer_.destroyUnusedTextures();
}

void RenderSystem::add(SpriteRenderer& sprite) { sprites_.push_back(&sprite); }
void RenderSystem::remove(SpriteRenderer& sprite) noexcept { std::erase(sprites_, &sprite); }
void RenderSystem::add(CameraComponent& camera) { cameras_.push_back(&camera); }
void RenderSystem::remove(CameraComponent& camera) noexcept { std::erase(cameras_, &camera); }

} // namespace e2d::render
