// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace e2d::core {

/// What readTextFile() found: the file's bytes, or why there are none.
struct TextFile {
    /// The whole file, byte for byte (no newline translation).
    std::string text;
    /// Empty when the file was read; else why not, to follow "cannot read <file>: ":
    /// `"no such file"`, `"it is a directory"`, the system's reason (`"Permission denied"`),
    /// `"a read error"`.
    std::string error;

    [[nodiscard]] bool ok() const noexcept { return error.empty(); }
};

/// Reads the whole file at `path`. Never throws for a file that cannot be read: the caller
/// decides whether that is an error (input scripts) or a warning (a missing config). A
/// directory is named as one (an ifstream opens a directory without complaint on POSIX
/// systems and reads nothing).
[[nodiscard]] TextFile readTextFile(const std::filesystem::path& path);

/// readTextFile() for a file the caller cannot do without: its bytes, or core::Error
/// `"<function>: cannot read '<path>': <why>"` (`"input::ActionMap::load(): cannot read
/// 'controls.txt': it is a directory"`).
[[nodiscard]] std::string readRequiredTextFile(const std::filesystem::path& path,
                                               std::string_view function);

/// `text` without a UTF-8 byte order mark at its start (editors on Windows write one; it is not
/// part of the first line's content).
[[nodiscard]] std::string_view withoutByteOrderMark(std::string_view text) noexcept;

} // namespace e2d::core
