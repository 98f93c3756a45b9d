// SPDX-License-Identifier: MIT
#include "texture_pool.hpp"

#include <e2d/core/error.hpp>
#include <e2d/core/error_text.hpp>

#include <algorithm>

namespace e2d::render::detail {

namespace {

bool hasPartialAlpha(const std::uint8_t* rgba, std::size_t pixels) {
    for (std::size_t i = 0; i < pixels; ++i) {
        std::uint8_t a = rgba[i * 4 + 3];
        if (a != 0 && a != 255) {
            return true;
        }
    }
    return false;
}

void applyFilter(const TextureDef& def) {
    GLint mag = def.filter == TextureFilter::Nearest ? GL_NEAREST : GL_LINEAR;
    GLint min = mag;
    if (def.mipmaps) {
        min = def.filter == TextureFilter::Nearest ? GL_NEAREST_MIPMAP_NEAREST
                                                   : GL_LINEAR_MIPMAP_LINEAR;
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

} // namespace

Image makeCheckerImage() {
    Image image;
    image.width = 64;
    image.height = 64;
    image.pixels.resize(64 * 64 * 4);
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            bool magenta = ((x / 8) + (y / 8)) % 2 == 0;
            std::uint8_t* p = image.pixels.data() +
                              (static_cast<std::size_t>(y) * 64 + static_cast<std::size_t>(x)) * 4;
            p[0] = magenta ? 255 : 0;
            p[1] = 0;
            p[2] = magenta ? 255 : 0;
            p[3] = 255;
        }
    }
    return image;
}

TexturePool::TexturePool(core::Logger* logger) : logger_(logger) {
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize_);
    Image white;
    white.width = 1;
    white.height = 1;
    white.pixels = {255, 255, 255, 255};
    add(white, TextureDef{TextureFilter::Nearest, false}, TextureInfo{});
    TextureInfo placeholder;
    placeholder.placeholder = true;
    placeholder.error = "stale texture id";
    add(makeCheckerImage(), TextureDef{TextureFilter::Nearest, false}, placeholder);
}

TexturePool::~TexturePool() {
    for (Slot& s : slots_) {
        if (s.texture != 0) {
            glDeleteTextures(1, &s.texture);
        }
    }
}

std::uint32_t TexturePool::add(const Image& image, const TextureDef& def, TextureInfo info) {
    std::uint32_t index;
    if (!free_.empty()) {
        index = free_.back();
        free_.pop_back();
    } else {
        index = static_cast<std::uint32_t>(slots_.size());
        slots_.emplace_back();
        facts_.emplace_back();
    }
    Slot& s = slots_[index];
    glGenTextures(1, &s.texture);
    glBindTexture(GL_TEXTURE_2D, s.texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    // Image rows run from the top; uploaded in that order, texture coordinate t equals the
    // image's top-left-origin v, so UV rectangles need no flip anywhere.
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, image.pixels.data());
    applyFilter(def);
    if (def.mipmaps) {
        glGenerateMipmap(GL_TEXTURE_2D);
    }
    info.size = {image.width, image.height};
    info.def = def;
    info.translucent = hasPartialAlpha(image.pixels.data(), image.pixels.size() / 4);
    s.info = std::move(info);
    TextureFacts& f = facts_[index];
    f.size = glm::vec2(image.width, image.height);
    f.translucent = s.info.translucent;
    f.generation = core::nextGeneration(f.generation);
    return index;
}

TextureId TexturePool::idOf(std::uint32_t slot) const noexcept {
    return TextureId::forSlot(slot, facts_[slot].generation);
}

TextureId TexturePool::load(const std::filesystem::path& path, const TextureDef& def) {
    std::string key = path.lexically_normal().string();
    auto found = byPath_.find(key);
    if (found != byPath_.end()) {
        return idOf(found->second);
    }
    TextureInfo info;
    info.path = path.string();
    std::uint32_t slot;
    try {
        Image image = loadImage(path);
        // GL would refuse it without a word to the caller, and the sprite would draw black.
        if (const std::string why = tooLarge(image); !why.empty()) {
            throw core::Error("render::Renderer::loadTexture(): " + info.path + ": " + why);
        }
        slot = add(image, def, std::move(info));
    } catch (const core::Error& error) {
        info.placeholder = true;
        info.error = error.what();
        if (logger_ != nullptr) {
            logger_->error(std::string(error.what()) + " (drawing the placeholder)");
        }
        slot = add(makeCheckerImage(), TextureDef{TextureFilter::Nearest, false}, std::move(info));
    }
    byPath_.emplace(std::move(key), slot);
    return idOf(slot);
}

TextureId TexturePool::create(const Image& image, const TextureDef& def, const char* function) {
    if (image.width < 1 || image.height < 1 ||
        image.pixels.size() !=
            static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4) {
        core::throwError(function,
                         "image must be at least 1 x 1 with width * height * 4 bytes, got " +
                             std::to_string(image.width) + " x " + std::to_string(image.height) +
                             " with " + std::to_string(image.pixels.size()) + " bytes");
    }
    if (const std::string why = tooLarge(image); !why.empty()) {
        core::throwError(function, why);
    }
    return idOf(add(image, def, TextureInfo{}));
}

std::string TexturePool::tooLarge(const Image& image) const {
    if (image.width <= maxSize_ && image.height <= maxSize_) {
        return {};
    }
    return "the image is " + std::to_string(image.width) + " x " + std::to_string(image.height) +
           " pixels, larger than this GPU's limit of " + std::to_string(maxSize_) + " x " +
           std::to_string(maxSize_) + " (GL_MAX_TEXTURE_SIZE)";
}

bool TexturePool::isValid(TextureId id) const noexcept {
    return core::findSlot(id, facts_.size(),
                          [this](std::uint32_t i) {
                              return slots_[i].texture != 0 ? facts_[i].generation
                                                            : std::uint16_t{0};
                          })
        .has_value();
}

const TextureInfo& TexturePool::info(TextureId id, const char* function) const {
    if (!isValid(id)) {
        core::throwError(function, id.isNull() ? "null texture id"
                                               : "stale texture id (index " +
                                                     std::to_string(id.index()) + ")");
    }
    return slots_[id.index()].info;
}

bool TexturePool::update(TextureId id, glm::ivec2 offset, glm::ivec2 size,
                         std::span<const std::uint8_t> rgba) {
    constexpr const char* fn = "render::Renderer::updateTexture()";
    const TextureInfo& current = info(id, fn);
    if (id.index() < 2) {
        core::throwError(fn, "the built-in textures cannot be changed");
    }
    if (size.x < 0 || size.y < 0 || offset.x < 0 || offset.y < 0 ||
        offset.x + size.x > current.size.x || offset.y + size.y > current.size.y) {
        core::throwError(fn, "rectangle at " + core::formatVector(offset) + " of size " +
                                 core::formatVector(size) + " is outside the " +
                                 std::to_string(current.size.x) + " x " +
                                 std::to_string(current.size.y) + " texture");
    }
    std::size_t needed = static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y) * 4;
    if (rgba.size() < needed) {
        core::throwError(fn, "expected " + std::to_string(needed) + " bytes of pixels, got " +
                                 std::to_string(rgba.size()));
    }
    if (size.x == 0 || size.y == 0) {
        return false;
    }
    Slot& s = slots_[id.index()];
    glBindTexture(GL_TEXTURE_2D, s.texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glTexSubImage2D(GL_TEXTURE_2D, 0, offset.x, offset.y, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE,
                    rgba.data());
    if (s.info.def.mipmaps) {
        glGenerateMipmap(GL_TEXTURE_2D);
    }
    if (!s.info.translucent && hasPartialAlpha(rgba.data(), needed / 4)) {
        s.info.translucent = true;
        facts_[id.index()].translucent = true;
        return true;
    }
    return false;
}

bool TexturePool::destroy(TextureId id) {
    if (!isValid(id) || id.index() < 2) {
        return false;
    }
    std::uint32_t index = id.index();
    Slot& s = slots_[index];
    glDeleteTextures(1, &s.texture);
    s.texture = 0;
    if (!s.info.path.empty()) {
        byPath_.erase(std::filesystem::path(s.info.path).lexically_normal().string());
    }
    s.info = TextureInfo{};
    facts_[index].generation = core::nextGeneration(facts_[index].generation);
    free_.push_back(index);
    return true;
}

} // namespace e2d::render::detail
