// SPDX-License-Identifier: MIT
#pragma once

#include "gl.hpp"
#include "instance.hpp"

#include <array>
#include <cstddef>

namespace e2d::render::detail {

// Where a frame's instance data goes.
// Persistent (OpenGL 4.4 / ARB_buffer_storage): one buffer of `frames` regions, mapped once
// (persistent, coherent); a frame writes the next region after waiting for the fence set when
// that region was last drawn from. Orphaning (3.3): the buffer's storage is re-specified each
// frame (the driver hands out fresh memory while the GPU still reads the old) and mapped for
// writing with GL_MAP_INVALIDATE_BUFFER_BIT.
class InstanceBuffer {
public:
    InstanceBuffer(bool persistent, int frames, GLuint vao);
    ~InstanceBuffer();
    InstanceBuffer(const InstanceBuffer&) = delete;
    InstanceBuffer& operator=(const InstanceBuffer&) = delete;

    // Room for `count` instances; valid until end().
    Instance* begin(std::size_t count);
    void end();
    // After the frame's draws: the region may not be written again until the GPU is done.
    void fence();
    // Index of the first instance of the current region (the draws' base instance).
    [[nodiscard]] std::size_t baseInstance() const noexcept { return base_; }
    [[nodiscard]] bool persistent() const noexcept { return persistent_; }
    // Points the instanced attributes at instance `first` of the buffer.
    void pointAttributes(std::size_t first) const;

private:
    void allocate(std::size_t capacity);
    void release();

    bool persistent_;
    int frames_;
    GLuint vao_;
    GLuint buffer_ = 0;
    std::size_t capacity_ = 0; // instances per region (persistent) or in the buffer (orphaning)
    Instance* mapped_ = nullptr;
    int region_ = 0;
    std::size_t base_ = 0;
    std::array<GLsync, 8> fences_{};
};

} // namespace e2d::render::detail
