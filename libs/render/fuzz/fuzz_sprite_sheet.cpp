// SPDX-License-Identifier: MIT
// Arbitrary bytes into the TexturePacker JSON reader: the result is either a sheet whose every
// frame lies inside its image with texture coordinates in [0, 1], or core::Error whose message
// is printable text (bytes quoted from the input escaped), never anything else (no crash, no
// stack overflow, no other exception). Seeds in corpus/fuzz_sprite_sheet/ nest near and past the
// depth limit and are cut mid-file; fuzz_sprite_sheet.dict holds the format's tokens.
#include <e2d/core/error.hpp>
#include <e2d/core/printable.hpp>
#include <e2d/core/utf8.hpp>
#include <e2d/render/sprite_sheet.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

namespace {

void check(bool condition) {
    if (!condition) {
        std::abort();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const auto sheet = e2d::render::SpriteSheet::fromString(text, "fuzz.json");
        const glm::ivec2 image = sheet.imageSize();
        check(image.x >= 1 && image.y >= 1);
        for (const auto& frame : sheet.frames()) {
            const auto& r = frame.region;
            check(r.x >= 0 && r.y >= 0 && r.w >= 1 && r.h >= 1);
            check(r.x + r.w <= image.x && r.y + r.h <= image.y);
            check(frame.uv.min.x >= 0.0f && frame.uv.max().x <= 1.0f && frame.uv.size.x > 0.0f);
            check(frame.uv.min.y >= 0.0f && frame.uv.max().y <= 1.0f && frame.uv.size.y > 0.0f);
            check(sheet.find(frame.name) != nullptr);
            // Every prefix of a name is a plausible animation base name.
            const std::string_view name = frame.name;
            for (std::size_t cut = 0; cut < name.size() && cut < 8; ++cut) {
                for (int index : sheet.animationFrames(name.substr(0, cut))) {
                    check(index >= 0 && static_cast<std::size_t>(index) < sheet.frames().size());
                }
            }
        }
        sheet.checkImageSize(image);
    } catch (const e2d::core::Error& e) {
        check(e2d::core::isPrintable(e.what()));
    }
    return 0;
}
