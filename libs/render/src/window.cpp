// SPDX-License-Identifier: MIT
#include "gl.hpp"

#include <e2d/render/window.hpp>

#include <e2d/core/error_text.hpp>

#include <GLFW/glfw3.h>

#include <cstring>
#include <string>

namespace e2d::render {

namespace {

constexpr const char* kCtor = "render::Window";

void validate(const WindowDef& def) {
    if (def.mode != WindowMode::Borderless && (def.size.x < 1 || def.size.y < 1)) {
        core::throwError(kCtor,
                         "size must be >= 1 in each axis, got " + core::formatVector(def.size));
    }
    if (def.samples < 0 || def.samples > 16) {
        core::throwError(kCtor, "samples must be in [0, 16], got " + std::to_string(def.samples));
    }
}

std::string glfwMessage() {
    const char* description = nullptr;
    int code = glfwGetError(&description);
    if (code == GLFW_NO_ERROR || description == nullptr) {
        return "no reason given";
    }
    return description;
}

bool hasExtension(const char* name) {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const auto* ext =
            reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
        if (ext != nullptr && std::strcmp(ext, name) == 0) {
            return true;
        }
    }
    return false;
}

} // namespace

Window::Window(const WindowDef& def)
    : glfw_(def.glfw), title_(def.title), vsync_(def.vsync), mode_(def.mode), logger_(def.logger) {
    validate(def);
    if (!glfw_) {
        glfw_ = std::make_shared<GlfwInstance>();
    }
    glfwDefaultWindowHints();
    // The baseline: 3.3 core, forward compatible (macOS stops at 4.1). Drivers give the
    // highest compatible version, so 4.4+ features are found below when present.
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, def.debugContext ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_SAMPLES, def.samples);
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    glfwWindowHint(GLFW_VISIBLE, def.visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_RESIZABLE, def.resizable ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);

    GLFWmonitor* monitor = nullptr;
    glm::ivec2 size = def.size;
    if (def.mode != WindowMode::Windowed) {
        monitor = glfwGetPrimaryMonitor();
        if (monitor == nullptr) {
            core::throwError(kCtor,
                             "no monitor for a fullscreen or borderless window: " + glfwMessage());
        }
        if (def.mode == WindowMode::Borderless) {
            const GLFWvidmode* video = glfwGetVideoMode(monitor);
            size = {video->width, video->height};
            glfwWindowHint(GLFW_DECORATED, GLFW_FALSE);
            glfwWindowHint(GLFW_RED_BITS, video->redBits);
            glfwWindowHint(GLFW_GREEN_BITS, video->greenBits);
            glfwWindowHint(GLFW_BLUE_BITS, video->blueBits);
            glfwWindowHint(GLFW_REFRESH_RATE, video->refreshRate);
        }
    }
    window_ = glfwCreateWindow(size.x, size.y, def.title.c_str(), monitor, nullptr);
    if (window_ == nullptr) {
        core::throwError(kCtor, "glfwCreateWindow() failed (no OpenGL 3.3 core context?): " +
                                    glfwMessage());
    }
    glfwMakeContextCurrent(window_);
    glewExperimental = GL_TRUE;
    GLenum glew = glewInit();
    // With an EGL context GLEW reports NO_GLX_DISPLAY although it loaded every function.
    if (glew != GLEW_OK && glew != GLEW_ERROR_NO_GLX_DISPLAY) {
        std::string message = reinterpret_cast<const char*>(glewGetErrorString(glew));
        glfwDestroyWindow(window_);
        window_ = nullptr;
        core::throwError(kCtor, "glewInit() failed: " + message);
    }
    // glewInit() may leave GL_INVALID_ENUM behind on core profiles.
    while (glGetError() != GL_NO_ERROR) {
    }
    glGetIntegerv(GL_MAJOR_VERSION, &context_.major);
    glGetIntegerv(GL_MINOR_VERSION, &context_.minor);
    int version = context_.major * 10 + context_.minor;
    context_.bufferStorage = version >= 44 || hasExtension("GL_ARB_buffer_storage");
    context_.baseInstance = version >= 42 || hasExtension("GL_ARB_base_instance");
    context_.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    context_.version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    GLint samples = 0;
    glGetIntegerv(GL_SAMPLES, &samples);
    samples_ = samples;
    glfwSwapInterval(def.vsync ? 1 : 0);

    glfwGetWindowSize(window_, &size_.x, &size_.y);
    glfwGetFramebufferSize(window_, &framebufferSize_.x, &framebufferSize_.y);
    if (logger_ != nullptr) {
        logger_->info("render::Window: OpenGL " + context_.version + " on " + context_.renderer +
                      (context_.bufferStorage ? " (buffer storage)" : ""));
    }
}

Window::~Window() {
    if (window_ != nullptr) {
        glfwDestroyWindow(window_);
    }
}

glm::vec2 Window::contentScale() const noexcept {
    if (size_.x <= 0 || size_.y <= 0) {
        return {1.0f, 1.0f};
    }
    return glm::vec2(framebufferSize_) / glm::vec2(size_);
}

void Window::setSize(glm::ivec2 size) {
    if (size.x < 1 || size.y < 1) {
        core::throwError("render::Window::setSize()",
                         "size must be >= 1 in each axis, got " + core::formatVector(size));
    }
    glfwSetWindowSize(window_, size.x, size.y);
}

void Window::setTitle(const std::string& title) {
    glfwSetWindowTitle(window_, title.c_str());
    title_ = title;
}

void Window::setVsync(bool on) {
    makeCurrent();
    glfwSwapInterval(on ? 1 : 0);
    vsync_ = on;
}

void Window::show() { glfwShowWindow(window_); }
void Window::hide() { glfwHideWindow(window_); }
bool Window::visible() const noexcept {
    return glfwGetWindowAttrib(window_, GLFW_VISIBLE) == GLFW_TRUE;
}
bool Window::shouldClose() const noexcept { return glfwWindowShouldClose(window_) == GLFW_TRUE; }
void Window::requestClose() noexcept { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

void Window::pollEvents() {
    glfwPollEvents();
    // Sizes are read back rather than taken from callbacks: the GLFW callbacks and user
    // pointer stay free for the input library.
    glm::ivec2 fb;
    glfwGetFramebufferSize(window_, &fb.x, &fb.y);
    // A minimised window reports 0 x 0: keep the last usable size.
    if (fb != framebufferSize_ && fb.x > 0 && fb.y > 0) {
        framebufferSize_ = fb;
        ++resizeCount_;
    }
    glfwGetWindowSize(window_, &size_.x, &size_.y);
}

void Window::swapBuffers() { glfwSwapBuffers(window_); }
void Window::makeCurrent() { glfwMakeContextCurrent(window_); }

} // namespace e2d::render
