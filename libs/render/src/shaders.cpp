// SPDX-License-Identifier: MIT
#include "shaders.hpp"

#include <e2d/core/error_text.hpp>

#include <string>

namespace e2d::render::detail {

namespace {

constexpr const char* kVertex = R"glsl(#version 330 core
layout(location = 0) in vec3 aOrigin;  // quad corner (0, 0) in world units, and z
layout(location = 1) in vec4 aEdges;   // edge to corner (1, 0), edge to corner (0, 1)
layout(location = 2) in vec4 aUv;      // u left, v top, u right, v bottom
layout(location = 3) in vec4 aTint;
uniform mat4 uWorldToClip;
uniform float uDepthScale;             // 1 / depth range: larger z is nearer
out vec2 vUv;
out vec4 vTint;
void main() {
    vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
    vec2 world = aOrigin.xy + corner.x * aEdges.xy + corner.y * aEdges.zw;
    vec4 clip = uWorldToClip * vec4(world, 0.0, 1.0);
    clip.z = -aOrigin.z * uDepthScale;
    gl_Position = clip;
    vUv = vec2(mix(aUv.x, aUv.z, corner.x), mix(aUv.w, aUv.y, corner.y));
    vTint = aTint;
}
)glsl";

constexpr const char* kFragment = R"glsl(#version 330 core
in vec2 vUv;
in vec4 vTint;
uniform sampler2D uTexture;
uniform float uAlphaCut;               // opaque pass: 0.5 (alpha test); translucent: ~0
out vec4 outColor;
void main() {
    vec4 color = texture(uTexture, vUv) * vTint;
    if (color.a < uAlphaCut) {
        discard;
    }
    outColor = color;
}
)glsl";

GLuint compile(GLenum type, const char* source, const char* name) {
    GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
        glGetShaderInfoLog(shader, length, nullptr, log.data());
        glDeleteShader(shader);
        core::throwError("render::Renderer",
                         std::string(name) + " shader does not compile: " + log);
    }
    return shader;
}

} // namespace

GLuint createSpriteProgram() {
    GLuint vertex = compile(GL_VERTEX_SHADER, kVertex, "sprite vertex");
    GLuint fragment = 0;
    try {
        fragment = compile(GL_FRAGMENT_SHADER, kFragment, "sprite fragment");
    } catch (...) {
        glDeleteShader(vertex);
        throw;
    }
    GLuint program = glCreateProgram();
    glAttachShader(program, vertex);
    glAttachShader(program, fragment);
    glLinkProgram(program);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint length = 0;
        glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
        glGetProgramInfoLog(program, length, nullptr, log.data());
        glDeleteProgram(program);
        core::throwError("render::Renderer", "sprite program does not link: " + log);
    }
    return program;
}

} // namespace e2d::render::detail
