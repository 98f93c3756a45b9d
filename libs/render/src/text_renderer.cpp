// SPDX-License-Identifier: MIT
#include <e2d/render/text_renderer.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>
#include <e2d/core/log.hpp>
#include <e2d/render/image.hpp>

#include <cmath>
#include <cstring>

namespace e2d::render {
namespace {

void checkDraw(const char* function, const TextDraw& where) {
    core::requireFinite(function, "position", where.position);
    core::requireFinite(function, "z", where.z);
    core::requireFinite(function, "rotation", where.rotation);
    if (!(where.scale.x > 0.0f && where.scale.y > 0.0f && core::isFinite(where.scale))) {
        core::throwError(function,
                         "scale must be > 0 and finite, got " + core::formatVector(where.scale));
    }
}

} // namespace

TextRenderer::TextRenderer(Renderer& renderer, core::Logger* logger)
    : renderer_(renderer), logger_(logger) {}

TextRenderer::~TextRenderer() {
    for (auto& [key, entry] : fonts_) {
        if (!entry.atlas.texture.isNull()) {
            renderer_.destroyTexture(entry.atlas.texture);
        }
    }
}

Font* TextRenderer::font(const std::filesystem::path& path, int pixelSize) {
    if (pixelSize < 1 || pixelSize > 1024) {
        throw core::Error("render::TextRenderer::font(): pixelSize must be in [1, 1024], got " +
                          std::to_string(pixelSize));
    }
    const std::string name = path.string();
    if (const auto failed = errors_.find(name); failed != errors_.end()) {
        return name == kDefaultFontPath ? nullptr : font(kDefaultFontPath, pixelSize);
    }
    const auto key = std::make_pair(name, pixelSize);
    if (const auto it = fonts_.find(key); it != fonts_.end()) {
        return it->second.font.get();
    }
    try {
        auto opened = std::make_unique<Font>(
            FontDef{.path = path, .pixelSize = pixelSize, .logger = logger_});
        Font* result = opened.get();
        fonts_.emplace(key, Entry{std::move(opened), {}});
        return result;
    } catch (const core::Error& e) {
        std::string message = e.what();
        if (name != kDefaultFontPath) {
            message +=
                "; drawing with the default font '" + std::string(kDefaultFontPath) + "' instead";
        } else {
            message += "; text in this font is not drawn";
        }
        if (logger_ != nullptr) {
            logger_->error(message);
        }
        errors_.emplace(name, e.what());
        return name == kDefaultFontPath ? nullptr : font(kDefaultFontPath, pixelSize);
    }
}

std::string TextRenderer::fontError(const std::filesystem::path& path) const {
    const auto it = errors_.find(path.string());
    return it == errors_.end() ? std::string() : it->second;
}

TextRenderer::Entry* TextRenderer::find(const Font& font) {
    for (auto& [key, entry] : fonts_) {
        if (entry.font.get() == &font) {
            return &entry;
        }
    }
    return nullptr;
}

TextureId TextRenderer::atlas(Font& font) {
    Entry* entry = find(font);
    if (entry == nullptr) {
        throw core::Error(
            "render::TextRenderer::atlas(): the font is not one of this TextRenderer's");
    }
    Atlas& atlas = entry->atlas;
    const glm::ivec2 size = font.atlasSize();
    const auto pixels = font.atlasPixels();
    if (atlas.texture.isNull() || atlas.generation != font.atlasGeneration() ||
        !renderer_.isValid(atlas.texture)) {
        if (!atlas.texture.isNull()) {
            renderer_.destroyTexture(atlas.texture);
        }
        Image image{size.x, size.y, std::vector<std::uint8_t>(pixels.begin(), pixels.end())};
        atlas.texture = renderer_.createTexture(image, TextureDef{.filter = TextureFilter::Linear});
        atlas.generation = font.atlasGeneration();
        font.clearDirty();
        return atlas.texture;
    }
    const PixelRect dirty = font.dirtyRect();
    if (dirty.w > 0 && dirty.h > 0) {
        const std::size_t rowBytes = static_cast<std::size_t>(dirty.w) * 4u;
        scratch_.resize(rowBytes * static_cast<std::size_t>(dirty.h));
        for (int row = 0; row < dirty.h; ++row) {
            std::memcpy(scratch_.data() + static_cast<std::size_t>(row) * rowBytes,
                        pixels.data() + (static_cast<std::size_t>(dirty.y + row) *
                                             static_cast<std::size_t>(size.x) +
                                         static_cast<std::size_t>(dirty.x)) *
                                            4u,
                        rowBytes);
        }
        renderer_.updateTexture(atlas.texture, {dirty.x, dirty.y}, {dirty.w, dirty.h}, scratch_);
        font.clearDirty();
    }
    return atlas.texture;
}

TextLayout TextRenderer::draw(Font& font, std::string_view utf8, const TextStyle& style,
                              const TextDraw& where) {
    checkDraw("render::TextRenderer::draw()", where);
    TextLayout layout = layoutText(font, utf8, style);
    submit(font, layout, where);
    return layout;
}

void TextRenderer::submit(Font& font, const TextLayout& layout, const TextDraw& where) {
    checkDraw("render::TextRenderer::submit()", where);
    if (layout.quads.empty()) {
        return;
    }
    const TextureId texture = atlas(font);
    const glm::vec2 atlasSize(font.atlasSize());
    const float c = std::cos(where.rotation);
    const float s = std::sin(where.rotation);
    Quad quad;
    quad.texture = texture;
    quad.z = where.z;
    quad.rotation = where.rotation;
    quad.pivot = {0.0f, 0.0f};
    quad.tint = where.color;
    quad.hud = where.hud;
    for (const GlyphQuad& g : layout.quads) {
        // The quad's bottom-left corner, scaled then rotated about the anchor.
        const glm::vec2 corner = g.rect.min * where.scale;
        quad.position =
            where.position + glm::vec2(c * corner.x - s * corner.y, s * corner.x + c * corner.y);
        quad.size = (g.rect.max - g.rect.min) * where.scale;
        quad.uv =
            Rect{glm::vec2(static_cast<float>(g.atlasRect.x), static_cast<float>(g.atlasRect.y)) /
                     atlasSize,
                 glm::vec2(static_cast<float>(g.atlasRect.w), static_cast<float>(g.atlasRect.h)) /
                     atlasSize};
        renderer_.submit(quad);
    }
}

} // namespace e2d::render
