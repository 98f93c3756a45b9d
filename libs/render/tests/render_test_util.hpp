// SPDX-License-Identifier: MIT
// Shared by the render tests: a hidden window with a renderer drawing offscreen, pixel reads
// in screen coordinates, and PNGs of every scene in the build directory.
#pragma once

// Defs are written with designated initialisers naming only what a test changes; GCC 12's
// -Wextra warns about every field left to its default member initialiser, which is the point.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

#include <e2d/render/renderer.hpp>
#include <e2d/render/window.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

namespace e2d::render::test {

// Which instance-buffer path a test runs: the 3.3 orphaning path or the 4.4 persistent ring.
enum class Path { Gl33, Gl44 };

inline std::string pathName(const testing::TestParamInfo<Path>& info) {
    return info.param == Path::Gl33 ? "Gl33" : "Gl44";
}

// Where tests leave their PNGs (the test's working directory is the build directory).
inline std::filesystem::path outputDir() {
    std::filesystem::path dir = std::filesystem::current_path() / "render_test_output";
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::string currentTestName() {
    const testing::TestInfo* info = testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "." + info->name();
    for (char& c : name) {
        if (c == '/') {
            c = '_';
        }
    }
    return name;
}

inline std::vector<char> readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void writeBytes(const std::filesystem::path& path, const std::vector<char>& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// A hidden window and a renderer drawing into a `size` offscreen framebuffer (or into the
// window's own framebuffer when `offscreen` is false).
struct Scene {
    Scene(Path path, glm::ivec2 size, bool offscreen = true, core::Logger* logger = nullptr)
        : window(WindowDef{
              .title = "e2d render test", .size = size, .vsync = false, .visible = false}),
          renderer(window, RendererDef{.offscreenSize = offscreen ? size : glm::ivec2(0),
                                       .forceGl33 = path == Path::Gl33,
                                       .logger = logger}) {}

    // Renders with `camera`, saves the frame as render_test_output/<test>[-suffix].png and
    // returns it.
    Image frame(Camera& camera, const std::string& suffix = {}) {
        renderer.render(camera);
        Image image = renderer.readPixels();
        std::string name = currentTestName() + (suffix.empty() ? "" : "-" + suffix) + ".png";
        writePng(image, outputDir() / name);
        return image;
    }

    Window window;
    Renderer renderer;
};

// Pixel (x, y) in screen coordinates (origin bottom-left, y up) of an Image (rows from the top).
inline Color pixel(const Image& image, int x, int y) {
    const std::uint8_t* p = image.at(x, image.height - 1 - y);
    return Color{p[0], p[1], p[2], p[3]};
}

inline bool near(Color a, Color b, int tolerance = 1) {
    auto d = [](int x, int y) { return x > y ? x - y : y - x; };
    return d(a.r, b.r) <= tolerance && d(a.g, b.g) <= tolerance && d(a.b, b.b) <= tolerance;
}

inline std::string str(Color c) {
    return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) +
           ", " + std::to_string(c.a) + ")";
}

// A camera whose world units are screen pixels on a `size` screen, world (0, 0) at the centre.
inline Camera pixelCamera(glm::ivec2 size) {
    return Camera(CameraDef{.referenceSize = glm::vec2(size), .fit = ScreenFit::BestFit});
}

inline constexpr Color kRed{255, 0, 0, 255};
inline constexpr Color kGreen{0, 255, 0, 255};
inline constexpr Color kBlue{0, 0, 255, 255};
inline constexpr Color kBlack{0, 0, 0, 255};
inline constexpr Color kWhite{255, 255, 255, 255};

} // namespace e2d::render::test
