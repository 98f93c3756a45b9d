// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/system.hpp>
#include <e2d/render/camera.hpp>

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace e2d::core {
class Logger;
}

/// The scene-graph side of the render library: a core::System that draws a Renderer every
/// frame, and the components that put game objects on screen (SpriteRenderer,
/// CameraComponent). Nothing here is needed to use Renderer on its own.
namespace e2d::render {

class CameraComponent;
class Renderer;
class SpriteRenderer;
class SpriteSheet;
class TextRenderer;
class Window;

/// Something a RenderSystem brings up to date every frame right before drawing, after the
/// sprites' transforms (AnimatedSpriteRenderer and TextLabel register themselves).
class RenderHook {
public:
    virtual ~RenderHook() = default;
    /// Put this frame's state into `renderer` (sprite fields, submitted quads).
    virtual void beforeRender(Renderer& renderer) = 0;

protected:
    RenderHook() = default;
    RenderHook(const RenderHook&) = default;
    RenderHook& operator=(const RenderHook&) = default;
};

/// Draws the scene every frame. Refers to a Renderer (and optionally the Window to swap),
/// both owned by the caller and outliving the system.
///
/// render(alpha): every SpriteRenderer copies its object's render transform (the world
/// transform, parent chain included, interpolated between fixed steps: see
/// core::GameObject::renderTransform()) to its sprite, the active CameraComponent (the first
/// one registered and enabled, else the system's own camera()) copies its object's, every
/// RenderHook runs (TextLabel draws at its object's render transform too), the Renderer
/// draws, and the window (if given) swaps buffers. clear() (scene change) destroys every sprite left in the Renderer.
/// Components find the system with `scene()->system<RenderSystem>()`.
class RenderSystem : public core::System {
public:
    /// `window`: swap its buffers after each frame; null: the caller does. `logger`: where
    /// font and sprite-sheet errors of the components go; null: nowhere (each component keeps
    /// its error readable).
    explicit RenderSystem(Renderer& renderer, Window* window = nullptr,
                          core::Logger* logger = nullptr);
    ~RenderSystem() override;
    RenderSystem(const RenderSystem&) = delete;
    RenderSystem& operator=(const RenderSystem&) = delete;

    [[nodiscard]] Renderer& renderer() const noexcept { return renderer_; }
    /// Fonts and glyph atlases of the renderer, shared by every TextLabel.
    [[nodiscard]] TextRenderer& text();
    /// The logger given at construction (may be null).
    [[nodiscard]] core::Logger* logger() const noexcept { return logger_; }
    /// Registers / unregisters a hook called every frame before drawing, in registration order.
    void addHook(RenderHook& hook);
    void removeHook(RenderHook& hook) noexcept;
    /// The sprite sheet (TexturePacker JSON) at `path`, read on the first call for that path
    /// and kept for the system's lifetime, so thousands of animated sprites share one parse.
    /// A file that cannot be read or parsed is logged once (file and reason) and gives
    /// nullptr, now and on later calls; sheetError(path) keeps the reason. Never throws.
    [[nodiscard]] const SpriteSheet* sheet(const std::filesystem::path& path);
    /// Why the sheet at `path` could not be used; empty if it could (or was never asked).
    [[nodiscard]] std::string sheetError(const std::filesystem::path& path) const;

    /// The camera used when no CameraComponent is active.
    [[nodiscard]] Camera& camera() noexcept { return camera_; }
    /// The camera of the last (or next) frame: the active component's, else camera().
    [[nodiscard]] Camera& activeCamera() noexcept;

    void render(double alpha) override;
    void clear() override;
    /// Closes every font (their atlas textures go; TextRenderer references handed out by
    /// text() become invalid) and destroys every texture no sprite uses
    /// (Renderer::destroyUnusedTextures()). Returns the number of textures destroyed. For a
    /// scene change, after clear(): the next scene loads what it uses.
    int releaseUnusedTextures();

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
    core::Logger* logger_ = nullptr;
    Camera camera_;
    std::unique_ptr<TextRenderer> text_;
    std::vector<RenderHook*> hooks_;
    std::vector<SpriteRenderer*> sprites_;
    std::vector<CameraComponent*> cameras_;
    std::map<std::string, std::unique_ptr<SpriteSheet>, std::less<>> sheets_;
    std::map<std::string, std::string, std::less<>> sheetErrors_;
};

} // namespace e2d::render
