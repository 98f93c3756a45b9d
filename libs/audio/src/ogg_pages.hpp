// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <span>
#include <string>

namespace e2d::audio::detail {

/// Walks every page of an Ogg file (`bytes`: the whole file) and returns what is wrong, or an
/// empty string: a page that fails its checksum or bytes that are no page ("damaged: ..."), a
/// file that ends inside a page, or a last page without the end-of-stream flag ("truncated:
/// ..."). libsndfile decodes such files as shorter sounds without an error (cut between two
/// pages, it even reports the shorter length as the file's; a damaged page can shrink the
/// reported length to the last page's), so only the container shows the damage. Bytes after
/// an end-of-stream page that are not a page (a tag appended by some tool) are ignored.
[[nodiscard]] std::string checkOggPages(std::span<const std::byte> bytes);

} // namespace e2d::audio::detail
