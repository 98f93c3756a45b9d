// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/component.hpp>
#include <e2d/render/renderer.hpp>

#include <string>

namespace e2d::render {

class RenderSystem;

/// How a SpriteRenderer starts.
struct SpriteRendererDef {
    /// Image file, loaded through the Renderer's cache when the component starts; empty: use
    /// `texture`. Default "".
    std::string texturePath{};
    /// Texture when `texturePath` is empty; null: plain white (tinted). Default null.
    TextureId texture{};
    /// Filtering and mipmaps for `texturePath`. Default linear, no mipmaps.
    TextureDef textureDef{};
    /// Quad size before the object's scale, world units; (0, 0): texture size times the UV
    /// rectangle's extent. Default (0, 0).
    glm::vec2 size{0.0f, 0.0f};
    /// Fraction of the quad at the object's position. Default (0.5, 0.5).
    glm::vec2 pivot{0.5f, 0.5f};
    /// Default opaque white.
    Color tint{};
    /// Default the whole texture.
    Rect uv = kFullUv;
    /// See SpriteDef::uvRotated. Default false.
    bool uvRotated = false;
    bool flipX = false;
    bool flipY = false;
    /// See SpriteDef::parallax. Default 1.
    float parallax = 1.0f;
    /// Camera space (HUD): the object's position is read as camera units. Default false.
    bool hud = false;
    /// Added to the object's world z (the sprite's depth order). Default 0.
    float zOffset = 0.0f;
    /// Default true.
    bool visible = true;
};

/// Puts a sprite at its game object: position (x, y), z, rotation and scale follow the
/// object's world transform (parent chain included) every frame, and it is hidden while the
/// object is inactive (core::GameObject::setActive()). The sprite is created when
/// the object enters the scene and destroyed with the component. The RenderSystem is found
/// with `scene()->system<RenderSystem>()` (core::Error naming the type when the scene has none).
class SpriteRenderer : public core::Component {
public:
    /// Throws core::Error naming an invalid field of `def` (checked as SpriteDef's).
    explicit SpriteRenderer(const SpriteRendererDef& def = {});
    ~SpriteRenderer() override;

    /// Null before the object entered the scene and after the component left.
    [[nodiscard]] SpriteId sprite() const noexcept { return sprite_; }
    /// Null before onInitialize.
    [[nodiscard]] RenderSystem* system() const noexcept { return system_; }
    [[nodiscard]] const SpriteRendererDef& def() const noexcept { return def_; }

    /// Change the look; applied at once when the sprite exists.
    void setTint(Color tint);
    /// The UV rectangle and whether the image is stored turned in it (SpriteDef::uvRotated).
    void setUv(const Rect& uv, bool uvRotated = false);
    /// Quad size before the object's scale, world units; (0, 0): the texture's size times the
    /// UV extent. Throws core::Error for a negative or non-finite size.
    void setSize(glm::vec2 size);
    void setFlip(bool flipX, bool flipY);
    void setVisible(bool visible);
    void setTexture(TextureId texture);

    void onInitialize() override;
    void onTerminate() override;

    /// Copies the object's world transform to the sprite (RenderSystem calls it each frame).
    void syncTransform();

protected:
    /// The def, for a derived component to fill in (texture, uv) before its sprite exists.
    [[nodiscard]] SpriteRendererDef& mutableDef() noexcept { return def_; }

private:
    SpriteRendererDef def_;
    RenderSystem* system_ = nullptr;
    SpriteId sprite_{};
};

/// How a CameraComponent starts: the camera's zoom, reference size and fit (its position and
/// rotation come from the object).
struct CameraComponentDef {
    /// Default 1.
    float zoom = 1.0f;
    /// Default 1280 x 720.
    glm::vec2 referenceSize{1280.0f, 720.0f};
    /// Default BestFit.
    ScreenFit fit = ScreenFit::BestFit;
};

/// A Camera as a component: its position and rotation follow the game object's
/// world transform. The RenderSystem draws through the first enabled one.
class CameraComponent : public core::Component {
public:
    /// Throws core::Error naming an invalid field (as CameraDef's).
    explicit CameraComponent(const CameraComponentDef& def = {});
    ~CameraComponent() override;

    [[nodiscard]] Camera& camera() noexcept { return camera_; }
    [[nodiscard]] const Camera& camera() const noexcept { return camera_; }
    /// A disabled camera is skipped by the RenderSystem. Default enabled.
    void setEnabled(bool enabled) noexcept { enabled_ = enabled; }
    [[nodiscard]] bool enabled() const noexcept { return enabled_; }

    void onInitialize() override;
    void onTerminate() override;

    /// Copies the object's world position and orientation to the camera.
    void syncTransform();

private:
    Camera camera_;
    RenderSystem* system_ = nullptr;
    bool enabled_ = true;
};

} // namespace e2d::render
