// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace e2d::input::detail {

/// The bytes of the text file at `path`. Throws core::Error
/// `"<function>: cannot read '<path>'"` when it cannot, with the reason when there is one
/// (`": it is a directory"`: an ifstream opens a directory without complaint on POSIX systems
/// and reads nothing, which loaded zero entries with no error).
[[nodiscard]] std::string readTextFile(const std::filesystem::path& path, std::string_view function);

/// `text` without a UTF-8 byte order mark at its start (editors on Windows write one; it is not
/// part of the first line's content).
[[nodiscard]] std::string_view withoutByteOrderMark(std::string_view text) noexcept;

} // namespace e2d::input::detail
