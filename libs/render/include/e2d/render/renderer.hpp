// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/id.hpp>
#include <e2d/core/log.hpp>
#include <e2d/render/camera.hpp>
#include <e2d/render/drawer.hpp>
#include <e2d/render/image.hpp>
#include <e2d/render/texture.hpp>
#include <e2d/render/types.hpp>

#include <glm/vec2.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>

/// Instanced sprite rendering.
///
/// Everything drawn is a textured quad. Persistent quads are *sprites* (createSprite(), kept
/// until destroyed, rebuilt only when changed); quads for one frame only go through
/// submit() (text glyphs that are re-laid out, debug shapes, particles). Both are sorted and
/// batched together, so a glyph is batched exactly like a sprite: a text label is sprites (or
/// submitted quads) with UV rectangles in a glyph-atlas texture (createTexture() +
/// updateTexture()).
///
/// Each frame (render()):
/// 1. opaque pass: quads whose tint alpha is 255 and whose texture has no texel with alpha
///    strictly between 0 and 255; strict depth test and write, texels with alpha < 0.5
///    discarded, sorted by texture (last first) then front to back, and of equal-z quads the
///    one that ends on top first (depth does the ordering, so one batch per texture, and the
///    quads it covers are rejected before shading);
/// 2. translucent pass: the rest, blended, depth-tested against the opaque pass, sorted back
///    to front by z, a batch broken only where the texture changes in that order.
/// Each batch is one instanced draw call (FrameStats::drawCalls == FrameStats::batches).
/// Quads of one texture at equal z overlap in the order of their ids' slots (creation order
/// while no sprite was destroyed; submitted quads after sprites, in submission order), the
/// later on top, in both passes; at equal z across textures the order is the texture's.
/// Larger z is nearer the viewer; z is mapped to depth over [-RendererDef::depthRange,
/// +depthRange] (clamped beyond).
///
/// Per-instance data is 32 bytes (see src/instance.hpp): the quad's origin corner x, y and z as
/// floats, its two edge vectors (size, scale, rotation and flips folded in) as four half
/// floats, the UV rectangle as four unorm16, the tint as RGBA8. On OpenGL >= 4.4 (or
/// GL_ARB_buffer_storage) it is written straight into a persistently mapped ring of buffers
/// guarded by fences; otherwise into an orphaned buffer mapped for writing. Half floats carry
/// 11 significant bits: a quad edge of length L is exact to about L / 2048 (0.06 px for 128 px).
namespace e2d::render {

class Window;

struct SpriteIdTag;
/// A sprite of a Renderer (core::Id: slot index + 1 and the slot's 16-bit generation, so an
/// id kept after Renderer::destroySprite() is refused). Default-constructed: null.
using SpriteId = core::Id<SpriteIdTag>;
static_assert(sizeof(SpriteId) == 8);

inline constexpr SpriteId kNullSpriteId{};

/// Everything a sprite is. Renderer::createSprite() and the setters validate every field.
///
/// The quad is `size * scale` large; the pivot (a fraction of the quad, (0, 0) bottom-left,
/// (1, 1) top-right) sits at `position` and the quad rotates about it.
struct SpriteDef {
    /// Image drawn; null: the renderer's 1 x 1 white texture (a plain tinted rectangle).
    /// Default null.
    TextureId texture{};
    /// Pivot position, world units (camera units for a HUD sprite), finite. Default (0, 0).
    glm::vec2 position{0.0f, 0.0f};
    /// Depth order: larger is nearer, finite. Default 0.
    float z = 0.0f;
    /// Quad size before scaling, world units, each >= 0 and finite; (0, 0): the texture's size
    /// in pixels times the UV rectangle's extent. Default (0, 0).
    glm::vec2 size{0.0f, 0.0f};
    /// Multiplies size, finite (negative mirrors about the pivot). Default (1, 1).
    glm::vec2 scale{1.0f, 1.0f};
    /// Radians counter-clockwise about the pivot, finite. Default 0.
    float rotation = 0.0f;
    /// Fraction of the quad at `position`, finite. Default (0.5, 0.5) (centre).
    glm::vec2 pivot{0.5f, 0.5f};
    /// Multiplies the texels; alpha < 255 puts the sprite in the translucent pass.
    /// Default opaque white.
    Color tint{};
    /// Part of the texture shown, fraction of the texture, top-left origin (see Image), each
    /// coordinate in [0, 1], size >= 0. Default the whole texture.
    Rect uv = kFullUv;
    /// The `uv` region holds the image stored turned 90 degrees clockwise (a TexturePacker
    /// frame with `rotated: true`): the sprite shows it upright, so the region's height is the
    /// image's width (the automatic size is the region's extent swapped). Default false.
    bool uvRotated = false;
    /// Mirror the image (not the quad: the pivot stays where it is). Default false.
    bool flipX = false;
    bool flipY = false;
    /// How much the sprite follows camera movement: it is drawn at
    /// `camera + parallax * (position - camera)`, so 0.5 moves half as far on screen as the
    /// camera moves, 0 stays put on screen, 1 is normal. Affects position only (not size or
    /// rotation), >= 0 and finite. Default 1.
    float parallax = 1.0f;
    /// Camera space (HUD): position and size are camera units (origin at the view's centre),
    /// camera position, rotation and zoom do not apply. Default false.
    bool hud = false;
    /// Default true.
    bool visible = true;
};

/// A quad for one frame only (Renderer::submit()); same meaning as the SpriteDef fields.
/// `size` must be given (no texture-size default).
struct Quad {
    TextureId texture{};
    glm::vec2 position{0.0f, 0.0f};
    float z = 0.0f;
    glm::vec2 size{0.0f, 0.0f};
    float rotation = 0.0f;
    glm::vec2 pivot{0.0f, 0.0f};
    Color tint{};
    Rect uv = kFullUv;
    bool hud = false;
};

/// How a Renderer is created. The constructor validates every field.
struct RendererDef {
    /// Draw into an offscreen framebuffer of this size (pixels, each >= 1) instead of the
    /// window's; (0, 0): the window's framebuffer. Default (0, 0).
    glm::ivec2 offscreenSize{0, 0};
    /// Use the OpenGL 3.3 path (orphaned buffers) even when the context offers buffer
    /// storage. Default false.
    bool forceGl33 = false;
    /// Frames in flight of the persistently mapped ring, in [2, 8]. Default 3.
    int ringFrames = 3;
    /// z in [-depthRange, depthRange] maps to the depth buffer's range, > 0 and finite.
    /// Default 1000.
    float depthRange = 1000.0f;
    /// When set, every texture loaded from a file (loadTexture()) is sampled with this filter,
    /// whatever its TextureDef says (a game-wide setting such as the config's
    /// textureFilteringMode); textures made from memory keep their own. Default unset.
    std::optional<TextureFilter> fileTextureFilter{};
    /// Screen colour inside the camera's region. Default opaque black.
    Color clearColor{0, 0, 0, 255};
    /// Screen colour of the letterbox bars. Default opaque black.
    Color letterboxColor{0, 0, 0, 255};
    /// Where load errors and GL messages go (each failing file once); null: nowhere (the
    /// error stays readable through textureInfo()). Default null.
    core::Logger* logger = nullptr;
};

/// Counts of the last render() call.
struct FrameStats {
    int sprites = 0;   ///< quads drawn (sprites and submitted quads after culling)
    int culled = 0;    ///< visible sprites and quads left out because they were off screen
    int rebuilt = 0;   ///< sprites whose instance data was recomputed this frame
    int batches = 0;   ///< batches formed (opaque + translucent)
    int drawCalls = 0; ///< glDraw* calls issued (counted where they are made)
    int opaqueBatches = 0;
    int translucentBatches = 0;
    bool persistentMapping = false; ///< the 4.4 ring was used
    int debugDrawCalls = 0; ///< glDraw* calls of the Drawer's shapes (0, 1 or 2; not in drawCalls)
};

namespace detail {
struct RendererImpl;
}

/// Owns textures and sprites and draws them with one instanced draw call per batch.
///
/// Needs the OpenGL context of `window` current on the calling thread; the window must
/// outlive the renderer.
class Renderer {
public:
    /// Throws core::Error naming an invalid field of `def`, or when the offscreen framebuffer
    /// cannot be created or the shaders fail to compile (with the driver's log).
    explicit Renderer(Window& window, const RendererDef& def = {});
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Textures ----------------------------------------------------------------------------

    /// The texture of the image file at `path`, loaded on the first call for that path
    /// (later calls return the same id; `def` of the first call wins). Never throws for a bad
    /// file: a missing, corrupt or 0 x 0 file, or an image wider or taller than the GPU takes
    /// (GL_MAX_TEXTURE_SIZE), gives a texture that draws the magenta/black checker placeholder,
    /// its error (file and reason) is logged once and kept in textureInfo(id).error.
    TextureId loadTexture(const std::filesystem::path& path, const TextureDef& def = {});
    /// A texture from RGBA8 pixels in memory (rows from the top). Throws core::Error for an
    /// empty image, a pixel count that does not match its size, or a size beyond
    /// GL_MAX_TEXTURE_SIZE.
    TextureId createTexture(const Image& image, const TextureDef& def = {});
    /// Replaces a `size` rectangle of texels at `offset` (pixels, top-left origin) with
    /// `rgba` (size.x * size.y * 4 bytes, rows from the top). Throws core::Error for a stale
    /// id, a rectangle outside the texture or a short buffer. Mipmaps are rebuilt.
    void updateTexture(TextureId id, glm::ivec2 offset, glm::ivec2 size,
                       std::span<const std::uint8_t> rgba);
    /// Frees a texture; sprites still using it draw the placeholder. False for a null or stale
    /// id.
    bool destroyTexture(TextureId id);
    [[nodiscard]] bool isValid(TextureId id) const noexcept;
    /// Throws core::Error for a null or stale id.
    [[nodiscard]] const TextureInfo& textureInfo(TextureId id) const;
    /// The 1 x 1 white texture used for a null texture id.
    [[nodiscard]] TextureId whiteTexture() const noexcept;
    /// Textures alive (loaded, created, or placeholders of failed loads), not counting the
    /// renderer's own white and checker textures.
    [[nodiscard]] int textureCount() const noexcept;
    /// Destroys every texture that no sprite uses, except those in `keep` (and the renderer's
    /// own); a later loadTexture() of the same file loads it again. Returns how many went.
    /// For a scene change: the new scene's textures are loaded as it asks for them.
    int destroyUnusedTextures(std::span<const TextureId> keep = {});

    // Sprites -----------------------------------------------------------------------------

    /// Throws core::Error naming the invalid field ("render::Renderer::createSprite(): parallax
    /// must be >= 0, got -1") or a stale texture id.
    SpriteId createSprite(const SpriteDef& def = {});
    /// False (and nothing happens) for a null or stale id.
    bool destroySprite(SpriteId id);
    /// Destroys every sprite (a scene change).
    void destroyAllSprites();
    [[nodiscard]] bool isValid(SpriteId id) const noexcept;
    [[nodiscard]] int spriteCount() const noexcept;
    /// The sprite's current definition. Throws core::Error for a null or stale id.
    [[nodiscard]] const SpriteDef& sprite(SpriteId id) const;
    /// Replaces every field at once (validated as in createSprite()).
    void setSprite(SpriteId id, const SpriteDef& def);

    /// Single-field setters: throw core::Error for a stale id or an invalid value. Setting the
    /// value a sprite already has costs nothing at the next frame.
    void setPosition(SpriteId id, glm::vec2 position);
    void setZ(SpriteId id, float z);
    void setSize(SpriteId id, glm::vec2 size);
    void setScale(SpriteId id, glm::vec2 scale);
    void setRotation(SpriteId id, float radians);
    void setPivot(SpriteId id, glm::vec2 pivot);
    void setTint(SpriteId id, Color tint);
    /// The UV rectangle and whether the image is stored turned in it (SpriteDef::uvRotated).
    void setUv(SpriteId id, const Rect& uv, bool uvRotated = false);
    void setFlip(SpriteId id, bool flipX, bool flipY);
    void setParallax(SpriteId id, float parallax);
    void setHud(SpriteId id, bool hud);
    void setVisible(SpriteId id, bool visible);
    void setTexture(SpriteId id, TextureId texture);
    /// Position, z, rotation and scale together (what a component does every frame).
    void setTransform(SpriteId id, glm::vec2 position, float z, float rotation, glm::vec2 scale);

    // Transient quads ---------------------------------------------------------------------

    /// Draws `quad` in the next render() only, sorted and batched with the sprites. Throws
    /// core::Error for a non-finite or negative size or a stale texture id.
    void submit(const Quad& quad);

    // Debug drawing -----------------------------------------------------------------------

    /// Debug lines and shapes for the next render(), drawn after (on top of) the sprites,
    /// clipped to the camera's region, in at most two draw calls; render() clears it.
    [[nodiscard]] Drawer& drawer() noexcept;

    // Frames ------------------------------------------------------------------------------

    /// Draws everything into the target (window framebuffer or offscreen) as seen by
    /// `camera`, after setting the camera's screen size to the target's size (so it refits
    /// on resize). Does not swap buffers (Window::swapBuffers()). Clears the transient quads.
    void render(Camera& camera);
    /// Counts of the last render().
    [[nodiscard]] const FrameStats& stats() const noexcept;
    /// Size in pixels of what render() draws into.
    [[nodiscard]] glm::ivec2 targetSize() const noexcept;
    /// True when the 4.4 persistently mapped ring is in use.
    [[nodiscard]] bool persistentMapping() const noexcept;

    /// The last rendered frame read back (rows from the top, as Image always is).
    [[nodiscard]] Image readPixels() const;
    /// readPixels() written as a PNG. Throws core::Error naming the file on failure.
    void screenshot(const std::filesystem::path& path) const;

private:
    std::unique_ptr<detail::RendererImpl> impl_;
};

} // namespace e2d::render
