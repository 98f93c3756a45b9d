// SPDX-License-Identifier: MIT
// The components on real game objects in a running scene, drawn by a RenderSystem with real
// OpenGL: sprites follow their object's world transform through the parent chain, an animated
// sprite shows the frame its time says, a text label draws at its object and moves with it.
#include "render_test_util.hpp"

#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/core/scene_director.hpp>
#include <e2d/core/scene_registry.hpp>
#include <e2d/render/animated_sprite_renderer.hpp>
#include <e2d/render/render_system.hpp>
#include <e2d/render/sprite_renderer.hpp>
#include <e2d/render/text_label.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

namespace e2d::render::test {
namespace {

using ::testing::HasSubstr;

// A 64 x 64 offscreen target, one world unit per pixel, world (0, 0) at screen (32, 32).
class RenderComponents : public ::testing::Test {
protected:
    void start(std::function<void(core::Scene&)> setup) {
        system.camera().setReferenceSize({64.0f, 64.0f});
        registry.add("Test", core::SceneFunctions{.initialize = setup});
        director.addSystem(system);
        ASSERT_TRUE(director.start("Test"));
    }
    Image frame(double dt, const std::string& name) {
        director.applyPendingChange();
        director.scene()->beginFrame();
        director.scene()->dispatchUpdate(dt);
        system.render(1.0);
        Image image = scene.renderer.readPixels();
        writePng(image, outputDir() / (currentTestName() + "-" + name + ".png"));
        return image;
    }

    core::Logger logger{core::LogLevel::Warning, [](core::LogLevel, std::string_view) {}};
    Scene scene{Path::Gl44, {64, 64}};
    RenderSystem system{scene.renderer};
    core::SceneRegistry registry;
    core::SceneDirector director{registry, logger};
};

TEST_F(RenderComponents, SpriteFollowsItsObjectThroughTheParentChain) {
    core::GameObject* parent = nullptr;
    core::GameObject* child = nullptr;
    SpriteRenderer* sprite = nullptr;
    start([&](core::Scene& s) {
        parent = &s.createGameObject();
        child = &s.createGameObject();
        parent->addChild(*child);
        parent->setPosition(glm::vec2(-10.0f, 4.0f));
        child->setPosition(glm::vec2(6.0f, 0.0f));
        sprite = child->addComponent<SpriteRenderer>(
            SpriteRendererDef{.size = {4.0f, 4.0f}, .tint = kRed});
    });
    Image first = frame(0.0, "first");
    ASSERT_NE(sprite, nullptr);
    // World position: parent (-10, 4) + child (6, 0) = (-4, 4): screen (28, 36), a 4 x 4 square
    // centred there covers x 26..29, y 34..37.
    EXPECT_EQ(scene.renderer.sprite(sprite->sprite()).position, glm::vec2(-4.0f, 4.0f));
    EXPECT_TRUE(near(pixel(first, 27, 35), kRed, 0)) << str(pixel(first, 27, 35));
    EXPECT_TRUE(near(pixel(first, 32, 35), kBlack, 0));

    // The parent turns a quarter turn counter-clockwise and doubles in scale: the child's offset
    // (6, 0) becomes (0, 12) and the sprite 8 x 8, turned.
    parent->setOrientation(std::numbers::pi_v<float> / 2.0f);
    parent->setScale(2.0f);
    Image turned = frame(0.0, "turned");
    const SpriteDef& def = scene.renderer.sprite(sprite->sprite());
    EXPECT_NEAR(def.position.x, -10.0f, 1e-4f);
    EXPECT_NEAR(def.position.y, 16.0f, 1e-4f);
    EXPECT_NEAR(def.rotation, std::numbers::pi_v<float> / 2.0f, 1e-5f);
    EXPECT_NEAR(def.scale.x, 2.0f, 1e-5f);
    // Screen (22, 48): the 8 x 8 square covers x 18..25, y 44..51.
    EXPECT_TRUE(near(pixel(turned, 19, 45), kRed, 0)) << str(pixel(turned, 19, 45));
    EXPECT_TRUE(near(pixel(turned, 24, 50), kRed, 0)) << str(pixel(turned, 24, 50));
    EXPECT_TRUE(near(pixel(turned, 27, 35), kBlack, 0)) << "the old place is empty";
}

// A texture of four 4 x 4 frames side by side: red, green, blue, white.
TextureId fourFrames(Renderer& renderer) {
    Image image{16, 4, std::vector<std::uint8_t>(16 * 4 * 4)};
    const Color colours[4] = {kRed, kGreen, kBlue, kWhite};
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 16; ++x) {
            std::uint8_t* p = &image.pixels[static_cast<std::size_t>((y * 16 + x) * 4)];
            const Color c = colours[x / 4];
            p[0] = c.r;
            p[1] = c.g;
            p[2] = c.b;
            p[3] = 255;
        }
    }
    return renderer.createTexture(image, TextureDef{.filter = TextureFilter::Nearest});
}

TEST_F(RenderComponents, AnimatedSpriteShowsTheFrameItsTimeSays) {
    const TextureId texture = fourFrames(scene.renderer);
    AnimatedSpriteRenderer* animated = nullptr;
    start([&](core::Scene& s) {
        core::GameObject& object = s.createGameObject();
        AnimatedSpriteRendererDef def;
        def.sprite.texture = texture;
        def.sprite.size = {16.0f, 16.0f};
        for (int i = 0; i < 4; ++i) {
            def.frames.push_back(AnimationFrame{Rect{{i * 0.25f, 0.0f}, {0.25f, 1.0f}}});
        }
        def.animation.frameDuration = 0.1;
        def.animation.mode = AnimationMode::PingPong;
        animated = object.addComponent<AnimatedSpriteRenderer>(def);
    });
    // Frame 0 at start; 0.25 s later frame 2 (two whole durations); 0.3 s more: 5 steps of
    // ping-pong 0 1 2 3 2 1: frame 1.
    const Color expected[3] = {kRed, kBlue, kGreen};
    const double dts[3] = {0.0, 0.25, 0.3};
    for (int i = 0; i < 3; ++i) {
        Image image = frame(dts[i], "step" + std::to_string(i));
        ASSERT_NE(animated, nullptr);
        EXPECT_TRUE(near(pixel(image, 32, 32), expected[i], 0))
            << "step " << i << ": " << str(pixel(image, 32, 32)) << ", frame "
            << animated->animation().frame();
    }
    EXPECT_EQ(animated->animation().frame(), 1);
}

TEST_F(RenderComponents, AnimatedSpriteBadFieldsAreErrors) {
    try {
        AnimatedSpriteRenderer bad(AnimatedSpriteRendererDef{});
        FAIL() << "expected an error";
    } catch (const core::Error& error) {
        EXPECT_THAT(error.what(),
                    HasSubstr("render::AnimatedSpriteRenderer: frames must not be empty"));
    }
    AnimatedSpriteRendererDef outside;
    outside.frames = {AnimationFrame{Rect{{0.0f, 0.0f}, {0.5f, 1.0f}}},
                      AnimationFrame{Rect{{0.75f, 0.0f}, {0.5f, 1.0f}}}};
    try {
        AnimatedSpriteRenderer bad(outside);
        FAIL() << "expected an error";
    } catch (const core::Error& error) {
        EXPECT_THAT(error.what(),
                    HasSubstr("frames[1].uv must lie in [0, 1], got min (0.75, 0) size (0.5, 1)"));
    }
}

// The display image of the rotated-frame test: 8 x 4 pixels, quadrants of 4 x 2 (rows from the
// top): red top-left, green top-right, blue bottom-left, white bottom-right.
Color quadrant(int x, int yDown) {
    const Color kWhite{255, 255, 255, 255};
    const Color top[2] = {kRed, kGreen};
    const Color bottom[2] = {kBlue, kWhite};
    return yDown < 2 ? top[x / 4] : bottom[x / 4];
}

// A 16 x 8 texture holding the display image twice: as is at (0, 0), and turned 90 degrees
// clockwise at (8, 0) (4 wide, 8 tall), as TexturePacker stores a `rotated` frame: display
// pixel (x, y) lands at (8 + 3 - y, x).
TextureId uprightAndTurned(Renderer& renderer) {
    Image image{16, 8, std::vector<std::uint8_t>(16 * 8 * 4, 0)};
    auto put = [&](int x, int y, Color c) {
        std::uint8_t* p = &image.pixels[static_cast<std::size_t>((y * 16 + x) * 4)];
        p[0] = c.r;
        p[1] = c.g;
        p[2] = c.b;
        p[3] = 255;
    };
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 8; ++x) {
            put(x, y, quadrant(x, y));
            put(8 + 3 - y, x, quadrant(x, y));
        }
    }
    return renderer.createTexture(image, TextureDef{.filter = TextureFilter::Nearest});
}

// An animation whose second frame is stored rotated (TexturePacker `rotated: true`) shows it
// upright: the same pixels as the unrotated first frame, with the automatic size (the stored
// region's extent swapped), and mirrored the same way by flipX.
TEST_F(RenderComponents, AnimatedSpriteShowsRotatedSheetFramesUpright) {
    const TextureId texture = uprightAndTurned(scene.renderer);
    const SpriteSheet sheet = SpriteSheet::fromString(R"({"frames": {
      "look1.png": {"frame": {"x": 0, "y": 0, "w": 8, "h": 4}, "rotated": false},
      "look2.png": {"frame": {"x": 8, "y": 0, "w": 8, "h": 4}, "rotated": true}},
      "meta": {"image": "looks.png", "size": {"w": 16, "h": 8}}})",
                                                      "looks.json");
    AnimatedSpriteRenderer* plain = nullptr;
    AnimatedSpriteRenderer* mirrored = nullptr;
    start([&](core::Scene& s) {
        AnimatedSpriteRendererDef def;
        def.sprite.texture = texture;
        def.frames = animationUvs(sheet, "look");
        def.animation.frameDuration = 0.1;
        core::GameObject& top = s.createGameObject();
        top.setPosition(glm::vec2(0.0f, 16.0f));
        top.setScale(4.0f);
        plain = top.addComponent<AnimatedSpriteRenderer>(def);
        core::GameObject& bottom = s.createGameObject();
        bottom.setPosition(glm::vec2(0.0f, -16.0f));
        bottom.setScale(4.0f);
        def.sprite.flipX = true;
        mirrored = bottom.addComponent<AnimatedSpriteRenderer>(def);
    });
    Image upright = frame(0.0, "upright");
    ASSERT_NE(plain, nullptr);
    ASSERT_TRUE(plain->frames()[1].rotated);
    Image turned = frame(0.1, "turned");
    EXPECT_EQ(plain->animation().frame(), 1);
    EXPECT_EQ(mirrored->animation().frame(), 1);
    EXPECT_TRUE(scene.renderer.sprite(plain->sprite()).uvRotated);
    // Each sprite is 32 x 16 pixels centred at screen (32, 48) and (32, 16); display pixel
    // (x, yDown) of the 8 x 4 image covers a 4 x 4 block.
    for (const Image* image : {&upright, &turned}) {
        int wrong = 0;
        for (int y = 0; y < 64; ++y) {
            for (int x = 0; x < 64; ++x) {
                Color want = kBlack;
                if (x >= 16 && x < 48 && y >= 40 && y < 56) {
                    want = quadrant((x - 16) / 4, (55 - y) / 4);
                } else if (x >= 16 && x < 48 && y >= 8 && y < 24) {
                    want = quadrant(7 - (x - 16) / 4, (23 - y) / 4);
                }
                if (!near(pixel(*image, x, y), want, 0) && ++wrong <= 5) {
                    ADD_FAILURE() << (image == &upright ? "upright" : "turned") << " pixel (" << x
                                  << ", " << y << ") is " << str(pixel(*image, x, y))
                                  << ", expected " << str(want);
                }
            }
        }
        EXPECT_EQ(wrong, 0);
    }
    EXPECT_EQ(turned.pixels, upright.pixels);
}

// A camera component views from its object: the sprite at the camera object's world position
// lands at the screen's centre; with the component disabled the system's own camera is used.
TEST_F(RenderComponents, CameraComponentViewsFromItsObject) {
    CameraComponent* camera = nullptr;
    start([&](core::Scene& s) {
        core::GameObject& target = s.createGameObject();
        target.setPosition(glm::vec2(20.0f, 10.0f));
        target.addComponent<SpriteRenderer>(
            SpriteRendererDef{.size = {6.0f, 6.0f}, .tint = kGreen});
        core::GameObject& rig = s.createGameObject();
        core::GameObject& eye = s.createGameObject();
        rig.addChild(eye);
        rig.setPosition(glm::vec2(15.0f, 10.0f));
        eye.setPosition(glm::vec2(5.0f, 0.0f));
        camera =
            eye.addComponent<CameraComponent>(CameraComponentDef{.referenceSize = {64.0f, 64.0f}});
    });
    Image viewed = frame(0.0, "component");
    ASSERT_NE(camera, nullptr);
    EXPECT_EQ(camera->camera().position(), glm::vec2(20.0f, 10.0f));
    EXPECT_TRUE(near(pixel(viewed, 32, 32), kGreen, 0)) << str(pixel(viewed, 32, 32));
    camera->setEnabled(false);
    Image own = frame(0.0, "system-camera");
    // The system's camera at (0, 0): the sprite at screen (52, 42).
    EXPECT_TRUE(near(pixel(own, 52, 42), kGreen, 0)) << str(pixel(own, 52, 42));
    EXPECT_TRUE(near(pixel(own, 32, 32), kBlack, 0));
}

// Frames of a sheet's animation in natural order; a rotated frame keeps its stored region and
// says it is rotated.
TEST(AnimationUvs, NaturalOrderAndRotatedFramesMarked) {
    const SpriteSheet sheet = SpriteSheet::fromString(R"({"frames": {
      "run10.png": {"frame": {"x": 32, "y": 0, "w": 16, "h": 16}, "rotated": false},
      "run2.png": {"frame": {"x": 16, "y": 0, "w": 16, "h": 16}, "rotated": false},
      "run1.png": {"frame": {"x": 0, "y": 0, "w": 16, "h": 16}, "rotated": false},
      "spin1.png": {"frame": {"x": 0, "y": 16, "w": 16, "h": 8}, "rotated": true}},
      "meta": {"image": "a.png", "size": {"w": 64, "h": 32}}})",
                                                      "anim.json");
    const std::vector<AnimationFrame> frames = animationUvs(sheet, "run");
    ASSERT_EQ(frames.size(), 3u);
    EXPECT_FLOAT_EQ(frames[0].uv.min.x, 0.0f);
    EXPECT_FLOAT_EQ(frames[1].uv.min.x, 16.0f / 64.0f);
    EXPECT_FLOAT_EQ(frames[2].uv.min.x, 32.0f / 64.0f);
    EXPECT_FLOAT_EQ(frames[2].uv.size.x, 16.0f / 64.0f);
    EXPECT_FALSE(frames[0].rotated || frames[1].rotated || frames[2].rotated);
    // Shown 16 x 8, stored 8 wide and 16 tall at (0, 16) of the 64 x 32 image.
    const std::vector<AnimationFrame> spin = animationUvs(sheet, "spin");
    ASSERT_EQ(spin.size(), 1u);
    EXPECT_TRUE(spin[0].rotated);
    EXPECT_EQ(spin[0].uv.min, glm::vec2(0.0f, 0.5f));
    EXPECT_EQ(spin[0].uv.size, glm::vec2(8.0f / 64.0f, 0.5f));
    EXPECT_THROW(static_cast<void>(animationUvs(sheet, "walk")), core::Error);
}

TEST_F(RenderComponents, TextLabelDrawsAtItsObjectAndMovesWithIt) {
    core::GameObject* object = nullptr;
    TextLabel* label = nullptr;
    start([&](core::Scene& s) {
        object = &s.createGameObject();
        object->setPosition(glm::vec2(-20.0f, 0.0f));
        TextLabelDef def;
        def.text = "Hi";
        def.pixelSize = 16;
        def.style.horizontal = HorizontalAlign::Left;
        def.style.vertical = VerticalAlign::Center;
        label = object->addComponent<TextLabel>(def);
    });
    auto inkColumns = [](const Image& image, int& first, int& last) {
        first = -1;
        last = -1;
        for (int x = 0; x < image.width; ++x) {
            for (int y = 0; y < image.height; ++y) {
                if (pixel(image, x, y).r > 128) {
                    first = first < 0 ? x : first;
                    last = x;
                    break;
                }
            }
        }
    };
    Image left = frame(0.0, "left");
    ASSERT_NE(label, nullptr);
    ASSERT_NE(label->font(), nullptr);
    int first = 0;
    int last = 0;
    inkColumns(left, first, last);
    // The anchor is at screen x 12; the ink lies within the layout's bounds from there.
    ASSERT_GE(first, 0) << "no ink";
    EXPECT_GE(first, 12 + static_cast<int>(std::floor(label->layout().bounds.min.x)));
    EXPECT_LE(last, 12 + static_cast<int>(std::ceil(label->layout().bounds.max.x)));
    EXPECT_LE(first, 14);

    object->setPosition(glm::vec2(0.0f, 0.0f));
    Image moved = frame(0.0, "moved");
    int first2 = 0;
    int last2 = 0;
    inkColumns(moved, first2, last2);
    EXPECT_EQ(first2 - first, 20) << "the ink moves with the object";
    EXPECT_EQ(last2 - last, 20);

    label->setVisible(false);
    Image hidden = frame(0.0, "hidden");
    inkColumns(hidden, first2, last2);
    EXPECT_EQ(first2, -1) << "a hidden label draws nothing";
    EXPECT_THROW(TextLabel(TextLabelDef{.pixelSize = 0}), core::Error);
}

} // namespace
} // namespace e2d::render::test
