// SPDX-License-Identifier: MIT
#pragma once

#include "canvas.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace e2d::assetgen {

/// One named image to pack into a sheet.
struct SheetFrame {
    /// The key in the sheet's `frames` object, e.g. "run3.png".
    std::string name;
    Canvas image;
};

/// Where each frame landed in a packed sheet, pixels, top-left origin.
struct PackedFrame {
    int x = 0;
    int y = 0;
    int w = 0;
    int h = 0;
};

/// Packs frames into rows ("shelves") of at most `maxWidth` pixels, tallest first, with
/// `padding` transparent pixels around each frame (so linear filtering never bleeds a
/// neighbour in). Returns one rectangle per frame, in the order given, and the sheet's size.
/// Throws core::Error if a frame is wider than `maxWidth` or two frames share a name.
struct SheetLayout {
    std::vector<PackedFrame> frames;
    int width = 0;
    int height = 0;
};
[[nodiscard]] SheetLayout packFrames(const std::vector<SheetFrame>& frames, int maxWidth = 1024,
                                     int padding = 1);

/// Packs `frames` and writes `<folder>/<baseName>.png` and `<folder>/<baseName>.json`, a
/// TexturePacker "hash" sheet (frames in the order given, untrimmed, unrotated, pivot at the
/// centre) that render::SpriteSheet reads.
void writeSheet(const std::vector<SheetFrame>& frames, const std::filesystem::path& folder,
                const std::string& baseName, int maxWidth = 1024, int padding = 1);

} // namespace e2d::assetgen
