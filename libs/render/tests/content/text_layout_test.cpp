// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
#include <e2d/core/log.hpp>
#include <e2d/render/font.hpp>
#include <e2d/render/text.hpp>

#include "font_files.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/common.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using e2d::core::Error;
using e2d::render::Font;
using e2d::render::FontDef;
using e2d::render::HorizontalAlign;
using e2d::render::layoutText;
using e2d::render::TextLayout;
using e2d::render::TextStyle;
using e2d::render::VerticalAlign;
using testing::HasSubstr;

namespace {

std::string fontError(const FontDef& def) {
    try {
        Font font(def);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

// Draws a layout's quads into a CPU image by copying atlas coverage, as the GPU would with
// nearest sampling: returns the coverage image and its origin in layout pixels.
struct Canvas {
    int width = 0;
    int height = 0;
    glm::vec2 origin{0.0f, 0.0f};
    std::vector<int> alpha;
    int at(int x, int y) const { return alpha[static_cast<std::size_t>(y * width + x)]; }
};

Canvas paint(const Font& font, const TextLayout& layout, int margin) {
    Canvas c;
    c.origin = layout.bounds.min - glm::vec2(static_cast<float>(margin));
    c.width = static_cast<int>(layout.bounds.max.x - layout.bounds.min.x) + 2 * margin;
    c.height = static_cast<int>(layout.bounds.max.y - layout.bounds.min.y) + 2 * margin;
    c.alpha.assign(static_cast<std::size_t>(c.width * c.height), 0);
    const glm::ivec2 atlas = font.atlasSize();
    const auto pixels = font.atlasPixels();
    for (const auto& q : layout.quads) {
        const int x0 = static_cast<int>(q.rect.min.x - c.origin.x);
        const int y0 = static_cast<int>(q.rect.min.y - c.origin.y);
        const int ax = q.atlasRect.x;
        const int ay = q.atlasRect.y;
        const int w = static_cast<int>(q.rect.max.x - q.rect.min.x);
        const int h = static_cast<int>(q.rect.max.y - q.rect.min.y);
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                // Canvas rows go up, atlas rows go down.
                const int a =
                    pixels[static_cast<std::size_t>(((ay + h - 1 - y) * atlas.x + ax + x) * 4 + 3)];
                int& dst = c.alpha[static_cast<std::size_t>((y0 + y) * c.width + x0 + x)];
                dst = std::max(dst, a);
            }
        }
    }
    return c;
}

} // namespace

TEST(Font, OpensTheDefaultFont) {
    Font font(FontDef{.pixelSize = 48});
    EXPECT_STREQ(font.familyName(), "DejaVu Sans");
    EXPECT_GT(font.ascender(), 0.0f);
    EXPECT_LT(font.descender(), 0.0f);
    // Line height and ascender - descender are rounded separately: within a pixel or two.
    EXPECT_NEAR(font.lineHeight(), font.ascender() - font.descender(), 2.0f);
    EXPECT_TRUE(font.hasKerning());
    EXPECT_EQ(font.glyphCount(), 1); // .notdef only
}

TEST(Font, KerningOfAVIsMinusThreePixelsAt48) {
    Font font(FontDef{.pixelSize = 48});
    const auto a = font.glyph(U'A');
    const auto v = font.glyph(U'V');
    EXPECT_EQ(font.kerning(a, v), -3.0f);
}

TEST(Font, GlyphsAreRasterisedIntoTheAtlasOnDemand) {
    Font font(FontDef{.pixelSize = 32});
    font.clearDirty();
    const auto a = font.glyph(U'A');
    EXPECT_FALSE(a.missing);
    EXPECT_NE(a.index, 0u);
    EXPECT_GT(a.atlasRect.w, 10);
    EXPECT_GT(a.atlasRect.h, 10);
    EXPECT_GT(a.advance, 0.0f);
    // The dirty rectangle holds the new glyph and the atlas has coverage inside it.
    const auto dirty = font.dirtyRect();
    EXPECT_LE(dirty.x, a.atlasRect.x);
    EXPECT_GE(dirty.x + dirty.w, a.atlasRect.x + a.atlasRect.w);
    int ink = 0;
    const auto pixels = font.atlasPixels();
    for (int y = a.atlasRect.y; y < a.atlasRect.y + a.atlasRect.h; ++y) {
        for (int x = a.atlasRect.x; x < a.atlasRect.x + a.atlasRect.w; ++x) {
            ink += pixels[static_cast<std::size_t>((y * font.atlasSize().x + x) * 4 + 3)] > 128 ? 1
                                                                                                : 0;
        }
    }
    EXPECT_GT(ink, 30);
    // An 'A' is wide at the bottom and narrow at the top: the atlas is top-down.
    const auto rowInk = [&](int y) {
        int n = 0;
        for (int x = a.atlasRect.x; x < a.atlasRect.x + a.atlasRect.w; ++x) {
            n += pixels[static_cast<std::size_t>((y * font.atlasSize().x + x) * 4 + 3)] > 0 ? 1 : 0;
        }
        return n;
    };
    int first = -1;
    int last = -1;
    for (int x = a.atlasRect.x; x < a.atlasRect.x + a.atlasRect.w; ++x) {
        if (pixels[static_cast<std::size_t>(
                ((a.atlasRect.y + a.atlasRect.h - 1) * font.atlasSize().x + x) * 4 + 3)] > 0) {
            last = x;
            first = first < 0 ? x : first;
        }
    }
    EXPECT_GT(last - first, a.atlasRect.w / 2);
    EXPECT_LT(rowInk(a.atlasRect.y), a.atlasRect.w / 2);
    // Asking again rasterises nothing.
    const int count = font.glyphCount();
    font.clearDirty();
    static_cast<void>(font.glyph(U'A'));
    EXPECT_EQ(font.glyphCount(), count);
    EXPECT_EQ(font.dirtyRect().w, 0);
}

TEST(Font, PrintableAsciiAndLatin1AreAllPresent) {
    Font font(FontDef{.pixelSize = 16});
    for (char32_t c = 0x21; c < 0x7F; ++c) {
        EXPECT_FALSE(font.glyph(c).missing) << static_cast<unsigned>(c);
    }
    for (char32_t c = 0xA1; c <= 0xFF; ++c) {
        EXPECT_FALSE(font.glyph(c).missing) << static_cast<unsigned>(c);
    }
}

TEST(Font, AMissingGlyphIsTheNotdefGlyph) {
    Font font(FontDef{.pixelSize = 32});
    // DejaVu Sans has no CJK ideographs.
    const auto g = font.glyph(U'\u4E00');
    EXPECT_TRUE(g.missing);
    EXPECT_EQ(g.index, 0u);
    EXPECT_GT(g.atlasRect.w, 0); // DejaVu's .notdef is a visible box
}

TEST(Font, TheAtlasGrowsWithoutMovingGlyphs) {
    Font font(FontDef{.pixelSize = 40, .atlasWidth = 128});
    const auto a = font.glyph(U'A');
    const auto generation = font.atlasGeneration();
    const auto before = font.atlasSize();
    std::vector<std::uint8_t> aPixels;
    const auto copyA = [&] {
        std::vector<std::uint8_t> out;
        const auto pixels = font.atlasPixels();
        for (int y = a.atlasRect.y; y < a.atlasRect.y + a.atlasRect.h; ++y) {
            for (int x = a.atlasRect.x; x < a.atlasRect.x + a.atlasRect.w; ++x) {
                out.push_back(
                    pixels[static_cast<std::size_t>((y * font.atlasSize().x + x) * 4 + 3)]);
            }
        }
        return out;
    };
    aPixels = copyA();
    for (char32_t c = 0x21; c <= 0xFF; ++c) {
        static_cast<void>(font.glyph(c));
    }
    EXPECT_GT(font.atlasSize().y, before.y);
    EXPECT_NE(font.atlasGeneration(), generation);
    EXPECT_EQ(font.glyph(U'A').atlasRect, a.atlasRect);
    EXPECT_EQ(copyA(), aPixels);
}

TEST(Font, AFullAtlasFallsBackToNotdefAndSaysSoOnce) {
    std::vector<std::string> messages;
    e2d::core::Logger logger(
        e2d::core::LogLevel::Info,
        [&](e2d::core::LogLevel, std::string_view m) { messages.emplace_back(m); });
    Font font(FontDef{.pixelSize = 48, .atlasWidth = 64, .maxAtlasHeight = 64, .logger = &logger});
    int missing = 0;
    for (char32_t c = U'A'; c <= U'Z'; ++c) {
        missing += font.glyph(c).missing ? 1 : 0;
    }
    EXPECT_GT(missing, 10);
    EXPECT_EQ(font.atlasSize(), glm::ivec2(64, 64));
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_THAT(messages[0], HasSubstr("glyph atlas full at 64x64"));
}

TEST(Font, AFileThatIsNotAFontIsAnErrorNamingIt) {
    const auto path = std::filesystem::temp_directory_path() / "e2d_not_a_font.ttf";
    std::ofstream(path) << "this is not a font";
    EXPECT_EQ(fontError({.path = path}),
              "render::Font: '" + path.string() +
                  "' is not a font FreeType reads: unknown file format (FreeType error 0x02)");
    EXPECT_EQ(fontError({.path = "/nonexistent/font.ttf"}),
              "render::Font: '/nonexistent/font.ttf' is not a font FreeType reads: cannot open "
              "resource (FreeType error 0x01)");
}

TEST(Font, AFontCutShortThatDrawsNothingSaysSo) {
    // head -c 60 % of a font whose outlines come last: FreeType opens it and every glyph is empty.
    const auto path = e2d::render::test::writeCutShortFont("e2d_cut_short.ttf");
    EXPECT_EQ(fontError({.path = path}),
              "render::Font: '" + path.string() +
                  "' draws nothing: none of its glyphs for A-Z, a-z and 0-9 has "
                  "an outline or a bitmap (is the file cut short or damaged?)");
    // Cut after its outlines, the same font draws.
    e2d::render::test::SfntFile whole;
    whole.moveToEnd("post");
    const auto tail = std::filesystem::temp_directory_path() / "e2d_cut_tail.ttf";
    whole.save(tail, 0.97);
    EXPECT_EQ(fontError({.path = tail}), "(no error)");
}

TEST(Font, AGlyphFreeTypeCannotDrawIsLoggedWithItsCodePointAndReason) {
    const unsigned a = Font(FontDef{}).glyph(U'A').index;
    e2d::render::test::SfntFile damaged;
    damaged.breakGlyph(a);
    const auto path = std::filesystem::temp_directory_path() / "e2d_broken_a.ttf";
    damaged.save(path);
    std::vector<std::string> messages;
    e2d::core::Logger logger(
        e2d::core::LogLevel::Info,
        [&](e2d::core::LogLevel, std::string_view m) { messages.emplace_back(m); });
    Font font(FontDef{.path = path, .pixelSize = 20, .logger = &logger});
    EXPECT_TRUE(font.glyph(U'A').missing);
    EXPECT_FALSE(font.glyph(U'B').missing);
    EXPECT_TRUE(font.glyph(U'A').missing); // asked again: not reported again
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_EQ(messages[0], "render::Font: '" + path.string() +
                               "' at 20 px: cannot draw U+0041 (glyph " + std::to_string(a) +
                               "): invalid outline (FreeType error 0x14); drawing .notdef instead");
}

TEST(Font, FreeTypeErrorsAreNamedFromFreeTypesOwnList) {
    // No hmtx table: FreeType's error 0x93, which FT_Error_String() leaves unnamed in Debian's build.
    e2d::render::test::SfntFile noMetrics;
    noMetrics.drop("hmtx");
    const auto path = std::filesystem::temp_directory_path() / "e2d_no_hmtx.ttf";
    noMetrics.save(path);
    EXPECT_EQ(fontError({.path = path}), "render::Font: '" + path.string() +
                                             "' is not a font FreeType reads: horizontal metrics "
                                             "(hmtx) table missing (FreeType error 0x93)");
}

TEST(Font, ADirectoryIsNamedAsOne) {
    const auto dir = std::filesystem::temp_directory_path() / "e2d_font_dir.ttf";
    std::filesystem::create_directories(dir);
    EXPECT_EQ(fontError({.path = dir}),
              "render::Font: '" + dir.string() + "' is a directory, not a font file");
}

TEST(Font, InvalidDefsNameFieldAndValue) {
    EXPECT_EQ(fontError({.pixelSize = 0}),
              "render::Font::Font(): pixelSize must be in [1, 1024], got 0");
    EXPECT_EQ(fontError({.atlasWidth = 32}),
              "render::Font::Font(): atlasWidth must be in [64, 8192], got 32");
    EXPECT_EQ(fontError({.maxAtlasHeight = 9000}),
              "render::Font::Font(): maxAtlasHeight must be in [64, 8192], got 9000");
}

TEST(TextLayout, KernedAVIsNarrowerThanUnkerned) {
    Font font(FontDef{.pixelSize = 48});
    const auto kerned = layoutText(font, "AV");
    const auto plain = layoutText(font, "AV", {.kerning = false});
    EXPECT_EQ(plain.lineWidths[0], font.glyph(U'A').advance + font.glyph(U'V').advance);
    EXPECT_EQ(kerned.lineWidths[0], plain.lineWidths[0] - 3.0f);
    ASSERT_EQ(kerned.quads.size(), 2u);
    EXPECT_EQ(kerned.quads[1].rect.min.x, plain.quads[1].rect.min.x - 3.0f);
}

TEST(TextLayout, HelloHasInkInsideItsBoxOnly) {
    Font font(FontDef{.pixelSize = 32});
    const auto layout = layoutText(font, "Hello");
    EXPECT_EQ(layout.quads.size(), 5u);
    const int margin = 4;
    const Canvas c = paint(font, layout, margin);
    // No glyph of "Hello" overhangs its advance or the font's ascender/descender, so the ink
    // lies inside the alignment box, and the box is not much larger than the ink.
    int inside = 0;
    int outside = 0;
    glm::vec2 inkMin{1e9f, 1e9f};
    glm::vec2 inkMax{-1e9f, -1e9f};
    for (int y = 0; y < c.height; ++y) {
        for (int x = 0; x < c.width; ++x) {
            if (c.at(x, y) == 0) {
                continue;
            }
            const glm::vec2 p =
                c.origin + glm::vec2(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
            const bool in = p.x > layout.box.min.x && p.x < layout.box.max.x &&
                            p.y > layout.box.min.y && p.y < layout.box.max.y;
            ++(in ? inside : outside);
            inkMin = glm::min(inkMin, p);
            inkMax = glm::max(inkMax, p);
        }
    }
    EXPECT_GT(inside, 100);
    EXPECT_EQ(outside, 0);
    EXPECT_LT(inkMin.x - layout.box.min.x, 5.0f);
    EXPECT_LT(layout.box.max.x - inkMax.x, 5.0f);
    // Left aligned at the top: the box starts at x = 0 and hangs below y = 0.
    EXPECT_EQ(layout.box.min.x, 0.0f);
    EXPECT_EQ(layout.box.max.y, 0.0f);
    EXPECT_EQ(layout.box.min.y, -(std::round(font.ascender()) - std::round(font.descender())));
}

TEST(TextLayout, AlignmentPlacesTheBoxAroundTheAnchor) {
    Font font(FontDef{.pixelSize = 24});
    const std::string text = "Wide line\nshort";
    const auto left = layoutText(font, text, {.horizontal = HorizontalAlign::Left});
    const float width = left.lineWidths[0];
    ASSERT_GT(width, left.lineWidths[1]);
    const float height = left.box.max.y - left.box.min.y;

    const auto center = layoutText(
        font, text, {.horizontal = HorizontalAlign::Center, .vertical = VerticalAlign::Center});
    EXPECT_NEAR(center.box.min.x, -width / 2.0f, 0.5f);
    EXPECT_NEAR(center.box.max.x, width / 2.0f, 0.5f);
    EXPECT_NEAR(center.box.max.y, height / 2.0f, 0.5f);
    EXPECT_NEAR(center.box.min.y, -height / 2.0f, 0.5f);

    const auto right = layoutText(
        font, text, {.horizontal = HorizontalAlign::Right, .vertical = VerticalAlign::Bottom});
    EXPECT_EQ(right.box.max.x, 0.0f);
    EXPECT_EQ(right.box.min.x, -width);
    EXPECT_EQ(right.box.min.y, 0.0f);
    EXPECT_EQ(right.box.max.y, height);
    // Each line ends at the anchor: the last glyph of each line ends near x = 0.
    const auto& lastOfShort = right.quads.back();
    EXPECT_NEAR(lastOfShort.rect.max.x, 0.0f, 3.0f);
    // Every alignment moves all quads by the same vector per line: the first line's first glyph.
    EXPECT_EQ(right.quads[0].rect.min.x - left.quads[0].rect.min.x, -width);
    EXPECT_EQ(right.quads[0].rect.min.y - left.quads[0].rect.min.y, height);
}

TEST(TextLayout, LineBreaksStackLinesOneLineHeightApart) {
    Font font(FontDef{.pixelSize = 20});
    const auto one = layoutText(font, "x");
    const auto three = layoutText(font, "x\nx\r\nx");
    EXPECT_EQ(three.lineCount, 3);
    ASSERT_EQ(three.quads.size(), 3u);
    const float step = std::round(font.lineHeight());
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(three.quads[static_cast<std::size_t>(i)].rect.min.x, one.quads[0].rect.min.x);
        EXPECT_EQ(three.quads[static_cast<std::size_t>(i)].rect.min.y,
                  one.quads[0].rect.min.y - step * static_cast<float>(i));
    }
    EXPECT_EQ(three.box.max.y - three.box.min.y, (one.box.max.y - one.box.min.y) + 2.0f * step);
    const auto spaced = layoutText(font, "x\nx", {.lineSpacing = 2.0f});
    EXPECT_EQ(spaced.quads[1].rect.min.y,
              one.quads[0].rect.min.y - std::round(2.0f * font.lineHeight()));
}

TEST(TextLayout, InvalidUtf8AndMissingGlyphsStillDraw) {
    Font font(FontDef{.pixelSize = 20});
    const auto layout = layoutText(font, "a\xFF"
                                         "b\xE4\xB8\x80");
    ASSERT_EQ(layout.quads.size(), 4u);
    EXPECT_EQ(layout.quads[1].codePoint, 0xFFFDu);
    EXPECT_EQ(layout.quads[3].codePoint, 0x4E00u);
    EXPECT_TRUE(layout.quads[3].missing);
    EXPECT_FALSE(layout.quads[2].missing);
    // Latin-1 is drawn, not replaced.
    const auto latin = layoutText(font, "\xC3\xA9t\xC3\xA9");
    for (const auto& q : latin.quads) {
        EXPECT_FALSE(q.missing);
    }
}

TEST(TextLayout, EmptyTextAndControlCharacters) {
    Font font(FontDef{.pixelSize = 20});
    const auto empty = layoutText(font, "");
    EXPECT_TRUE(empty.quads.empty());
    EXPECT_EQ(empty.lineCount, 1);
    EXPECT_EQ(empty.lineWidths[0], 0.0f);
    const auto tabbed = layoutText(font, "\ta\x01");
    ASSERT_EQ(tabbed.quads.size(), 1u);
    EXPECT_EQ(tabbed.lineWidths[0], 4.0f * font.glyph(U' ').advance + font.glyph(U'a').advance);
    try {
        static_cast<void>(layoutText(font, "x", {.lineSpacing = 0.0f}));
        FAIL();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(),
                    HasSubstr("render::layoutText(): lineSpacing must be finite and > 0, got 0"));
    }
}
