// SPDX-License-Identifier: MIT
#include <e2d/core/text_file.hpp>

#include <e2d/core/error_text.hpp>

#include <cerrno>
#include <fstream>
#include <iterator>
#include <system_error>
#include <utility>

namespace e2d::core {

TextFile readTextFile(const std::filesystem::path& path) {
    TextFile out;
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (status.type() == std::filesystem::file_type::not_found) {
        out.error = "no such file";
        return out;
    }
    if (status.type() == std::filesystem::file_type::directory) {
        out.error = "it is a directory";
        return out;
    }
    errno = 0;
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        const int code = errno;
        out.error =
            code != 0 ? std::generic_category().message(code) : std::string("it cannot be opened");
        return out;
    }
    out.text.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
    if (file.bad()) {
        out.text.clear();
        out.error = "a read error";
    }
    return out;
}

std::string readRequiredTextFile(const std::filesystem::path& path, std::string_view function) {
    TextFile file = readTextFile(path);
    if (!file.ok()) {
        throwError(function, "cannot read " + quote(path.string(), 1000) + ": " + file.error);
    }
    return std::move(file.text);
}

std::string_view withoutByteOrderMark(std::string_view text) noexcept {
    constexpr std::string_view kBom = "\xEF\xBB\xBF";
    if (text.starts_with(kBom)) {
        text.remove_prefix(kBom.size());
    }
    return text;
}

} // namespace e2d::core
