// SPDX-License-Identifier: MIT
#include <e2d/core/error.hpp>
#include <e2d/render/camera.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

namespace e2d::render {
namespace {

using ::testing::HasSubstr;

TEST(Camera, RejectsBadFields) {
    CameraDef def;
    def.zoom = 0.0f;
    try {
        Camera camera(def);
        FAIL() << "expected an error";
    } catch (const core::Error& error) {
        EXPECT_THAT(error.what(), HasSubstr("render::Camera: zoom must be > 0 and finite, got 0"));
    }
    def.zoom = 1.0f;
    def.referenceSize = {-1.0f, 10.0f};
    EXPECT_THROW(Camera{def}, core::Error);
    Camera camera;
    EXPECT_THROW(camera.setScreenSize({0, 10}), core::Error);
    EXPECT_THROW(camera.setPosition({NAN, 0.0f}), core::Error);
}

// Every fit mode on screens wider and taller than the reference: the scale and letterbox
// follow from the definitions (uniform scale = width ratio, height ratio, or the smaller).
TEST(Camera, FitModesScaleAndLetterbox) {
    CameraDef def;
    def.referenceSize = {200.0f, 100.0f};
    struct Case {
        ScreenFit fit;
        glm::ivec2 screen;
        glm::vec2 ppu;
        Rect region;
    };
    const Case cases[] = {
        // 400 x 400: width ratio 2, height ratio 4.
        {ScreenFit::Expand, {400, 400}, {2.0f, 4.0f}, {{0, 0}, {400, 400}}},
        {ScreenFit::WidthFit, {400, 400}, {2.0f, 2.0f}, {{0, 100}, {400, 200}}},
        {ScreenFit::HeightFit, {400, 400}, {4.0f, 4.0f}, {{0, 0}, {400, 400}}}, // 800 wide: cut off
        {ScreenFit::BestFit, {400, 400}, {2.0f, 2.0f}, {{0, 100}, {400, 200}}},
        // 800 x 200: width ratio 4, height ratio 2.
        {ScreenFit::WidthFit, {800, 200}, {4.0f, 4.0f}, {{0, 0}, {800, 200}}}, // 400 high: cut off
        {ScreenFit::HeightFit, {800, 200}, {2.0f, 2.0f}, {{200, 0}, {400, 200}}},
        {ScreenFit::BestFit, {800, 200}, {2.0f, 2.0f}, {{200, 0}, {400, 200}}},
    };
    for (const Case& c : cases) {
        def.fit = c.fit;
        Camera camera(def);
        camera.setScreenSize(c.screen);
        SCOPED_TRACE(static_cast<int>(c.fit));
        EXPECT_FLOAT_EQ(camera.pixelsPerUnit().x, c.ppu.x);
        EXPECT_FLOAT_EQ(camera.pixelsPerUnit().y, c.ppu.y);
        Rect region = camera.screenRegion();
        EXPECT_FLOAT_EQ(region.min.x, c.region.min.x);
        EXPECT_FLOAT_EQ(region.min.y, c.region.min.y);
        EXPECT_FLOAT_EQ(region.size.x, c.region.size.x);
        EXPECT_FLOAT_EQ(region.size.y, c.region.size.y);
    }
}

TEST(Camera, ConversionsFollowTheDefinition) {
    CameraDef def;
    def.referenceSize = {100.0f, 100.0f};
    def.position = {10.0f, 20.0f};
    def.rotation = 0.5f;
    def.zoom = 2.0f;
    Camera camera(def);
    camera.setScreenSize({200, 200}); // 2 px per unit
    // A world point 3 units along the camera's rotated x axis: camera (6, 0) at zoom 2.
    glm::vec2 world = def.position + 3.0f * glm::vec2(std::cos(0.5f), std::sin(0.5f));
    glm::vec2 cam = camera.worldToCamera(world);
    EXPECT_NEAR(cam.x, 6.0f, 1e-5f);
    EXPECT_NEAR(cam.y, 0.0f, 1e-5f);
    glm::vec2 screen = camera.worldToScreen(world);
    EXPECT_NEAR(screen.x, 100.0f + 12.0f, 1e-4f);
    EXPECT_NEAR(screen.y, 100.0f, 1e-4f);
    // The camera position is the screen centre.
    glm::vec2 centre = camera.worldToScreen(def.position);
    EXPECT_NEAR(centre.x, 100.0f, 1e-4f);
    EXPECT_NEAR(centre.y, 100.0f, 1e-4f);
}

TEST(Camera, RoundTripsEveryDirection) {
    for (ScreenFit fit :
         {ScreenFit::Expand, ScreenFit::WidthFit, ScreenFit::HeightFit, ScreenFit::BestFit}) {
        CameraDef def;
        def.fit = fit;
        def.referenceSize = {320.0f, 180.0f};
        def.position = {-37.5f, 12.25f};
        def.rotation = -1.1f;
        def.zoom = 1.7f;
        Camera camera(def);
        camera.setScreenSize({257, 391});
        for (glm::vec2 p :
             {glm::vec2(0.0f), glm::vec2(100.0f, -40.0f), glm::vec2(-250.5f, 33.3f)}) {
            glm::vec2 w = camera.screenToWorld(camera.worldToScreen(p));
            EXPECT_NEAR(w.x, p.x, 1e-4f);
            EXPECT_NEAR(w.y, p.y, 1e-4f);
            glm::vec2 c = camera.worldToCamera(camera.cameraToWorld(p));
            EXPECT_NEAR(c.x, p.x, 1e-4f);
            EXPECT_NEAR(c.y, p.y, 1e-4f);
            glm::vec2 s = camera.cameraToScreen(camera.screenToCamera(p));
            EXPECT_NEAR(s.x, p.x, 1e-4f);
            EXPECT_NEAR(s.y, p.y, 1e-4f);
            // worldToClip agrees with worldToScreen.
            glm::vec4 clip = camera.worldToClip() * glm::vec4(p, 0.0f, 1.0f);
            glm::vec2 viaClip = (glm::vec2(clip) * 0.5f + 0.5f) * glm::vec2(257.0f, 391.0f);
            glm::vec2 direct = camera.worldToScreen(p);
            EXPECT_NEAR(viaClip.x, direct.x, 1e-3f);
            EXPECT_NEAR(viaClip.y, direct.y, 1e-3f);
        }
    }
}

} // namespace
} // namespace e2d::render
