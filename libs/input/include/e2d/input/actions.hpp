// SPDX-License-Identifier: MIT
#pragma once

#include <e2d/core/id.hpp>
#include <e2d/input/event.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace e2d::input {

class Input;

/// What one binding reads.
enum class BindingKind : std::uint8_t {
    Key,           ///< a keyboard key: 1 while down
    MouseButton,   ///< a mouse button: 1 while down
    GamepadButton, ///< a gamepad button (names.hpp, triggers included): 1 while down
    GamepadAxis,   ///< a gamepad axis after its dead zone (negated when `inverted`)
    KeyAxis,       ///< two keys as an axis: `negativeKey` gives -1, `code` +1, both 0
};

/// One input an action listens to. Write it with the factories (`Binding::key(Key::Space)`)
/// or parseBinding(); `code` and `negativeKey` hold the enum's value (GLFW's code).
///
/// Text form (bindings files): `key:space`, `mouse:left`, `button:a`, `axis:leftx`,
/// `axis:-lefty` (inverted), `keys:a/d` (negative/positive), and for one gamepad slot only
/// `button@1:start`, `axis@0:righttrigger` (slots 0..15; without `@` any gamepad).
struct Binding {
    BindingKind kind = BindingKind::Key;
    /// Key, mouse button, gamepad button or axis (for KeyAxis: the positive key).
    int code = 0;
    /// KeyAxis: the key giving -1.
    int negativeKey = 0;
    /// GamepadButton / GamepadAxis: the slot, or -1 for any gamepad (the strongest wins).
    int gamepad = -1;
    /// GamepadAxis: read the axis negated.
    bool inverted = false;

    [[nodiscard]] static Binding key(Key key) noexcept {
        return {BindingKind::Key, static_cast<int>(key), 0, -1, false};
    }
    [[nodiscard]] static Binding mouseButton(MouseButton button) noexcept {
        return {BindingKind::MouseButton, static_cast<int>(button), 0, -1, false};
    }
    [[nodiscard]] static Binding gamepadButton(GamepadButton button, int gamepad = -1) noexcept {
        return {BindingKind::GamepadButton, static_cast<int>(button), 0, gamepad, false};
    }
    [[nodiscard]] static Binding gamepadAxis(GamepadAxis axis, bool inverted = false,
                                             int gamepad = -1) noexcept {
        return {BindingKind::GamepadAxis, static_cast<int>(axis), 0, gamepad, inverted};
    }
    [[nodiscard]] static Binding keyAxis(Key negativeKey, Key positiveKey) noexcept {
        return {BindingKind::KeyAxis, static_cast<int>(positiveKey), static_cast<int>(negativeKey),
                -1, false};
    }
    friend bool operator==(const Binding&, const Binding&) = default;
};

/// Parses the text form of a binding; throws core::Error naming the problem
/// (`"input::parseBinding(): unknown key name 'spcae' in 'key:spcae'"`).
[[nodiscard]] Binding parseBinding(std::string_view text);
/// The text form of a binding (the names of names.hpp); throws core::Error for a code that
/// has no name.
[[nodiscard]] std::string formatBinding(const Binding& binding);

struct ActionIdTag;
/// A named action's handle (core::Id, 4 bytes): index + 1 (zero is null). Actions are never
/// removed, so the id has no generation and stays valid for the life of its ActionMap.
using ActionId = core::Id<ActionIdTag, core::NoGeneration>;

/// Settings of an ActionMap.
struct ActionMapDef {
    /// |value| at or above which an action bound to an axis counts as held, in (0, 1].
    /// Default 0.5.
    float pressThreshold = 0.5f;
    /// While listening for a rebinding, an axis must move this far (|value|, after its dead
    /// zone) to be taken, in (0, 1]. Default 0.5.
    float listenAxisThreshold = 0.5f;
    /// While listening, this key cancels instead of being bound; Key::Unknown: none.
    /// Default Key::Escape.
    Key listenCancelKey = Key::Escape;
};

/// How a captured rebinding is applied.
enum class ListenMode : std::uint8_t {
    Replace, ///< the captured input becomes the action's only binding
    Add,     ///< it is added to the existing bindings (if not already there)
};

/// Named actions ("jump", "move_x") bound to any mix of inputs, evaluated once per frame.
///
/// `update(input)` after `Input::beginFrame()` computes each action's value in [-1, 1] (the
/// binding with the largest magnitude wins), `held` (a digital binding down, or |value| at or
/// above `pressThreshold`), `pressed` and `released` (edges against the previous frame; a key,
/// mouse or pad button pressed and released within one frame makes the action both pressed and
/// released).
///
/// Bindings file: one action per line, `name = binding, binding, ...` (binding text form in
/// Binding; `#` starts a comment line; blank lines are ignored; an action may have no
/// bindings; a UTF-8 byte order mark at the start is skipped). Names are letters, digits, `_`,
/// `-`, `.`.
class ActionMap {
public:
    /// Throws core::Error naming the field for a value out of range.
    explicit ActionMap(ActionMapDef def = {});

    /// Adds an action; throws core::Error for a bad or duplicate name.
    ActionId add(std::string_view name);
    /// The action of that name, or null.
    [[nodiscard]] ActionId find(std::string_view name) const noexcept;
    /// Like find(), but adds the action when missing.
    ActionId findOrAdd(std::string_view name);
    [[nodiscard]] std::size_t size() const noexcept { return actions_.size(); }
    /// The action's name; throws core::Error for a null or foreign handle (as do all methods
    /// taking an ActionId).
    [[nodiscard]] const std::string& name(ActionId id) const;

    /// Adds a binding (ignored if the action already has it).
    void bind(ActionId id, const Binding& binding);
    void clearBindings(ActionId id);
    [[nodiscard]] std::span<const Binding> bindings(ActionId id) const;

    /// Evaluates every action from `input`'s state and this frame's events (see the class).
    void update(const Input& input);

    [[nodiscard]] bool pressed(ActionId id) const;
    [[nodiscard]] bool held(ActionId id) const;
    [[nodiscard]] bool released(ActionId id) const;
    [[nodiscard]] float value(ActionId id) const;
    /// By name: throw core::Error naming an unknown action.
    [[nodiscard]] bool pressed(std::string_view name) const {
        return pressed(require(name, "pressed"));
    }
    [[nodiscard]] bool held(std::string_view name) const { return held(require(name, "held")); }
    [[nodiscard]] bool released(std::string_view name) const {
        return released(require(name, "released"));
    }
    [[nodiscard]] float value(std::string_view name) const { return value(require(name, "value")); }

    // Rebinding ---------------------------------------------------------------------------

    /// Listens for the next input (key, mouse button or gamepad button press, or an axis moved
    /// past `listenAxisThreshold`: bound as `axis:x` or `axis:-x` by direction) seen by
    /// update(), and binds it to `id`. A new listen replaces one in progress.
    void listen(ActionId id, ListenMode mode = ListenMode::Replace);
    void cancelListen() noexcept { listening_ = {}; }
    [[nodiscard]] bool listening() const noexcept { return !listening_.isNull(); }
    /// The binding the last listen captured (nullopt while listening, after a cancel, or
    /// before any).
    [[nodiscard]] const std::optional<Binding>& captured() const noexcept { return captured_; }

    // Bindings files ----------------------------------------------------------------------

    /// Reads bindings text: actions it names get exactly the listed bindings (created if
    /// missing); other actions are untouched. On any error throws core::Error
    /// `"<source>:<line>: ..."` and changes nothing.
    void loadFromString(std::string_view text, std::string_view source = "<string>");
    /// Same from a file (the message names the file); throws if it cannot be read (a directory
    /// included).
    void load(const std::filesystem::path& path);
    /// Every action in creation order, in the file format.
    [[nodiscard]] std::string toString() const;
    /// Writes toString() to `path`; throws core::Error naming the file if it cannot.
    void save(const std::filesystem::path& path) const;

private:
    struct Action {
        std::string name;
        std::vector<Binding> bindings;
        float value = 0.0f;
        bool held = false;
        bool pressed = false;
        bool released = false;
    };

    const Action& at(ActionId id, const char* function) const;
    Action& at(ActionId id, const char* function);
    ActionId require(std::string_view name, const char* function) const;
    void evaluate(Action& action, const Input& input) const;
    void listenStep(const Input& input);

    ActionMapDef def_;
    std::vector<Action> actions_;
    ActionId listening_;
    ListenMode listenMode_ = ListenMode::Replace;
    std::optional<Binding> captured_;
};

} // namespace e2d::input
