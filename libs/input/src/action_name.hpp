// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <string_view>

namespace e2d::input::detail {

/// What an action name may hold, as messages say it.
inline constexpr std::string_view kActionNameRule =
    "action name must be letters, digits, '_', '-' or '.'";

/// True for a name ActionMap takes (kActionNameRule, not empty).
inline bool isActionName(std::string_view name) noexcept {
    return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_' || c == '-' || c == '.';
    });
}

} // namespace e2d::input::detail
