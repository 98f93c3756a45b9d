// SPDX-License-Identifier: MIT
#pragma once

#include "gl.hpp"

#include <e2d/core/log.hpp>
#include <e2d/render/image.hpp>
#include <e2d/render/texture.hpp>

#include "sprite_batcher.hpp"

#include <filesystem>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

namespace e2d::render::detail {

// The renderer's textures: GL texture objects by slot, their facts for the batcher, and the
// cache by path. Slot 0 is the 1 x 1 white texture, slot 1 the checker placeholder drawn for
// stale ids. A file that fails to load gets a slot of its own holding another checker, so its
// id stays valid and its error stays readable.
class TexturePool {
public:
    explicit TexturePool(core::Logger* logger);
    ~TexturePool();
    TexturePool(const TexturePool&) = delete;
    TexturePool& operator=(const TexturePool&) = delete;

    [[nodiscard]] const std::vector<TextureFacts>& facts() const noexcept { return facts_; }
    static constexpr std::uint32_t kWhiteSlot = 0;
    static constexpr std::uint32_t kPlaceholderSlot = 1;

    TextureId load(const std::filesystem::path& path, const TextureDef& def);
    TextureId create(const Image& image, const TextureDef& def, const char* function);
    // Returns true when the texture's translucency changed (the batcher must re-sort).
    bool update(TextureId id, glm::ivec2 offset, glm::ivec2 size,
                std::span<const std::uint8_t> rgba);
    bool destroy(TextureId id);
    [[nodiscard]] bool isValid(TextureId id) const noexcept;
    [[nodiscard]] const TextureInfo& info(TextureId id, const char* function) const;
    [[nodiscard]] TextureId idOf(std::uint32_t slot) const noexcept;
    /// Slots in use, the white and placeholder slots included.
    [[nodiscard]] std::uint32_t slotCount() const noexcept {
        return static_cast<std::uint32_t>(slots_.size());
    }
    [[nodiscard]] bool slotAlive(std::uint32_t slot) const noexcept {
        return slots_[slot].texture != 0;
    }
    [[nodiscard]] GLuint glTexture(std::uint32_t slot) const noexcept {
        return slots_[slot].texture;
    }

private:
    struct Slot {
        GLuint texture = 0;
        TextureInfo info;
    };
    std::uint32_t add(const Image& image, const TextureDef& def, TextureInfo info);
    // Why the GPU cannot hold `image` (wider or taller than GL_MAX_TEXTURE_SIZE), or empty.
    [[nodiscard]] std::string tooLarge(const Image& image) const;

    core::Logger* logger_;
    GLint maxSize_ = 0;
    std::vector<Slot> slots_;
    std::vector<TextureFacts> facts_;
    std::vector<std::uint32_t> free_;
    std::unordered_map<std::string, std::uint32_t> byPath_;
};

// The magenta/black checker drawn in place of an image that failed to load (64 x 64, 8 px
// squares).
Image makeCheckerImage();

} // namespace e2d::render::detail
