// SPDX-License-Identifier: MIT
#include <e2d/input/names.hpp>

#include <GLFW/glfw3.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <string_view>

namespace e2d::input {

namespace {

struct KeyEntry {
    int code;
    std::string_view name;
};

// Sorted by code (GLFW's own order), so a lookup by code is a binary search.
constexpr KeyEntry kKeys[] = {
    {32, "space"},
    {39, "apostrophe"},
    {44, "comma"},
    {45, "minus"},
    {46, "period"},
    {47, "slash"},
    {48, "0"},
    {49, "1"},
    {50, "2"},
    {51, "3"},
    {52, "4"},
    {53, "5"},
    {54, "6"},
    {55, "7"},
    {56, "8"},
    {57, "9"},
    {59, "semicolon"},
    {61, "equal"},
    {65, "a"},
    {66, "b"},
    {67, "c"},
    {68, "d"},
    {69, "e"},
    {70, "f"},
    {71, "g"},
    {72, "h"},
    {73, "i"},
    {74, "j"},
    {75, "k"},
    {76, "l"},
    {77, "m"},
    {78, "n"},
    {79, "o"},
    {80, "p"},
    {81, "q"},
    {82, "r"},
    {83, "s"},
    {84, "t"},
    {85, "u"},
    {86, "v"},
    {87, "w"},
    {88, "x"},
    {89, "y"},
    {90, "z"},
    {91, "left_bracket"},
    {92, "backslash"},
    {93, "right_bracket"},
    {96, "grave_accent"},
    {161, "world_1"},
    {162, "world_2"},
    {256, "escape"},
    {257, "enter"},
    {258, "tab"},
    {259, "backspace"},
    {260, "insert"},
    {261, "delete"},
    {262, "right"},
    {263, "left"},
    {264, "down"},
    {265, "up"},
    {266, "page_up"},
    {267, "page_down"},
    {268, "home"},
    {269, "end"},
    {280, "caps_lock"},
    {281, "scroll_lock"},
    {282, "num_lock"},
    {283, "print_screen"},
    {284, "pause"},
    {290, "f1"},
    {291, "f2"},
    {292, "f3"},
    {293, "f4"},
    {294, "f5"},
    {295, "f6"},
    {296, "f7"},
    {297, "f8"},
    {298, "f9"},
    {299, "f10"},
    {300, "f11"},
    {301, "f12"},
    {302, "f13"},
    {303, "f14"},
    {304, "f15"},
    {305, "f16"},
    {306, "f17"},
    {307, "f18"},
    {308, "f19"},
    {309, "f20"},
    {310, "f21"},
    {311, "f22"},
    {312, "f23"},
    {313, "f24"},
    {314, "f25"},
    {320, "kp_0"},
    {321, "kp_1"},
    {322, "kp_2"},
    {323, "kp_3"},
    {324, "kp_4"},
    {325, "kp_5"},
    {326, "kp_6"},
    {327, "kp_7"},
    {328, "kp_8"},
    {329, "kp_9"},
    {330, "kp_decimal"},
    {331, "kp_divide"},
    {332, "kp_multiply"},
    {333, "kp_subtract"},
    {334, "kp_add"},
    {335, "kp_enter"},
    {336, "kp_equal"},
    {340, "left_shift"},
    {341, "left_control"},
    {342, "left_alt"},
    {343, "left_super"},
    {344, "right_shift"},
    {345, "right_control"},
    {346, "right_alt"},
    {347, "right_super"},
    {348, "menu"},
};

static_assert(GLFW_KEY_LAST == kKeyLast);
static_assert(GLFW_GAMEPAD_BUTTON_LAST + 1 == static_cast<int>(GamepadButton::LeftTrigger));
static_assert(static_cast<int>(GamepadButton::RightTrigger) + 1 == kGamepadButtonCount);
static_assert(GLFW_GAMEPAD_AXIS_LAST + 1 == kGamepadAxisCount);
static_assert(GLFW_MOUSE_BUTTON_LAST + 1 == kMouseButtonCount);

constexpr std::array<std::string_view, kMouseButtonCount> kMouseButtons = {
    "left", "right", "middle", "button4", "button5", "button6", "button7", "button8"};

constexpr std::array<std::string_view, kGamepadButtonCount> kGamepadButtons = {
    "a",       "b",      "x",      "y",           "leftshoulder", "rightshoulder",
    "back",    "start",  "guide",  "leftstick",   "rightstick",   "dpup",
    "dpright", "dpdown", "dpleft", "lefttrigger", "righttrigger"};

constexpr std::array<std::string_view, kGamepadAxisCount> kGamepadAxes = {
    "leftx", "lefty", "rightx", "righty", "lefttrigger", "righttrigger"};

bool equalsIgnoringCase(std::string_view a, std::string_view b) noexcept {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

template <class Enum, std::size_t N>
std::optional<Enum> indexOf(const std::array<std::string_view, N>& names,
                            std::string_view name) noexcept {
    for (std::size_t i = 0; i < N; ++i) {
        if (equalsIgnoringCase(names[i], name)) {
            return static_cast<Enum>(i);
        }
    }
    return std::nullopt;
}

// The name at the enum's value, or empty outside the table.
template <class Enum, std::size_t N>
std::string_view nameAt(const std::array<std::string_view, N>& names, Enum value) noexcept {
    const auto i = static_cast<std::size_t>(static_cast<int>(value)); // negative: huge
    return i < N ? names[i] : std::string_view{};
}

} // namespace

std::string_view keyName(Key key) noexcept {
    const int code = static_cast<int>(key);
    const auto* it = std::lower_bound(std::begin(kKeys), std::end(kKeys), code,
                                      [](const KeyEntry& e, int c) { return e.code < c; });
    return it != std::end(kKeys) && it->code == code ? it->name : std::string_view{};
}

std::optional<Key> keyFromName(std::string_view name) noexcept {
    for (const KeyEntry& e : kKeys) {
        if (equalsIgnoringCase(e.name, name)) {
            return static_cast<Key>(e.code);
        }
    }
    return std::nullopt;
}

std::string_view mouseButtonName(MouseButton button) noexcept {
    return nameAt(kMouseButtons, button);
}

std::optional<MouseButton> mouseButtonFromName(std::string_view name) noexcept {
    if (auto button = indexOf<MouseButton>(kMouseButtons, name)) {
        return button;
    }
    if (equalsIgnoringCase(name, "button1")) {
        return MouseButton::Left;
    }
    if (equalsIgnoringCase(name, "button2")) {
        return MouseButton::Right;
    }
    if (equalsIgnoringCase(name, "button3")) {
        return MouseButton::Middle;
    }
    return std::nullopt;
}

std::string_view gamepadButtonName(GamepadButton button) noexcept {
    return nameAt(kGamepadButtons, button);
}

std::optional<GamepadButton> gamepadButtonFromName(std::string_view name) noexcept {
    return indexOf<GamepadButton>(kGamepadButtons, name);
}

std::string_view gamepadAxisName(GamepadAxis axis) noexcept { return nameAt(kGamepadAxes, axis); }

std::optional<GamepadAxis> gamepadAxisFromName(std::string_view name) noexcept {
    return indexOf<GamepadAxis>(kGamepadAxes, name);
}

} // namespace e2d::input
