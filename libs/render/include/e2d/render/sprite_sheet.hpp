// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/render/types.hpp>

#include <glm/vec2.hpp>

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace e2d::render {

/// A rectangle in whole pixels of an image, origin at the image's top-left corner, y down (as
/// TexturePacker writes it).
struct PixelRect {
    int x = 0;
    int y = 0;
    int w = 0;
    int h = 0;
    friend bool operator==(const PixelRect&, const PixelRect&) = default;
};

/// One image of a sprite sheet, as TexturePacker describes it.
struct SpriteFrame {
    /// The frame's name (the key in the hash format, `filename` in the array format).
    std::string name;
    /// Where the frame's pixels lie in the sheet image, pixels, top-left origin. For a rotated
    /// frame this is the region as stored in the image: `w` and `h` are the frame's display
    /// size swapped (TexturePacker writes the display size in `frame.w`/`frame.h`).
    PixelRect region;
    /// The frame is stored rotated 90 degrees clockwise in the image. Default false.
    bool rotated = false;
    /// Transparent borders were cut off: `trimRect` is smaller than `sourceSize`. Default false.
    bool trimmed = false;
    /// Where the stored (trimmed) pixels lie in the untrimmed source image, pixels, top-left
    /// origin, display orientation (`spriteSourceSize`). Default: the whole source.
    PixelRect trimRect;
    /// Size of the untrimmed source image, pixels (`sourceSize`). Default: the frame's size.
    glm::ivec2 sourceSize{0, 0};
    /// Pivot as a fraction of the source size, origin top-left (`pivot`). Default (0.5, 0.5).
    glm::vec2 pivot{0.5f, 0.5f};
    /// The region as a UV rectangle (fractions of the image, top-left origin, as SpriteDef::uv).
    /// For a rotated frame this is the stored (rotated) region.
    Rect uv{};

    /// Display size of the stored pixels (the trimmed size), pixels: `region` un-swapped.
    [[nodiscard]] glm::ivec2 size() const noexcept {
        return rotated ? glm::ivec2{region.h, region.w} : glm::ivec2{region.w, region.h};
    }
    /// Offset of the centre of the stored pixels from the centre of the untrimmed source,
    /// pixels, x right, y up. Zero for an untrimmed frame. Draw the trimmed quad there to keep
    /// the frame where an untrimmed one would have been.
    [[nodiscard]] glm::vec2 trimOffset() const noexcept {
        return {static_cast<float>(trimRect.x) + 0.5f * static_cast<float>(trimRect.w) -
                    0.5f * static_cast<float>(sourceSize.x),
                0.5f * static_cast<float>(sourceSize.y) - static_cast<float>(trimRect.y) -
                    0.5f * static_cast<float>(trimRect.h)};
    }
};

/// A TexturePacker sprite sheet (JSON, "hash" or "array" format): the frames of one image.
///
/// Pure data: parsing needs no OpenGL context, so sheets can be read, checked and fuzzed
/// anywhere. The renderer loads `imagePath()` as a texture.
///
/// Keys read: `frames` (object of name -> frame, or array of frames with `filename`), per frame
/// `frame` {x, y, w, h} (required), `rotated`, `trimmed`, `spriteSourceSize` {x, y, w, h},
/// `sourceSize` {w, h}, `pivot` {x, y} (optional), and `meta.image`, `meta.size` {w, h}
/// (required). Other keys are ignored. Arrays and objects may nest at most
/// core::kMaxJsonDepth (256) levels deep, checked before parsing. Every error is a
/// core::ParseError (a core::Error) whose core::Diagnostic names the sheet and the key path
/// (Diagnostic::field), or the line and column for malformed JSON, e.g.
/// `render::SpriteSheet: hero.json: frames["run1.png"].frame.w: expected an integer, got
/// string "12"`, `render::SpriteSheet: hero.json:2:14: malformed JSON: ...`; bytes quoted from
/// the file that are not printable UTF-8 are escaped (core::printable()).
class SpriteSheet {
public:
    /// Reads and parses the JSON file at `path`; `meta.image` is resolved against the file's
    /// folder. Throws core::Error if the file cannot be read (a directory is named as one) or is
    /// not a valid sheet.
    [[nodiscard]] static SpriteSheet fromFile(const std::filesystem::path& path);
    /// Parses `json`; `name` is used in error messages, `imageFolder` to resolve `meta.image`.
    /// Throws core::Error if `json` is not a valid sheet.
    [[nodiscard]] static SpriteSheet fromString(std::string_view json, std::string_view name,
                                                const std::filesystem::path& imageFolder = {});

    /// The name given at parse time (the file path for fromFile()).
    [[nodiscard]] const std::string& name() const noexcept { return name_; }
    /// `meta.image` resolved against the sheet's folder.
    [[nodiscard]] const std::filesystem::path& imagePath() const noexcept { return imagePath_; }
    /// `meta.size`: the image size the frames refer to, pixels.
    [[nodiscard]] glm::ivec2 imageSize() const noexcept { return imageSize_; }

    /// Every frame, in file order.
    [[nodiscard]] std::span<const SpriteFrame> frames() const noexcept { return frames_; }
    /// The frame called `name` (exact match), or nullptr.
    [[nodiscard]] const SpriteFrame* find(std::string_view name) const;
    /// The frame called `name`. Throws core::Error naming the sheet and the frame if absent.
    [[nodiscard]] const SpriteFrame& frame(std::string_view name) const;

    /// Indices (into frames()) of the frames named `baseName` followed by a decimal number and
    /// optionally an extension starting with '.' ("run" gives "run1.png", "run2.png",
    /// "run10.png", not "running1.png"), in natural numeric order (run2 before run10; equal
    /// numbers by digit count, then name). Empty if there are none.
    [[nodiscard]] std::vector<int> animationFrames(std::string_view baseName) const;

    /// Checks every frame against the real size of the loaded image, pixels. Throws
    /// core::Error naming the sheet, the first frame outside it and both sizes.
    void checkImageSize(glm::ivec2 actualSize) const;

private:
    SpriteSheet() = default;

    std::string name_;
    std::filesystem::path imagePath_;
    glm::ivec2 imageSize_{0, 0};
    std::vector<SpriteFrame> frames_;
    std::unordered_map<std::string, int> byName_;
};

} // namespace e2d::render
