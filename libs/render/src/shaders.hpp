// SPDX-License-Identifier: MIT
#pragma once

#include "gl.hpp"

namespace e2d::render::detail {

// The sprite program (GLSL 330 core): corners from gl_VertexID, everything else per instance
// (see instance.hpp). Throws core::Error with the driver's log when it does not compile/link.
GLuint createSpriteProgram();

} // namespace e2d::render::detail
