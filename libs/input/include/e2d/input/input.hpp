// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/input/event.hpp>
#include <e2d/input/names.hpp>

#include <glm/vec2.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

struct GLFWwindow;

namespace e2d::core {
class Logger;
}

namespace e2d::input {

class ScriptedInput;

/// Number of gamepad / joystick slots (GLFW_JOYSTICK_1 ... GLFW_JOYSTICK_16).
inline constexpr int kMaxGamepads = 16;

/// How the cursor behaves over the window.
enum class CursorMode : std::uint8_t {
    Normal,   ///< visible, moves freely
    Hidden,   ///< invisible over the window, moves freely
    Captured, ///< invisible and locked to the window; use mouseDelta() for relative motion
};

/// Settings of an Input.
struct InputDef {
    /// Window to attach to (not owned; must outlive the Input or be detached first). nullptr:
    /// a detached Input, fed only through the handle* entry points (tests, replays).
    GLFWwindow* window = nullptr;
    /// Screen (pixels, origin top left) to world units, for mouse events; the engine passes
    /// the active camera's. Empty (default): world positions equal screen positions.
    std::function<glm::vec2(glm::vec2)> screenToWorld{};
    /// Read GLFW's 16 joystick slots in beginFrame() (only while attached to a window, since
    /// GLFW must be initialised). Default true.
    bool pollGamepads = true;
    /// Radial dead zone of each stick, as a fraction of full deflection, in [0, 1): a stick
    /// closer to its centre reads (0, 0); beyond, the length is rescaled so the edge of the
    /// dead zone reads 0 and full deflection 1, keeping the direction. Default 0.2.
    float stickDeadZone = 0.2f;
    /// Trigger travel below which a trigger reads 0, in [0, 1); above it the travel is
    /// rescaled to [0, 1]. Default 0.1.
    float triggerDeadZone = 0.1f;
    /// Trigger value (after its dead zone) at or above which the trigger counts as the
    /// buttons GamepadButton::LeftTrigger / RightTrigger, in (0, 1]. Default 0.5.
    float triggerPressThreshold = 0.5f;
    /// Window events queued between two frames beyond this are dropped and counted
    /// (droppedEvents()), so a stalled game does not grow without bound. >= 1, default 4096.
    std::size_t maxQueuedEvents = 4096;
    /// Warnings (dropped events) go here; nullptr: none.
    core::Logger* logger = nullptr;
};

/// One joystick slot as GLFW reports it, handed to Input::handleJoystick() (by beginFrame()
/// when polling, or by a test). The strings only need to live during the call.
struct JoystickSnapshot {
    bool present = false;
    /// True when GLFW has a gamepad mapping for it (glfwJoystickIsGamepad).
    bool gamepad = false;
    std::string_view guid;
    std::string_view name;
    /// GLFW's gamepad state: axes in [-1, 1] (triggers rest at -1), buttons 0/1.
    std::array<float, kGamepadAxisCount> axes{};
    std::array<std::uint8_t, 15> buttons{};
};

/// A joystick that is plugged in, mapped or not.
struct JoystickInfo {
    int slot = 0;
    /// SDL-style GUID (32 hex digits): what a mapping line starts with.
    std::string guid;
    std::string name;
    /// True when a gamepad mapping applies (its buttons and axes are read).
    bool gamepad = false;
};

/// Keyboard, mouse, text and gamepad input of one window.
///
/// GLFW's callbacks only queue events (the handle* entry points); `beginFrame()` delivers
/// them in order once per frame: it updates the polling state, adds the gamepad events from
/// polling, and exposes the frame's events through `events()`. Polling answers describe the
/// state after the frame's events (`wasKeyPressed`: at least one press this frame, even if the
/// key was released again in the same frame).
///
/// Window user pointer: while attached, the Input owns the window's GLFW user pointer (its
/// callbacks find the Input through it). The pointer the window had before is kept as
/// `userData()` and put back on detach, as are the callbacks that were installed before; code
/// that needs its own per-window data reaches it as `Input::fromWindow(w)->userData()`.
/// Several windows may each have their own Input; one window has at most one.
class Input {
public:
    /// Throws core::Error naming the field for a value out of range.
    explicit Input(InputDef def = {});
    /// Detaches from the window.
    ~Input();
    Input(const Input&) = delete;
    Input& operator=(const Input&) = delete;

    // Window --------------------------------------------------------------------------------

    /// Attaches to `window` (detaching from the previous one first); nullptr detaches.
    /// Throws core::Error if another Input is attached to `window`.
    void attach(GLFWwindow* window);
    void detach() { attach(nullptr); }
    [[nodiscard]] GLFWwindow* window() const noexcept { return window_; }
    /// The Input attached to `window`, or nullptr if none.
    [[nodiscard]] static Input* fromWindow(GLFWwindow* window) noexcept;
    /// Per-window data for other code (initially the window's previous user pointer).
    [[nodiscard]] void* userData() const noexcept { return userData_; }
    void setUserData(void* data) noexcept { userData_ = data; }

    /// Replaces the screen-to-world converter (empty: world = screen).
    void setScreenToWorld(std::function<glm::vec2(glm::vec2)> converter);

    // Entry points (GLFW's callbacks call these; they only queue) ----------------------------

    /// GLFW key callback: `action` is GLFW_PRESS, GLFW_RELEASE or GLFW_REPEAT.
    void handleKey(int key, int scancode, int action, int mods);
    /// GLFW char callback: one Unicode code point.
    void handleChar(char32_t codepoint);
    /// GLFW mouse button callback (position: the last reported cursor position).
    void handleMouseButton(int button, int action, int mods);
    /// GLFW cursor position callback, window pixels.
    void handleCursorPos(double x, double y);
    /// GLFW scroll callback.
    void handleScroll(double dx, double dy);
    /// GLFW focus callback.
    void handleFocus(bool focused);
    /// One joystick slot's state; beginFrame() calls it for all 16 slots when polling. Applied
    /// at the next beginFrame(), after the window events. Throws core::Error for a bad slot.
    void handleJoystick(int slot, const JoystickSnapshot& snapshot);

    // Frame ---------------------------------------------------------------------------------

    /// Delivers everything queued since the last call (see the class description).
    void beginFrame();
    /// This frame's events, in order.
    [[nodiscard]] std::span<const Event> events() const noexcept { return events_; }
    /// Plays `script` as one more device, from the next beginFrame() on: each beginFrame()
    /// first queues the script's events of that frame (0 for the first beginFrame() after this
    /// call), after the window's, through the same entry points. While a script that drives
    /// gamepads plays, the real joysticks are not read. Replaces a script already playing.
    void play(ScriptedInput script);
    /// Window events dropped so far because the queue was full.
    [[nodiscard]] std::size_t droppedEvents() const noexcept { return dropped_; }

    // Keyboard and mouse polling --------------------------------------------------------------

    /// Keys and buttons as the events name them (`input.isKeyDown(Key::Space)`; names.hpp
    /// converts config names); Key::Unknown and values outside the enum read false.
    [[nodiscard]] bool isKeyDown(Key key) const noexcept;
    [[nodiscard]] bool wasKeyPressed(Key key) const noexcept;
    [[nodiscard]] bool wasKeyReleased(Key key) const noexcept;
    [[nodiscard]] bool isMouseButtonDown(MouseButton button) const noexcept;
    [[nodiscard]] bool wasMouseButtonPressed(MouseButton button) const noexcept;
    [[nodiscard]] bool wasMouseButtonReleased(MouseButton button) const noexcept;
    /// Cursor position after this frame's events, window pixels (origin top left).
    [[nodiscard]] glm::vec2 mousePosition() const noexcept { return mouse_; }
    /// Same in world units, converted at delivery.
    [[nodiscard]] glm::vec2 mouseWorldPosition() const noexcept { return mouseWorld_; }
    /// Cursor motion this frame, pixels (in Captured mode: the relative motion).
    [[nodiscard]] glm::vec2 mouseDelta() const noexcept { return mouseDelta_; }
    /// Scroll offset summed over this frame.
    [[nodiscard]] glm::vec2 scroll() const noexcept { return scroll_; }
    /// Text typed this frame, UTF-32.
    [[nodiscard]] std::u32string_view text() const noexcept { return text_; }
    /// Whether the window has keyboard focus (true for a detached Input until told otherwise).
    [[nodiscard]] bool focused() const noexcept { return focused_; }

    /// Sets the cursor mode (applied to the window at once when attached). Entering or leaving
    /// Captured does not count as motion.
    void setCursorMode(CursorMode mode);
    [[nodiscard]] CursorMode cursorMode() const noexcept { return cursorMode_; }

    // Gamepads ----------------------------------------------------------------------------

    /// True when `slot` has a joystick with a gamepad mapping.
    [[nodiscard]] bool isGamepadConnected(int slot) const noexcept;
    /// A button of the gamepad in `slot` (0..15), the triggers included; false for a bad slot.
    [[nodiscard]] bool isGamepadButtonDown(int slot, GamepadButton button) const noexcept;
    [[nodiscard]] bool wasGamepadButtonPressed(int slot, GamepadButton button) const noexcept;
    [[nodiscard]] bool wasGamepadButtonReleased(int slot, GamepadButton button) const noexcept;
    /// Axis after dead zones (sticks [-1, 1], y down is positive as in GLFW; triggers [0, 1]);
    /// 0 for a bad slot or a disconnected pad.
    [[nodiscard]] float gamepadAxis(int slot, GamepadAxis axis) const noexcept;
    /// Every joystick plugged in, mapped or not, by slot.
    [[nodiscard]] std::vector<JoystickInfo> joysticks() const;

    /// The radial dead zone applied to a raw stick position (see InputDef::stickDeadZone).
    [[nodiscard]] static glm::vec2 applyStickDeadZone(glm::vec2 raw, float deadZone) noexcept;
    /// A raw GLFW trigger axis ([-1, 1], rest -1) to [0, 1] after `deadZone`.
    [[nodiscard]] static float applyTriggerDeadZone(float raw, float deadZone) noexcept;

private:
    struct KeyState {
        bool down = false;
        bool pressed = false;
        bool released = false;
        int scancode = 0;
    };
    struct Pad {
        bool present = false;
        bool gamepad = false;
        std::string guid;
        std::string name;
        std::array<float, kGamepadAxisCount> axes{};
        std::array<bool, kGamepadButtonCount> down{};
        std::array<bool, kGamepadButtonCount> pressed{};
        std::array<bool, kGamepadButtonCount> released{};
    };
    struct PendingPad {
        bool fed = false;
        JoystickSnapshot snapshot;
        std::string guid;
        std::string name;
    };
    struct SavedCallbacks;

    void queue(const Event& event);
    void deliver(Event event);
    void releaseEverything();
    void pollJoysticks();
    void applyPad(int slot, PendingPad& pending);
    void setPadButton(int slot, Pad& pad, int button, bool down);
    glm::vec2 toWorld(glm::vec2 screen) const;
    void installCallbacks();
    void restoreCallbacks();

    InputDef def_;
    GLFWwindow* window_ = nullptr;
    void* userData_ = nullptr;
    std::unique_ptr<SavedCallbacks> saved_;
    std::unique_ptr<ScriptedInput> script_;
    std::int64_t scriptFrame_ = 0;

    // Callback side.
    std::vector<Event> queue_;
    glm::vec2 queuedCursor_{0.0f};
    std::size_t dropped_ = 0;
    std::size_t droppedReported_ = 0;
    std::array<PendingPad, kMaxGamepads> pendingPads_{};

    // Delivered side.
    std::vector<Event> events_;
    std::array<KeyState, kKeyLast + 1> keys_{};
    std::vector<int> touchedKeys_;
    std::array<KeyState, kMouseButtonCount> buttons_{};
    glm::vec2 mouse_{0.0f};
    glm::vec2 mouseWorld_{0.0f};
    glm::vec2 mouseDelta_{0.0f};
    glm::vec2 scroll_{0.0f};
    std::u32string text_;
    bool focused_ = true;
    CursorMode cursorMode_ = CursorMode::Normal;
    std::array<Pad, kMaxGamepads> pads_{};
};

} // namespace e2d::input
