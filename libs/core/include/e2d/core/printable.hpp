// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <string_view>

namespace e2d::core {

/// `text` made safe to quote in a message: printable ASCII and well-formed UTF-8 stay as they
/// are; a backslash, control bytes (a NUL included, which would cut `what()` short) and bytes
/// that are not valid UTF-8 become `\\`, `\n`, `\t`, `\r` or `\xHH`. For messages that quote
/// what a file contained ("unknown key 'wi\x00dth'").
[[nodiscard]] std::string printable(std::string_view text);

} // namespace e2d::core
