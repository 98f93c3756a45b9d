// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/system.hpp>
#include <e2d/render/camera.hpp>

#include <vector>

/// The scene-graph side of the render library: a core::System that draws a Renderer every
/// frame, and the components that put game objects on screen (SpriteRenderer,
/// CameraComponent). Nothing here is needed to use Renderer on its own.
namespace e2d::render {

class CameraComponent;
class Renderer;
class SpriteRenderer;
class Window;

/// Draws the scene every frame. Refers to a Renderer (and optionally the Window to swap),
/// both owned by the caller and outliving the system.
///
/// render(alpha): every SpriteRenderer copies its object's world transform (parent chain
/// included) to its sprite, the active CameraComponent (the first one registered and enabled,
/// else the system's own camera()) copies its object's, the Renderer draws, and the window (if
/// given) swaps buffers. clear() (scene change) destroys every sprite left in the Renderer.
/// Components find the system with `scene()->system<RenderSystem>()`.
class RenderSystem : public core::System {
public:
    /// `window`: swap its buffers after each frame; null: the caller does.
    explicit RenderSystem(Renderer& renderer, Window* window = nullptr);
    ~RenderSystem() override;
    RenderSystem(const RenderSystem&) = delete;
    RenderSystem& operator=(const RenderSystem&) = delete;

    [[nodiscard]] Renderer& renderer() const noexcept { return renderer_; }
    /// The camera used when no CameraComponent is active.
    [[nodiscard]] Camera& camera() noexcept { return camera_; }
    /// The camera of the last (or next) frame: the active component's, else camera().
    [[nodiscard]] Camera& activeCamera() noexcept;

    void render(double alpha) override;
    void clear() override;

    /// Copies every component's object transform to the renderer (render() does this first;
    /// exposed for tests that read state without drawing).
    void syncTransforms();

private:
    friend class SpriteRenderer;
    friend class CameraComponent;

    void add(SpriteRenderer& sprite);
    void remove(SpriteRenderer& sprite) noexcept;
    void add(CameraComponent& camera);
    void remove(CameraComponent& camera) noexcept;

    Renderer& renderer_;
    Window* window_ = nullptr;
    Camera camera_;
    std::vector<SpriteRenderer*> sprites_;
    std::vector<CameraComponent*> cameras_;
};

} // namespace e2d::render
