// SPDX-License-Identifier: MIT
#include "gl.hpp"

#include <e2d/core/error_text.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/window.hpp>

#include "debug_draw.hpp"
#include "instance_buffer.hpp"
#include "shaders.hpp"
#include "sprite_batcher.hpp"
#include "texture_pool.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace e2d::render {

namespace detail {

// Everything behind Renderer: GL objects, the texture pool and the sprite batcher.
struct RendererImpl {
    RendererImpl(Window& w, const RendererDef& d)
        : window(w), def(d), textures(d.logger),
          batcher(textures.facts(), TexturePool::kWhiteSlot, TexturePool::kPlaceholderSlot) {}

    ~RendererImpl() {
        buffer.reset();
        if (program != 0) {
            glDeleteProgram(program);
        }
        if (vao != 0) {
            glDeleteVertexArrays(1, &vao);
        }
        if (fbo != 0) {
            glDeleteFramebuffers(1, &fbo);
            glDeleteRenderbuffers(1, &colorRb);
            glDeleteRenderbuffers(1, &depthRb);
        }
    }

    void createOffscreen() {
        glm::ivec2 size = def.offscreenSize;
        glGenFramebuffers(1, &fbo);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glGenRenderbuffers(1, &colorRb);
        glBindRenderbuffer(GL_RENDERBUFFER, colorRb);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, size.x, size.y);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colorRb);
        glGenRenderbuffers(1, &depthRb);
        glBindRenderbuffer(GL_RENDERBUFFER, depthRb);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size.x, size.y);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depthRb);
        GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            core::throwError("render::Renderer",
                             "the offscreen framebuffer of " + core::formatVector(size) +
                                 " is incomplete (status 0x" + std::to_string(status) + ")");
        }
    }

    [[nodiscard]] glm::ivec2 targetSize() const {
        return fbo != 0 ? def.offscreenSize : glm::max(window.framebufferSize(), glm::ivec2(1));
    }

    void draw(const std::vector<Batch>& list, std::size_t base) {
        for (const Batch& b : list) {
            if (b.count == 0) {
                continue;
            }
            if (b.translucent != inTranslucentPass) {
                beginPass(b.translucent);
            }
            glBindTexture(GL_TEXTURE_2D, textures.glTexture(b.texture));
            if (useBaseInstance) {
                glDrawArraysInstancedBaseInstance(GL_TRIANGLE_STRIP, 0, 4,
                                                  static_cast<GLsizei>(b.count),
                                                  static_cast<GLuint>(base + b.first));
            } else {
                buffer->pointAttributes(base + b.first);
                glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(b.count));
            }
            ++stats.drawCalls;
        }
    }

    void beginPass(bool translucent) {
        inTranslucentPass = translucent;
        if (translucent) {
            glEnable(GL_BLEND);
            glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE,
                                GL_ONE_MINUS_SRC_ALPHA);
            glDepthMask(GL_FALSE);
            // At equal z a translucent quad draws over the opaque ones.
            glDepthFunc(GL_LEQUAL);
            glUniform1f(alphaCutLocation, 1.0f / 512.0f);
        } else {
            glDisable(GL_BLEND);
            glDepthMask(GL_TRUE);
            // Strict: the batcher draws the opaque quad that must end on top of an equal-z
            // pile first, and llvmpipe (like GPUs) rejects the ones under it before shading.
            glDepthFunc(GL_LESS);
            glUniform1f(alphaCutLocation, 0.5f);
        }
    }

    Window& window;
    RendererDef def;
    TexturePool textures;
    SpriteBatcher batcher;
    GLuint program = 0;
    GLuint vao = 0;
    GLint worldToClipLocation = -1;
    GLint depthScaleLocation = -1;
    GLint alphaCutLocation = -1;
    GLuint fbo = 0;
    GLuint colorRb = 0;
    GLuint depthRb = 0;
    std::unique_ptr<InstanceBuffer> buffer;
    bool useBaseInstance = false;
    bool inTranslucentPass = false;
    std::vector<Batch> batches;
    std::size_t lastBase = 0;
    FrameStats stats;
    // Debug shapes of the frame; their pipeline is made on first use.
    Drawer drawer;
    std::unique_ptr<DebugDraw> debugDraw;
};

} // namespace detail

namespace {

constexpr const char* kCtor = "render::Renderer";

void validate(const RendererDef& def) {
    if (def.offscreenSize != glm::ivec2(0) &&
        (def.offscreenSize.x < 1 || def.offscreenSize.y < 1)) {
        core::throwError(kCtor, "offscreenSize must be (0, 0) or >= 1 in each axis, got " +
                                    core::formatVector(def.offscreenSize));
    }
    if (def.ringFrames < 2 || def.ringFrames > 8) {
        core::throwError(kCtor,
                         "ringFrames must be in [2, 8], got " + std::to_string(def.ringFrames));
    }
    if (!(def.depthRange > 0.0f) || !std::isfinite(def.depthRange)) {
        core::throwError(kCtor, "depthRange must be > 0 and finite, got " +
                                    core::formatNumber(def.depthRange));
    }
}

void setClearColor(Color c) {
    glClearColor(static_cast<float>(c.r) / 255.0f, static_cast<float>(c.g) / 255.0f,
                 static_cast<float>(c.b) / 255.0f, static_cast<float>(c.a) / 255.0f);
}

} // namespace

Renderer::Renderer(Window& window, const RendererDef& def) {
    validate(def);
    window.makeCurrent();
    impl_ = std::make_unique<detail::RendererImpl>(window, def);
    detail::RendererImpl& r = *impl_;
    r.program = detail::createSpriteProgram();
    r.worldToClipLocation = glGetUniformLocation(r.program, "uWorldToClip");
    r.depthScaleLocation = glGetUniformLocation(r.program, "uDepthScale");
    r.alphaCutLocation = glGetUniformLocation(r.program, "uAlphaCut");
    glUseProgram(r.program);
    glUniform1i(glGetUniformLocation(r.program, "uTexture"), 0);
    glGenVertexArrays(1, &r.vao);
    bool persistent = window.context().bufferStorage && !def.forceGl33;
    r.useBaseInstance = persistent && window.context().baseInstance;
    r.buffer = std::make_unique<detail::InstanceBuffer>(persistent, def.ringFrames, r.vao);
    if (def.offscreenSize != glm::ivec2(0)) {
        r.createOffscreen();
    }
}

Renderer::~Renderer() {
    if (impl_) {
        impl_->window.makeCurrent();
    }
}

TextureId Renderer::loadTexture(const std::filesystem::path& path, const TextureDef& def) {
    if (impl_->def.fileTextureFilter) {
        TextureDef forced = def;
        forced.filter = *impl_->def.fileTextureFilter;
        return impl_->textures.load(path, forced);
    }
    return impl_->textures.load(path, def);
}

TextureId Renderer::createTexture(const Image& image, const TextureDef& def) {
    return impl_->textures.create(image, def, "render::Renderer::createTexture()");
}

void Renderer::updateTexture(TextureId id, glm::ivec2 offset, glm::ivec2 size,
                             std::span<const std::uint8_t> rgba) {
    if (impl_->textures.update(id, offset, size, rgba)) {
        impl_->batcher.texturesChanged();
    }
}

bool Renderer::destroyTexture(TextureId id) {
    if (!impl_->textures.destroy(id)) {
        return false;
    }
    impl_->batcher.texturesChanged();
    return true;
}

bool Renderer::isValid(TextureId id) const noexcept { return impl_->textures.isValid(id); }

const TextureInfo& Renderer::textureInfo(TextureId id) const {
    return impl_->textures.info(id, "render::Renderer::textureInfo()");
}

TextureId Renderer::whiteTexture() const noexcept {
    return impl_->textures.idOf(detail::TexturePool::kWhiteSlot);
}

SpriteId Renderer::createSprite(const SpriteDef& def) { return impl_->batcher.create(def); }
bool Renderer::destroySprite(SpriteId id) { return impl_->batcher.destroy(id); }
int Renderer::textureCount() const noexcept {
    int count = 0;
    for (std::uint32_t slot = 2; slot < impl_->textures.slotCount(); ++slot) {
        count += impl_->textures.slotAlive(slot) ? 1 : 0;
    }
    return count;
}

int Renderer::destroyUnusedTextures(std::span<const TextureId> keep) {
    std::vector<bool> used(impl_->textures.slotCount(), false);
    const auto mark = [&](TextureId id) {
        if (impl_->textures.isValid(id)) {
            used[id.index()] = true;
        }
    };
    impl_->batcher.forEachTexture(mark);
    for (const TextureId id : keep) {
        mark(id);
    }
    int destroyed = 0;
    for (std::uint32_t slot = 2; slot < impl_->textures.slotCount(); ++slot) {
        if (impl_->textures.slotAlive(slot) && !used[slot]) {
            destroyed += impl_->textures.destroy(impl_->textures.idOf(slot)) ? 1 : 0;
        }
    }
    if (destroyed > 0) {
        impl_->batcher.texturesChanged();
    }
    return destroyed;
}

void Renderer::destroyAllSprites() { impl_->batcher.destroyAll(); }
bool Renderer::isValid(SpriteId id) const noexcept { return impl_->batcher.isValid(id); }
int Renderer::spriteCount() const noexcept { return impl_->batcher.count(); }
const SpriteDef& Renderer::sprite(SpriteId id) const {
    return impl_->batcher.def(id, "render::Renderer::sprite()");
}
void Renderer::setSprite(SpriteId id, const SpriteDef& def) {
    impl_->batcher.set(id, def, "render::Renderer::setSprite()");
}
void Renderer::setPosition(SpriteId id, glm::vec2 position) {
    impl_->batcher.setPosition(id, position);
}
void Renderer::setZ(SpriteId id, float z) { impl_->batcher.setZ(id, z); }
void Renderer::setSize(SpriteId id, glm::vec2 size) { impl_->batcher.setSize(id, size); }
void Renderer::setScale(SpriteId id, glm::vec2 scale) { impl_->batcher.setScale(id, scale); }
void Renderer::setRotation(SpriteId id, float radians) { impl_->batcher.setRotation(id, radians); }
void Renderer::setPivot(SpriteId id, glm::vec2 pivot) { impl_->batcher.setPivot(id, pivot); }
void Renderer::setTint(SpriteId id, Color tint) { impl_->batcher.setTint(id, tint); }
void Renderer::setUv(SpriteId id, const Rect& uv, bool uvRotated) {
    impl_->batcher.setUv(id, uv, uvRotated);
}
void Renderer::setFlip(SpriteId id, bool flipX, bool flipY) {
    impl_->batcher.setFlip(id, flipX, flipY);
}
void Renderer::setParallax(SpriteId id, float parallax) {
    impl_->batcher.setParallax(id, parallax);
}
void Renderer::setHud(SpriteId id, bool hud) { impl_->batcher.setHud(id, hud); }
void Renderer::setVisible(SpriteId id, bool visible) { impl_->batcher.setVisible(id, visible); }
void Renderer::setTexture(SpriteId id, TextureId texture) {
    impl_->batcher.setTexture(id, texture);
}
void Renderer::setTransform(SpriteId id, glm::vec2 position, float z, float rotation,
                            glm::vec2 scale) {
    impl_->batcher.setTransform(id, position, z, rotation, scale);
}

void Renderer::submit(const Quad& quad) { impl_->batcher.submit(quad); }

void Renderer::render(Camera& camera) {
    detail::RendererImpl& r = *impl_;
    r.window.makeCurrent();
    glm::ivec2 size = r.targetSize();
    camera.setScreenSize(size);

    Rect region = camera.screenRegion();
    Rect world = camera.visibleWorldBounds();
    detail::CameraState state{camera.position(), camera.rotation(), camera.zoom()};
    detail::ViewBounds view{world.min, world.max()};

    r.stats = FrameStats{};
    r.stats.persistentMapping = r.buffer->persistent();
    bool changed = true;
    std::size_t most = r.batcher.prepare(state, view, changed);
    detail::BuildCounts counts;
    if (changed) {
        detail::Instance* dst = r.buffer->begin(most);
        r.batcher.emit(dst, r.batches, counts);
        r.buffer->end();
        r.lastBase = r.buffer->baseInstance();
        r.stats.sprites = counts.drawn;
        r.stats.culled = counts.culled;
        r.stats.rebuilt = counts.rebuilt;
    } else {
        // Nothing changed: draw last frame's instances again, straight from their region.
        for (const detail::Batch& b : r.batches) {
            r.stats.sprites += static_cast<int>(b.count);
        }
    }

    glBindFramebuffer(GL_FRAMEBUFFER, r.fbo);
    glViewport(0, 0, size.x, size.y);
    glDisable(GL_SCISSOR_TEST);
    setClearColor(r.def.letterboxColor);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // Letterbox: the camera's region is cleared to the scene colour and drawing is clipped to
    // it; the bars keep the letterbox colour.
    auto x0 = static_cast<GLint>(std::lround(region.min.x));
    auto y0 = static_cast<GLint>(std::lround(region.min.y));
    auto x1 = static_cast<GLint>(std::lround(region.max().x));
    auto y1 = static_cast<GLint>(std::lround(region.max().y));
    glEnable(GL_SCISSOR_TEST);
    glScissor(x0, y0, x1 - x0, y1 - y0);
    setClearColor(r.def.clearColor);
    glClear(GL_COLOR_BUFFER_BIT);

    glUseProgram(r.program);
    glBindVertexArray(r.vao);
    glUniformMatrix4fv(r.worldToClipLocation, 1, GL_FALSE, glm::value_ptr(camera.worldToClip()));
    glUniform1f(r.depthScaleLocation, 1.0f / r.def.depthRange);
    glActiveTexture(GL_TEXTURE0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_DEPTH_CLAMP);
    glDisable(GL_CULL_FACE);
    r.beginPass(false);
    if (!r.useBaseInstance) {
        // The 3.3 path re-points the attributes per batch; start from the buffer's start.
        r.buffer->pointAttributes(r.lastBase);
    }
    r.draw(r.batches, r.lastBase);
    r.buffer->fence();
    for (const detail::Batch& b : r.batches) {
        if (b.count == 0) {
            continue;
        }
        ++r.stats.batches;
        ++(b.translucent ? r.stats.translucentBatches : r.stats.opaqueBatches);
    }
    if (!r.drawer.empty()) {
        if (!r.debugDraw) {
            r.debugDraw = std::make_unique<detail::DebugDraw>();
        }
        r.stats.debugDrawCalls = r.debugDraw->draw(r.drawer, camera.worldToClip(), size);
        r.drawer.clear();
    }
    glDisable(GL_SCISSOR_TEST);
    glDepthMask(GL_TRUE);
    glBindVertexArray(0);
}

Drawer& Renderer::drawer() noexcept { return impl_->drawer; }

const FrameStats& Renderer::stats() const noexcept { return impl_->stats; }
glm::ivec2 Renderer::targetSize() const noexcept { return impl_->targetSize(); }
bool Renderer::persistentMapping() const noexcept { return impl_->buffer->persistent(); }

Image Renderer::readPixels() const {
    detail::RendererImpl& r = *impl_;
    r.window.makeCurrent();
    glm::ivec2 size = r.targetSize();
    glBindFramebuffer(GL_READ_FRAMEBUFFER, r.fbo);
    glReadBuffer(r.fbo != 0 ? GL_COLOR_ATTACHMENT0 : GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    std::vector<std::uint8_t> bottomUp(static_cast<std::size_t>(size.x) *
                                       static_cast<std::size_t>(size.y) * 4);
    glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    // glReadPixels rows are bottom-up; Image rows run from the top.
    Image image;
    image.width = size.x;
    image.height = size.y;
    image.pixels.resize(bottomUp.size());
    std::size_t row = static_cast<std::size_t>(size.x) * 4;
    for (int y = 0; y < size.y; ++y) {
        std::copy_n(bottomUp.data() + static_cast<std::size_t>(size.y - 1 - y) * row, row,
                    image.pixels.data() + static_cast<std::size_t>(y) * row);
    }
    return image;
}

void Renderer::screenshot(const std::filesystem::path& path) const { writePng(readPixels(), path); }

} // namespace e2d::render
