// SPDX-License-Identifier: MIT
// Scenes drawn with real OpenGL (Mesa llvmpipe under Xvfb) on both instance-buffer paths,
// read back and compared with what the scene says each pixel must be.
#include "render_test_util.hpp"

#include <e2d/core/error.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace e2d::render::test {
namespace {

using ::testing::HasSubstr;

class SpriteRender : public testing::TestWithParam<Path> {};

// Screen rectangle [x0, x1) x [y0, y1) of a pivot-(0, 0) sprite at world (x, y) with size (w, h)
// under pixelCamera(64 x 64): world (0, 0) is screen (32, 32), one unit one pixel.
struct PixelRect {
    int x0, y0, x1, y1;
    [[nodiscard]] bool contains(int x, int y) const {
        return x >= x0 && x < x1 && y >= y0 && y < y1;
    }
};

TEST_P(SpriteRender, PathIsTheOneAskedFor) {
    Scene scene(GetParam(), {16, 16});
    EXPECT_EQ(scene.renderer.persistentMapping(),
              GetParam() == Path::Gl44 && scene.window.context().bufferStorage);
    if (GetParam() == Path::Gl44) {
        // llvmpipe offers buffer storage: the 4.4 path must really be exercised here.
        EXPECT_TRUE(scene.renderer.persistentMapping()) << scene.window.context().version;
    }
}

TEST_P(SpriteRender, RedSpriteCoversExactlyItsPixels) {
    Scene scene(GetParam(), {64, 64});
    Camera camera = pixelCamera({64, 64});
    scene.renderer.createSprite(SpriteDef{
        .position = {-12.0f, 4.0f}, .size = {10.0f, 6.0f}, .pivot = {0.0f, 0.0f}, .tint = kRed});
    Image image = scene.frame(camera);
    PixelRect rect{32 - 12, 32 + 4, 32 - 12 + 10, 32 + 4 + 6};
    int wrong = 0;
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            Color expected = rect.contains(x, y) ? kRed : kBlack;
            if (!near(pixel(image, x, y), expected, 0)) {
                ++wrong;
                ADD_FAILURE_AT(__FILE__, __LINE__)
                    << "pixel (" << x << ", " << y << ") is " << str(pixel(image, x, y))
                    << ", expected " << str(expected);
                if (wrong > 5) {
                    return;
                }
            }
        }
    }
    const FrameStats& stats = scene.renderer.stats();
    EXPECT_EQ(stats.sprites, 1);
    EXPECT_EQ(stats.batches, 1);
    EXPECT_EQ(stats.drawCalls, 1);
    EXPECT_EQ(stats.opaqueBatches, 1);
}

// Equal z, one texture: the later sprite is on top, opaque or translucent alike (painter's order).
TEST_P(SpriteRender, EqualZDrawsInCreationOrderInBothPasses) {
    Scene scene(GetParam(), {32, 32});
    Camera camera = pixelCamera({32, 32});
    // Opaque: red, then green over its right half.
    scene.renderer.createSprite(
        SpriteDef{.position = {-8.0f, 8.0f}, .size = {12.0f, 8.0f}, .tint = kRed});
    scene.renderer.createSprite(
        SpriteDef{.position = {-2.0f, 8.0f}, .size = {12.0f, 8.0f}, .tint = kGreen});
    // Translucent (alpha 254): blue, then red over its right half.
    scene.renderer.createSprite(
        SpriteDef{.position = {-8.0f, -8.0f}, .size = {12.0f, 8.0f}, .tint = {0, 0, 255, 254}});
    scene.renderer.createSprite(
        SpriteDef{.position = {-2.0f, -8.0f}, .size = {12.0f, 8.0f}, .tint = {255, 0, 0, 254}});
    Image image = scene.frame(camera);
    // Overlap of the top pair is x in [-8, -4] world, i.e. screen x 10..11 at y 24.
    EXPECT_TRUE(near(pixel(image, 11, 24), kGreen, 0)) << str(pixel(image, 11, 24));
    EXPECT_TRUE(near(pixel(image, 6, 24), kRed, 0)) << str(pixel(image, 6, 24));
    EXPECT_TRUE(near(pixel(image, 11, 8), kRed, 2)) << str(pixel(image, 11, 8));
    EXPECT_TRUE(near(pixel(image, 6, 8), kBlue, 2)) << str(pixel(image, 6, 8));
    EXPECT_EQ(scene.renderer.stats().opaqueBatches, 1);
    EXPECT_EQ(scene.renderer.stats().translucentBatches, 1);
}

TEST_P(SpriteRender, HalfAlphaOverBlueBlends) {
    Scene scene(GetParam(), {32, 32});
    Camera camera = pixelCamera({32, 32});
    scene.renderer.createSprite(SpriteDef{.z = 0.0f, .size = {32.0f, 32.0f}, .tint = kBlue});
    scene.renderer.createSprite(
        SpriteDef{.z = 1.0f, .size = {8.0f, 8.0f}, .tint = {255, 0, 0, 128}});
    Image image = scene.frame(camera);
    // Straight alpha: src * a + dst * (1 - a), a = 128 / 255.
    float a = 128.0f / 255.0f;
    Color expected{static_cast<std::uint8_t>(std::lround(255.0f * a)), 0,
                   static_cast<std::uint8_t>(std::lround(255.0f * (1.0f - a))), 255};
    EXPECT_TRUE(near(pixel(image, 16, 16), expected))
        << str(pixel(image, 16, 16)) << " vs " << str(expected);
    EXPECT_TRUE(near(pixel(image, 2, 2), kBlue, 0));
    EXPECT_EQ(scene.renderer.stats().opaqueBatches, 1);
    EXPECT_EQ(scene.renderer.stats().translucentBatches, 1);
    EXPECT_EQ(scene.renderer.stats().drawCalls, scene.renderer.stats().batches);
}

// Two overlapping sprites created in the opposite order to their z: z decides, in both passes.
TEST_P(SpriteRender, ZOrderDecidesOverlapInBothPasses) {
    for (bool translucent : {false, true}) {
        for (bool redInFront : {false, true}) {
            Scene scene(GetParam(), {32, 32});
            Camera camera = pixelCamera({32, 32});
            std::uint8_t alpha = translucent ? 200 : 255;
            float redZ = redInFront ? 3.0f : 1.0f;
            float greenZ = redInFront ? 1.0f : 3.0f;
            // The front one is created first, so drawing in creation order would be wrong.
            if (redInFront) {
                scene.renderer.createSprite(SpriteDef{.position = {-4.0f, 0.0f},
                                                      .z = redZ,
                                                      .size = {12.0f, 12.0f},
                                                      .tint = {255, 0, 0, alpha}});
                scene.renderer.createSprite(SpriteDef{.position = {4.0f, 0.0f},
                                                      .z = greenZ,
                                                      .size = {12.0f, 12.0f},
                                                      .tint = {0, 255, 0, alpha}});
            } else {
                scene.renderer.createSprite(SpriteDef{.position = {4.0f, 0.0f},
                                                      .z = greenZ,
                                                      .size = {12.0f, 12.0f},
                                                      .tint = {0, 255, 0, alpha}});
                scene.renderer.createSprite(SpriteDef{.position = {-4.0f, 0.0f},
                                                      .z = redZ,
                                                      .size = {12.0f, 12.0f},
                                                      .tint = {255, 0, 0, alpha}});
            }
            Image image = scene.frame(camera, std::string(translucent ? "translucent" : "opaque") +
                                                  (redInFront ? "-red-front" : "-green-front"));
            Color overlap = pixel(image, 16, 16);
            Color expected;
            if (!translucent) {
                expected = redInFront ? kRed : kGreen;
            } else {
                // back over black, then front over that.
                float a = alpha / 255.0f;
                float back = 255.0f * a;
                float front = 255.0f * a;
                float behind = back * (1.0f - a);
                expected = redInFront
                               ? Color{static_cast<std::uint8_t>(std::lround(front)),
                                       static_cast<std::uint8_t>(std::lround(behind)), 0, 255}
                               : Color{static_cast<std::uint8_t>(std::lround(behind)),
                                       static_cast<std::uint8_t>(std::lround(front)), 0, 255};
            }
            EXPECT_TRUE(near(overlap, expected, 2))
                << (translucent ? "translucent" : "opaque")
                << (redInFront ? " red front" : " green front") << ": " << str(overlap) << " vs "
                << str(expected);
            EXPECT_EQ(scene.renderer.stats().drawCalls, scene.renderer.stats().batches);
        }
    }
}

// A translucent sprite behind an opaque one is hidden where they overlap (depth test), and
// in front of it, it blends over it.
TEST_P(SpriteRender, TranslucentBehindOpaqueIsHidden) {
    Scene scene(GetParam(), {32, 32});
    Camera camera = pixelCamera({32, 32});
    scene.renderer.createSprite(SpriteDef{.z = 2.0f, .size = {8.0f, 8.0f}, .tint = kBlue});
    scene.renderer.createSprite(SpriteDef{
        .position = {-6.0f, 0.0f}, .z = 1.0f, .size = {8.0f, 4.0f}, .tint = {255, 0, 0, 128}});
    scene.renderer.createSprite(SpriteDef{
        .position = {6.0f, 0.0f}, .z = 3.0f, .size = {8.0f, 4.0f}, .tint = {0, 255, 0, 128}});
    Image image = scene.frame(camera);
    EXPECT_TRUE(near(pixel(image, 16 - 3, 16), kBlue, 0)) << str(pixel(image, 13, 16));
    Color front = pixel(image, 16 + 3, 16);
    EXPECT_TRUE(near(front, Color{0, 128, 127, 255})) << str(front);
    EXPECT_TRUE(near(pixel(image, 16 - 9, 16), Color{128, 0, 0, 255})) << str(pixel(image, 7, 16));
}

// Rotated 30 degrees about its centre: each corner of the transform is red just inside and
// black just outside.
TEST_P(SpriteRender, RotatedCornersLandWhereTheTransformSays) {
    Scene scene(GetParam(), {64, 64});
    Camera camera = pixelCamera({64, 64});
    const float angle = 0.5235988f;
    const glm::vec2 centre{3.0f, -2.0f};
    const glm::vec2 size{36.0f, 18.0f};
    scene.renderer.createSprite(
        SpriteDef{.position = centre, .size = size, .rotation = angle, .tint = kRed});
    Image image = scene.frame(camera);
    glm::vec2 ax{std::cos(angle), std::sin(angle)};
    glm::vec2 ay{-std::sin(angle), std::cos(angle)};
    for (glm::vec2 sign :
         {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(-1, 1), glm::vec2(1, 1)}) {
        glm::vec2 corner = centre + ax * (sign.x * size.x * 0.5f) + ay * (sign.y * size.y * 0.5f);
        glm::vec2 inward = glm::normalize(centre - corner);
        glm::vec2 inside = corner + inward * 2.5f + glm::vec2(32.0f);
        glm::vec2 outside = corner - inward * 2.5f + glm::vec2(32.0f);
        Color in = pixel(image, static_cast<int>(std::floor(inside.x)),
                         static_cast<int>(std::floor(inside.y)));
        Color out = pixel(image, static_cast<int>(std::floor(outside.x)),
                          static_cast<int>(std::floor(outside.y)));
        EXPECT_TRUE(near(in, kRed, 0))
            << "inside corner " << corner.x << ", " << corner.y << ": " << str(in);
        EXPECT_TRUE(near(out, kBlack, 0))
            << "outside corner " << corner.x << ", " << corner.y << ": " << str(out);
    }
}

// Parallax 0.5 moves half as far on screen as the camera; 1 moves as far; HUD does not move
// (nor rotate or zoom with the camera).
TEST_P(SpriteRender, ParallaxAndHudFollowTheCameraAsDefined) {
    Scene scene(GetParam(), {64, 64});
    Camera camera = pixelCamera({64, 64});
    SpriteId normal = scene.renderer.createSprite(SpriteDef{
        .position = {-20.0f, 10.0f}, .size = {4.0f, 4.0f}, .pivot = {0.0f, 0.0f}, .tint = kRed});
    SpriteId half = scene.renderer.createSprite(SpriteDef{.position = {-20.0f, -10.0f},
                                                          .size = {4.0f, 4.0f},
                                                          .pivot = {0.0f, 0.0f},
                                                          .tint = kGreen,
                                                          .parallax = 0.5f});
    SpriteId hud = scene.renderer.createSprite(SpriteDef{.position = {-20.0f, -24.0f},
                                                         .size = {4.0f, 4.0f},
                                                         .pivot = {0.0f, 0.0f},
                                                         .tint = kBlue,
                                                         .hud = true});
    static_cast<void>(normal);
    static_cast<void>(half);
    static_cast<void>(hud);
    auto leftmost = [](const Image& image, int y, Color color) {
        for (int x = 0; x < image.width; ++x) {
            if (near(pixel(image, x, y), color, 0)) {
                return x;
            }
        }
        return -1;
    };
    // Parallax k draws the sprite at camera + k * (position - camera): on screen at
    // 32 + k * (x - camera x).
    Image before = scene.frame(camera, "before");
    EXPECT_EQ(leftmost(before, 32 + 12, kRed), 12);
    EXPECT_EQ(leftmost(before, 32 - 5 + 1, kGreen), 32 - 10);
    EXPECT_EQ(leftmost(before, 32 - 22, kBlue), 12);
    camera.setPosition({-16.0f, 0.0f}); // the camera moves 16 left: the world moves 16 right
    Image after = scene.frame(camera, "after");
    EXPECT_EQ(leftmost(after, 32 + 12, kRed), 12 + 16);
    EXPECT_EQ(leftmost(after, 32 - 5 + 1, kGreen), 32 - 10 + 8);
    EXPECT_EQ(leftmost(after, 32 - 22, kBlue), 12);
    // Zoom and rotation leave the HUD sprite alone too.
    camera.setZoom(2.0f);
    camera.setRotation(0.7f);
    Image zoomed = scene.frame(camera, "zoomed");
    EXPECT_EQ(leftmost(zoomed, 32 - 22, kBlue), 12);
    int width = 0;
    for (int x = 0; x < 64; ++x) {
        width += near(pixel(zoomed, x, 32 - 22), kBlue, 0) ? 1 : 0;
    }
    EXPECT_EQ(width, 4);
}

// Batches break only where the texture changes in sorted order; one draw call each.
TEST_P(SpriteRender, DrawCallsEqualBatchesOfTheScene) {
    Scene scene(GetParam(), {64, 64});
    Camera camera = pixelCamera({64, 64});
    std::vector<TextureId> textures;
    for (int i = 0; i < 3; ++i) {
        Image image;
        image.width = 2;
        image.height = 2;
        image.pixels.assign(16, static_cast<std::uint8_t>(60 + 60 * i));
        for (int p = 0; p < 4; ++p) {
            image.pixels[static_cast<std::size_t>(p) * 4 + 3] = 255;
        }
        textures.push_back(scene.renderer.createTexture(image));
    }
    // Opaque: textures 0, 1, 2, 0, 1 at various z -> one batch per distinct texture.
    const int opaqueTex[] = {0, 1, 2, 0, 1};
    for (int i = 0; i < 5; ++i) {
        scene.renderer.createSprite(
            SpriteDef{.texture = textures[static_cast<std::size_t>(opaqueTex[i])],
                      .position = {-25.0f + 10.0f * i, 20.0f},
                      .z = static_cast<float>(5 - i),
                      .size = {6.0f, 6.0f}});
    }
    // Translucent, listed by z: 0, 0, 1, 0, 2, 2 -> texture changes give 4 batches.
    const int translucentTex[] = {0, 0, 1, 0, 2, 2};
    const float translucentZ[] = {1, 2, 3, 4, 5, 6};
    // Created in a scrambled order: sorting must put them back.
    for (int i : {3, 0, 5, 1, 4, 2}) {
        scene.renderer.createSprite(
            SpriteDef{.texture = textures[static_cast<std::size_t>(translucentTex[i])],
                      .position = {-25.0f + 9.0f * i, -10.0f},
                      .z = translucentZ[i],
                      .size = {6.0f, 6.0f},
                      .tint = {255, 255, 255, 128}});
    }
    // Expected from the scene: distinct opaque textures + texture changes along z.
    int expectedOpaque = 3;
    int expectedTranslucent = 1;
    for (int i = 1; i < 6; ++i) {
        expectedTranslucent += translucentTex[i] != translucentTex[i - 1] ? 1 : 0;
    }
    scene.frame(camera);
    const FrameStats& stats = scene.renderer.stats();
    EXPECT_EQ(stats.opaqueBatches, expectedOpaque);
    EXPECT_EQ(stats.translucentBatches, expectedTranslucent);
    EXPECT_EQ(stats.batches, expectedOpaque + expectedTranslucent);
    EXPECT_EQ(stats.drawCalls, stats.batches);
    EXPECT_EQ(stats.sprites, 11);
}

// Off-screen sprites are culled (not drawn, counted); unchanged sprites are not rebuilt.
TEST_P(SpriteRender, CullsOffscreenAndRebuildsOnlyWhatChanged) {
    Scene scene(GetParam(), {32, 32});
    Camera camera = pixelCamera({32, 32});
    std::vector<SpriteId> sprites;
    for (int i = 0; i < 10; ++i) {
        // Every other sprite lies far outside the 32 x 32 view.
        float x = i % 2 == 0 ? -12.0f + 2.0f * i : 500.0f + 10.0f * i;
        sprites.push_back(scene.renderer.createSprite(
            SpriteDef{.position = {x, 0.0f}, .size = {2.0f, 2.0f}, .tint = kRed}));
    }
    scene.frame(camera);
    EXPECT_EQ(scene.renderer.stats().sprites, 5);
    EXPECT_EQ(scene.renderer.stats().culled, 5);
    EXPECT_EQ(scene.renderer.stats().rebuilt, 10);
    scene.renderer.setPosition(sprites[0], {-14.0f, 4.0f});
    scene.renderer.setPosition(sprites[2],
                               scene.renderer.sprite(sprites[2]).position); // same value: no change
    Image image = scene.frame(camera, "moved");
    EXPECT_EQ(scene.renderer.stats().rebuilt, 1);
    EXPECT_TRUE(near(pixel(image, 16 - 14, 16 + 4), kRed, 0));
    EXPECT_TRUE(near(pixel(image, 16 - 12, 16), kBlack, 0)); // where sprite 0 was
    // Nothing changed: the last frame's instances are drawn again, nothing rebuilt.
    Image again = scene.frame(camera, "again");
    EXPECT_EQ(scene.renderer.stats().rebuilt, 0);
    EXPECT_EQ(scene.renderer.stats().sprites, 5);
    EXPECT_EQ(again.pixels, image.pixels);
}

// A moved sprite's instance is written straight away when nothing else about it changed; every
// other case goes through the repack: a move, a resize and a second move in one frame; a
// parallax sprite and a HUD sprite under a moving camera; a sprite moved while hidden; a slot
// reused by a new sprite and moved before the next frame. The whole image is compared with
// the rectangles the scene says.
TEST_P(SpriteRender, MovesOfEveryKindOfSpriteLandWhereTheSceneSays) {
    Scene scene(GetParam(), {64, 64});
    Camera camera = pixelCamera({64, 64});
    const Color kWhite{255, 255, 255, 255};
    const Color kYellow{255, 255, 0, 255};
    auto def = [](glm::vec2 position, Color tint) {
        return SpriteDef{
            .position = position, .size = {4.0f, 4.0f}, .pivot = {0.0f, 0.0f}, .tint = tint};
    };
    const SpriteId a = scene.renderer.createSprite(def({-30.0f, 20.0f}, kRed));
    SpriteDef parallax = def({0.0f, 20.0f}, kGreen);
    parallax.parallax = 0.5f;
    const SpriteId b = scene.renderer.createSprite(parallax);
    SpriteDef hud = def({20.0f, 20.0f}, kBlue);
    hud.hud = true;
    const SpriteId c = scene.renderer.createSprite(hud);
    const SpriteId d = scene.renderer.createSprite(def({-30.0f, -30.0f}, kWhite));
    const SpriteId e = scene.renderer.createSprite(def({0.0f, -30.0f}, kYellow));
    scene.frame(camera, "before");

    // Screen rectangles [x0, x1) x [y0, y1) and colours, y up, camera at `cam`.
    struct Expect {
        PixelRect rect;
        Color color;
    };
    auto check = [&](const Image& image, const std::vector<Expect>& expected) {
        int wrong = 0;
        for (int y = 0; y < 64; ++y) {
            for (int x = 0; x < 64; ++x) {
                Color want = kBlack;
                for (const Expect& ex : expected) {
                    if (ex.rect.contains(x, y)) {
                        want = ex.color;
                    }
                }
                if (!near(pixel(image, x, y), want, 0) && ++wrong <= 5) {
                    ADD_FAILURE() << "pixel (" << x << ", " << y << ") is "
                                  << str(pixel(image, x, y)) << ", expected " << str(want);
                }
            }
        }
        EXPECT_EQ(wrong, 0);
    };
    // World (wx, wy) with camera at cam: screen 32 + (w - cam).
    auto at = [](glm::vec2 world, glm::vec2 cam, glm::vec2 size) {
        const int x0 = 32 + static_cast<int>(world.x - cam.x);
        const int y0 = 32 + static_cast<int>(world.y - cam.y);
        return PixelRect{x0, y0, x0 + static_cast<int>(size.x), y0 + static_cast<int>(size.y)};
    };

    const glm::vec2 cam{4.0f, -2.0f};
    camera.setPosition(cam);
    scene.renderer.setPosition(a, {-20.0f, 10.0f});
    scene.renderer.setSize(a, {6.0f, 6.0f});
    scene.renderer.setPosition(a, {-26.0f, 12.0f});
    scene.renderer.setPosition(b, {10.0f, 18.0f});
    scene.renderer.setPosition(c, {-10.0f, 14.0f});
    scene.renderer.setVisible(d, false);
    scene.renderer.setPosition(d, {-20.0f, -24.0f});
    scene.renderer.destroySprite(e);
    const SpriteId f = scene.renderer.createSprite(def({0.0f, 0.0f}, kYellow));
    scene.renderer.setPosition(f, {16.0f, -20.0f});
    Image moved = scene.frame(camera, "moved");
    // Parallax 0.5 draws b at cam + 0.5 * (position - cam); the HUD sprite ignores the camera.
    const glm::vec2 bDrawn = cam + 0.5f * (glm::vec2(10.0f, 18.0f) - cam);
    check(moved, {{at({-26.0f, 12.0f}, cam, {6.0f, 6.0f}), kRed},
                  {at(bDrawn, cam, {4.0f, 4.0f}), kGreen},
                  {at({-10.0f, 14.0f}, {0.0f, 0.0f}, {4.0f, 4.0f}), kBlue},
                  {at({16.0f, -20.0f}, cam, {4.0f, 4.0f}), kYellow}});
    EXPECT_EQ(scene.renderer.stats().sprites, 4);

    // Shown again where it was moved while hidden; a plain move of the reused slot's sprite.
    scene.renderer.setVisible(d, true);
    scene.renderer.setPosition(f, {20.0f, -26.0f});
    Image shown = scene.frame(camera, "shown");
    check(shown, {{at({-26.0f, 12.0f}, cam, {6.0f, 6.0f}), kRed},
                  {at(bDrawn, cam, {4.0f, 4.0f}), kGreen},
                  {at({-10.0f, 14.0f}, {0.0f, 0.0f}, {4.0f, 4.0f}), kBlue},
                  {at({-20.0f, -24.0f}, cam, {4.0f, 4.0f}), kWhite},
                  {at({20.0f, -26.0f}, cam, {4.0f, 4.0f}), kYellow}});
    EXPECT_EQ(scene.renderer.stats().rebuilt, 2); // d (shown again) and f (moved)
    EXPECT_EQ(scene.renderer.sprite(f).position, glm::vec2(20.0f, -26.0f));
    EXPECT_EQ(scene.renderer.sprite(a).position, glm::vec2(-26.0f, 12.0f));
}

// Opaque quads at equal z: the later texture on top whatever the creation order, a cut-out
// (alpha 0) texel of the top one shows the one under it, and a submitted quad lies over a
// sprite of its texture.
TEST_P(SpriteRender, EqualZOpaqueOverlapsFollowTextureThenSubmission) {
    Scene scene(GetParam(), {32, 32});
    Camera camera = pixelCamera({32, 32});
    auto solid = [](Color c, bool cutTopRight) {
        Image image{2, 2, {}};
        for (int i = 0; i < 4; ++i) {
            const bool cut = cutTopRight && i == 1; // rows from the top: texel 1 is the top-right
            image.pixels.insert(image.pixels.end(),
                                {c.r, c.g, c.b, static_cast<std::uint8_t>(cut ? 0 : 255)});
        }
        return image;
    };
    const TextureDef nearest{.filter = TextureFilter::Nearest};
    const TextureId red = scene.renderer.createTexture(solid(kRed, false), nearest);
    const TextureId green = scene.renderer.createTexture(solid(kGreen, true), nearest);
    // Green (the later texture) made first, red over its right half made second.
    scene.renderer.createSprite(SpriteDef{
        .texture = green, .position = {-12.0f, 0.0f}, .size = {8.0f, 8.0f}, .pivot = {0.0f, 0.0f}});
    scene.renderer.createSprite(SpriteDef{
        .texture = red, .position = {-8.0f, 0.0f}, .size = {8.0f, 8.0f}, .pivot = {0.0f, 0.0f}});
    // A blue plain sprite and a submitted white quad over its right half.
    scene.renderer.createSprite(SpriteDef{
        .position = {4.0f, -8.0f}, .size = {8.0f, 8.0f}, .pivot = {0.0f, 0.0f}, .tint = kBlue});
    scene.renderer.submit(
        Quad{.position = {8.0f, -8.0f}, .size = {8.0f, 8.0f}, .pivot = {0.0f, 0.0f}});
    Image image = scene.frame(camera, "equal-z");
    // Green covers screen [4, 12) x [16, 24); red [8, 16) x [16, 24); green's top-right
    // quarter [8, 12) x [20, 24) is cut out.
    EXPECT_TRUE(near(pixel(image, 9, 17), kGreen, 0)) << str(pixel(image, 9, 17)); // overlap, uncut
    EXPECT_TRUE(near(pixel(image, 9, 22), kRed, 0)) << str(pixel(image, 9, 22));   // overlap, cut
    EXPECT_TRUE(near(pixel(image, 5, 22), kGreen, 0)) << str(pixel(image, 5, 22)); // green alone
    EXPECT_TRUE(near(pixel(image, 14, 18), kRed, 0)) << str(pixel(image, 14, 18)); // red alone
    // Blue covers [20, 28) x [8, 16), the quad [24, 32) x [8, 16).
    EXPECT_TRUE(near(pixel(image, 21, 10), kBlue, 0)) << str(pixel(image, 21, 10));
    EXPECT_TRUE(near(pixel(image, 25, 10), Color{255, 255, 255, 255}, 0))
        << str(pixel(image, 25, 10));
    EXPECT_EQ(scene.renderer.stats().opaqueBatches, 3);
}

// A UV region holding its image turned 90 degrees clockwise (SpriteDef::uvRotated) is shown
// upright with a corner pivot, mirrored by flipY along the image's own vertical, and a plain
// move (written straight into the instance) keeps it upright.
TEST_P(SpriteRender, TurnedUvRegionsShowUpright) {
    Scene scene(GetParam(), {32, 32});
    Camera camera = pixelCamera({32, 32});
    // The shown image: 4 x 2 texels, rows from the top: red red green green / blue blue white
    // white. Stored turned clockwise in a 2 x 4 texture: shown texel (x, y) at (1 - y, x).
    const Color kWhite{255, 255, 255, 255};
    auto shown = [&](int x, int yDown) {
        return yDown == 0 ? (x < 2 ? kRed : kGreen) : (x < 2 ? kBlue : kWhite);
    };
    Image image{2, 4, std::vector<std::uint8_t>(2 * 4 * 4, 255)};
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 4; ++x) {
            std::uint8_t* p = &image.pixels[static_cast<std::size_t>((x * 2 + (1 - y)) * 4)];
            const Color c = shown(x, y);
            p[0] = c.r;
            p[1] = c.g;
            p[2] = c.b;
        }
    }
    const TextureId texture =
        scene.renderer.createTexture(image, TextureDef{.filter = TextureFilter::Nearest});
    // 8 x 4 world units: each shown texel a 2 x 2 block.
    const SpriteId plain = scene.renderer.createSprite(SpriteDef{.texture = texture,
                                                                 .position = {-12.0f, 4.0f},
                                                                 .size = {8.0f, 4.0f},
                                                                 .pivot = {0.0f, 0.0f},
                                                                 .uvRotated = true});
    const SpriteId flipped = scene.renderer.createSprite(SpriteDef{.texture = texture,
                                                                   .position = {2.0f, -10.0f},
                                                                   .size = {8.0f, 4.0f},
                                                                   .pivot = {0.0f, 0.0f},
                                                                   .uvRotated = true,
                                                                   .flipY = true});
    auto check = [&](const Image& frame, glm::vec2 plainAt, glm::vec2 flippedAt) {
        int wrong = 0;
        for (int y = 0; y < 32; ++y) {
            for (int x = 0; x < 32; ++x) {
                Color want = kBlack;
                const int px = x - (16 + static_cast<int>(plainAt.x));
                const int py = y - (16 + static_cast<int>(plainAt.y));
                const int fx = x - (16 + static_cast<int>(flippedAt.x));
                const int fy = y - (16 + static_cast<int>(flippedAt.y));
                if (px >= 0 && px < 8 && py >= 0 && py < 4) {
                    want = shown(px / 2, 1 - py / 2);
                } else if (fx >= 0 && fx < 8 && fy >= 0 && fy < 4) {
                    want = shown(fx / 2, fy / 2); // flipY: the bottom row on top
                }
                if (!near(pixel(frame, x, y), want, 0) && ++wrong <= 5) {
                    ADD_FAILURE() << "pixel (" << x << ", " << y << ") is "
                                  << str(pixel(frame, x, y)) << ", expected " << str(want);
                }
            }
        }
        EXPECT_EQ(wrong, 0);
    };
    check(scene.frame(camera, "turned"), {-12.0f, 4.0f}, {2.0f, -10.0f});
    scene.renderer.setPosition(plain, {-6.0f, -14.0f});
    check(scene.frame(camera, "moved"), {-6.0f, -14.0f}, {2.0f, -10.0f});
    EXPECT_EQ(scene.renderer.stats().rebuilt, 1);
    EXPECT_TRUE(scene.renderer.sprite(flipped).uvRotated);
}

// Transient quads share the sprites' batches (same texture, same pass) and last one frame.
TEST_P(SpriteRender, SubmittedQuadsBatchWithSprites) {
    Scene scene(GetParam(), {32, 32});
    Camera camera = pixelCamera({32, 32});
    scene.renderer.createSprite(
        SpriteDef{.position = {-8.0f, 0.0f}, .size = {4.0f, 4.0f}, .tint = kRed});
    scene.renderer.submit(Quad{
        .position = {8.0f, 0.0f}, .size = {4.0f, 4.0f}, .pivot = {0.5f, 0.5f}, .tint = kGreen});
    Image first = scene.frame(camera, "with-quad");
    EXPECT_TRUE(near(pixel(first, 24, 16), kGreen, 0));
    EXPECT_EQ(scene.renderer.stats().sprites, 2);
    EXPECT_EQ(scene.renderer.stats().batches, 1);
    Image second = scene.frame(camera, "without-quad");
    EXPECT_TRUE(near(pixel(second, 24, 16), kBlack, 0));
    EXPECT_TRUE(near(pixel(second, 8, 16), kRed, 0));
    EXPECT_EQ(scene.renderer.stats().sprites, 1);
}

// A texture's top-left texel is drawn at the sprite's top-left, flips mirror it, and a UV
// rectangle (top-left origin) picks texels.
TEST_P(SpriteRender, TextureOrientationFlipsAndUvRects) {
    Scene scene(GetParam(), {32, 32});
    Camera camera = pixelCamera({32, 32});
    Image image;
    image.width = 2;
    image.height = 2;
    // Rows from the top: red, green / blue, white.
    image.pixels = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    TextureId texture =
        scene.renderer.createTexture(image, TextureDef{.filter = TextureFilter::Nearest});
    SpriteId sprite = scene.renderer.createSprite(
        SpriteDef{.texture = texture, .size = {8.0f, 8.0f}, .pivot = {0.0f, 0.0f}});
    // Sprite covers screen [16, 24) x [16, 24); its top-left quarter is [16, 20) x [20, 24).
    Image plain = scene.frame(camera, "plain");
    EXPECT_TRUE(near(pixel(plain, 17, 22), kRed, 0)) << str(pixel(plain, 17, 22));
    EXPECT_TRUE(near(pixel(plain, 22, 22), kGreen, 0));
    EXPECT_TRUE(near(pixel(plain, 17, 17), kBlue, 0));
    EXPECT_TRUE(near(pixel(plain, 22, 17), kWhite, 0));
    scene.renderer.setFlip(sprite, true, false);
    Image flipped = scene.frame(camera, "flip-x");
    EXPECT_TRUE(near(pixel(flipped, 17, 22), kGreen, 0));
    scene.renderer.setFlip(sprite, false, true);
    Image flippedY = scene.frame(camera, "flip-y");
    EXPECT_TRUE(near(pixel(flippedY, 17, 22), kBlue, 0));
    scene.renderer.setFlip(sprite, false, false);
    scene.renderer.setUv(sprite, Rect{{0.5f, 0.5f}, {0.5f, 0.5f}}); // bottom-right texel: white
    Image uv = scene.frame(camera, "uv");
    EXPECT_TRUE(near(pixel(uv, 17, 22), kWhite, 0));
    EXPECT_TRUE(near(pixel(uv, 22, 17), kWhite, 0));
}

TEST_P(SpriteRender, StaleIdsAndBadFieldsAreErrors) {
    Scene scene(GetParam(), {8, 8});
    SpriteId sprite = scene.renderer.createSprite();
    EXPECT_TRUE(scene.renderer.destroySprite(sprite));
    EXPECT_FALSE(scene.renderer.destroySprite(sprite));
    EXPECT_FALSE(scene.renderer.isValid(sprite));
    try {
        scene.renderer.setPosition(sprite, {1.0f, 1.0f});
        FAIL() << "expected an error";
    } catch (const core::Error& error) {
        EXPECT_THAT(error.what(), HasSubstr("render::Renderer::setPosition(): stale sprite id"));
    }
    SpriteId reused = scene.renderer.createSprite();
    EXPECT_EQ(reused.index1, sprite.index1);
    EXPECT_NE(reused.generation, sprite.generation);
    try {
        scene.renderer.createSprite(SpriteDef{.parallax = -1.0f});
        FAIL() << "expected an error";
    } catch (const core::Error& error) {
        EXPECT_THAT(
            error.what(),
            HasSubstr(
                "render::Renderer::createSprite(): parallax must be >= 0 and finite, got -1"));
    }
    try {
        scene.renderer.createSprite(SpriteDef{.size = {-2.0f, 1.0f}});
        FAIL() << "expected an error";
    } catch (const core::Error& error) {
        EXPECT_THAT(error.what(), HasSubstr("size must be >= 0 and finite, got (-2, 1)"));
    }
    EXPECT_THROW(scene.renderer.setUv(reused, Rect{{0.5f, 0.0f}, {0.75f, 1.0f}}), core::Error);
    try {
        Renderer bad(scene.window, RendererDef{.ringFrames = 1});
        FAIL() << "expected an error";
    } catch (const core::Error& error) {
        EXPECT_THAT(error.what(),
                    HasSubstr("render::Renderer: ringFrames must be in [2, 8], got 1"));
    }
}

INSTANTIATE_TEST_SUITE_P(BothPaths, SpriteRender, testing::Values(Path::Gl33, Path::Gl44),
                         pathName);

} // namespace
} // namespace e2d::render::test
