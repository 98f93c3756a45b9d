// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/render/drawer.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

namespace e2d::render::detail {

// Draws a Drawer's shapes with the OpenGL context current at construction: every line as one
// instance of a quad expanded to its pixel width in the vertex shader (one instanced draw
// call), every filled triangle from one streamed buffer (one draw call). No depth test, alpha
// blending, on top of whatever is in the framebuffer. GL 3.3 core.
class DebugDraw {
public:
    // Throws core::Error with the driver's log if the shaders do not compile.
    DebugDraw();
    ~DebugDraw();
    DebugDraw(const DebugDraw&) = delete;
    DebugDraw& operator=(const DebugDraw&) = delete;

    // `worldToClip`: the camera's; screen space is `targetSize` pixels, origin bottom-left.
    // Returns the number of draw calls made (0, 1 or 2).
    int draw(const Drawer& drawer, const glm::mat4& worldToClip, glm::ivec2 targetSize);

private:
    unsigned lineProgram_ = 0;
    unsigned triangleProgram_ = 0;
    unsigned lineVao_ = 0;
    unsigned triangleVao_ = 0;
    unsigned quadBuffer_ = 0;
    unsigned lineBuffer_ = 0;
    unsigned triangleBuffer_ = 0;
    long long lineCapacity_ = 0;
    long long triangleCapacity_ = 0;
    int lineWorld_ = -1;
    int lineScreen_ = -1;
    int lineViewport_ = -1;
    int triangleWorld_ = -1;
    int triangleScreen_ = -1;
};

} // namespace e2d::render::detail
