// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace e2d::render {

/// RGBA8 pixels in memory, rows from the TOP of the image down (the order of image files,
/// image editors, TexturePacker and FreeType). This is the library's single image convention:
/// pixel rectangles and UV rectangles everywhere have their origin at the image's top-left.
/// The one place that meets OpenGL's bottom-left row order is the texture upload.
struct Image {
    int width = 0;
    int height = 0;
    /// width * height * 4 bytes, R, G, B, A per pixel, top row first.
    std::vector<std::uint8_t> pixels;

    /// Pointer to pixel (x, y), y counted from the top.
    [[nodiscard]] const std::uint8_t* at(int x, int y) const {
        return pixels.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                static_cast<std::size_t>(x)) *
                                   4;
    }
};

/// Reads PNG, JPEG, BMP, TGA, GIF (anything FreeImage reads) and converts it to RGBA8.
/// 16-bit channels keep their high byte; a JPEG is turned upright as its EXIF orientation
/// says; a 32-bit BMP whose alpha is 0 everywhere (BI_RGB padding) is opaque, as viewers
/// show it. The format is taken from the file's content; when the extension names another format the
/// file FreeImage knows (a JPEG named .png) it is refused. Throws core::Error naming the file
/// and the reason (FreeImage's own message when it gives one): missing file, unknown or
/// mismatched format, corrupt or truncated data, a 0 x 0 image.
[[nodiscard]] Image loadImage(const std::filesystem::path& path);

/// Writes `image` as a PNG. Throws core::Error naming the file when it cannot, or when the
/// image is empty or its pixel count does not match its size.
void writePng(const Image& image, const std::filesystem::path& path);

} // namespace e2d::render
