// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

namespace e2d::render::detail {

// One quad as the vertex shader reads it (divisor 1), 32 bytes:
//   origin   3 x float32  world position of the quad corner that corner (0, 0) maps to, and z
//   edges    4 x float16  edge vectors: corner (1, 0) = origin + edgeX, (0, 1) = origin + edgeY
//                         (size, scale, rotation and the pivot's offset all folded in)
//   uv       4 x unorm16  u0, v0 (texel at corner (0, 1): the image's top-left when unflipped),
//                         u1, v1 (at corner (1, 0)); flips swap them
//   tint     4 x unorm8   RGBA
// The shader builds the four corners from gl_VertexID (a triangle strip) and the instance.
struct Instance {
    float x;
    float y;
    float z;
    std::uint16_t edges[4];
    std::uint16_t uv[4];
    std::uint8_t tint[4];
};
static_assert(sizeof(Instance) == 32, "instance data must stay 32 bytes");

// A run of instances drawn with one instanced draw call.
struct Batch {
    std::uint32_t first = 0; // index of the first instance in the frame's data
    std::uint32_t count = 0;
    std::uint32_t texture = 0; // texture slot
    bool translucent = false;
};

} // namespace e2d::render::detail
