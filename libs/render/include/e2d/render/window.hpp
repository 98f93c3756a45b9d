// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/log.hpp>

#include <glm/vec2.hpp>

#include <memory>
#include <string>

struct GLFWwindow;

/// The window and its OpenGL context.
namespace e2d::render {

/// Keeps the GLFW library initialised while it lives: glfwInit() in the constructor,
/// glfwTerminate() in the destructor. GLFW's state is process-wide (a fact of GLFW), so every
/// window alive at the same time must share one instance: each Window holds a shared_ptr to
/// it, and a second window is created with `WindowDef::glfw = first.glfw()`. The instance is
/// terminated when the last owner goes.
class GlfwInstance {
public:
    /// Throws core::Error carrying GLFW's message when initialisation fails (no display:
    /// "render::GlfwInstance: glfwInit() failed: X11: The DISPLAY environment variable is
    /// missing"). A display that is set but refuses the connection (an X server under load
    /// may reset it) is tried up to 4 times, about 0.2 s in all, before that is an error.
    /// Throws core::Error too when GLFW is already initialised in this process (a second
    /// instance, or a Game run inside a running one): its glfwTerminate() would close the
    /// first one's windows.
    GlfwInstance();
    ~GlfwInstance();
    GlfwInstance(const GlfwInstance&) = delete;
    GlfwInstance& operator=(const GlfwInstance&) = delete;
};

/// How the window occupies the screen.
enum class WindowMode {
    Windowed,   ///< a decorated window of the requested size
    Fullscreen, ///< exclusive fullscreen on the primary monitor at the requested size
    Borderless, ///< an undecorated window covering the primary monitor at its current mode
};

/// How a Window is created. The constructor validates every field.
struct WindowDef {
    /// Window title (UTF-8). Default "e2d".
    std::string title = "e2d";
    /// Client-area size in screen coordinates (on HiDPI screens the framebuffer is larger, see
    /// Window::contentScale()), each >= 1. Ignored for Borderless. Default 1280 x 720.
    glm::ivec2 size{1280, 720};
    /// Default Windowed.
    WindowMode mode = WindowMode::Windowed;
    /// Multisample anti-aliasing samples of the default framebuffer, 0 (off) to 16; the
    /// driver may give fewer (llvmpipe: at most 4). Default 0.
    int samples = 0;
    /// Swap buffers at the monitor's refresh rate. Default true.
    bool vsync = true;
    /// Shown on screen. A hidden window still renders (offscreen tests, screenshots).
    /// Default true.
    bool visible = true;
    /// The user may resize the window. Default true.
    bool resizable = true;
    /// Ask for an OpenGL debug context. Default false.
    bool debugContext = false;
    /// The GLFW library to use; null: the window creates its own instance. Default null.
    std::shared_ptr<GlfwInstance> glfw{};
    /// Where the window logs (context version, warnings); null: nowhere. Default null.
    core::Logger* logger = nullptr;
};

/// What the created context offers. The baseline is OpenGL 3.3 core, forward compatible; the
/// renderer uses 4.4 buffer storage (persistent mapping) when `bufferStorage` is true.
struct ContextInfo {
    int major = 0; ///< OpenGL version the driver gave
    int minor = 0;
    bool bufferStorage = false; ///< GL_ARB_buffer_storage or OpenGL >= 4.4
    bool baseInstance = false;  ///< GL_ARB_base_instance or OpenGL >= 4.2
    std::string renderer;       ///< GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string version;        ///< GL_VERSION string
};

/// A GLFW window with a current OpenGL 3.3+ core context (GLEW loaded).
///
/// The context is made current on the creating thread and stays current there; one window at a
/// time is the simple case (two windows: call makeCurrent() before drawing into each).
/// Framebuffer-size changes (resize, moving to another monitor) are read back in pollEvents().
/// The Window installs no GLFW callbacks and no window user pointer: those are left to the
/// input library.
class Window {
public:
    /// Throws core::Error for an invalid field ("render::Window: samples must be in [0, 16],
    /// got 32"), or carrying GLFW's or GLEW's message when there is no display, no suitable
    /// context, or GLEW fails.
    explicit Window(const WindowDef& def = {});
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    /// The GLFW window, for libraries that attach to it (input). Owned by this Window.
    [[nodiscard]] GLFWwindow* handle() const noexcept { return window_; }
    /// The GLFW instance this window keeps alive (give it to a second window's def).
    [[nodiscard]] const std::shared_ptr<GlfwInstance>& glfw() const noexcept { return glfw_; }
    [[nodiscard]] const ContextInfo& context() const noexcept { return context_; }

    /// Client-area size in screen coordinates.
    [[nodiscard]] glm::ivec2 size() const noexcept { return size_; }
    /// Framebuffer size in pixels (what the renderer draws into).
    [[nodiscard]] glm::ivec2 framebufferSize() const noexcept { return framebufferSize_; }
    /// Framebuffer pixels per screen coordinate (1 on ordinary screens, 2 on most HiDPI ones).
    [[nodiscard]] glm::vec2 contentScale() const noexcept;
    /// Increments each time the framebuffer size changes (so a camera can tell it must refit).
    [[nodiscard]] unsigned resizeCount() const noexcept { return resizeCount_; }

    /// Requests a new client-area size in screen coordinates (each >= 1); the framebuffer size
    /// follows once the window system has applied it (pollEvents()).
    void setSize(glm::ivec2 size);
    void setTitle(const std::string& title);
    [[nodiscard]] const std::string& title() const noexcept { return title_; }
    void setVsync(bool on);
    [[nodiscard]] bool vsync() const noexcept { return vsync_; }
    void show();
    void hide();
    [[nodiscard]] bool visible() const noexcept;
    /// Samples the default framebuffer actually has (GL_SAMPLES).
    [[nodiscard]] int samples() const noexcept { return samples_; }
    [[nodiscard]] WindowMode mode() const noexcept { return mode_; }

    /// The window's close button was pressed (or requestClose() was called).
    [[nodiscard]] bool shouldClose() const noexcept;
    void requestClose() noexcept;

    /// Processes pending window-system events (resize, close, input callbacks of others).
    void pollEvents();
    /// Shows the frame drawn since the last call.
    void swapBuffers();
    /// Makes this window's context current on the calling thread.
    void makeCurrent();

private:
    std::shared_ptr<GlfwInstance> glfw_;
    GLFWwindow* window_ = nullptr;
    ContextInfo context_;
    std::string title_;
    glm::ivec2 size_{0, 0};
    glm::ivec2 framebufferSize_{0, 0};
    unsigned resizeCount_ = 0;
    int samples_ = 0;
    bool vsync_ = true;
    WindowMode mode_ = WindowMode::Windowed;
    core::Logger* logger_ = nullptr;
};

} // namespace e2d::render
