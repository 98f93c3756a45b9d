// SPDX-License-Identifier: MIT
#include <e2d/render/font.hpp>

#include <e2d/core/error.hpp>
#include <e2d/core/log.hpp>

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace e2d::render {
namespace {

// One pixel of empty border around every glyph, so linear filtering never bleeds neighbours in.
constexpr int kPadding = 1;

// FreeType's own list of its errors, made into a table at compile time from its header: the
// library is usually built without the texts FT_Error_String() would return.
struct FreetypeErrorText {
    int code;
    const char* text;
};
// clang-format off: the macros open and close an array, which clang-format cannot see
#undef FTERRORS_H_
#define FT_ERROR_START_LIST constexpr FreetypeErrorText kFreetypeErrors[] = {
#define FT_ERRORDEF(e, v, s) {v, s},
#define FT_ERROR_END_LIST                                                                          \
    }                                                                                              \
    ;
#include FT_ERRORS_H
// clang-format on

std::string freetypeReason(FT_Error error) {
    char code[16];
    std::snprintf(code, sizeof(code), "0x%02X", static_cast<unsigned>(error));
    for (const FreetypeErrorText& known : kFreetypeErrors) {
        if (known.code == error) {
            return std::string(known.text) + " (FreeType error " + code + ")";
        }
    }
    return std::string("FreeType error ") + code;
}

std::string codePointName(char32_t codePoint) {
    char text[16];
    std::snprintf(text, sizeof(text), "U+%04X", static_cast<unsigned>(codePoint));
    return text;
}

// Damaged glyphs reported per font; the last report says later ones are not.
constexpr int kMaxGlyphReports = 8;

[[noreturn]] void badField(const char* field, int value, const char* range) {
    throw core::Error(std::string("render::Font::Font(): ") + field + " must be in " + range +
                      ", got " + std::to_string(value));
}

} // namespace

struct Font::Impl {
    FontDef def;
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    std::unordered_map<char32_t, unsigned> indexOf;
    std::unordered_map<unsigned, Glyph> glyphs;
    std::vector<std::uint8_t> pixels;
    glm::ivec2 size{0, 0};
    std::uint64_t generation = 1;
    PixelRect dirty;
    // Shelf packing: glyphs go left to right on the current shelf; a new shelf starts above it.
    int shelfX = 0;
    int shelfY = 0;
    int shelfHeight = 0;
    bool reportedFull = false;
    int damagedGlyphs = 0;

    ~Impl() {
        if (face != nullptr) {
            FT_Done_Face(face);
        }
        if (library != nullptr) {
            FT_Done_FreeType(library);
        }
    }

    void markDirty(const PixelRect& r) {
        if (dirty.w == 0 || dirty.h == 0) {
            dirty = r;
            return;
        }
        const int x0 = std::min(dirty.x, r.x);
        const int y0 = std::min(dirty.y, r.y);
        const int x1 = std::max(dirty.x + dirty.w, r.x + r.w);
        const int y1 = std::max(dirty.y + dirty.h, r.y + r.h);
        dirty = {x0, y0, x1 - x0, y1 - y0};
    }

    // Finds room for a w x h bitmap (padding included), growing the atlas if needed.
    bool place(int w, int h, int& outX, int& outY) {
        const int pw = w + 2 * kPadding;
        const int ph = h + 2 * kPadding;
        if (pw > size.x) {
            return false;
        }
        if (shelfX + pw > size.x) {
            shelfY += shelfHeight;
            shelfX = 0;
            shelfHeight = 0;
        }
        while (shelfY + ph > size.y) {
            if (size.y * 2 > def.maxAtlasHeight) {
                return false;
            }
            size.y *= 2;
            pixels.resize(static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y) * 4u);
            ++generation;
            // The whole new texture must be uploaded.
            dirty = {0, 0, size.x, size.y};
        }
        outX = shelfX + kPadding;
        outY = shelfY + kPadding;
        shelfX += pw;
        shelfHeight = std::max(shelfHeight, ph);
        return true;
    }

    // Rasterises glyph `index`: empty on success, else why not (`atlasFull` tells the reasons
    // apart: a full atlas is a limit of the def, the others are the font's).
    std::string rasterise(unsigned index, Glyph& out, bool& atlasFull) {
        atlasFull = false;
        if (const FT_Error e = FT_Load_Glyph(face, index, FT_LOAD_RENDER | FT_LOAD_TARGET_NORMAL);
            e != 0) {
            return freetypeReason(e);
        }
        const FT_GlyphSlot slot = face->glyph;
        const FT_Bitmap& bitmap = slot->bitmap;
        out.index = index;
        out.advance = static_cast<float>(slot->advance.x) / 64.0f;
        out.bearing = {slot->bitmap_left, slot->bitmap_top};
        const int w = static_cast<int>(bitmap.width);
        const int h = static_cast<int>(bitmap.rows);
        if (w == 0 || h == 0) {
            out.atlasRect = {};
            return {};
        }
        if (bitmap.pixel_mode != FT_PIXEL_MODE_GRAY && bitmap.pixel_mode != FT_PIXEL_MODE_MONO) {
            return "FreeType gave a bitmap in pixel mode " + std::to_string(bitmap.pixel_mode) +
                   " (only grey and mono are drawn)";
        }
        int x = 0;
        int y = 0;
        if (!place(w, h, x, y)) {
            atlasFull = true;
            return "glyph atlas full at " + std::to_string(size.x) + "x" + std::to_string(size.y);
        }
        for (int row = 0; row < h; ++row) {
            const unsigned char* source =
                bitmap.buffer + static_cast<std::ptrdiff_t>(row) * bitmap.pitch;
            std::uint8_t* target = pixels.data() + (static_cast<std::size_t>(y + row) *
                                                        static_cast<std::size_t>(size.x) +
                                                    static_cast<std::size_t>(x)) *
                                                       4u;
            for (int col = 0; col < w; ++col) {
                const std::uint8_t coverage =
                    bitmap.pixel_mode == FT_PIXEL_MODE_GRAY
                        ? source[col]
                        : (((source[col / 8] >> (7 - col % 8)) & 1u) != 0 ? 255 : 0);
                target[col * 4 + 0] = 255;
                target[col * 4 + 1] = 255;
                target[col * 4 + 2] = 255;
                target[col * 4 + 3] = coverage;
            }
        }
        out.atlasRect = {x, y, w, h};
        markDirty(out.atlasRect);
        return {};
    }

    // Why the font draws nothing, or empty if it draws. A file cut short can open without an
    // error: FreeType drops a table that ends past the end of the file, and every glyph then
    // loads empty. So the letters and digits the font maps are loaded until one has ink.
    std::string inkless() const {
        std::string firstError;
        bool mapsAny = false;
        for (const auto& [first, last] :
             {std::pair{U'A', U'Z'}, std::pair{U'a', U'z'}, std::pair{U'0', U'9'}}) {
            for (char32_t c = first; c <= last; ++c) {
                const FT_UInt index = FT_Get_Char_Index(face, c);
                if (index == 0) {
                    continue;
                }
                mapsAny = true;
                if (const FT_Error e = FT_Load_Glyph(face, index, FT_LOAD_DEFAULT); e != 0) {
                    if (firstError.empty()) {
                        firstError = "; " + codePointName(c) + " (glyph " + std::to_string(index) +
                                     "): " + freetypeReason(e);
                    }
                    continue;
                }
                const FT_GlyphSlot slot = face->glyph;
                if (slot->format == FT_GLYPH_FORMAT_OUTLINE
                        ? slot->outline.n_points > 0
                        : slot->bitmap.width > 0 && slot->bitmap.rows > 0) {
                    return {};
                }
            }
        }
        if (!mapsAny) {
            return {};
        }
        return "draws nothing: none of its glyphs for A-Z, a-z and 0-9 has an outline or a bitmap "
               "(is the "
               "file cut short or damaged?)" +
               firstError;
    }

    // Says once per glyph why it is drawn as .notdef; a full atlas once per font.
    void reportUndrawable(char32_t codePoint, unsigned index, const std::string& why,
                          bool atlasFull) {
        if (def.logger == nullptr) {
            return;
        }
        const std::string font = "render::Font: '" + def.path.string() + "' at " +
                                 std::to_string(def.pixelSize) + " px: ";
        if (atlasFull) {
            if (!reportedFull) {
                def.logger->warning(font + why + "; new glyphs draw .notdef");
                reportedFull = true;
            }
            return;
        }
        ++damagedGlyphs;
        if (damagedGlyphs <= kMaxGlyphReports) {
            def.logger->warning(font + "cannot draw " + codePointName(codePoint) + " (glyph " +
                                std::to_string(index) + "): " + why + "; drawing .notdef instead" +
                                (damagedGlyphs == kMaxGlyphReports
                                     ? " (further damaged glyphs are not reported)"
                                     : ""));
        }
    }
};

Font::Font(const FontDef& def) : impl_(std::make_unique<Impl>()) {
    if (def.pixelSize < 1 || def.pixelSize > 1024) {
        badField("pixelSize", def.pixelSize, "[1, 1024]");
    }
    if (def.atlasWidth < 64 || def.atlasWidth > 8192) {
        badField("atlasWidth", def.atlasWidth, "[64, 8192]");
    }
    if (def.maxAtlasHeight < 64 || def.maxAtlasHeight > 8192) {
        badField("maxAtlasHeight", def.maxAtlasHeight, "[64, 8192]");
    }
    Impl& m = *impl_;
    m.def = def;
    const std::string name = def.path.string();
    std::error_code ec;
    if (std::filesystem::is_directory(def.path, ec)) {
        throw core::Error("render::Font: '" + name + "' is a directory, not a font file");
    }
    if (const FT_Error e = FT_Init_FreeType(&m.library); e != 0) {
        throw core::Error("render::Font: cannot start FreeType: " + freetypeReason(e));
    }
    if (const FT_Error e = FT_New_Face(m.library, name.c_str(), 0, &m.face); e != 0) {
        m.face = nullptr;
        throw core::Error("render::Font: '" + name +
                          "' is not a font FreeType reads: " + freetypeReason(e));
    }
    if (const FT_Error e = FT_Set_Pixel_Sizes(m.face, 0, static_cast<FT_UInt>(def.pixelSize));
        e != 0) {
        throw core::Error("render::Font: '" + name + "' has no size " +
                          std::to_string(def.pixelSize) + " px: " + freetypeReason(e));
    }
    if (const std::string why = m.inkless(); !why.empty()) {
        throw core::Error("render::Font: '" + name + "' " + why);
    }
    m.size = {def.atlasWidth, std::min(def.maxAtlasHeight, 64)};
    m.pixels.assign(static_cast<std::size_t>(m.size.x) * static_cast<std::size_t>(m.size.y) * 4u,
                    0);
    m.dirty = {0, 0, m.size.x, m.size.y};
    Glyph notdef;
    bool atlasFull = false;
    if (!m.rasterise(0, notdef, atlasFull).empty()) {
        // A font whose .notdef cannot be drawn still lays text out; missing glyphs are blank.
        notdef = Glyph{};
        notdef.advance = static_cast<float>(def.pixelSize) * 0.5f;
    }
    notdef.missing = true;
    m.glyphs.emplace(0u, notdef);
}

Font::~Font() = default;
Font::Font(Font&&) noexcept = default;
Font& Font::operator=(Font&&) noexcept = default;

const Glyph& Font::glyph(char32_t codePoint) {
    Impl& m = *impl_;
    if (const auto it = m.indexOf.find(codePoint); it != m.indexOf.end()) {
        return m.glyphs.at(it->second);
    }
    const unsigned index = FT_Get_Char_Index(m.face, codePoint);
    if (const auto it = m.glyphs.find(index); it != m.glyphs.end()) {
        m.indexOf.emplace(codePoint, index);
        return it->second;
    }
    Glyph g;
    bool atlasFull = false;
    if (const std::string why = m.rasterise(index, g, atlasFull); !why.empty()) {
        m.reportUndrawable(codePoint, index, why, atlasFull);
        m.indexOf.emplace(codePoint, 0u);
        return m.glyphs.at(0u);
    }
    m.indexOf.emplace(codePoint, index);
    return m.glyphs.emplace(index, g).first->second;
}

float Font::kerning(const Glyph& left, const Glyph& right) const {
    if (!FT_HAS_KERNING(impl_->face)) {
        return 0.0f;
    }
    FT_Vector delta{0, 0};
    if (FT_Get_Kerning(impl_->face, left.index, right.index, FT_KERNING_DEFAULT, &delta) != 0) {
        return 0.0f;
    }
    return static_cast<float>(delta.x) / 64.0f;
}

bool Font::hasKerning() const noexcept { return FT_HAS_KERNING(impl_->face); }
const FontDef& Font::def() const noexcept { return impl_->def; }
const char* Font::familyName() const noexcept {
    return impl_->face->family_name != nullptr ? impl_->face->family_name : "";
}
float Font::ascender() const noexcept {
    return static_cast<float>(impl_->face->size->metrics.ascender) / 64.0f;
}
float Font::descender() const noexcept {
    return static_cast<float>(impl_->face->size->metrics.descender) / 64.0f;
}
float Font::lineHeight() const noexcept {
    return static_cast<float>(impl_->face->size->metrics.height) / 64.0f;
}
glm::ivec2 Font::atlasSize() const noexcept { return impl_->size; }
std::span<const std::uint8_t> Font::atlasPixels() const noexcept { return impl_->pixels; }
std::uint64_t Font::atlasGeneration() const noexcept { return impl_->generation; }
PixelRect Font::dirtyRect() const noexcept { return impl_->dirty; }
void Font::clearDirty() noexcept { impl_->dirty = {}; }
int Font::glyphCount() const noexcept { return static_cast<int>(impl_->glyphs.size()); }

} // namespace e2d::render
