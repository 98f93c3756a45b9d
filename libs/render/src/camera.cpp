// SPDX-License-Identifier: MIT
#include <e2d/render/camera.hpp>

#include <e2d/core/error_text.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace e2d::render {

namespace {

void validate(const char* function, const CameraDef& def) {
    core::requireFinite(function, "position", def.position);
    core::requireFinite(function, "rotation", def.rotation);
    if (!(def.zoom > 0.0f) || !std::isfinite(def.zoom)) {
        core::throwError(function,
                         "zoom must be > 0 and finite, got " + core::formatNumber(def.zoom));
    }
    if (!(def.referenceSize.x > 0.0f) || !(def.referenceSize.y > 0.0f) ||
        !core::isFinite(def.referenceSize)) {
        core::throwError(function, "referenceSize must be > 0 and finite, got " +
                                       core::formatVector(def.referenceSize));
    }
}

glm::vec2 rotate(glm::vec2 v, float angle) {
    float c = std::cos(angle);
    float s = std::sin(angle);
    return {c * v.x - s * v.y, s * v.x + c * v.y};
}

} // namespace

Camera::Camera(const CameraDef& def) : def_(def) {
    validate("render::Camera", def);
    screen_ = glm::ivec2(std::max(1, static_cast<int>(std::lround(def.referenceSize.x))),
                         std::max(1, static_cast<int>(std::lround(def.referenceSize.y))));
}

void Camera::setPosition(glm::vec2 position) {
    core::requireFinite("render::Camera::setPosition()", "position", position);
    def_.position = position;
}

void Camera::setRotation(float radians) {
    core::requireFinite("render::Camera::setRotation()", "rotation", radians);
    def_.rotation = radians;
}

void Camera::setZoom(float zoom) {
    CameraDef def = def_;
    def.zoom = zoom;
    validate("render::Camera::setZoom()", def);
    def_ = def;
}

void Camera::setReferenceSize(glm::vec2 size) {
    CameraDef def = def_;
    def.referenceSize = size;
    validate("render::Camera::setReferenceSize()", def);
    def_ = def;
}

void Camera::setFit(ScreenFit fit) { def_.fit = fit; }

void Camera::setScreenSize(glm::ivec2 pixels) {
    if (pixels.x < 1 || pixels.y < 1) {
        core::throwError("render::Camera::setScreenSize()",
                         "size must be >= 1 in each axis, got " + core::formatVector(pixels));
    }
    screen_ = pixels;
}

glm::vec2 Camera::pixelsPerUnit() const noexcept {
    glm::vec2 screen(screen_);
    glm::vec2 ratio = screen / def_.referenceSize;
    switch (def_.fit) {
    case ScreenFit::Expand:
        return ratio;
    case ScreenFit::WidthFit:
        return glm::vec2(ratio.x);
    case ScreenFit::HeightFit:
        return glm::vec2(ratio.y);
    case ScreenFit::BestFit:
        return glm::vec2(std::min(ratio.x, ratio.y));
    }
    return ratio;
}

Rect Camera::screenRegion() const noexcept {
    glm::vec2 screen(screen_);
    // The reference region at zoom 1, centred; the fit's scale decides how much of the
    // screen it covers (zoom does not change the letterbox, as in the seed).
    glm::vec2 extent = def_.referenceSize * pixelsPerUnit();
    glm::vec2 lo = glm::max(glm::vec2(0.0f), (screen - extent) * 0.5f);
    glm::vec2 hi = glm::min(screen, (screen + extent) * 0.5f);
    return Rect{lo, hi - lo};
}

Rect Camera::visibleWorldBounds() const noexcept {
    Rect region = screenRegion();
    glm::vec2 corners[4] = {
        screenToWorld(region.min),
        screenToWorld(region.min + glm::vec2(region.size.x, 0.0f)),
        screenToWorld(region.min + glm::vec2(0.0f, region.size.y)),
        screenToWorld(region.max()),
    };
    glm::vec2 lo = corners[0];
    glm::vec2 hi = corners[0];
    for (glm::vec2 corner : corners) {
        lo = glm::min(lo, corner);
        hi = glm::max(hi, corner);
    }
    return Rect{lo, hi - lo};
}

glm::vec2 Camera::worldToCamera(glm::vec2 world) const noexcept {
    return def_.zoom * rotate(world - def_.position, -def_.rotation);
}

glm::vec2 Camera::cameraToWorld(glm::vec2 camera) const noexcept {
    return def_.position + rotate(camera / def_.zoom, def_.rotation);
}

glm::vec2 Camera::cameraToScreen(glm::vec2 camera) const noexcept {
    return glm::vec2(screen_) * 0.5f + pixelsPerUnit() * camera;
}

glm::vec2 Camera::screenToCamera(glm::vec2 screen) const noexcept {
    return (screen - glm::vec2(screen_) * 0.5f) / pixelsPerUnit();
}

glm::vec2 Camera::worldToScreen(glm::vec2 world) const noexcept {
    return cameraToScreen(worldToCamera(world));
}

glm::vec2 Camera::screenToWorld(glm::vec2 screen) const noexcept {
    return cameraToWorld(screenToCamera(screen));
}

glm::mat4 Camera::cameraToClip() const noexcept {
    // camera -> screen -> clip: clip = 2 * screen / size - 1 = 2 * ppu * camera / size.
    glm::vec2 scale = 2.0f * pixelsPerUnit() / glm::vec2(screen_);
    glm::mat4 m(1.0f);
    m[0][0] = scale.x;
    m[1][1] = scale.y;
    return m;
}

glm::mat4 Camera::worldToClip() const noexcept {
    glm::mat4 view(1.0f);
    view = glm::scale(view, glm::vec3(def_.zoom, def_.zoom, 1.0f));
    view = glm::rotate(view, -def_.rotation, glm::vec3(0.0f, 0.0f, 1.0f));
    view = glm::translate(view, glm::vec3(-def_.position, 0.0f));
    return cameraToClip() * view;
}

} // namespace e2d::render
