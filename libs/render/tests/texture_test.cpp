// SPDX-License-Identifier: MIT
// Image files through FreeImage: every format, orientation, the cache, and broken files that
// must give an error naming the file, a placeholder on screen, and a next frame that renders.
#include "render_test_util.hpp"

#include <e2d/core/error.hpp>
#include <e2d/core/log.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

namespace e2d::render::test {
namespace {

using ::testing::HasSubstr;

const std::filesystem::path kData = E2D_RENDER_TEST_DATA;

bool close(const std::uint8_t* p, Color c, int tolerance) {
    return near(Color{p[0], p[1], p[2], p[3]}, c, tolerance);
}

// The quadrant images (made with ImageMagick): 16 x 16 blue with the top-left 8 x 8 red.
TEST(LoadImage, ReadsEveryFormatTopRowFirst) {
    for (const char* ext : {"png", "jpg", "bmp", "tga", "gif"}) {
        SCOPED_TRACE(ext);
        Image image = loadImage(kData / (std::string("quadrant.") + ext));
        ASSERT_EQ(image.width, 16);
        ASSERT_EQ(image.height, 16);
        int tolerance = std::string(ext) == "jpg" ? 40 : 0;
        EXPECT_TRUE(close(image.at(2, 2), kRed, tolerance));
        EXPECT_TRUE(close(image.at(13, 2), kBlue, tolerance));
        EXPECT_TRUE(close(image.at(2, 13), kBlue, tolerance));
        EXPECT_TRUE(close(image.at(13, 13), kBlue, tolerance));
        EXPECT_EQ(image.at(5, 5)[3], 255);
    }
}

TEST(LoadImage, PngRoundTripKeepsEveryPixel) {
    Image image;
    image.width = 7;
    image.height = 5;
    for (int i = 0; i < 7 * 5; ++i) {
        image.pixels.insert(image.pixels.end(),
                            {static_cast<std::uint8_t>(i * 7), static_cast<std::uint8_t>(255 - i),
                             static_cast<std::uint8_t>(i * 3),
                             static_cast<std::uint8_t>(i * 5 + 10)});
    }
    std::filesystem::path file = outputDir() / "round_trip.png";
    writePng(image, file);
    Image back = loadImage(file);
    EXPECT_EQ(back.width, 7);
    EXPECT_EQ(back.height, 5);
    EXPECT_EQ(back.pixels, image.pixels);
    EXPECT_THROW(writePng(Image{}, outputDir() / "empty.png"), core::Error);
}

// Files that cannot be images, each with the reason that must be in the error.
struct Broken {
    std::string name;
    std::string reason;
};

std::vector<Broken> makeBrokenFiles(const std::filesystem::path& dir) {
    // A valid PNG of noise cut in half.
    Image noise;
    noise.width = 64;
    noise.height = 64;
    for (int i = 0; i < 64 * 64; ++i) {
        noise.pixels.insert(noise.pixels.end(),
                            {static_cast<std::uint8_t>(i * 31), static_cast<std::uint8_t>(i * 17),
                             static_cast<std::uint8_t>(i * 7), 255});
    }
    writePng(noise, dir / "whole.png");
    std::vector<char> png = readBytes(dir / "whole.png");
    png.resize(png.size() / 2);
    writeBytes(dir / "truncated.png", png);
    // A JPEG with a .png name.
    writeBytes(dir / "jpeg_named.png", readBytes(kData / "quadrant.jpg"));
    // A BMP header that says 0 x 0 pixels.
    std::vector<char> bmp(54, 0);
    auto put32 = [&](std::size_t at, std::uint32_t v) {
        for (int b = 0; b < 4; ++b) {
            bmp[at + static_cast<std::size_t>(b)] = static_cast<char>((v >> (8 * b)) & 0xffu);
        }
    };
    bmp[0] = 'B';
    bmp[1] = 'M';
    put32(2, 54);
    put32(10, 54);
    put32(14, 40);
    put32(18, 0); // width
    put32(22, 0); // height
    bmp[26] = 1;  // planes
    bmp[28] = 24; // bits per pixel
    writeBytes(dir / "empty.bmp", bmp);
    return {
        {"truncated.png", ""},
        {"jpeg_named.png", "the content is JPEG but the extension says PNG"},
        {"empty.bmp", ""},
        {"missing.png", "no such file"},
    };
}

TEST(LoadImage, BrokenFilesNameTheFileAndTheReason) {
    std::filesystem::path dir = outputDir() / "broken";
    std::filesystem::create_directories(dir);
    for (const Broken& broken : makeBrokenFiles(dir)) {
        SCOPED_TRACE(broken.name);
        try {
            static_cast<void>(loadImage(dir / broken.name));
            ADD_FAILURE() << "expected an error";
        } catch (const core::Error& error) {
            std::string what = error.what();
            EXPECT_THAT(what,
                        HasSubstr("render::loadImage(): " + (dir / broken.name).string() + ": "));
            EXPECT_THAT(what, HasSubstr(broken.reason));
            // Some reason follows the file name.
            EXPECT_GT(what.size(),
                      ("render::loadImage(): " + (dir / broken.name).string() + ": ").size() + 3)
                << what;
            std::cout << "  " << what << "\n";
        }
    }
}

class TextureRender : public testing::TestWithParam<Path> {};

// Each broken file: an error naming it, logged once however often it is loaded, the checker
// drawn where the sprite is, and the next frame renders normally.
TEST_P(TextureRender, BrokenFileDrawsThePlaceholderAndTheFrameGoesOn) {
    std::filesystem::path dir = outputDir() / ("broken-" + pathName({GetParam(), 0}));
    std::filesystem::create_directories(dir);
    std::vector<std::string> logged;
    core::Logger logger(core::LogLevel::Info, [&](core::LogLevel level, std::string_view message) {
        if (level == core::LogLevel::Error) {
            logged.emplace_back(message);
        }
    });
    Scene scene(GetParam(), {64, 64}, true, &logger);
    Camera camera = pixelCamera({64, 64});
    for (const Broken& broken : makeBrokenFiles(dir)) {
        SCOPED_TRACE(broken.name);
        scene.renderer.destroyAllSprites();
        logged.clear();
        std::filesystem::path file = dir / broken.name;
        TextureId texture =
            scene.renderer.loadTexture(file, TextureDef{.filter = TextureFilter::Nearest});
        EXPECT_EQ(scene.renderer.loadTexture(file), texture); // cached, failure included
        ASSERT_EQ(logged.size(), 1u);
        EXPECT_THAT(logged[0], HasSubstr(file.string()));
        const TextureInfo& info = scene.renderer.textureInfo(texture);
        EXPECT_TRUE(info.placeholder);
        EXPECT_THAT(info.error, HasSubstr(file.string()));
        EXPECT_THAT(info.error, HasSubstr(broken.reason));
        EXPECT_EQ(info.size, glm::ivec2(64, 64));
        // The checker (8 px squares, magenta at its top-left) fills the sprite: 64 x 64 at the
        // screen's centre covers the whole screen.
        scene.renderer.createSprite(SpriteDef{.texture = texture});
        Image image = scene.frame(camera, broken.name);
        const Color magenta{255, 0, 255, 255};
        int wrong = 0;
        for (int y = 0; y < 64; y += 3) {
            for (int x = 0; x < 64; x += 3) {
                int row = 63 - y; // image row from the top
                Color expected = ((x / 8) + (row / 8)) % 2 == 0 ? magenta : kBlack;
                wrong += near(pixel(image, x, y), expected, 0) ? 0 : 1;
            }
        }
        EXPECT_EQ(wrong, 0);
        // The next frame still renders what it is given.
        scene.renderer.createSprite(SpriteDef{.z = 1.0f, .size = {10.0f, 10.0f}, .tint = kRed});
        Image next = scene.frame(camera, broken.name + "-next");
        EXPECT_TRUE(near(pixel(next, 32, 32), kRed, 0));
        EXPECT_EQ(logged.size(), 1u);
    }
}

// A good file is loaded once (same id, same texture), drawn the right way up.
TEST_P(TextureRender, FileTextureIsCachedAndDrawnUpright) {
    Scene scene(GetParam(), {32, 32});
    Camera camera = pixelCamera({32, 32});
    TextureId texture = scene.renderer.loadTexture(kData / "quadrant.png",
                                                   TextureDef{.filter = TextureFilter::Nearest});
    EXPECT_EQ(scene.renderer.loadTexture(kData / "." / "quadrant.png"), texture);
    const TextureInfo& info = scene.renderer.textureInfo(texture);
    EXPECT_FALSE(info.placeholder);
    EXPECT_EQ(info.size, glm::ivec2(16, 16));
    EXPECT_FALSE(info.translucent);
    // Size (0, 0): the texture's 16 x 16 pixels, centred: screen [8, 24).
    scene.renderer.createSprite(SpriteDef{.texture = texture});
    Image image = scene.frame(camera);
    EXPECT_TRUE(near(pixel(image, 10, 21), kRed, 0))
        << str(pixel(image, 10, 21)); // top-left quarter
    EXPECT_TRUE(near(pixel(image, 21, 21), kBlue, 0));
    EXPECT_TRUE(near(pixel(image, 10, 10), kBlue, 0));
    EXPECT_TRUE(near(pixel(image, 4, 4), kBlack, 0));
}

// Updating a sub-rectangle of a memory texture (a glyph atlas does this) shows at once.
TEST_P(TextureRender, UpdateTextureReplacesASubRectangle) {
    Scene scene(GetParam(), {32, 32});
    Camera camera = pixelCamera({32, 32});
    Image image;
    image.width = 4;
    image.height = 4;
    image.pixels.assign(64, 0);
    TextureId texture =
        scene.renderer.createTexture(image, TextureDef{.filter = TextureFilter::Nearest});
    EXPECT_FALSE(scene.renderer.textureInfo(texture).translucent);
    scene.renderer.createSprite(
        SpriteDef{.texture = texture, .size = {16.0f, 16.0f}, .pivot = {0.0f, 0.0f}});
    // Texels (2..3, 0..1): the top-right 2 x 2, opaque green.
    std::vector<std::uint8_t> green(2 * 2 * 4);
    for (std::size_t i = 0; i < 4; ++i) {
        green[i * 4 + 1] = 255;
        green[i * 4 + 3] = 255;
    }
    scene.renderer.updateTexture(texture, {2, 0}, {2, 2}, green);
    Image frame = scene.frame(camera);
    // The sprite covers screen [16, 32); its top-right quarter is [24, 32) x [24, 32).
    EXPECT_TRUE(near(pixel(frame, 28, 28), kGreen, 0)) << str(pixel(frame, 28, 28));
    EXPECT_TRUE(near(pixel(frame, 20, 28), kBlack, 0));
    EXPECT_TRUE(near(pixel(frame, 28, 20), kBlack, 0));
    try {
        scene.renderer.updateTexture(texture, {3, 3}, {2, 2}, green);
        FAIL() << "expected an error";
    } catch (const core::Error& error) {
        EXPECT_THAT(
            error.what(),
            HasSubstr("render::Renderer::updateTexture(): rectangle at (3, 3) of size (2, 2) is "
                      "outside the 4 x 4 texture"));
    }
    // Partial alpha makes it translucent (the sprite moves to the blended pass).
    std::vector<std::uint8_t> half(4, 128);
    scene.renderer.updateTexture(texture, {0, 3}, {1, 1}, half);
    EXPECT_TRUE(scene.renderer.textureInfo(texture).translucent);
    scene.frame(camera, "translucent");
    EXPECT_EQ(scene.renderer.stats().translucentBatches, 1);
    EXPECT_EQ(scene.renderer.stats().opaqueBatches, 0);
}

TEST_P(TextureRender, DestroyedTextureDrawsThePlaceholder) {
    Scene scene(GetParam(), {16, 16});
    Camera camera = pixelCamera({16, 16});
    Image image;
    image.width = 1;
    image.height = 1;
    image.pixels = {0, 255, 0, 255};
    TextureId texture = scene.renderer.createTexture(image);
    scene.renderer.createSprite(SpriteDef{.texture = texture, .size = {16.0f, 16.0f}});
    EXPECT_TRUE(near(pixel(scene.frame(camera, "before"), 8, 8), kGreen, 0));
    EXPECT_TRUE(scene.renderer.destroyTexture(texture));
    EXPECT_FALSE(scene.renderer.isValid(texture));
    EXPECT_THROW(static_cast<void>(scene.renderer.textureInfo(texture)), core::Error);
    // The 64 x 64 checker squeezed onto 16 x 16: 2 px squares, magenta at the top-left.
    Image after = scene.frame(camera, "after");
    EXPECT_TRUE(near(pixel(after, 1, 14), Color{255, 0, 255, 255}, 0)) << str(pixel(after, 1, 14));
}

// RendererDef::fileTextureFilter overrides the filter of file textures only.
TEST(TextureFilterOverride, AppliesToFileTexturesOnly) {
    Window window(
        WindowDef{.title = "e2d render test", .size = {16, 16}, .vsync = false, .visible = false});
    RendererDef def;
    def.fileTextureFilter = TextureFilter::Nearest;
    Renderer renderer(window, def);
    const TextureId file =
        renderer.loadTexture(kData / "quadrant.png", TextureDef{.filter = TextureFilter::Linear});
    EXPECT_EQ(renderer.textureInfo(file).def.filter, TextureFilter::Nearest);
    Image image;
    image.width = 1;
    image.height = 1;
    image.pixels = {1, 2, 3, 255};
    const TextureId memory =
        renderer.createTexture(image, TextureDef{.filter = TextureFilter::Linear});
    EXPECT_EQ(renderer.textureInfo(memory).def.filter, TextureFilter::Linear);
}

// A scene change: textures no sprite uses go (except those kept), used ones and the sprites
// drawing them stay, and a released file loads again on the next request.
TEST_P(TextureRender, DestroyUnusedTexturesKeepsWhatSpritesUse) {
    Scene scene(GetParam(), {16, 16});
    Camera camera = pixelCamera({16, 16});
    Image green;
    green.width = 1;
    green.height = 1;
    green.pixels = {0, 255, 0, 255};
    EXPECT_EQ(scene.renderer.textureCount(), 0);
    const TextureId used = scene.renderer.createTexture(green);
    const TextureId kept = scene.renderer.createTexture(green);
    const TextureId unused = scene.renderer.createTexture(green);
    const TextureId file = scene.renderer.loadTexture(kData / "quadrant.png");
    const TextureId missing = scene.renderer.loadTexture(kData / "no-such-file.png");
    EXPECT_EQ(scene.renderer.textureCount(), 5);
    scene.renderer.createSprite(SpriteDef{.texture = used, .size = {16.0f, 16.0f}});

    const TextureId keep[] = {kept};
    EXPECT_EQ(scene.renderer.destroyUnusedTextures(keep), 3);
    EXPECT_EQ(scene.renderer.textureCount(), 2);
    EXPECT_TRUE(scene.renderer.isValid(used));
    EXPECT_TRUE(scene.renderer.isValid(kept));
    EXPECT_FALSE(scene.renderer.isValid(unused));
    EXPECT_FALSE(scene.renderer.isValid(file));
    EXPECT_FALSE(scene.renderer.isValid(missing));
    EXPECT_TRUE(near(pixel(scene.frame(camera), 8, 8), kGreen, 0));

    const TextureId again = scene.renderer.loadTexture(kData / "quadrant.png");
    EXPECT_TRUE(scene.renderer.isValid(again));
    EXPECT_EQ(scene.renderer.textureInfo(again).size, glm::ivec2(16, 16));
    EXPECT_EQ(scene.renderer.textureCount(), 3);

    scene.renderer.destroyAllSprites();
    EXPECT_EQ(scene.renderer.destroyUnusedTextures(), 3);
    EXPECT_EQ(scene.renderer.textureCount(), 0);
    EXPECT_EQ(scene.renderer.destroyUnusedTextures(), 0);
}

INSTANTIATE_TEST_SUITE_P(BothPaths, TextureRender, testing::Values(Path::Gl33, Path::Gl44),
                         pathName);

} // namespace
} // namespace e2d::render::test
