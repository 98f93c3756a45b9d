// SPDX-License-Identifier: MIT
// Real GLFW windows under Xvfb: context, sizes, resize with every screen-fit mode, errors, and
// the library on its own (window, sprites, screenshot, close).
#include "render_test_util.hpp"

#include <e2d/core/error.hpp>

#include <GLFW/glfw3.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

namespace e2d::render::test {
namespace {

using ::testing::HasSubstr;

TEST(Window, HiddenWindowHasACoreContextAndItsSize) {
    Window window(WindowDef{.title = "ctx", .size = {40, 30}, .vsync = false, .visible = false});
    EXPECT_NE(window.handle(), nullptr);
    EXPECT_GE(window.context().major * 10 + window.context().minor, 33);
    EXPECT_FALSE(window.context().renderer.empty());
    EXPECT_EQ(window.size(), glm::ivec2(40, 30));
    EXPECT_EQ(window.framebufferSize(), glm::ivec2(40, 30));
    EXPECT_FLOAT_EQ(window.contentScale().x, 1.0f); // Xvfb has no HiDPI
    EXPECT_FALSE(window.visible());
    EXPECT_EQ(glfwGetWindowAttrib(window.handle(), GLFW_OPENGL_PROFILE), GLFW_OPENGL_CORE_PROFILE);
    window.setTitle("renamed");
    EXPECT_EQ(window.title(), "renamed");
    EXPECT_FALSE(window.shouldClose());
    window.requestClose();
    EXPECT_TRUE(window.shouldClose());
}

TEST(Window, SecondWindowSharesTheGlfwInstance) {
    Window first(WindowDef{.size = {16, 16}, .visible = false});
    Window second(WindowDef{.size = {16, 16}, .visible = false, .glfw = first.glfw()});
    EXPECT_EQ(first.glfw(), second.glfw());
    EXPECT_EQ(first.glfw().use_count(), 2);
}

TEST(Window, BadFieldsAreErrors) {
    try {
        Window window(WindowDef{.samples = 32});
        FAIL() << "expected an error";
    } catch (const core::Error& error) {
        EXPECT_THAT(error.what(), HasSubstr("render::Window: samples must be in [0, 16], got 32"));
    }
    EXPECT_THROW(Window(WindowDef{.size = {0, 10}}), core::Error);
}

// With no display GLFW cannot start: its own message comes back in a core::Error.
TEST(Window, NoDisplayIsAnErrorCarryingGlfwsMessage) {
    const char* display = std::getenv("DISPLAY");
    std::string saved = display != nullptr ? display : "";
    unsetenv("DISPLAY");
    try {
        Window window(WindowDef{.visible = false});
        ADD_FAILURE() << "expected an error";
    } catch (const core::Error& error) {
        EXPECT_THAT(error.what(), HasSubstr("render::GlfwInstance: glfwInit() failed: "));
        EXPECT_THAT(error.what(), HasSubstr("DISPLAY"));
    }
    if (!saved.empty()) {
        setenv("DISPLAY", saved.c_str(), 1);
    }
    // And GLFW works again afterwards.
    Window window(WindowDef{.size = {8, 8}, .visible = false});
    EXPECT_NE(window.handle(), nullptr);
}

bool waitForFramebuffer(Window& window, glm::ivec2 size) {
    for (int i = 0; i < 200 && window.framebufferSize() != size; ++i) {
        window.pollEvents();
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return window.framebufferSize() == size;
}

// The window is resized; the renderer refits the camera to the new framebuffer; the white
// reference region lands where each fit mode puts it and the rest is letterboxed black.
TEST(Window, EveryFitModeLetterboxesAfterAResize) {
    const glm::vec2 reference{64.0f, 32.0f};
    for (ScreenFit fit :
         {ScreenFit::Expand, ScreenFit::WidthFit, ScreenFit::HeightFit, ScreenFit::BestFit}) {
        Window window(WindowDef{.size = {64, 32}, .vsync = false, .visible = false});
        Renderer renderer(window);
        Camera camera(CameraDef{.referenceSize = reference, .fit = fit});
        // The whole reference region in white, and far beyond it in red underneath.
        renderer.createSprite(SpriteDef{.z = -1.0f, .size = {1000.0f, 1000.0f}, .tint = kRed});
        renderer.createSprite(SpriteDef{.size = reference, .tint = kWhite});
        for (glm::ivec2 screen : {glm::ivec2(128, 48), glm::ivec2(64, 96)}) {
            window.setSize(screen);
            ASSERT_TRUE(waitForFramebuffer(window, screen))
                << "framebuffer stayed " << window.framebufferSize().x;
            unsigned resizes = window.resizeCount();
            EXPECT_GT(resizes, 0u);
            // As in a game loop: Mesa resizes a window's buffers at a swap, so the frame after
            // the one that saw the new size is the first drawn at it.
            renderer.render(camera);
            window.swapBuffers();
            renderer.render(camera);
            EXPECT_EQ(camera.screenSize(), screen);
            Image image = renderer.readPixels();
            std::string name = currentTestName() + "-" + std::to_string(static_cast<int>(fit)) +
                               "-" + std::to_string(screen.x) + "x" + std::to_string(screen.y) +
                               ".png";
            writePng(image, outputDir() / name);
            // Expected from the definitions: the scale per fit, the reference region centred.
            glm::vec2 ratio = glm::vec2(screen) / reference;
            glm::vec2 scale = fit == ScreenFit::Expand      ? ratio
                              : fit == ScreenFit::WidthFit  ? glm::vec2(ratio.x)
                              : fit == ScreenFit::HeightFit ? glm::vec2(ratio.y)
                                                            : glm::vec2(std::min(ratio.x, ratio.y));
            glm::vec2 extent = reference * scale;
            glm::vec2 lo = glm::max(glm::vec2(0.0f), (glm::vec2(screen) - extent) * 0.5f);
            glm::vec2 hi = glm::min(glm::vec2(screen), (glm::vec2(screen) + extent) * 0.5f);
            int wrong = 0;
            for (int y = 0; y < screen.y; ++y) {
                for (int x = 0; x < screen.x; ++x) {
                    bool inside =
                        x + 0.5f > lo.x && x + 0.5f < hi.x && y + 0.5f > lo.y && y + 0.5f < hi.y;
                    if (!near(pixel(image, x, y), inside ? kWhite : kBlack, 0)) {
                        if (++wrong < 4) {
                            ADD_FAILURE() << name << ": pixel (" << x << ", " << y << ") is "
                                          << str(pixel(image, x, y)) << ", expected "
                                          << (inside ? "white" : "black (letterbox)");
                        }
                    }
                }
            }
            EXPECT_EQ(wrong, 0) << name;
        }
    }
}

// Borderless covers the primary monitor at its current mode (Xvfb's screen); fullscreen takes the
// monitor at the requested size; both draw a frame that reads back; the hints they set do not
// leak into the next windowed window.
TEST(Window, BorderlessAndFullscreenCoverTheMonitor) {
    auto glfw = std::make_shared<GlfwInstance>();
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    ASSERT_NE(monitor, nullptr);
    const GLFWvidmode* video = glfwGetVideoMode(monitor);
    const glm::ivec2 screen{video->width, video->height};
    for (WindowMode mode : {WindowMode::Borderless, WindowMode::Fullscreen}) {
        const char* name = mode == WindowMode::Borderless ? "borderless" : "fullscreen";
        Window window(WindowDef{.size = screen, .mode = mode, .vsync = false, .glfw = glfw});
        EXPECT_EQ(window.mode(), mode) << name;
        EXPECT_EQ(glfwGetWindowMonitor(window.handle()), monitor) << name;
        EXPECT_EQ(window.size(), screen) << name;
        EXPECT_EQ(window.framebufferSize(), screen) << name;
        if (mode == WindowMode::Borderless) {
            EXPECT_EQ(glfwGetWindowAttrib(window.handle(), GLFW_DECORATED), GLFW_FALSE);
        }
        Renderer renderer(window);
        Camera camera = pixelCamera(screen);
        renderer.createSprite(SpriteDef{.size = {20.0f, 20.0f}, .tint = kRed});
        renderer.render(camera);
        Image frame = renderer.readPixels();
        ASSERT_EQ(frame.width, screen.x) << name;
        EXPECT_TRUE(near(pixel(frame, screen.x / 2, screen.y / 2), kRed, 0)) << name;
        EXPECT_TRUE(near(pixel(frame, screen.x / 2 + 15, screen.y / 2), kBlack, 0)) << name;
    }
    Window windowed(WindowDef{.size = {32, 24}, .vsync = false, .visible = false, .glfw = glfw});
    EXPECT_EQ(glfwGetWindowMonitor(windowed.handle()), nullptr);
    EXPECT_EQ(glfwGetWindowAttrib(windowed.handle(), GLFW_DECORATED), GLFW_TRUE);
    EXPECT_EQ(windowed.size(), glm::ivec2(32, 24));
}

// MSAA: the default framebuffer has the samples asked for (llvmpipe offers 4) or none; vsync
// follows setVsync(); the content scale is the framebuffer's pixels per screen coordinate.
TEST(Window, SamplesVsyncAndContentScale) {
    Window plain(WindowDef{.size = {32, 32}, .samples = 0, .vsync = true, .visible = false});
    EXPECT_EQ(plain.samples(), 0);
    EXPECT_TRUE(plain.vsync());
    plain.setVsync(false);
    EXPECT_FALSE(plain.vsync());
    Window msaa(WindowDef{
        .size = {32, 32}, .samples = 4, .vsync = false, .visible = false, .glfw = plain.glfw()});
    EXPECT_EQ(msaa.samples(), 4);
    int width = 0;
    int height = 0;
    glfwGetWindowSize(msaa.handle(), &width, &height);
    EXPECT_FLOAT_EQ(msaa.contentScale().x,
                    static_cast<float>(msaa.framebufferSize().x) / static_cast<float>(width));
    // A multisampled window still draws: a sprite reads back (resolved) in the middle.
    Renderer renderer(msaa);
    Camera camera = pixelCamera({32, 32});
    renderer.createSprite(SpriteDef{.size = {10.0f, 10.0f}, .tint = kGreen});
    renderer.render(camera);
    Image frame = renderer.readPixels();
    EXPECT_TRUE(near(pixel(frame, 16, 16), kGreen, 0));
    EXPECT_TRUE(near(pixel(frame, 2, 2), kBlack, 0));
    try {
        Window bad(WindowDef{.samples = -1, .glfw = plain.glfw()});
        FAIL() << "expected an error";
    } catch (const core::Error& error) {
        EXPECT_THAT(error.what(), HasSubstr("render::Window: samples must be in [0, 16], got -1"));
    }
}

// The library alone: a window, a few sprites, a screenshot on disk that reads back right.
TEST(Standalone, OpenDrawScreenshotClose) {
    std::filesystem::path file = outputDir() / "standalone.png";
    std::filesystem::remove(file);
    {
        Window window(WindowDef{
            .title = "e2d standalone", .size = {48, 48}, .vsync = false, .visible = false});
        Renderer renderer(window, RendererDef{.clearColor = {0, 0, 64, 255}});
        Camera camera(CameraDef{.referenceSize = {48.0f, 48.0f}});
        renderer.createSprite(
            SpriteDef{.position = {-12.0f, 0.0f}, .size = {8.0f, 8.0f}, .tint = kRed});
        renderer.createSprite(
            SpriteDef{.position = {12.0f, 0.0f}, .size = {8.0f, 8.0f}, .tint = kGreen});
        renderer.render(camera);
        renderer.screenshot(file);
        window.swapBuffers();
    }
    Image shot = loadImage(file);
    ASSERT_EQ(shot.width, 48);
    EXPECT_TRUE(near(pixel(shot, 12, 24), kRed, 0));
    EXPECT_TRUE(near(pixel(shot, 36, 24), kGreen, 0));
    EXPECT_TRUE(near(pixel(shot, 2, 2), Color{0, 0, 64, 255}, 0));
}

} // namespace
} // namespace e2d::render::test
