// SPDX-License-Identifier: MIT
// Image files other programs write that FreeImage reads in its own way: 16-bit PNGs, 32-bit
// BMPs whose fourth byte is padding, JPEGs turned by their EXIF orientation; and images larger
// than the GPU takes. Each test writes its own small input file.
#include "render_test_util.hpp"

#include <e2d/core/error.hpp>
#include <e2d/core/log.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace e2d::render::test {
namespace {

using ::testing::HasSubstr;

const std::filesystem::path kData = E2D_RENDER_TEST_DATA;

void putBig(std::vector<char>& out, std::uint32_t v, int bytes) {
    for (int b = bytes - 1; b >= 0; --b) {
        out.push_back(static_cast<char>((v >> (8 * b)) & 0xffu));
    }
}

void putLittle(std::vector<char>& out, std::uint32_t v, int bytes) {
    for (int b = 0; b < bytes; ++b) {
        out.push_back(static_cast<char>((v >> (8 * b)) & 0xffu));
    }
}

std::uint32_t crc32(const char* data, std::size_t size) {
    std::uint32_t crc = 0xffffffffu;
    for (std::size_t i = 0; i < size; ++i) {
        crc ^= static_cast<std::uint8_t>(data[i]);
        for (int k = 0; k < 8; ++k) {
            crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
        }
    }
    return ~crc;
}

void pngChunk(std::vector<char>& png, const char* type, const std::vector<char>& data) {
    putBig(png, static_cast<std::uint32_t>(data.size()), 4);
    std::vector<char> typed(type, type + 4);
    typed.insert(typed.end(), data.begin(), data.end());
    png.insert(png.end(), typed.begin(), typed.end());
    putBig(png, crc32(typed.data(), typed.size()), 4);
}

// A PNG with 16 bits per channel (colour type 0 grey, 4 grey + alpha, 2 RGB, 6 RGBA), written
// by hand: its pixel data in one stored (uncompressed) deflate block. `samples` holds width *
// height * channels values, rows from the top.
std::vector<char> png16(int width, int height, int colourType,
                        const std::vector<std::uint16_t>& samples) {
    std::vector<char> rows;
    const std::size_t perRow = samples.size() / static_cast<std::size_t>(height);
    for (int y = 0; y < height; ++y) {
        rows.push_back(0); // filter: none
        for (std::size_t i = 0; i < perRow; ++i) {
            putBig(rows, samples[static_cast<std::size_t>(y) * perRow + i], 2);
        }
    }
    std::vector<char> zlib = {0x78, 0x01, 0x01}; // deflate, then one final stored block
    putLittle(zlib, static_cast<std::uint32_t>(rows.size()), 2);
    putLittle(zlib, static_cast<std::uint32_t>(~rows.size() & 0xffffu), 2);
    zlib.insert(zlib.end(), rows.begin(), rows.end());
    std::uint32_t a = 1;
    std::uint32_t b = 0;
    for (char c : rows) {
        a = (a + static_cast<std::uint8_t>(c)) % 65521u;
        b = (b + a) % 65521u;
    }
    putBig(zlib, (b << 16) | a, 4);

    std::vector<char> png = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};
    std::vector<char> header;
    putBig(header, static_cast<std::uint32_t>(width), 4);
    putBig(header, static_cast<std::uint32_t>(height), 4);
    header.insert(header.end(), {16, static_cast<char>(colourType), 0, 0, 0});
    pngChunk(png, "IHDR", header);
    pngChunk(png, "IDAT", zlib);
    pngChunk(png, "IEND", {});
    return png;
}

// A 32-bit BI_RGB BMP, rows bottom-up, each pixel B, G, R and the fourth byte `fourth[i]`.
std::vector<char> bmp32(int width, int height, const std::vector<std::uint8_t>& fourth) {
    std::vector<char> bmp = {'B', 'M'};
    const auto pixelBytes = static_cast<std::uint32_t>(width * height * 4);
    putLittle(bmp, 54 + pixelBytes, 4);
    putLittle(bmp, 0, 4);
    putLittle(bmp, 54, 4);
    putLittle(bmp, 40, 4); // BITMAPINFOHEADER
    putLittle(bmp, static_cast<std::uint32_t>(width), 4);
    putLittle(bmp, static_cast<std::uint32_t>(height), 4);
    putLittle(bmp, 1, 2);  // planes
    putLittle(bmp, 32, 2); // bits per pixel
    putLittle(bmp, 0, 4);  // BI_RGB
    putLittle(bmp, pixelBytes, 4);
    putLittle(bmp, 2835, 4);
    putLittle(bmp, 2835, 4);
    putLittle(bmp, 0, 4);
    putLittle(bmp, 0, 4);
    for (int i = 0; i < width * height; ++i) {
        bmp.insert(bmp.end(),
                   {static_cast<char>(200), static_cast<char>(100), static_cast<char>(50),
                    static_cast<char>(fourth[static_cast<std::size_t>(i)])});
    }
    return bmp;
}

// quadrant.jpg with an EXIF block (APP1) after its JFIF block saying `orientation`.
std::vector<char> quadrantWithOrientation(std::uint16_t orientation) {
    std::vector<char> jpeg = readBytes(kData / "quadrant.jpg");
    // SOI, then APP0 (FF E0, length): the EXIF segment goes right after it.
    const std::size_t app0End =
        4 + ((static_cast<std::size_t>(static_cast<std::uint8_t>(jpeg[4])) << 8) |
             static_cast<std::uint8_t>(jpeg[5]));
    std::vector<char> exif = {'\xFF', '\xE1'};
    putBig(exif, 2 + 6 + 8 + 2 + 12 + 4, 2);
    exif.insert(exif.end(), {'E', 'x', 'i', 'f', 0, 0, 'M', 'M', 0, 42});
    putBig(exif, 8, 4);      // IFD0 right after the TIFF header
    putBig(exif, 1, 2);      // one entry:
    putBig(exif, 0x0112, 2); // Orientation,
    putBig(exif, 3, 2);      // SHORT,
    putBig(exif, 1, 4);      // one value,
    putBig(exif, orientation, 2);
    putBig(exif, 0, 2);
    putBig(exif, 0, 4); // no next IFD
    jpeg.insert(jpeg.begin() + static_cast<std::ptrdiff_t>(app0End), exif.begin(), exif.end());
    return jpeg;
}

Color at(const Image& image, int x, int y) {
    const std::uint8_t* p = image.at(x, y);
    return Color{p[0], p[1], p[2], p[3]};
}

std::filesystem::path dir() {
    std::filesystem::path d = outputDir() / "image_formats";
    std::filesystem::create_directories(d);
    return d;
}

TEST(ImageFormats, SixteenBitPngsKeepTheHighByte) {
    const std::filesystem::path grey = dir() / "grey16.png";
    writeBytes(grey,
               png16(4, 2, 0, {0x0000, 0x8000, 0xFFFF, 0x12FF, 0x4000, 0x4001, 0xC0DE, 0x0100}));
    const Image g = loadImage(grey);
    ASSERT_EQ(g.width, 4);
    ASSERT_EQ(g.height, 2);
    const std::uint8_t expected[] = {0x00, 0x80, 0xFF, 0x12, 0x40, 0x40, 0xC0, 0x01};
    for (int i = 0; i < 8; ++i) {
        const Color c = at(g, i % 4, i / 4);
        EXPECT_EQ(c.r, expected[i]) << i;
        EXPECT_EQ(c.g, expected[i]) << i;
        EXPECT_EQ(c.b, expected[i]) << i;
        EXPECT_EQ(c.a, 255) << i;
    }

    const std::filesystem::path rgba = dir() / "rgba16.png";
    writeBytes(rgba,
               png16(2, 1, 6, {0xFF00, 0x8000, 0x0000, 0xFFFF, 0x0000, 0x00FF, 0xFFFF, 0x7FFF}));
    const Image c = loadImage(rgba);
    EXPECT_TRUE(at(c, 0, 0) == (Color{255, 128, 0, 255}));
    EXPECT_TRUE(at(c, 1, 0) == (Color{0, 0, 255, 127}));

    const std::filesystem::path greyAlpha = dir() / "grey_alpha16.png";
    writeBytes(greyAlpha, png16(1, 1, 4, {0x8000, 0x4000}));
    EXPECT_TRUE(at(loadImage(greyAlpha), 0, 0) == (Color{128, 128, 128, 64}));
}

TEST(ImageFormats, A32BitBmpWhoseFourthByteIsZeroEverywhereIsOpaque) {
    const std::filesystem::path padded = dir() / "padding.bmp";
    writeBytes(padded, bmp32(2, 2, {0, 0, 0, 0}));
    const Image image = loadImage(padded);
    for (int i = 0; i < 4; ++i) {
        EXPECT_TRUE(at(image, i % 2, i / 2) == (Color{50, 100, 200, 255})) << i;
    }
    // Where some pixel has alpha, the fourth byte is alpha.
    const std::filesystem::path alpha = dir() / "alpha.bmp";
    writeBytes(alpha, bmp32(2, 1, {0, 128}));
    const Image translucent = loadImage(alpha);
    EXPECT_EQ(at(translucent, 0, 0).a, 0);
    EXPECT_EQ(at(translucent, 1, 0).a, 128);
}

TEST(ImageFormats, JpegsAreTurnedAsTheirExifOrientationSays) {
    // quadrant.jpg: 16 x 16 blue, its top-left 8 x 8 red as stored.
    struct Case {
        std::uint16_t orientation;
        int redX; // where the red quarter shows, pixels from the top-left
        int redY;
    };
    for (const Case& c : {Case{1, 2, 2}, Case{3, 13, 13}, Case{6, 13, 2}, Case{8, 2, 13}}) {
        SCOPED_TRACE(c.orientation);
        const std::filesystem::path file =
            dir() / ("exif" + std::to_string(c.orientation) + ".jpg");
        writeBytes(file, quadrantWithOrientation(c.orientation));
        const Image image = loadImage(file);
        ASSERT_EQ(image.width, 16);
        ASSERT_EQ(image.height, 16);
        for (int y : {2, 13}) {
            for (int x : {2, 13}) {
                const bool red = x == c.redX && y == c.redY;
                EXPECT_TRUE(near(at(image, x, y), red ? kRed : kBlue, 40))
                    << x << ", " << y << ": " << str(at(image, x, y));
            }
        }
    }
}

// llvmpipe's limit is 16384 (GL_MAX_TEXTURE_SIZE); GL would refuse a larger image silently and
// the sprite would draw black.
TEST(ImageFormats, AnImageLargerThanTheGpuTakesIsAnErrorAndDrawsThePlaceholder) {
    std::vector<std::string> logged;
    core::Logger logger(core::LogLevel::Info, [&](core::LogLevel level, std::string_view message) {
        if (level == core::LogLevel::Error) {
            logged.emplace_back(message);
        }
    });
    Scene scene(Path::Gl44, {16, 16}, true, &logger);
    Image wide;
    wide.width = 16400;
    wide.height = 4;
    wide.pixels.assign(static_cast<std::size_t>(wide.width) * 4 * 4, 255);
    const std::filesystem::path file = dir() / "wide.png";
    writePng(wide, file);

    const TextureId texture = scene.renderer.loadTexture(file);
    const TextureInfo& info = scene.renderer.textureInfo(texture);
    EXPECT_TRUE(info.placeholder);
    const std::string expected =
        "render::Renderer::loadTexture(): " + file.string() +
        ": the image is 16400 x 4 pixels, larger than this GPU's limit of 16384 x 16384 "
        "(GL_MAX_TEXTURE_SIZE)";
    EXPECT_EQ(info.error, expected);
    ASSERT_EQ(logged.size(), 1u);
    EXPECT_EQ(logged[0], expected + " (drawing the placeholder)");
    // The checker covers the sprite (magenta at its top-left), not black.
    scene.renderer.createSprite(SpriteDef{.texture = texture, .size = {16.0f, 16.0f}});
    Camera camera = pixelCamera({16, 16});
    EXPECT_TRUE(near(pixel(scene.frame(camera), 1, 14), Color{255, 0, 255, 255}, 0));

    try {
        static_cast<void>(scene.renderer.createTexture(wide));
        ADD_FAILURE() << "no error";
    } catch (const core::Error& e) {
        EXPECT_THAT(e.what(),
                    HasSubstr("render::Renderer::createTexture(): the image is 16400 x 4 pixels"));
    }
}

} // namespace
} // namespace e2d::render::test
