// SPDX-License-Identifier: MIT
#include "instance_buffer.hpp"

#include <algorithm>
#include <cstdint>

namespace e2d::render::detail {

namespace {

void waitFence(GLsync& fence) {
    if (fence == nullptr) {
        return;
    }
    // Flush on the first wait so the fence is sure to signal; then wait in 1 ms slices.
    GLenum status = glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 0);
    while (status == GL_TIMEOUT_EXPIRED) {
        status = glClientWaitSync(fence, 0, 1'000'000);
    }
    glDeleteSync(fence);
    fence = nullptr;
}

} // namespace

InstanceBuffer::InstanceBuffer(bool persistent, int frames, GLuint vao)
    : persistent_(persistent), frames_(persistent ? frames : 1), vao_(vao) {
    allocate(1024);
}

InstanceBuffer::~InstanceBuffer() { release(); }

void InstanceBuffer::release() {
    for (GLsync& fence : fences_) {
        waitFence(fence);
    }
    if (buffer_ != 0) {
        if (mapped_ != nullptr && persistent_) {
            glBindBuffer(GL_ARRAY_BUFFER, buffer_);
            glUnmapBuffer(GL_ARRAY_BUFFER);
        }
        glDeleteBuffers(1, &buffer_);
        buffer_ = 0;
        mapped_ = nullptr;
    }
}

void InstanceBuffer::allocate(std::size_t capacity) {
    release();
    capacity_ = capacity;
    glGenBuffers(1, &buffer_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    auto bytes =
        static_cast<GLsizeiptr>(capacity_ * sizeof(Instance) * static_cast<std::size_t>(frames_));
    if (persistent_) {
        GLbitfield flags = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
        glBufferStorage(GL_ARRAY_BUFFER, bytes, nullptr, flags);
        mapped_ = static_cast<Instance*>(glMapBufferRange(GL_ARRAY_BUFFER, 0, bytes, flags));
    } else {
        glBufferData(GL_ARRAY_BUFFER, bytes, nullptr, GL_STREAM_DRAW);
    }
    region_ = 0;
    pointAttributes(0);
}

void InstanceBuffer::pointAttributes(std::size_t first) const {
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    auto stride = static_cast<GLsizei>(sizeof(Instance));
    auto offset = [&](std::size_t field) {
        return reinterpret_cast<const void*>(
            static_cast<std::uintptr_t>(first * sizeof(Instance) + field));
    };
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, offset(offsetof(Instance, x)));
    glVertexAttribDivisor(0, 1);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_HALF_FLOAT, GL_FALSE, stride, offset(offsetof(Instance, edges)));
    glVertexAttribDivisor(1, 1);
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 4, GL_UNSIGNED_SHORT, GL_TRUE, stride, offset(offsetof(Instance, uv)));
    glVertexAttribDivisor(2, 1);
    glEnableVertexAttribArray(3);
    glVertexAttribPointer(3, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                          offset(offsetof(Instance, tint)));
    glVertexAttribDivisor(3, 1);
}

Instance* InstanceBuffer::begin(std::size_t count) {
    count = std::max<std::size_t>(count, 1);
    if (count > capacity_) {
        std::size_t capacity = capacity_;
        while (capacity < count) {
            capacity *= 2;
        }
        allocate(capacity);
    }
    if (persistent_) {
        region_ = (region_ + 1) % frames_;
        waitFence(fences_[static_cast<std::size_t>(region_)]);
        base_ = static_cast<std::size_t>(region_) * capacity_;
        return mapped_ + base_;
    }
    base_ = 0;
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    auto bytes = static_cast<GLsizeiptr>(capacity_ * sizeof(Instance));
    glBufferData(GL_ARRAY_BUFFER, bytes, nullptr, GL_STREAM_DRAW); // orphan
    mapped_ = static_cast<Instance*>(
        glMapBufferRange(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(count * sizeof(Instance)),
                         GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT));
    return mapped_;
}

void InstanceBuffer::end() {
    if (!persistent_) {
        glBindBuffer(GL_ARRAY_BUFFER, buffer_);
        glUnmapBuffer(GL_ARRAY_BUFFER);
        mapped_ = nullptr;
    }
}

void InstanceBuffer::fence() {
    if (!persistent_) {
        return;
    }
    GLsync& slot = fences_[static_cast<std::size_t>(region_)];
    if (slot != nullptr) {
        glDeleteSync(slot);
    }
    slot = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

} // namespace e2d::render::detail
