// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/id.hpp>

#include <glm/vec2.hpp>

#include <cstdint>
#include <string>

/// Textures are owned by a Renderer (Renderer::loadTexture(), Renderer::createTexture()) and
/// addressed by TextureId.
namespace e2d::render {

struct TextureIdTag;
/// A texture of a Renderer (core::Id: slot index + 1 and the slot's 16-bit generation, so an
/// id kept after Renderer::destroyTexture() is refused). Default-constructed: null (draws the
/// renderer's white texture).
using TextureId = core::Id<TextureIdTag>;
static_assert(sizeof(TextureId) == 8);

inline constexpr TextureId kNullTextureId{};

/// How texels are sampled.
enum class TextureFilter {
    Nearest, ///< crisp pixels (pixel art, exact-pixel tests)
    Linear,  ///< bilinear (and trilinear between mip levels when mipmapped)
};

/// How a texture is created.
struct TextureDef {
    /// Default Linear.
    TextureFilter filter = TextureFilter::Linear;
    /// Build a mip chain (for sprites drawn much smaller than their texture). Default false.
    bool mipmaps = false;
};

/// What a Renderer knows about one of its textures.
struct TextureInfo {
    /// Size in pixels. For a texture whose file failed to load: the placeholder's size (64 x 64).
    glm::ivec2 size{0, 0};
    /// The file it came from ("" for textures made from memory).
    std::string path;
    /// Some texel has an alpha strictly between 0 and 255: sprites using it are drawn in the
    /// translucent pass. (Alpha 0 or 255 only: the opaque pass, with alpha testing.)
    bool translucent = false;
    /// The file could not be loaded; the magenta/black checker is drawn instead.
    bool placeholder = false;
    /// Why it could not be loaded ("" when it loaded): names the file and the reason.
    std::string error;
    TextureDef def{};
};

} // namespace e2d::render
