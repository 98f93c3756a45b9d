// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/render/renderer.hpp>

#include "instance.hpp"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace e2d::render::detail {

// What the batcher needs to know about a texture slot (kept by the texture pool).
struct TextureFacts {
    glm::vec2 size{1.0f, 1.0f};
    bool translucent = false;
    std::uint16_t generation = 0; // 0: the slot is free
};

// The camera state that HUD and parallax sprites depend on.
struct CameraState {
    glm::vec2 position{0.0f, 0.0f};
    float rotation = 0.0f;
    float zoom = 1.0f;
    friend bool operator==(const CameraState&, const CameraState&) = default;
};

// World-space rectangle that is drawn; quads entirely outside are culled.
struct ViewBounds {
    glm::vec2 min{0.0f, 0.0f};
    glm::vec2 max{0.0f, 0.0f};
    friend bool operator==(const ViewBounds&, const ViewBounds&) = default;
};

struct BuildCounts {
    int drawn = 0;
    int culled = 0;
    int rebuilt = 0;
};

// Owns the sprites and turns them into sorted, culled, batched instance data. No OpenGL here,
// so the benchmark can time the CPU side alone.
//
// Each sprite keeps its packed Instance and bounds between frames, in draw order; a setter marks
// it dirty and only dirty sprites are repacked, except a plain move (setPosition() of a drawn
// sprite that does not depend on the camera), which writes the new origin in place. The draw order (opaque by texture then front to
// back, translucent back to front) is re-sorted only when something that decides it changed
// (z, texture, opacity, visibility, HUD/parallax, creation, destruction). A frame copies the
// packed instances of the sorted, unculled sprites into the destination, merging in the
// frame's transient quads by the same keys.
class SpriteBatcher {
public:
    SpriteBatcher(const std::vector<TextureFacts>& textures, std::uint32_t whiteSlot,
                  std::uint32_t placeholderSlot);

    SpriteId create(const SpriteDef& def);
    bool destroy(SpriteId id);
    void destroyAll();
    [[nodiscard]] bool isValid(SpriteId id) const noexcept;
    [[nodiscard]] int count() const noexcept { return alive_; }
    /// Calls `f(texture)` with the texture of every live sprite.
    template <class F>
    void forEachTexture(F&& f) const {
        for (const Slot& s : slots_) {
            if (s.alive) {
                f(s.def.texture);
            }
        }
    }
    // Not const: the position lives in a packed array and is copied into the definition here.
    [[nodiscard]] const SpriteDef& def(SpriteId id, const char* function);
    void set(SpriteId id, const SpriteDef& def, const char* function);

    void setPosition(SpriteId id, glm::vec2 position);
    void setZ(SpriteId id, float z);
    void setSize(SpriteId id, glm::vec2 size);
    void setScale(SpriteId id, glm::vec2 scale);
    void setRotation(SpriteId id, float radians);
    void setPivot(SpriteId id, glm::vec2 pivot);
    void setTint(SpriteId id, Color tint);
    void setUv(SpriteId id, const Rect& uv, bool uvRotated);
    void setFlip(SpriteId id, bool flipX, bool flipY);
    void setParallax(SpriteId id, float parallax);
    void setHud(SpriteId id, bool hud);
    void setVisible(SpriteId id, bool visible);
    void setTexture(SpriteId id, TextureId texture);
    void setTransform(SpriteId id, glm::vec2 position, float z, float rotation, glm::vec2 scale);

    void submit(const Quad& quad);
    // Texture facts changed (a texture was destroyed or replaced): repack and re-sort all.
    void texturesChanged();

    // Brings every sprite up to date for this camera and view. Returns the most instances
    // emit() may write; `changed` is false when emit() would write exactly what it wrote last
    // time (nothing moved, no transient quads, same camera and view).
    std::size_t prepare(const CameraState& camera, const ViewBounds& view, bool& changed);
    // Writes the frame's instances and batches; clears the transient quads.
    std::size_t emit(Instance* dst, std::vector<Batch>& batches, BuildCounts& counts);
    // Drops the transient quads without drawing them.
    void clearTransient() noexcept;

private:
    enum : std::uint8_t {
        kMoved = 1,  // position or z: origin and bounds
        kShape = 2,  // size, scale, rotation, pivot, texture size: edges
        kLook = 4,   // uv, flips, tint
        kQueued = 8, // in dirtyList_
    };

    // The cold part of a sprite: its definition (whose position is kept in pos_ and copied
    // back by def()) and what repack() derives from its shape.
    struct Slot {
        std::uint16_t generation = 1;
        bool alive = false;
        std::uint32_t texture = 0;   // resolved texture slot
        glm::vec2 edgeX{0.0f, 0.0f}; // local (world or camera) units, before HUD transform
        glm::vec2 edgeY{0.0f, 0.0f};
        SpriteDef def;
    };

    Slot& slot(SpriteId id, const char* function);
    const Slot& slot(SpriteId id, const char* function) const;
    void markDirty(std::uint32_t index, std::uint8_t bits) {
        std::uint8_t& d = dirty_[index];
        if ((d & kQueued) == 0) {
            dirtyList_.push_back(index);
            d |= kQueued;
        }
        d |= bits;
    }
    // The id check every setter starts with: one 2-byte load (liveGen_ holds the generation of
    // a live slot, 0 for a free one; a valid id's generation is never 0).
    std::optional<std::uint32_t> liveIndex(SpriteId id) const noexcept {
        return core::findSlot(id, liveGen_.size(), [this](std::uint32_t i) { return liveGen_[i]; });
    }
    std::uint32_t index(SpriteId id, const char* function) const {
        const std::optional<std::uint32_t> i = liveIndex(id);
        if (!i) [[unlikely]] {
            failBadId(id, function);
        }
        return *i;
    }
    // The texture slot of a live texture id, else std::nullopt.
    std::optional<std::uint32_t> textureSlot(TextureId id) const noexcept;
    // The slot a quad with this texture draws: white for null, the placeholder for a stale id.
    std::uint32_t drawnTexture(TextureId id) const noexcept;
    // Throws (naming `function`) for a stale texture id; null is fine.
    void requireTexture(const char* function, TextureId id) const;
    [[noreturn, gnu::cold, gnu::noinline]] static void failBadId(SpriteId id, const char* function);
    void moveTo(std::uint32_t index, glm::vec2 position);
    void resolveTexture(Slot& s) const;
    void repack(std::uint32_t index, const CameraState& camera);
    void sortOrder();
    [[nodiscard]] bool opaque(const Slot& s) const;
    [[nodiscard]] std::uint64_t key(float z, std::uint32_t texture, bool isOpaque) const;

    const std::vector<TextureFacts>& textures_;
    std::uint32_t whiteSlot_;
    std::uint32_t placeholderSlot_;

    std::vector<Slot> slots_;
    // Per slot, what a moving sprite's setPosition() touches, each array walked in slot order:
    // generation if alive (else 0), position, origin - position (local units), dirty bits.
    std::vector<std::uint16_t> liveGen_;
    std::vector<glm::vec2> pos_;
    std::vector<glm::vec2> pivotOffset_;
    std::vector<std::uint8_t> dirty_;
    std::vector<std::uint32_t> free_;
    std::vector<std::uint32_t> dirtyList_;
    std::vector<std::uint32_t> cameraDependent_; // visible HUD or parallax != 1 sprites
    std::vector<std::uint32_t> order_;           // visible sprites in draw order
    std::vector<std::uint64_t> orderKeys_;
    std::vector<std::uint8_t> orderTranslucent_;
    // Per drawn sprite in draw order, kept up to date by repack() and setPosition(), so a
    // frame's emit() reads them front to back (a streaming copy): the packed instance, its
    // bounds relative to the instance's origin (min x, min y, max x, max y) and texture slot.
    std::vector<Instance> orderPacked_;
    std::vector<glm::vec4> orderBounds_;
    std::vector<std::uint32_t> orderTexture_;
    // Per slot: its index in order_; kCameraBit set when it depends on the camera (HUD or
    // parallax != 1, so a move is repacked by prepare()); kNotDrawn when hidden or dead.
    // setPosition() of a drawn sprite that does not depend on the camera writes the new origin
    // straight into orderPacked_: a moving sprite costs no dirty-list entry and no repack.
    std::vector<std::uint32_t> orderPosition_;
    static constexpr std::uint32_t kCameraBit = 0x80000000u;
    static constexpr std::uint32_t kNotDrawn = 0xffffffffu;
    int movedThrough_ = 0; // sprites setPosition() moved in orderPacked_ since the last emit()
    int alive_ = 0;
    bool orderDirty_ = true;
    bool allDirty_ = false;

    struct Transient {
        Quad quad;
        Instance instance;
        glm::vec4 bounds;
        std::uint64_t key;
        std::uint32_t texture;
        bool translucent;
    };
    std::vector<Transient> quads_;
    std::vector<std::uint32_t> quadOrder_;

    CameraState camera_{};
    ViewBounds view_{};
    int rebuiltLast_ = 0;
    bool emittedOnce_ = false;
    bool lastHadQuads_ = false;
};

} // namespace e2d::render::detail
