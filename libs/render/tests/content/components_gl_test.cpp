// SPDX-License-Identifier: MIT
// TextLabel and AnimatedSpriteRenderer on game objects of a core::Scene, drawn by a real
// RenderSystem (Mesa llvmpipe under Xvfb) and read back. Frames are written as PNGs
// (components_gl_*.png) in the working directory.
#include <e2d/core/error.hpp>
#include <e2d/core/game_object.hpp>
#include <e2d/core/log.hpp>
#include <e2d/core/scene.hpp>
#include <e2d/core/scene_host.hpp>
#include <e2d/render/animated_sprite_renderer.hpp>
#include <e2d/render/image.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/sprite_sheet.hpp>
#include <e2d/render/text_label.hpp>
#include <e2d/render/window.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

using namespace e2d;
using namespace e2d::render;
using testing::HasSubstr;

namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 200;

class Host : public core::SceneHost {
public:
    explicit Host(core::System* system) : systems_{system} {}
    void changeToScene(std::string_view) override {}
    void terminateGame() override {}
    [[nodiscard]] glm::ivec2 windowSize() const override { return {kWidth, kHeight}; }
    [[nodiscard]] glm::ivec2 referenceWindowSize() const override { return {kWidth, kHeight}; }
    [[nodiscard]] core::Logger& logger() override { return logger_; }
    [[nodiscard]] std::span<core::System* const> systems() const override { return systems_; }
    std::vector<std::string> messages;

private:
    core::Logger logger_{core::LogLevel::Trace,
                         [this](core::LogLevel, std::string_view m) { messages.emplace_back(m); }};
    std::vector<core::System*> systems_;
};

// Counts pixels of a read-back frame (rows from the top) whose colour is within `tolerance`
// of `colour`, in the rectangle [x0, x1) x [y0, y1) given bottom-up (y up, as the world).
int count(const Image& image, int x0, int y0, int x1, int y1, Color colour, int tolerance = 40) {
    int n = 0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            const std::uint8_t* p = image.at(x, kHeight - 1 - y);
            if (std::abs(p[0] - colour.r) <= tolerance && std::abs(p[1] - colour.g) <= tolerance &&
                std::abs(p[2] - colour.b) <= tolerance) {
                ++n;
            }
        }
    }
    return n;
}

class Components : public ::testing::Test {
protected:
    void SetUp() override {
        setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
        WindowDef def;
        def.title = "e2d components test";
        def.size = {kWidth, kHeight};
        def.vsync = false;
        def.visible = false;
        window_ = std::make_unique<Window>(def);
        renderer_ =
            std::make_unique<Renderer>(*window_, RendererDef{.offscreenSize = {kWidth, kHeight}});
        system_ = std::make_unique<RenderSystem>(*renderer_, nullptr, nullptr);
        // One world unit per pixel, world (0, 0) at the bottom-left corner.
        system_->camera() = Camera(CameraDef{.position = {kWidth / 2.0f, kHeight / 2.0f},
                                             .referenceSize = {kWidth, kHeight}});
        host_ = std::make_unique<Host>(system_.get());
        scene_.attachHost(host_.get(), "test");
        scene_.dispatchInitialize();
        folder_ = std::filesystem::temp_directory_path() /
                  ("e2d_components_" + std::to_string(::getpid()));
        std::filesystem::create_directories(folder_);
    }
    void TearDown() override {
        scene_.dispatchTerminate();
        std::filesystem::remove_all(folder_);
    }
    Image frame(const std::string& name) {
        scene_.beginFrame();
        system_->render(0.0);
        Image image = renderer_->readPixels();
        writePng(image, "components_gl_" + name + ".png");
        return image;
    }
    // A sheet of three 10 x 10 frames: red, green, blue, named spin1..spin3.
    std::filesystem::path writeSheet() {
        Image image{30, 10, std::vector<std::uint8_t>(30 * 10 * 4, 255)};
        for (int x = 0; x < 30; ++x) {
            for (int y = 0; y < 10; ++y) {
                auto* p = image.pixels.data() + (y * 30 + x) * 4;
                p[0] = x < 10 ? 255 : 0;
                p[1] = x >= 10 && x < 20 ? 255 : 0;
                p[2] = x >= 20 ? 255 : 0;
            }
        }
        writePng(image, folder_ / "spin.png");
        std::ofstream(folder_ / "spin.json") << R"({"frames": {
            "spin1.png": {"frame": {"x": 0, "y": 0, "w": 10, "h": 10}},
            "spin2.png": {"frame": {"x": 10, "y": 0, "w": 10, "h": 10}},
            "spin3.png": {"frame": {"x": 20, "y": 0, "w": 10, "h": 10}}},
            "meta": {"image": "spin.png", "size": {"w": 30, "h": 10}}})";
        return folder_ / "spin.json";
    }

    // An object at (100, 100) playing the frames `base`<n> of `sheet`, one every 0.25 s, at
    // their own size.
    AnimatedSpriteRenderer* addAnimation(const SpriteSheet& sheet, std::string_view base) {
        core::GameObject& object = scene_.createGameObject();
        object.setPosition(glm::vec2{100.0f, 100.0f});
        AnimatedSpriteRendererDef def;
        def.sprite.texturePath = sheet.imagePath().string();
        def.frames = animationUvs(sheet, base);
        def.animation.frameDuration = 0.25;
        return object.addComponent<AnimatedSpriteRenderer>(def);
    }

    std::unique_ptr<Window> window_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<RenderSystem> system_;
    std::unique_ptr<Host> host_;
    core::Scene scene_;
    std::filesystem::path folder_;
};

TEST_F(Components, TextLabelDrawsAtItsObjectWithItsAlignment) {
    core::GameObject& object = scene_.createGameObject();
    object.setPosition(glm::vec2{160.0f, 100.0f});
    TextLabelDef def;
    def.text = "Hello";
    def.pixelSize = 32;
    auto* label = object.addComponent<TextLabel>(def);
    Image left = frame("label_left_top");
    ASSERT_GT(label->layout().quads.size(), 0u);
    // Left/top: the text lies right of and below the anchor.
    EXPECT_GT(count(left, 160, 60, 320, 100, {255, 255, 255, 255}, 100), 50);
    EXPECT_EQ(count(left, 0, 0, 158, 200, {255, 255, 255, 255}, 100), 0);
    EXPECT_EQ(count(left, 0, 102, 320, 200, {255, 255, 255, 255}, 100), 0);

    label->setAlignment(HorizontalAlign::Right, VerticalAlign::Bottom);
    Image right = frame("label_right_bottom");
    EXPECT_GT(count(right, 0, 100, 160, 160, {255, 255, 255, 255}, 100), 50);
    EXPECT_EQ(count(right, 162, 0, 320, 200, {255, 255, 255, 255}, 100), 0);
    EXPECT_EQ(count(right, 0, 0, 320, 98, {255, 255, 255, 255}, 100), 0);

    // A style with a bad line spacing is refused and changes nothing.
    TextStyle badStyle;
    badStyle.lineSpacing = 0.0f;
    EXPECT_THAT([&] { label->setStyle(badStyle); },
                testing::ThrowsMessage<core::Error>(
                    HasSubstr("render::TextLabel::setStyle(): style.lineSpacing")));
    EXPECT_EQ(label->def().style.horizontal, HorizontalAlign::Right);

    // Moving the object moves the text; an emptied label draws nothing.
    object.setPosition(glm::vec2{60.0f, 40.0f});
    label->setText("");
    Image empty = frame("label_empty");
    EXPECT_EQ(count(empty, 0, 0, 320, 200, {255, 255, 255, 255}, 100), 0);
    TextLabelDef zero;
    zero.pixelSize = 0;
    EXPECT_THAT([&] { TextLabel bad(zero); }, testing::ThrowsMessage<core::Error>(HasSubstr(
                                                  "pixelSize must be in [1, 1024], got 0")));
}

TEST_F(Components, AnimatedSpritePlaysTheSheetFramesInOrder) {
    const auto path = writeSheet();
    const SpriteSheet* sheet = system_->sheet(path);
    ASSERT_NE(sheet, nullptr);
    // Thousands of sprites of one sheet share one parse.
    EXPECT_EQ(system_->sheet(path), sheet);
    auto* sprite = addAnimation(*sheet, "spin");
    const Color colours[] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}};
    for (int step = 0; step < 5; ++step) {
        Image image = frame("anim_" + std::to_string(step));
        const Color want = colours[step % 3];
        // The 10 x 10 frame centred on (100, 100), in the frame's colour, nothing elsewhere.
        EXPECT_EQ(count(image, 95, 95, 105, 105, want, 10), 100) << "step " << step;
        EXPECT_EQ(count(image, 0, 0, 320, 200, {0, 0, 0, 255}, 10), 320 * 200 - 100);
        EXPECT_EQ(sprite->animation().frame(), step % 3);
        scene_.dispatchUpdate(0.25);
    }
}

TEST_F(Components, FramesOfASheetWhoseImageFailedKeepTheirDeclaredSize) {
    // The image is missing: the 64 x 64 placeholder is drawn, at each frame's own size (it used
    // to be the placeholder's size times the frame's UV extent: 42.7 x 21.3 for the first).
    std::ofstream(folder_ / "gone.json") << R"({"frames": {
        "big1.png": {"frame": {"x": 0, "y": 0, "w": 40, "h": 10}},
        "big2.png": {"frame": {"x": 40, "y": 0, "w": 20, "h": 30}}},
        "meta": {"image": "gone.png", "size": {"w": 60, "h": 30}}})";
    const SpriteSheet* sheet = system_->sheet(folder_ / "gone.json");
    ASSERT_NE(sheet, nullptr);
    // A white background, so both colours of the checker count as the sprite.
    renderer_->createSprite(
        SpriteDef{.position = {160.0f, 100.0f}, .z = -1.0f, .size = {320.0f, 200.0f}});
    addAnimation(*sheet, "big");
    EXPECT_TRUE(renderer_->textureInfo(renderer_->loadTexture(sheet->imagePath())).placeholder);
    const Color white{255, 255, 255, 255};
    const Image first = frame("placeholder_frame_1");
    EXPECT_EQ(320 * 200 - count(first, 0, 0, 320, 200, white, 10), 40 * 10);
    EXPECT_EQ(count(first, 80, 95, 120, 105, white, 10), 0);
    scene_.dispatchUpdate(0.25);
    const Image second = frame("placeholder_frame_2");
    EXPECT_EQ(320 * 200 - count(second, 0, 0, 320, 200, white, 10), 20 * 30);
    EXPECT_EQ(count(second, 90, 85, 110, 115, white, 10), 0);
}

TEST_F(Components, ABrokenSheetIsReportedOnceAndGivesNull) {
    std::vector<std::string> messages;
    core::Logger logger(core::LogLevel::Trace,
                        [&](core::LogLevel, std::string_view m) { messages.emplace_back(m); });
    RenderSystem system(*renderer_, nullptr, &logger);
    EXPECT_EQ(system.sheet(folder_ / "missing.json"), nullptr);
    EXPECT_EQ(system.sheet(folder_ / "missing.json"), nullptr);
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_THAT(messages[0], HasSubstr("missing.json"));
    EXPECT_EQ(system.sheetError(folder_ / "missing.json"), messages[0]);
    std::ofstream(folder_ / "bad.json") << R"({"frames": {}, "meta": {"image": "x.png"}})";
    EXPECT_EQ(system.sheet(folder_ / "bad.json"), nullptr);
    EXPECT_THAT(system.sheetError(folder_ / "bad.json"), HasSubstr("missing key \"size\""));
    EXPECT_EQ(messages.size(), 2u);
    EXPECT_EQ(system.sheetError(writeSheet()), "");
}

} // namespace
