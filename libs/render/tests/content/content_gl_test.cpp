// SPDX-License-Identifier: MIT
// Text, debug drawing and sprite sheets drawn by the real Renderer (Mesa llvmpipe under Xvfb),
// read back and compared with what the scene says. Every test writes its frame as a PNG in the
// working directory (content_gl_*.png).
#include <e2d/core/error.hpp>
#include <e2d/core/log.hpp>
#include <e2d/render/camera.hpp>
#include <e2d/render/drawer.hpp>
#include <e2d/render/font.hpp>
#include <e2d/render/image.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/sprite_sheet.hpp>
#include <e2d/render/text_renderer.hpp>
#include <e2d/render/window.hpp>

#include "font_files.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/common.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

using namespace e2d::render;
using e2d::core::Error;
using testing::HasSubstr;

namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 200;

// Screen pixels (origin bottom-left, y up) of a read-back frame.
struct Frame {
    Image image;
    [[nodiscard]] const std::uint8_t* at(int x, int y) const {
        return image.at(x, kHeight - 1 - y);
    }
    [[nodiscard]] int red(int x, int y) const { return at(x, y)[0]; }
};

// The ink of a frame: pixels whose red channel is above `threshold`, and their bounding box.
struct Ink {
    int count = 0;
    glm::ivec2 min{1 << 20, 1 << 20};
    glm::ivec2 max{-1, -1};
};

Ink inkIn(const Frame& f, int x0, int y0, int x1, int y1, int threshold = 0) {
    Ink ink;
    for (int y = std::max(0, y0); y < std::min(kHeight, y1); ++y) {
        for (int x = std::max(0, x0); x < std::min(kWidth, x1); ++x) {
            if (f.red(x, y) > threshold) {
                ++ink.count;
                ink.min = glm::min(ink.min, glm::ivec2(x, y));
                ink.max = glm::max(ink.max, glm::ivec2(x, y));
            }
        }
    }
    return ink;
}

class ContentGl : public ::testing::Test {
protected:
    void SetUp() override {
        setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
        WindowDef def;
        def.title = "e2d content test";
        def.size = {kWidth, kHeight};
        def.vsync = false;
        def.visible = false;
        window_ = std::make_unique<Window>(def);
        renderer_ =
            std::make_unique<Renderer>(*window_, RendererDef{.offscreenSize = {kWidth, kHeight}});
        // One world unit per pixel, world (0, 0) at the bottom-left pixel corner.
        camera_ = std::make_unique<Camera>(CameraDef{.position = {kWidth / 2.0f, kHeight / 2.0f},
                                                     .referenceSize = {kWidth, kHeight}});
    }

    Frame render(const std::string& png) {
        renderer_->render(*camera_);
        Frame f{renderer_->readPixels()};
        writePng(f.image, "content_gl_" + png + ".png");
        return f;
    }

    std::unique_ptr<Window> window_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<Camera> camera_;
};

} // namespace

TEST_F(ContentGl, HelloHasInkInsideItsMeasuredBoxAndTheAtlasCoverageExactly) {
    TextRenderer text(*renderer_);
    Font* font = text.font(kDefaultFontPath, 32);
    ASSERT_NE(font, nullptr);
    const glm::vec2 anchor{20.0f, 120.0f};
    const TextLayout layout = text.draw(*font, "Hello", {}, {.position = anchor});
    const Frame f = render("hello");

    // One quad per glyph, one batch (one atlas texture), one instanced draw call.
    EXPECT_EQ(renderer_->stats().sprites, 5);
    EXPECT_EQ(renderer_->stats().batches, 1);
    EXPECT_EQ(renderer_->stats().drawCalls, 1);

    // Every inked pixel lies inside the measured box; the box is filled with some ink.
    const Ink all = inkIn(f, 0, 0, kWidth, kHeight);
    const glm::vec2 boxMin = anchor + layout.box.min;
    const glm::vec2 boxMax = anchor + layout.box.max;
    const Ink inside = inkIn(f, static_cast<int>(boxMin.x), static_cast<int>(boxMin.y),
                             static_cast<int>(boxMax.x), static_cast<int>(boxMax.y));
    EXPECT_GT(all.count, 150);
    EXPECT_EQ(inside.count, all.count);
    EXPECT_LE(inside.min.x - boxMin.x, 4.0f);
    EXPECT_LE(boxMax.x - inside.max.x, 4.0f);

    // Glyph quads sit on whole pixels and sample texel centres: white text on black shows the
    // atlas coverage itself (within blending's rounding).
    const auto pixels = font->atlasPixels();
    const int atlasWidth = font->atlasSize().x;
    int compared = 0;
    for (const GlyphQuad& q : layout.quads) {
        const int x0 = static_cast<int>(anchor.x + q.rect.min.x);
        const int top = static_cast<int>(anchor.y + q.rect.max.y) - 1;
        for (int row = 0; row < q.atlasRect.h; ++row) {
            for (int col = 0; col < q.atlasRect.w; ++col) {
                const int coverage = pixels[static_cast<std::size_t>(
                    ((q.atlasRect.y + row) * atlasWidth + q.atlasRect.x + col) * 4 + 3)];
                ASSERT_NEAR(f.red(x0 + col, top - row), coverage, 1)
                    << "glyph " << static_cast<char>(q.codePoint) << " texel " << col << ", "
                    << row;
                ++compared;
            }
        }
    }
    EXPECT_GT(compared, 500);
}

TEST_F(ContentGl, KernedAVIsNarrowerThanUnkerned) {
    TextRenderer text(*renderer_);
    Font* font = text.font(kDefaultFontPath, 48);
    ASSERT_NE(font, nullptr);
    static_cast<void>(text.draw(*font, "AV", {}, {.position = {20.0f, 190.0f}}));
    static_cast<void>(text.draw(*font, "AV", {.kerning = false}, {.position = {20.0f, 95.0f}}));
    const Frame f = render("kerning");
    const Ink kerned = inkIn(f, 0, 100, kWidth, kHeight);
    const Ink plain = inkIn(f, 0, 0, kWidth, 100);
    ASSERT_GT(kerned.count, 100);
    ASSERT_GT(plain.count, 100);
    // DejaVu Sans kerns A-V by -3 px at 48 px; the V moves left, the A stays.
    EXPECT_EQ(kerned.min.x, plain.min.x);
    EXPECT_EQ((kerned.max.x - kerned.min.x) - (plain.max.x - plain.min.x), -3);
}

TEST_F(ContentGl, AlignmentModesPutTheInkWhereTheLayoutSays) {
    TextRenderer text(*renderer_);
    Font* font = text.font(kDefaultFontPath, 20);
    ASSERT_NE(font, nullptr);
    // Three labels in three corners / the centre, each in its own region of the frame.
    const glm::vec2 topLeft{10.0f, kHeight - 10.0f};
    const glm::vec2 centre{kWidth / 2.0f, kHeight / 2.0f};
    const glm::vec2 bottomRight{kWidth - 10.0f, 10.0f};
    const TextLayout a = text.draw(*font, "Top left", {}, {.position = topLeft});
    const TextLayout b =
        text.draw(*font, "Mid\nmiddle",
                  {.horizontal = HorizontalAlign::Center, .vertical = VerticalAlign::Center},
                  {.position = centre});
    const TextLayout c =
        text.draw(*font, "Bottom right",
                  {.horizontal = HorizontalAlign::Right, .vertical = VerticalAlign::Bottom},
                  {.position = bottomRight});
    const Frame f = render("alignment");

    const auto check = [&](const TextLayout& layout, glm::vec2 anchor, const char* name) {
        // All ink of this label is inside its bounds (the box joined with glyphs that overhang
        // it, like this 'T' whose antialiased edge reaches one pixel left of the pen).
        const glm::vec2 lo = anchor + layout.bounds.min;
        const glm::vec2 hi = anchor + layout.bounds.max;
        const Ink ink = inkIn(f, static_cast<int>(lo.x) - 8, static_cast<int>(lo.y) - 8,
                              static_cast<int>(hi.x) + 8, static_cast<int>(hi.y) + 8);
        const Ink bounded = inkIn(f, static_cast<int>(lo.x), static_cast<int>(lo.y),
                                  static_cast<int>(hi.x), static_cast<int>(hi.y));
        EXPECT_GT(ink.count, 50) << name;
        EXPECT_EQ(bounded.count, ink.count) << name;
        // Bounds exceed the box by at most a pixel or two for these strings.
        EXPECT_LE(layout.box.min.x - layout.bounds.min.x, 2.0f) << name;
        EXPECT_LE(layout.bounds.max.x - layout.box.max.x, 2.0f) << name;
        return ink;
    };
    const Ink inkA = check(a, topLeft, "top left");
    const Ink inkB = check(b, centre, "centre");
    const Ink inkC = check(c, bottomRight, "bottom right");
    // Left/top: the box starts at the anchor and hangs below it.
    EXPECT_EQ(a.box.min.x, 0.0f);
    EXPECT_EQ(a.box.max.y, 0.0f);
    EXPECT_LE(std::abs(static_cast<float>(inkA.min.x) - topLeft.x), 3.0f);
    EXPECT_LT(static_cast<float>(inkA.max.y), topLeft.y);
    // Centre: the box is centred on the anchor, and so (within the glyphs' bearings) is the ink.
    EXPECT_NEAR((b.box.min.x + b.box.max.x) / 2.0f, 0.0f, 0.5f);
    EXPECT_NEAR((b.box.min.y + b.box.max.y) / 2.0f, 0.0f, 0.5f);
    EXPECT_NEAR((inkB.min.x + inkB.max.x + 1) / 2.0f, centre.x, 3.0f);
    // Right/bottom: the box ends at the anchor.
    EXPECT_EQ(c.box.max.x, 0.0f);
    EXPECT_EQ(c.box.min.y, 0.0f);
    EXPECT_LE(bottomRight.x - static_cast<float>(inkC.max.x + 1), 3.0f);
    EXPECT_GE(static_cast<float>(inkC.min.y), bottomRight.y);
}

// A file that is not a font, and a font cut short (it used to open without a word and draw no
// quad at all): each gives its error, and the default font draws instead.
TEST_F(ContentGl, ABadFontGivesItsErrorTheDefaultFontAndTheNextFrameStillRenders) {
    const auto notAFont = std::filesystem::temp_directory_path() / "e2d_content_gl_not_a_font.ttf";
    std::ofstream(notAFont) << "plain text, not a font";
    const auto cutShort = e2d::render::test::writeCutShortFont("e2d_content_gl_cut_short.ttf");
    for (const auto& [path, reason] : {std::pair{notAFont, "is not a font FreeType reads"},
                                       std::pair{cutShort, "draws nothing"}}) {
        SCOPED_TRACE(path.string());
        std::vector<std::string> logged;
        e2d::core::Logger logger(
            e2d::core::LogLevel::Info,
            [&](e2d::core::LogLevel, std::string_view m) { logged.emplace_back(m); });
        TextRenderer text(*renderer_, &logger);
        Font* font = text.font(path, 24);
        // The default font stands in.
        ASSERT_NE(font, nullptr);
        EXPECT_EQ(font->def().path, kDefaultFontPath);
        EXPECT_THAT(text.fontError(path), HasSubstr("'" + path.string() + "' " + reason));
        ASSERT_EQ(logged.size(), 1u);
        EXPECT_THAT(logged[0], HasSubstr(path.string()));
        EXPECT_THAT(logged[0], HasSubstr("drawing with the default font"));
        // Asking again neither reloads nor logs again.
        EXPECT_EQ(text.font(path, 24), font);
        EXPECT_EQ(logged.size(), 1u);

        EXPECT_EQ(text.draw(*font, "first", {}, {.position = {10.0f, 150.0f}}).quads.size(), 5u);
        EXPECT_GT(inkIn(render("bad_font_1"), 0, 0, kWidth, kHeight).count, 50);
        static_cast<void>(text.draw(*font, "second", {}, {.position = {10.0f, 60.0f}}));
        const Frame second = render("bad_font_2");
        EXPECT_GT(inkIn(second, 0, 0, kWidth, 100).count, 50);
        EXPECT_EQ(inkIn(second, 0, 100, kWidth, kHeight).count, 0); // last frame's text is gone
    }
}

TEST_F(ContentGl, NewGlyphsAndAGrowingAtlasReachTheTexture) {
    TextRenderer text(*renderer_);
    Font* font = text.font(kDefaultFontPath, 28);
    ASSERT_NE(font, nullptr);
    static_cast<void>(text.draw(*font, "ab", {}, {.position = {10.0f, 190.0f}}));
    render("atlas_1");
    const auto generation = font->atlasGeneration();
    // Enough new glyphs to grow the atlas, then a line of them drawn: each must show ink.
    std::string latin;
    for (char32_t c = 0xC0; c <= 0xFF; ++c) {
        latin += static_cast<char>(0xC0 | (c >> 6));
        latin += static_cast<char>(0x80 | (c & 0x3F));
    }
    static_cast<void>(layoutText(*font, latin));
    EXPECT_NE(font->atlasGeneration(), generation);
    const TextLayout layout =
        text.draw(*font, "\xC3\x80\xC3\xBF ab", {}, {.position = {10.0f, 100.0f}});
    const Frame f = render("atlas_2");
    ASSERT_EQ(layout.quads.size(), 4u);
    for (const GlyphQuad& q : layout.quads) {
        const glm::vec2 lo = glm::vec2(10.0f, 100.0f) + q.rect.min;
        const glm::vec2 hi = glm::vec2(10.0f, 100.0f) + q.rect.max;
        EXPECT_GT(inkIn(f, static_cast<int>(lo.x), static_cast<int>(lo.y), static_cast<int>(hi.x),
                        static_cast<int>(hi.y), 128)
                      .count,
                  5)
            << "glyph U+" << std::hex << static_cast<unsigned>(q.codePoint);
    }
}

TEST_F(ContentGl, ASheetWhoseFrameLiesOutsideItsImageGivesItsError) {
    const auto dir = std::filesystem::temp_directory_path() / "e2d_content_gl_sheet";
    std::filesystem::create_directories(dir);
    Image image{32, 32, std::vector<std::uint8_t>(32 * 32 * 4, 255)};
    writePng(image, dir / "small.png");
    // meta.size claims 64 x 64; the real image is 32 x 32 and "b" lies beyond it.
    std::ofstream(dir / "sheet.json") << R"({"frames": {
        "a": {"frame": {"x": 0, "y": 0, "w": 16, "h": 16}},
        "b": {"frame": {"x": 40, "y": 0, "w": 16, "h": 16}}},
        "meta": {"image": "small.png", "size": {"w": 64, "h": 64}}})";
    const SpriteSheet sheet = SpriteSheet::fromFile(dir / "sheet.json");
    const TextureId texture = renderer_->loadTexture(sheet.imagePath());
    const glm::ivec2 size = renderer_->textureInfo(texture).size;
    EXPECT_EQ(size, glm::ivec2(32, 32));
    try {
        sheet.checkImageSize(size);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr((dir / "sheet.json").string() +
                                        ": frames[\"b\"].frame: frame \"b\" (x 40"));
        EXPECT_THAT(e.what(), HasSubstr("outside the 32x32 image loaded from '" +
                                        (dir / "small.png").string() + "'"));
    }
    // The frame that fits draws, and the next frame renders.
    const SpriteFrame& a = sheet.frame("a");
    renderer_->createSprite(
        {.texture = texture, .position = {50.0f, 50.0f}, .size = glm::vec2(a.size()), .uv = a.uv});
    EXPECT_EQ(render("sheet_1").red(50, 50), 255);
    EXPECT_EQ(render("sheet_2").red(50, 50), 255);
}

TEST_F(ContentGl, ALineCoversExactlyItsPixels) {
    // Ends on pixel centres, 3 px wide, square caps: x in [9, 102], y in [19, 22] exactly, so
    // columns 9..101 and rows 19..21.
    renderer_->drawer().line({10.5f, 20.5f}, {100.5f, 20.5f}, {1, 0, 0, 1}, 3.0f);
    // A vertical one in screen space, 1 px wide: column 200, rows 30..69 (caps add half a pixel).
    renderer_->drawer().line({200.5f, 30.5f}, {200.5f, 69.5f}, {1, 0, 0, 1}, 1.0f,
                             DrawSpace::Screen);
    const Frame f = render("line");
    EXPECT_EQ(renderer_->stats().debugDrawCalls, 1);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const bool horizontal = x >= 9 && x <= 101 && y >= 19 && y <= 21;
            const bool vertical = x == 200 && y >= 30 && y <= 69;
            ASSERT_EQ(f.red(x, y), horizontal || vertical ? 255 : 0) << x << ", " << y;
        }
    }
}

TEST_F(ContentGl, FilledRectAndCircleCoverTheirArea) {
    renderer_->drawer().fillRect({30.0f, 40.0f}, {70.0f, 60.0f}, {1, 0, 0, 1});
    const glm::vec2 centre{200.0f, 100.0f};
    const float radius = 40.0f;
    renderer_->drawer().fillCircle(centre, radius, {1, 0, 0, 1}, DrawSpace::World, 128);
    renderer_->drawer().rect({100.0f, 150.0f}, {140.0f, 180.0f}, {1, 0, 0, 1}, 2.0f);
    const Frame f = render("shapes");
    EXPECT_EQ(renderer_->stats().debugDrawCalls, 2);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const glm::vec2 p{static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f};
            const bool inRect = x >= 30 && x < 70 && y >= 40 && y < 60;
            const float d = glm::length(p - centre);
            // The 128-gon lies within 0.012 px of the circle inside; pixels on the rim are free.
            if (inRect || d < radius - 0.5f) {
                ASSERT_EQ(f.red(x, y), 255) << x << ", " << y;
            } else if (d > radius + 0.5f && !(x >= 98 && x <= 142 && y >= 148 && y <= 182)) {
                ASSERT_EQ(f.red(x, y), 0) << x << ", " << y;
            }
        }
    }
    // The outline: 2 px wide centred on the edges, hollow inside.
    EXPECT_EQ(f.red(99, 165), 255);
    EXPECT_EQ(f.red(100, 165), 255);
    EXPECT_EQ(f.red(98, 165), 0);
    EXPECT_EQ(f.red(101, 165), 0);
    EXPECT_EQ(f.red(120, 165), 0);
    EXPECT_EQ(f.red(120, 179), 255);
    EXPECT_EQ(f.red(120, 181), 0);
}

TEST_F(ContentGl, WorldShapesFollowTheCameraScreenShapesDoNot) {
    camera_->setPosition({kWidth / 2.0f + 40.0f, kHeight / 2.0f});
    renderer_->drawer().fillRect({100.0f, 100.0f}, {110.0f, 110.0f}, {1, 0, 0, 1});
    renderer_->drawer().fillRect({100.0f, 50.0f}, {110.0f, 60.0f}, {1, 0, 0, 1}, DrawSpace::Screen);
    const Frame f = render("spaces");
    // The camera moved 40 units right: the world square shows 40 px further left.
    EXPECT_EQ(f.red(65, 105), 255);
    EXPECT_EQ(f.red(105, 105), 0);
    EXPECT_EQ(f.red(105, 55), 255);
    EXPECT_EQ(f.red(65, 55), 0);
}

TEST_F(ContentGl, ThousandsOfLinesTakeOneDrawCall) {
    Drawer& d = renderer_->drawer();
    int lines = 0;
    for (int i = 0; i < 5000; ++i) {
        const float x = static_cast<float>(i % 300) + 10.5f;
        d.line({x, 10.5f}, {x, 10.5f + static_cast<float>(i % 150)}, {1, 0, 0, 1}, 1.0f);
        ++lines;
    }
    EXPECT_EQ(d.lines().size(), static_cast<std::size_t>(lines));
    const Frame f = render("many_lines");
    EXPECT_EQ(renderer_->stats().debugDrawCalls, 1);
    // The longest line of each column reaches its end: column 10 + k has lines of lengths
    // k, k + 300, ... mod 150.
    EXPECT_EQ(f.red(10 + 149, 10 + 149 - 1), 255);
    EXPECT_EQ(f.red(10 + 5, 10), 255);
    // The drawer is empty after the frame.
    EXPECT_TRUE(renderer_->drawer().empty());
    render("after_lines");
    EXPECT_EQ(renderer_->stats().debugDrawCalls, 0);
}
