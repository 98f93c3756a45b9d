// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/render/font.hpp>

#include <glm/vec2.hpp>

#include <string_view>
#include <vector>

namespace e2d::render {

/// Where a text block sits horizontally relative to its anchor (each line on its own).
enum class HorizontalAlign {
    Left,   ///< Lines start at the anchor.
    Center, ///< Lines are centred on the anchor.
    Right,  ///< Lines end at the anchor.
};

/// Where a text block sits vertically relative to its anchor.
enum class VerticalAlign {
    Top,    ///< The first line's ascender is at the anchor.
    Center, ///< The block's middle is at the anchor.
    Bottom, ///< The last line's descender is at the anchor.
};

/// How text is laid out.
struct TextStyle {
    /// Default HorizontalAlign::Left.
    HorizontalAlign horizontal = HorizontalAlign::Left;
    /// Default VerticalAlign::Top.
    VerticalAlign vertical = VerticalAlign::Top;
    /// Apply the font's kerning between glyph pairs. Default true.
    bool kerning = true;
    /// Multiplies the font's line height between baselines, finite, > 0. Default 1.
    float lineSpacing = 1.0f;
};

/// An axis-aligned rectangle, pixels, x right, y up.
struct TextRect {
    glm::vec2 min{0.0f, 0.0f};
    glm::vec2 max{0.0f, 0.0f};
};

/// One glyph to draw: a quad and where its pixels are in the font's atlas.
struct GlyphQuad {
    /// Quad corners, pixels relative to the anchor, x right, y up; whole numbers, so glyphs at
    /// a whole-pixel anchor land on pixel centres.
    TextRect rect;
    /// Where the glyph's pixels are in the font's atlas, pixels, top-left origin (the glyph's
    /// top-left corner goes with the quad's top-left). Pixels rather than texture coordinates,
    /// because the atlas may grow after the layout was made.
    PixelRect atlasRect;
    /// The code point drawn (U+FFFD for an ill-formed UTF-8 sequence).
    char32_t codePoint = 0;
    /// The font lacks it: the quad shows the font's .notdef glyph.
    bool missing = false;
};

/// Text laid out with one font: quads in drawing order and measurements.
struct TextLayout {
    /// One quad per visible glyph (spaces and control characters have none).
    std::vector<GlyphQuad> quads;
    /// The alignment box: from the first line's ascender to the last line's descender, from the
    /// leftmost line start to the rightmost line end (pen advances, kerning included).
    TextRect box;
    /// Everything drawn lies inside: `box` joined with every quad (glyphs may overhang their
    /// advance, e.g. a 'j' or an italic 'f').
    TextRect bounds;
    /// Number of lines ('\n' separates lines; "\r\n" counts once). At least 1.
    int lineCount = 1;
    /// Width of each line, pixels (pen advance, kerning included).
    std::vector<float> lineWidths;
};

/// Lays `utf8` out with `font` (rasterising glyphs into its atlas as needed) and `style`.
/// Ill-formed UTF-8 draws U+FFFD (the font's .notdef if it lacks that), a tab advances to the
/// next multiple of four spaces, other control characters are skipped. Never throws for any
/// input text; throws core::Error for a style with lineSpacing not finite and > 0.
[[nodiscard]] TextLayout layoutText(Font& font, std::string_view utf8, const TextStyle& style = {});

} // namespace e2d::render
