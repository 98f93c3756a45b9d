// SPDX-License-Identifier: MIT
#include "sheet.hpp"

#include <e2d/core/error.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <numeric>
#include <set>

namespace e2d::assetgen {

SheetLayout packFrames(const std::vector<SheetFrame>& frames, int maxWidth, int padding) {
    std::set<std::string> names;
    for (const SheetFrame& f : frames) {
        if (!names.insert(f.name).second) {
            throw core::Error("assetgen::packFrames(): two frames are called '" + f.name + "'");
        }
        if (f.image.width() + 2 * padding > maxWidth) {
            throw core::Error("assetgen::packFrames(): frame '" + f.name + "' is " +
                              std::to_string(f.image.width()) + " pixels wide, the sheet at most " +
                              std::to_string(maxWidth - 2 * padding));
        }
    }
    std::vector<std::size_t> order(frames.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return frames[a].image.height() > frames[b].image.height();
    });

    SheetLayout layout;
    layout.frames.resize(frames.size());
    int x = 0;
    int y = 0;
    int shelf = 0;
    for (std::size_t i : order) {
        const int w = frames[i].image.width() + 2 * padding;
        const int h = frames[i].image.height() + 2 * padding;
        if (x + w > maxWidth) {
            x = 0;
            y += shelf;
            shelf = 0;
        }
        layout.frames[i] = {x + padding, y + padding, frames[i].image.width(),
                            frames[i].image.height()};
        x += w;
        shelf = std::max(shelf, h);
        layout.width = std::max(layout.width, x);
    }
    layout.height = y + shelf;
    return layout;
}

void writeSheet(const std::vector<SheetFrame>& frames, const std::filesystem::path& folder,
                const std::string& baseName, int maxWidth, int padding) {
    if (frames.empty()) {
        throw core::Error("assetgen::writeSheet(): sheet '" + baseName + "' has no frames");
    }
    const SheetLayout layout = packFrames(frames, maxWidth, padding);
    Canvas sheet(layout.width, layout.height);
    // ordered_json keeps the frames in the order given (SpriteSheet lists them in file order).
    nlohmann::ordered_json json;
    json["frames"] = nlohmann::ordered_json::object();
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const PackedFrame& p = layout.frames[i];
        sheet.copyFrom(frames[i].image, p.x, p.y);
        json["frames"][frames[i].name] = {
            {"frame", {{"x", p.x}, {"y", p.y}, {"w", p.w}, {"h", p.h}}},
            {"rotated", false},
            {"trimmed", false},
            {"spriteSourceSize", {{"x", 0}, {"y", 0}, {"w", p.w}, {"h", p.h}}},
            {"sourceSize", {{"w", p.w}, {"h", p.h}}},
            {"pivot", {{"x", 0.5}, {"y", 0.5}}},
        };
    }
    const std::string imageName = baseName + ".png";
    json["meta"] = {
        {"app", "e2d_assetgen"},
        {"version", "1.0"},
        {"image", imageName},
        {"format", "RGBA8888"},
        {"size", {{"w", layout.width}, {"h", layout.height}}},
        {"scale", "1"},
    };
    sheet.writePng(folder / imageName);
    const std::filesystem::path jsonPath = folder / (baseName + ".json");
    std::ofstream out(jsonPath);
    out << json.dump(2) << '\n';
    if (!out) {
        throw core::Error("assetgen::writeSheet(): cannot write '" + jsonPath.string() + "'");
    }
}

} // namespace e2d::assetgen
