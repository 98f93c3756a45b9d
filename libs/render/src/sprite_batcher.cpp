// SPDX-License-Identifier: MIT
#include "sprite_batcher.hpp"

#include <e2d/core/error_text.hpp>

#include "half.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <string>

namespace e2d::render::detail {

namespace {

constexpr const char* kCreate = "render::Renderer::createSprite()";

void validate(const char* function, const SpriteDef& def) {
    core::requireFinite(function, "position", def.position);
    core::requireFinite(function, "z", def.z);
    core::requireFinite(function, "scale", def.scale);
    core::requireFinite(function, "rotation", def.rotation);
    core::requireFinite(function, "pivot", def.pivot);
    if (!core::isFinite(def.size) || def.size.x < 0.0f || def.size.y < 0.0f) {
        core::throwError(function,
                         "size must be >= 0 and finite, got " + core::formatVector(def.size));
    }
    if (!core::isFinite(def.uv.min) || !core::isFinite(def.uv.size) || def.uv.size.x < 0.0f ||
        def.uv.size.y < 0.0f || def.uv.min.x < 0.0f || def.uv.min.y < 0.0f ||
        def.uv.max().x > 1.0f || def.uv.max().y > 1.0f) {
        core::throwError(function, "uv must lie in [0, 1] with size >= 0, got min " +
                                       core::formatVector(def.uv.min) + " size " +
                                       core::formatVector(def.uv.size));
    }
    if (!std::isfinite(def.parallax) || def.parallax < 0.0f) {
        core::throwError(function, "parallax must be >= 0 and finite, got " +
                                       core::formatNumber(def.parallax));
    }
}

std::uint16_t unorm16(float v) {
    return static_cast<std::uint16_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 65535.0f));
}

bool isTranslucentKey(std::uint64_t key) { return (key >> 63) != 0; }

// Of two equal keys, whether `a` (created or submitted before `b` when a < b) is drawn first:
// in the translucent pass the later one is drawn last (painter's order); in the opaque pass
// first (the strict depth test keeps the first).
bool tieFirst(std::uint64_t key, std::uint32_t a, std::uint32_t b) {
    return isTranslucentKey(key) ? a < b : a > b;
}

// Monotonic unsigned image of a float: a < b  <=>  bits(a) < bits(b).
std::uint32_t orderedBits(float z) {
    std::uint32_t bits = std::bit_cast<std::uint32_t>(z == 0.0f ? 0.0f : z);
    return (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
}

glm::vec2 rotate(glm::vec2 v, float c, float s) { return {c * v.x - s * v.y, s * v.x + c * v.y}; }

void packLook(Instance& out, const Rect& uv, bool flipX, bool flipY, Color tint) {
    float u0 = uv.min.x;
    float u1 = uv.min.x + uv.size.x;
    float vTop = uv.min.y;
    float vBottom = uv.min.y + uv.size.y;
    if (flipX) {
        std::swap(u0, u1);
    }
    if (flipY) {
        std::swap(vTop, vBottom);
    }
    out.uv[0] = unorm16(u0);
    out.uv[1] = unorm16(vTop);
    out.uv[2] = unorm16(u1);
    out.uv[3] = unorm16(vBottom);
    out.tint[0] = tint.r;
    out.tint[1] = tint.g;
    out.tint[2] = tint.b;
    out.tint[3] = tint.a;
}

void packEdges(Instance& out, glm::vec2 ex, glm::vec2 ey) {
    out.edges[0] = toHalf(ex.x);
    out.edges[1] = toHalf(ex.y);
    out.edges[2] = toHalf(ey.x);
    out.edges[3] = toHalf(ey.y);
}

// Bounds of the parallelogram origin + [0,1] ex + [0,1] ey.
// Scalar std::min/max: these run for every moved sprite and must inline.
inline glm::vec4 boundsOf(glm::vec2 o, glm::vec2 ex, glm::vec2 ey) {
    return {o.x + std::min(ex.x, 0.0f) + std::min(ey.x, 0.0f),
            o.y + std::min(ex.y, 0.0f) + std::min(ey.y, 0.0f),
            o.x + std::max(ex.x, 0.0f) + std::max(ey.x, 0.0f),
            o.y + std::max(ex.y, 0.0f) + std::max(ey.y, 0.0f)};
}

bool outside(const glm::vec4& b, const ViewBounds& view) {
    return b.z < view.min.x || b.x > view.max.x || b.w < view.min.y || b.y > view.max.y;
}

// The same for bounds relative to an instance's origin.
inline bool outside(const Instance& in, const glm::vec4& b, const ViewBounds& view) {
    return in.x + b.z < view.min.x || in.x + b.x > view.max.x || in.y + b.w < view.min.y ||
           in.y + b.y > view.max.y;
}

// World placement of a quad given in local units (world, or camera units for HUD).
struct Placement {
    glm::vec2 origin;
    glm::vec2 ex;
    glm::vec2 ey;
};

inline Placement place(glm::vec2 position, glm::vec2 pivotOffset, glm::vec2 ex, glm::vec2 ey,
                       float parallax, bool hud, const CameraState& camera) {
    if (hud) {
        // camera -> world: position + R(rotation) * v / zoom, applied to the whole quad.
        float c = std::cos(camera.rotation) / camera.zoom;
        float s = std::sin(camera.rotation) / camera.zoom;
        return {camera.position + rotate(position + pivotOffset, c, s), rotate(ex, c, s),
                rotate(ey, c, s)};
    }
    glm::vec2 anchor = position;
    if (parallax != 1.0f) {
        anchor = camera.position + parallax * (position - camera.position);
    }
    return {anchor + pivotOffset, ex, ey};
}

} // namespace

SpriteBatcher::SpriteBatcher(const std::vector<TextureFacts>& textures, std::uint32_t whiteSlot,
                             std::uint32_t placeholderSlot)
    : textures_(textures), whiteSlot_(whiteSlot), placeholderSlot_(placeholderSlot) {}

SpriteBatcher::Slot& SpriteBatcher::slot(SpriteId id, const char* function) {
    return slots_[index(id, function)];
}

const SpriteBatcher::Slot& SpriteBatcher::slot(SpriteId id, const char* function) const {
    return slots_[index(id, function)];
}

// Every setter's id check inlines (index()); the message is built out of line.
void SpriteBatcher::failBadId(SpriteId id, const char* function) {
    core::throwError(function, id.isNull()
                                   ? std::string("null sprite id")
                                   : "stale sprite id (index " + std::to_string(id.index()) +
                                         ", generation " + std::to_string(id.generation) + ")");
}

bool SpriteBatcher::isValid(SpriteId id) const noexcept { return liveIndex(id).has_value(); }

std::optional<std::uint32_t> SpriteBatcher::textureSlot(TextureId id) const noexcept {
    return core::findSlot(id, textures_.size(),
                          [this](std::uint32_t i) { return textures_[i].generation; });
}

std::uint32_t SpriteBatcher::drawnTexture(TextureId id) const noexcept {
    return id.isNull() ? whiteSlot_ : textureSlot(id).value_or(placeholderSlot_);
}

void SpriteBatcher::requireTexture(const char* function, TextureId id) const {
    if (!id.isNull() && !textureSlot(id)) {
        core::throwError(function, "stale texture id (index " + std::to_string(id.index()) + ")");
    }
}

void SpriteBatcher::resolveTexture(Slot& s) const { s.texture = drawnTexture(s.def.texture); }

bool SpriteBatcher::opaque(const Slot& s) const {
    return s.def.tint.a == 255 && !textures_[s.texture].translucent;
}

std::uint64_t SpriteBatcher::key(float z, std::uint32_t texture, bool isOpaque) const {
    std::uint64_t zBits = orderedBits(z);
    if (isOpaque) {
        // Pass 0, drawn with a strict depth test, so of equal-z quads the first drawn stays on
        // top: by texture, last texture first, then front to back (larger z first); equal keys
        // draw the latest-created first (the comparators). The quad that ends on top is the
        // same as painter's order would give, and the depth test rejects the quads it covers
        // before they are shaded.
        return (static_cast<std::uint64_t>(~texture & 0x7fffffffu) << 32) | (~zBits & 0xffffffffu);
    }
    // Pass 1, back to front (smaller z first), then texture so equal z shares batches.
    return (1ull << 63) | (zBits << 31) | (texture & 0x7fffffffu);
}

SpriteId SpriteBatcher::create(const SpriteDef& def) {
    validate(kCreate, def);
    requireTexture(kCreate, def.texture);
    std::uint32_t index;
    if (!free_.empty()) {
        index = free_.back();
        free_.pop_back();
    } else {
        index = static_cast<std::uint32_t>(slots_.size());
        slots_.emplace_back();
        orderPosition_.push_back(kNotDrawn);
        liveGen_.push_back(0);
        pos_.emplace_back(0.0f);
        pivotOffset_.emplace_back(0.0f);
        dirty_.push_back(0);
    }
    Slot& s = slots_[index];
    s.def = def;
    s.alive = true;
    liveGen_[index] = s.generation;
    pos_[index] = def.position;
    dirty_[index] = 0;
    resolveTexture(s);
    ++alive_;
    markDirty(index, kMoved | kShape | kLook);
    orderDirty_ = true;
    return SpriteId::forSlot(index, s.generation);
}

bool SpriteBatcher::destroy(SpriteId id) {
    if (!isValid(id)) {
        return false;
    }
    std::uint32_t index = id.index();
    Slot& s = slots_[index];
    s.alive = false;
    liveGen_[index] = 0;
    dirty_[index] = 0;
    orderPosition_[index] = kNotDrawn; // the draw order is rebuilt before the next frame
    s.generation = core::nextGeneration(s.generation);
    free_.push_back(index);
    --alive_;
    orderDirty_ = true;
    return true;
}

void SpriteBatcher::destroyAll() {
    for (std::uint32_t i = 0; i < slots_.size(); ++i) {
        if (slots_[i].alive) {
            destroy(SpriteId::forSlot(i, slots_[i].generation));
        }
    }
    dirtyList_.clear();
}

const SpriteDef& SpriteBatcher::def(SpriteId id, const char* function) {
    const std::uint32_t i = index(id, function);
    slots_[i].def.position = pos_[i];
    return slots_[i].def;
}

void SpriteBatcher::set(SpriteId id, const SpriteDef& def, const char* function) {
    Slot& s = slot(id, function);
    validate(function, def);
    s.def = def;
    pos_[id.index()] = def.position;
    resolveTexture(s);
    markDirty(id.index(), kMoved | kShape | kLook);
    orderDirty_ = true;
}

void SpriteBatcher::setPosition(SpriteId id, glm::vec2 position) {
    constexpr const char* fn = "render::Renderer::setPosition()";
    const std::uint32_t i = index(id, fn);
    core::requireFinite(fn, "position", position);
    if (pos_[i] != position) {
        moveTo(i, position);
    }
}

void SpriteBatcher::moveTo(std::uint32_t i, glm::vec2 position) {
    pos_[i] = position;
    const std::uint32_t at = orderPosition_[i];
    if (at < kCameraBit && (dirty_[i] & kQueued) == 0) {
        // Drawn, independent of the camera and not queued for a repack: the origin is all
        // that changes.
        Instance& out = orderPacked_[at];
        out.x = position.x + pivotOffset_[i].x;
        out.y = position.y + pivotOffset_[i].y;
        ++movedThrough_;
    } else {
        markDirty(i, kMoved);
    }
}

void SpriteBatcher::setZ(SpriteId id, float z) {
    constexpr const char* fn = "render::Renderer::setZ()";
    Slot& s = slot(id, fn);
    core::requireFinite(fn, "z", z);
    if (s.def.z != z) {
        s.def.z = z;
        markDirty(id.index(), kMoved);
        orderDirty_ = true;
    }
}

void SpriteBatcher::setSize(SpriteId id, glm::vec2 size) {
    constexpr const char* fn = "render::Renderer::setSize()";
    Slot& s = slot(id, fn);
    if (!core::isFinite(size) || size.x < 0.0f || size.y < 0.0f) {
        core::throwError(fn, "size must be >= 0 and finite, got " + core::formatVector(size));
    }
    if (s.def.size != size) {
        s.def.size = size;
        markDirty(id.index(), kShape);
    }
}

void SpriteBatcher::setScale(SpriteId id, glm::vec2 scale) {
    constexpr const char* fn = "render::Renderer::setScale()";
    Slot& s = slot(id, fn);
    core::requireFinite(fn, "scale", scale);
    if (s.def.scale != scale) {
        s.def.scale = scale;
        markDirty(id.index(), kShape);
    }
}

void SpriteBatcher::setRotation(SpriteId id, float radians) {
    constexpr const char* fn = "render::Renderer::setRotation()";
    Slot& s = slot(id, fn);
    core::requireFinite(fn, "rotation", radians);
    if (s.def.rotation != radians) {
        s.def.rotation = radians;
        markDirty(id.index(), kShape);
    }
}

void SpriteBatcher::setPivot(SpriteId id, glm::vec2 pivot) {
    constexpr const char* fn = "render::Renderer::setPivot()";
    Slot& s = slot(id, fn);
    core::requireFinite(fn, "pivot", pivot);
    if (s.def.pivot != pivot) {
        s.def.pivot = pivot;
        markDirty(id.index(), kShape);
    }
}

void SpriteBatcher::setTint(SpriteId id, Color tint) {
    Slot& s = slot(id, "render::Renderer::setTint()");
    if (s.def.tint != tint) {
        if ((s.def.tint.a == 255) != (tint.a == 255)) {
            orderDirty_ = true; // changes pass
        }
        s.def.tint = tint;
        markDirty(id.index(), kLook);
    }
}

void SpriteBatcher::setUv(SpriteId id, const Rect& uv, bool uvRotated) {
    constexpr const char* fn = "render::Renderer::setUv()";
    Slot& s = slot(id, fn);
    SpriteDef def = s.def;
    def.uv = uv;
    validate(fn, def);
    if (s.def.uv != uv || s.def.uvRotated != uvRotated) {
        // A turned image turns the quad's edges; the automatic size follows the UV extent.
        const bool shape = s.def.uvRotated != uvRotated || s.def.size == glm::vec2(0.0f);
        s.def.uv = uv;
        s.def.uvRotated = uvRotated;
        markDirty(id.index(), shape ? kLook | kShape : kLook);
    }
}

void SpriteBatcher::setFlip(SpriteId id, bool flipX, bool flipY) {
    Slot& s = slot(id, "render::Renderer::setFlip()");
    if (s.def.flipX != flipX || s.def.flipY != flipY) {
        s.def.flipX = flipX;
        s.def.flipY = flipY;
        markDirty(id.index(), kLook);
    }
}

void SpriteBatcher::setParallax(SpriteId id, float parallax) {
    constexpr const char* fn = "render::Renderer::setParallax()";
    Slot& s = slot(id, fn);
    if (!std::isfinite(parallax) || parallax < 0.0f) {
        core::throwError(fn,
                         "parallax must be >= 0 and finite, got " + core::formatNumber(parallax));
    }
    if (s.def.parallax != parallax) {
        s.def.parallax = parallax;
        markDirty(id.index(), kMoved);
        orderDirty_ = true; // camera-dependent list
    }
}

void SpriteBatcher::setHud(SpriteId id, bool hud) {
    Slot& s = slot(id, "render::Renderer::setHud()");
    if (s.def.hud != hud) {
        s.def.hud = hud;
        markDirty(id.index(), kMoved | kShape);
        orderDirty_ = true;
    }
}

void SpriteBatcher::setVisible(SpriteId id, bool visible) {
    Slot& s = slot(id, "render::Renderer::setVisible()");
    if (s.def.visible != visible) {
        s.def.visible = visible;
        orderDirty_ = true;
    }
}

void SpriteBatcher::setTexture(SpriteId id, TextureId texture) {
    constexpr const char* fn = "render::Renderer::setTexture()";
    Slot& s = slot(id, fn);
    requireTexture(fn, texture);
    if (s.def.texture != texture) {
        s.def.texture = texture;
        resolveTexture(s);
        markDirty(id.index(), kShape);
        orderDirty_ = true;
    }
}

void SpriteBatcher::setTransform(SpriteId id, glm::vec2 position, float z, float rotation,
                                 glm::vec2 scale) {
    constexpr const char* fn = "render::Renderer::setTransform()";
    Slot& s = slot(id, fn);
    core::requireFinite(fn, "position", position);
    core::requireFinite(fn, "z", z);
    core::requireFinite(fn, "rotation", rotation);
    core::requireFinite(fn, "scale", scale);
    const std::uint32_t i = id.index();
    if (s.def.z == z && s.def.rotation == rotation && s.def.scale == scale) {
        if (pos_[i] != position) {
            moveTo(i, position);
        }
        return;
    }
    std::uint8_t bits = kMoved;
    if (s.def.z != z) {
        orderDirty_ = true;
    }
    if (s.def.rotation != rotation || s.def.scale != scale) {
        bits |= kShape;
    }
    pos_[i] = position;
    s.def.z = z;
    s.def.rotation = rotation;
    s.def.scale = scale;
    markDirty(i, bits);
}

void SpriteBatcher::submit(const Quad& quad) {
    constexpr const char* fn = "render::Renderer::submit()";
    core::requireFinite(fn, "position", quad.position);
    core::requireFinite(fn, "z", quad.z);
    core::requireFinite(fn, "rotation", quad.rotation);
    core::requireFinite(fn, "pivot", quad.pivot);
    if (!core::isFinite(quad.size) || quad.size.x < 0.0f || quad.size.y < 0.0f) {
        core::throwError(fn, "size must be >= 0 and finite, got " + core::formatVector(quad.size));
    }
    requireTexture(fn, quad.texture);
    Transient t{};
    t.quad = quad;
    quads_.push_back(t);
}

void SpriteBatcher::texturesChanged() {
    allDirty_ = true;
    orderDirty_ = true;
}

void SpriteBatcher::clearTransient() noexcept { quads_.clear(); }

void SpriteBatcher::repack(std::uint32_t index, const CameraState& camera) {
    Slot& s = slots_[index];
    const std::uint8_t dirty = dirty_[index];
    dirty_[index] = 0;
    const std::uint32_t at = orderPosition_[index];
    if (at == kNotDrawn) {
        // Hidden (or destroyed): sortOrder() marks it dirty again when it is drawn again.
        return;
    }
    Instance& out = orderPacked_[at & ~kCameraBit];
    const SpriteDef& d = s.def;
    glm::vec2& pivotOffset = pivotOffset_[index];
    if ((dirty & kShape) != 0) {
        glm::vec2 size = d.size;
        if (size == glm::vec2(0.0f)) {
            size = textures_[s.texture].size * d.uv.size;
            if (d.uvRotated) {
                size = {size.y, size.x};
            }
        }
        const glm::vec2 extent = size * d.scale;
        if (d.rotation == 0.0f) {
            // Axis-aligned: no sin/cos.
            s.edgeX = {extent.x, 0.0f};
            s.edgeY = {0.0f, extent.y};
        } else {
            const float c = std::cos(d.rotation);
            const float sn = std::sin(d.rotation);
            s.edgeX = glm::vec2(c, sn) * extent.x;
            s.edgeY = glm::vec2(-sn, c) * extent.y;
        }
        pivotOffset = -(s.edgeX * d.pivot.x + s.edgeY * d.pivot.y);
        if (d.uvRotated) {
            // The image is stored turned 90 degrees clockwise: the texture's u axis runs up the
            // shown image and its v axis (down) to the right. The instance maps u along its
            // edge X and v down along -edge Y, so its corner (0, 0) is the shown image's
            // bottom-right corner, edge X the image's up edge and edge Y its leftward edge.
            pivotOffset += s.edgeX;
            const glm::vec2 up = s.edgeY;
            s.edgeY = -s.edgeX;
            s.edgeX = up;
        }
        if (!d.hud) {
            packEdges(out, s.edgeX, s.edgeY);
            orderBounds_[at & ~kCameraBit] = boundsOf(glm::vec2(0.0f), s.edgeX, s.edgeY);
        }
    }
    if ((dirty & kLook) != 0) {
        // A turned image mirrors left-right along the texture's v axis, up-down along u.
        packLook(out, d.uv, d.uvRotated ? d.flipY : d.flipX, d.uvRotated ? d.flipX : d.flipY,
                 d.tint);
    }
    const Placement p =
        place(pos_[index], pivotOffset, s.edgeX, s.edgeY, d.parallax, d.hud, camera);
    if (d.hud) {
        // The camera turns and scales a HUD sprite's edges.
        packEdges(out, p.ex, p.ey);
        orderBounds_[at & ~kCameraBit] = boundsOf(glm::vec2(0.0f), p.ex, p.ey);
    }
    out.x = p.origin.x;
    out.y = p.origin.y;
    out.z = d.z;
}

void SpriteBatcher::sortOrder() {
    order_.clear();
    cameraDependent_.clear();
    for (std::uint32_t i = 0; i < slots_.size(); ++i) {
        Slot& s = slots_[i];
        if (!s.alive || !s.def.visible) {
            continue;
        }
        order_.push_back(i);
        if (s.def.hud || s.def.parallax != 1.0f) {
            cameraDependent_.push_back(i);
        }
    }
    std::vector<std::uint64_t> keys(slots_.size());
    for (std::uint32_t i : order_) {
        const Slot& s = slots_[i];
        keys[i] = key(s.def.z, s.texture, opaque(s));
    }
    // Ties keep creation (slot) order, so equal keys draw the same way every frame.
    std::sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) {
        return keys[a] != keys[b] ? keys[a] < keys[b] : tieFirst(keys[a], a, b);
    });
    // The packed instances live only in draw order: sprites drawn last frame move to their new
    // place; the others (new, shown again) are packed from scratch by prepare().
    std::vector<Instance> oldPacked = std::move(orderPacked_);
    std::vector<glm::vec4> oldBounds = std::move(orderBounds_);
    std::vector<std::uint32_t> oldPosition = std::move(orderPosition_);
    orderPosition_.assign(oldPosition.size(), kNotDrawn);
    orderPacked_.assign(order_.size(), Instance{});
    orderBounds_.assign(order_.size(), glm::vec4(0.0f));
    orderKeys_.resize(order_.size());
    orderTranslucent_.resize(order_.size());
    orderTexture_.resize(order_.size());
    for (std::size_t k = 0; k < order_.size(); ++k) {
        const std::uint32_t i = order_[k];
        const SpriteDef& d = slots_[i].def;
        orderKeys_[k] = keys[i];
        orderTranslucent_[k] = static_cast<std::uint8_t>(orderKeys_[k] >> 63);
        orderTexture_[k] = slots_[i].texture;
        orderPosition_[i] =
            static_cast<std::uint32_t>(k) | (d.hud || d.parallax != 1.0f ? kCameraBit : 0u);
        if (const std::uint32_t was = oldPosition[i] & ~kCameraBit;
            oldPosition[i] != kNotDrawn && was < oldPacked.size()) {
            orderPacked_[k] = oldPacked[was];
            orderBounds_[k] = oldBounds[was];
        } else {
            markDirty(i, kMoved | kShape | kLook);
        }
    }
    orderDirty_ = false;
}

std::size_t SpriteBatcher::prepare(const CameraState& camera, const ViewBounds& view,
                                   bool& changed) {
    changed = !emittedOnce_ || orderDirty_ || allDirty_ || movedThrough_ != 0 ||
              !dirtyList_.empty() || !quads_.empty() || lastHadQuads_ || !(camera == camera_) ||
              !(view == view_);
    if (allDirty_) {
        for (std::uint32_t i = 0; i < slots_.size(); ++i) {
            if (slots_[i].alive) {
                resolveTexture(slots_[i]);
                markDirty(i, kMoved | kShape | kLook);
            }
        }
        allDirty_ = false;
    }
    if (orderDirty_) {
        sortOrder();
    }
    if (!(camera == camera_)) {
        for (std::uint32_t i : cameraDependent_) {
            markDirty(i, slots_[i].def.hud ? kMoved | kShape : kMoved);
        }
    }
    camera_ = camera;
    view_ = view;
    rebuiltLast_ = static_cast<int>(dirtyList_.size()) + movedThrough_;
    for (std::uint32_t i : dirtyList_) {
        if (slots_[i].alive) {
            repack(i, camera);
        } else {
            dirty_[i] = 0;
        }
    }
    dirtyList_.clear();

    // Transient quads: packed and keyed every frame.
    quadOrder_.resize(quads_.size());
    for (std::uint32_t k = 0; k < quads_.size(); ++k) {
        Transient& t = quads_[k];
        const Quad& q = t.quad;
        t.texture = drawnTexture(q.texture);
        float c = std::cos(q.rotation);
        float sn = std::sin(q.rotation);
        glm::vec2 ex = glm::vec2(c, sn) * q.size.x;
        glm::vec2 ey = glm::vec2(-sn, c) * q.size.y;
        glm::vec2 pivotOffset = -(ex * q.pivot.x + ey * q.pivot.y);
        Placement p = place(q.position, pivotOffset, ex, ey, 1.0f, q.hud, camera);
        t.instance.x = p.origin.x;
        t.instance.y = p.origin.y;
        t.instance.z = q.z;
        packEdges(t.instance, p.ex, p.ey);
        packLook(t.instance, q.uv, false, false, q.tint);
        t.bounds = boundsOf(p.origin, p.ex, p.ey);
        t.translucent = q.tint.a != 255 || textures_[t.texture].translucent;
        t.key = key(q.z, t.texture, !t.translucent);
        quadOrder_[k] = k;
    }
    std::sort(quadOrder_.begin(), quadOrder_.end(), [&](std::uint32_t a, std::uint32_t b) {
        return quads_[a].key != quads_[b].key ? quads_[a].key < quads_[b].key
                                              : tieFirst(quads_[a].key, a, b);
    });
    return order_.size() + quads_.size();
}

std::size_t SpriteBatcher::emit(Instance* dst, std::vector<Batch>& batches, BuildCounts& counts) {
    batches.clear();
    std::uint32_t n = 0;
    int culled = 0;
    std::uint32_t currentTexture = 0xffffffffu;
    bool currentTranslucent = false;
    const ViewBounds view = view_;
    auto open = [&](std::uint32_t texture, bool translucent) {
        if (texture != currentTexture || translucent != currentTranslucent || batches.empty()) {
            if (!batches.empty()) {
                batches.back().count = n - batches.back().first;
            }
            batches.push_back(Batch{n, 0, texture, translucent});
            currentTexture = texture;
            currentTranslucent = translucent;
        }
    };
    const std::size_t sprites = order_.size();
    if (quads_.empty()) {
        // Sequential reads of the draw-order copies: bounds, texture, pass, instance.
        const glm::vec4* bounds = orderBounds_.data();
        const Instance* packed = orderPacked_.data();
        const std::uint32_t* textureOf = orderTexture_.data();
        const std::uint8_t* translucentOf = orderTranslucent_.data();
        for (std::size_t k = 0; k < sprites; ++k) {
            if (outside(packed[k], bounds[k], view)) {
                ++culled;
                continue;
            }
            const std::uint32_t texture = textureOf[k];
            const bool translucent = translucentOf[k] != 0;
            if (texture != currentTexture || translucent != currentTranslucent) [[unlikely]] {
                open(texture, translucent);
            }
            dst[n++] = packed[k];
        }
    } else {
        std::size_t k = 0;
        std::size_t q = 0;
        while (k < sprites || q < quadOrder_.size()) {
            // At equal keys the later of the two (the quad, submitted after the sprites were
            // made) is drawn first in the opaque pass and last in the translucent one.
            const std::uint64_t quadKey = q < quadOrder_.size() ? quads_[quadOrder_[q]].key : 0;
            bool takeSprite =
                q == quadOrder_.size() ||
                (k < sprites && (orderKeys_[k] < quadKey ||
                                 (orderKeys_[k] == quadKey && isTranslucentKey(quadKey))));
            if (takeSprite) {
                const std::size_t at = k++;
                if (outside(orderPacked_[at], orderBounds_[at], view)) {
                    ++culled;
                    continue;
                }
                open(orderTexture_[at], orderTranslucent_[at] != 0);
                dst[n++] = orderPacked_[at];
            } else {
                const Transient& t = quads_[quadOrder_[q++]];
                if (outside(t.bounds, view)) {
                    ++culled;
                    continue;
                }
                open(t.texture, t.translucent);
                dst[n++] = t.instance;
            }
        }
    }
    if (!batches.empty()) {
        batches.back().count = n - batches.back().first;
    }
    lastHadQuads_ = !quads_.empty();
    movedThrough_ = 0;
    quads_.clear();
    emittedOnce_ = true;
    counts.drawn = static_cast<int>(n);
    counts.culled = culled;
    counts.rebuilt = rebuiltLast_;
    return n;
}

} // namespace e2d::render::detail
