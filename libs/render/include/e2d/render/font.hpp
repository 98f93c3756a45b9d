// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/render/sprite_sheet.hpp>

#include <glm/vec2.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>

namespace e2d::core {
class Logger;
}

namespace e2d::render {

/// The font used when none is given or a requested one cannot be loaded (fonts-dejavu-core).
inline constexpr const char* kDefaultFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// How a Font is opened. Font's constructor validates every field.
struct FontDef {
    /// TrueType / OpenType (or any format FreeType reads) file. Default kDefaultFontPath.
    std::filesystem::path path = kDefaultFontPath;
    /// Nominal size (em height), pixels, in [1, 1024]. Default 32.
    int pixelSize = 32;
    /// Width of the glyph atlas, pixels, in [64, 8192]. Default 512.
    int atlasWidth = 512;
    /// The atlas grows in height (doubling) up to this, pixels, in [64, 8192]. Default 4096.
    int maxAtlasHeight = 4096;
    /// Where a full atlas (once) and glyphs FreeType cannot draw (code point, glyph and
    /// FreeType's reason; the first 8) are reported; nullptr: not reported. Default nullptr.
    core::Logger* logger = nullptr;
};

/// One rasterised glyph of a Font.
struct Glyph {
    /// FreeType glyph index (0 is the font's .notdef).
    unsigned index = 0;
    /// Where the coverage lies in the atlas, pixels, top-left origin (row `y` is the glyph's
    /// top row). Zero size for blank glyphs (space).
    PixelRect atlasRect;
    /// From the pen position on the baseline to the bitmap's left edge and top edge, pixels,
    /// x right, y up (FreeType's bitmap_left / bitmap_top).
    glm::ivec2 bearing{0, 0};
    /// How far the pen moves after this glyph, pixels (hinted, so whole pixels).
    float advance = 0.0f;
    /// The font has no glyph for the code point: this is its .notdef glyph.
    bool missing = false;
};

/// A font face at one pixel size, with its glyph atlas: an RGBA8 image (white, coverage in
/// alpha) filled on demand as code points are asked for, which the renderer uploads as a
/// texture. Owns its FreeType library instance: no global state, fonts may live on different
/// threads (one font is not thread-safe).
class Font {
public:
    /// Opens `def.path` at `def.pixelSize` and rasterises its .notdef glyph. Throws core::Error
    /// naming the function, field and value for a bad def, or the file and FreeType's reason
    /// when the file cannot be read as a font (`render::Font: '/x/readme.txt' is not a font
    /// FreeType reads: unknown file format (FreeType error 0x02)`), is a directory, or opens
    /// but draws nothing (a file cut short: none of the letters and digits it maps has ink).
    explicit Font(const FontDef& def = {});
    ~Font();
    Font(Font&&) noexcept;
    Font& operator=(Font&&) noexcept;
    Font(const Font&) = delete;
    Font& operator=(const Font&) = delete;

    /// The glyph of `codePoint`, rasterised into the atlas the first time it is asked for.
    /// A code point the font lacks gives the .notdef glyph (`missing` set). If the atlas is full
    /// at maxAtlasHeight, new glyphs also come back as .notdef (reported once to the logger), and
    /// so does a glyph FreeType cannot draw (reported with the code point and FreeType's reason).
    /// The reference stays valid until the next call that rasterises a glyph.
    [[nodiscard]] const Glyph& glyph(char32_t codePoint);
    /// Pen adjustment between two glyphs, pixels (negative moves the right one closer), from the
    /// font's kerning table; 0 when the font has none.
    [[nodiscard]] float kerning(const Glyph& left, const Glyph& right) const;
    /// The font has a kerning table.
    [[nodiscard]] bool hasKerning() const noexcept;

    [[nodiscard]] const FontDef& def() const noexcept;
    /// Family name as the font gives it ("DejaVu Sans").
    [[nodiscard]] const char* familyName() const noexcept;
    /// Baseline to the top of the tallest glyphs, pixels, > 0.
    [[nodiscard]] float ascender() const noexcept;
    /// Baseline to the bottom of the lowest glyphs, pixels, <= 0.
    [[nodiscard]] float descender() const noexcept;
    /// Baseline-to-baseline distance, pixels.
    [[nodiscard]] float lineHeight() const noexcept;

    /// Atlas size, pixels. The height grows; positions of glyphs already in it never move.
    [[nodiscard]] glm::ivec2 atlasSize() const noexcept;
    /// Atlas pixels, RGBA8, top row first (as Image), atlasSize().x * atlasSize().y * 4 bytes.
    [[nodiscard]] std::span<const std::uint8_t> atlasPixels() const noexcept;
    /// Changes whenever atlasSize() changes (the texture must be recreated).
    [[nodiscard]] std::uint64_t atlasGeneration() const noexcept;
    /// The part of the atlas written since the last clearDirty() (pixels, top-left origin);
    /// zero size when nothing changed.
    [[nodiscard]] PixelRect dirtyRect() const noexcept;
    void clearDirty() noexcept;
    /// Glyphs rasterised so far (.notdef included).
    [[nodiscard]] int glyphCount() const noexcept;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace e2d::render
