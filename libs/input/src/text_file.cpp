// SPDX-License-Identifier: MIT
#include "text_file.hpp"

#include <e2d/core/error.hpp>

#include <fstream>
#include <sstream>

namespace e2d::input::detail {

std::string readTextFile(const std::filesystem::path& path, std::string_view function) {
    const auto fail = [&](std::string_view reason) {
        throw core::Error(std::string(function) + ": cannot read '" + path.string() + "'" + std::string(reason));
    };
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        fail(": it is a directory");
    }
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        fail("");
    }
    std::ostringstream text;
    text << file.rdbuf();
    if (file.bad()) {
        fail(": a read error");
    }
    return std::move(text).str();
}

std::string_view withoutByteOrderMark(std::string_view text) noexcept {
    constexpr std::string_view kBom = "\xEF\xBB\xBF";
    if (text.starts_with(kBom)) {
        text.remove_prefix(kBom.size());
    }
    return text;
}

} // namespace e2d::input::detail
