// SPDX-License-Identifier: MIT
#include "debug_draw.hpp"

#include <e2d/core/error.hpp>

#include <GL/glew.h>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstddef>
#include <string>

namespace e2d::render::detail {
namespace {

// Each line is a quad from a to b, widened to `width` pixels across and extended by half the
// width at both ends (square caps, so outlines close at their corners). The expansion happens
// in pixels, after projection, so the width is the same at any zoom.
const char* const kLineVertex = R"(#version 330 core
layout(location = 0) in vec2 corner;
layout(location = 1) in vec4 ends;
layout(location = 2) in float width;
layout(location = 3) in vec4 color;
layout(location = 4) in uint space;
uniform mat4 worldToClip;
uniform mat4 screenToClip;
uniform vec2 viewport;
out vec4 vertexColor;
void main() {
    mat4 m = space == 0u ? worldToClip : screenToClip;
    vec2 a = (m * vec4(ends.xy, 0.0, 1.0)).xy * 0.5 * viewport;
    vec2 b = (m * vec4(ends.zw, 0.0, 1.0)).xy * 0.5 * viewport;
    vec2 d = b - a;
    float len = length(d);
    vec2 along = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    vec2 across = vec2(-along.y, along.x);
    float halfWidth = 0.5 * width;
    vec2 p = mix(a - along * halfWidth, b + along * halfWidth, corner.x) + across * (corner.y * width);
    gl_Position = vec4(p / (0.5 * viewport), 0.0, 1.0);
    vertexColor = color;
}
)";

const char* const kTriangleVertex = R"(#version 330 core
layout(location = 0) in vec2 position;
layout(location = 1) in vec4 color;
layout(location = 2) in uint space;
uniform mat4 worldToClip;
uniform mat4 screenToClip;
out vec4 vertexColor;
void main() {
    mat4 m = space == 0u ? worldToClip : screenToClip;
    gl_Position = vec4((m * vec4(position, 0.0, 1.0)).xy, 0.0, 1.0);
    vertexColor = color;
}
)";

const char* const kFragment = R"(#version 330 core
in vec4 vertexColor;
out vec4 outColor;
void main() { outColor = vertexColor; }
)";

unsigned compile(GLenum type, const char* source, const char* what) {
    const GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        char log[2048] = {};
        glGetShaderInfoLog(shader, sizeof(log), nullptr, log);
        glDeleteShader(shader);
        throw core::Error(std::string("render::Renderer: debug drawing ") + what +
                          " shader does not compile: " + log);
    }
    return shader;
}

unsigned link(const char* vertexSource, const char* what) {
    const GLuint vertex = compile(GL_VERTEX_SHADER, vertexSource, what);
    GLuint fragment = 0;
    try {
        fragment = compile(GL_FRAGMENT_SHADER, kFragment, what);
    } catch (...) {
        glDeleteShader(vertex);
        throw;
    }
    const GLuint program = glCreateProgram();
    glAttachShader(program, vertex);
    glAttachShader(program, fragment);
    glLinkProgram(program);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        char log[2048] = {};
        glGetProgramInfoLog(program, sizeof(log), nullptr, log);
        glDeleteProgram(program);
        throw core::Error(std::string("render::Renderer: debug drawing ") + what +
                          " program does not link: " + log);
    }
    return program;
}

void* offset(std::size_t bytes) { return reinterpret_cast<void*>(bytes); }

// Grows with doubling, orphans the old storage each frame (the 3.3 streaming idiom).
void upload(GLuint buffer, long long& capacity, const void* data, long long bytes) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    if (bytes > capacity) {
        capacity = std::max(bytes, capacity * 2);
    }
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity), nullptr, GL_STREAM_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), data);
}

} // namespace

DebugDraw::DebugDraw() {
    lineProgram_ = link(kLineVertex, "line");
    try {
        triangleProgram_ = link(kTriangleVertex, "triangle");
    } catch (...) {
        glDeleteProgram(lineProgram_);
        throw;
    }
    lineWorld_ = glGetUniformLocation(lineProgram_, "worldToClip");
    lineScreen_ = glGetUniformLocation(lineProgram_, "screenToClip");
    lineViewport_ = glGetUniformLocation(lineProgram_, "viewport");
    triangleWorld_ = glGetUniformLocation(triangleProgram_, "worldToClip");
    triangleScreen_ = glGetUniformLocation(triangleProgram_, "screenToClip");

    GLuint buffers[3] = {};
    glGenBuffers(3, buffers);
    quadBuffer_ = buffers[0];
    lineBuffer_ = buffers[1];
    triangleBuffer_ = buffers[2];
    GLuint arrays[2] = {};
    glGenVertexArrays(2, arrays);
    lineVao_ = arrays[0];
    triangleVao_ = arrays[1];

    // Corners of a line's quad: x along the segment in [0, 1], y across in [-0.5, 0.5].
    const float corners[8] = {0.0f, -0.5f, 1.0f, -0.5f, 0.0f, 0.5f, 1.0f, 0.5f};
    glBindVertexArray(lineVao_);
    glBindBuffer(GL_ARRAY_BUFFER, quadBuffer_);
    glBufferData(GL_ARRAY_BUFFER, sizeof(corners), corners, GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), offset(0));
    glBindBuffer(GL_ARRAY_BUFFER, lineBuffer_);
    constexpr GLsizei lineStride = sizeof(DebugLine);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, lineStride, offset(offsetof(DebugLine, a)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, lineStride, offset(offsetof(DebugLine, width)));
    glEnableVertexAttribArray(3);
    glVertexAttribPointer(3, 4, GL_UNSIGNED_BYTE, GL_TRUE, lineStride,
                          offset(offsetof(DebugLine, color)));
    glEnableVertexAttribArray(4);
    glVertexAttribIPointer(4, 1, GL_UNSIGNED_INT, lineStride, offset(offsetof(DebugLine, space)));
    for (GLuint attribute = 1; attribute <= 4; ++attribute) {
        glVertexAttribDivisor(attribute, 1);
    }

    glBindVertexArray(triangleVao_);
    glBindBuffer(GL_ARRAY_BUFFER, triangleBuffer_);
    constexpr GLsizei vertexStride = sizeof(DebugVertex);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, vertexStride,
                          offset(offsetof(DebugVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, vertexStride,
                          offset(offsetof(DebugVertex, color)));
    glEnableVertexAttribArray(2);
    glVertexAttribIPointer(2, 1, GL_UNSIGNED_INT, vertexStride,
                           offset(offsetof(DebugVertex, space)));
    glBindVertexArray(0);
}

DebugDraw::~DebugDraw() {
    const GLuint arrays[2] = {lineVao_, triangleVao_};
    glDeleteVertexArrays(2, arrays);
    const GLuint buffers[3] = {quadBuffer_, lineBuffer_, triangleBuffer_};
    glDeleteBuffers(3, buffers);
    glDeleteProgram(lineProgram_);
    glDeleteProgram(triangleProgram_);
}

int DebugDraw::draw(const Drawer& drawer, const glm::mat4& worldToClip, glm::ivec2 targetSize) {
    if (drawer.empty() || targetSize.x <= 0 || targetSize.y <= 0) {
        return 0;
    }
    const glm::vec2 size(targetSize);
    // Pixels, origin bottom-left -> clip space.
    glm::mat4 screenToClip(1.0f);
    screenToClip[0][0] = 2.0f / size.x;
    screenToClip[1][1] = 2.0f / size.y;
    screenToClip[3][0] = -1.0f;
    screenToClip[3][1] = -1.0f;

    const GLboolean depthWasOn = glIsEnabled(GL_DEPTH_TEST);
    GLboolean depthMask = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

    int calls = 0;
    const auto triangles = drawer.triangles();
    if (!triangles.empty()) {
        upload(triangleBuffer_, triangleCapacity_, triangles.data(),
               static_cast<long long>(triangles.size_bytes()));
        glUseProgram(triangleProgram_);
        glUniformMatrix4fv(triangleWorld_, 1, GL_FALSE, glm::value_ptr(worldToClip));
        glUniformMatrix4fv(triangleScreen_, 1, GL_FALSE, glm::value_ptr(screenToClip));
        glBindVertexArray(triangleVao_);
        glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(triangles.size()));
        ++calls;
    }
    // Lines after fills, so outlines stay visible on filled shapes.
    const auto lines = drawer.lines();
    if (!lines.empty()) {
        upload(lineBuffer_, lineCapacity_, lines.data(),
               static_cast<long long>(lines.size_bytes()));
        glUseProgram(lineProgram_);
        glUniformMatrix4fv(lineWorld_, 1, GL_FALSE, glm::value_ptr(worldToClip));
        glUniformMatrix4fv(lineScreen_, 1, GL_FALSE, glm::value_ptr(screenToClip));
        glUniform2f(lineViewport_, size.x, size.y);
        glBindVertexArray(lineVao_);
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(lines.size()));
        ++calls;
    }
    glBindVertexArray(0);
    glUseProgram(0);
    if (depthWasOn == GL_TRUE) {
        glEnable(GL_DEPTH_TEST);
    }
    glDepthMask(depthMask);
    return calls;
}

} // namespace e2d::render::detail
