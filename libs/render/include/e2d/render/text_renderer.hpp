// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/render/font.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/text.hpp>

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

namespace e2d::core {
class Logger;
}

namespace e2d::render {

/// Where and how laid-out text is drawn.
struct TextDraw {
    /// The layout's anchor (see TextStyle's alignment), world units (camera units for HUD
    /// text), finite. Default (0, 0).
    glm::vec2 position{0.0f, 0.0f};
    /// Depth order, as SpriteDef::z. Default 0.
    float z = 0.0f;
    /// Radians counter-clockwise about the anchor, finite. Default 0.
    float rotation = 0.0f;
    /// World units per font pixel, each > 0 and finite. Default (1, 1).
    glm::vec2 scale{1.0f, 1.0f};
    /// Multiplies the glyphs (white) with their coverage as alpha. Default opaque white.
    Color color{};
    /// Camera space (HUD), as SpriteDef::hud. Default false.
    bool hud = false;
};

/// Fonts and their glyph atlases as textures of one Renderer, and text drawn through the
/// Renderer's own batching: every glyph is a quad submitted with Renderer::submit(), UV
/// rectangle in its font's atlas texture, so a text is one batch per font atlas (sorted with
/// the sprites by z in the translucent pass, as glyph edges are translucent).
///
/// The Renderer must outlive this object.
class TextRenderer {
public:
    /// `logger`: where font load errors go (each failing file once); null: nowhere (the error
    /// stays readable through fontError()).
    explicit TextRenderer(Renderer& renderer, core::Logger* logger = nullptr);
    ~TextRenderer();
    TextRenderer(const TextRenderer&) = delete;
    TextRenderer& operator=(const TextRenderer&) = delete;

    /// The font at `path` and `pixelSize` (in [1, 1024]), opened on the first call for that
    /// pair. A file FreeType cannot read is reported once (file and reason, kept in
    /// fontError(path)) and the default font (kDefaultFontPath) at that size is used instead;
    /// if that cannot be read either, nullptr: the text is not drawn and the frame goes on.
    /// Never throws for a bad file; core::Error for a pixelSize out of range.
    [[nodiscard]] Font* font(const std::filesystem::path& path, int pixelSize);
    /// Why the font file at `path` could not be used; empty if it could (or was never asked).
    [[nodiscard]] std::string fontError(const std::filesystem::path& path) const;

    /// The atlas texture of `font` (a font of this TextRenderer), with every glyph rasterised
    /// so far uploaded: a new texture when the atlas grew, else only the changed rectangle.
    TextureId atlas(Font& font);

    /// Lays `utf8` out (see layoutText()) and submits it for the next Renderer::render().
    /// Returns the layout, in font pixels relative to the anchor. Throws core::Error for an
    /// invalid `where` or `style`.
    TextLayout draw(Font& font, std::string_view utf8, const TextStyle& style,
                    const TextDraw& where);
    /// Submits an existing layout of `font` (glyphs still in its atlas: a layout is valid for
    /// the font it was made with) for the next render().
    void submit(Font& font, const TextLayout& layout, const TextDraw& where);

private:
    struct Atlas {
        TextureId texture{};
        std::uint64_t generation = 0;
    };
    struct Entry {
        std::unique_ptr<Font> font;
        Atlas atlas;
    };

    Entry* find(const Font& font);

    Renderer& renderer_;
    core::Logger* logger_ = nullptr;
    std::map<std::pair<std::string, int>, Entry> fonts_;
    // Errors by path; a failed path maps to the default font's entry for its size.
    std::map<std::string, std::string> errors_;
    std::vector<std::uint8_t> scratch_;
};

} // namespace e2d::render
