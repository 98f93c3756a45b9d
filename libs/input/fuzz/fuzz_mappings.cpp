// SPDX-License-Identifier: MIT
// Arbitrary bytes as a gamepad mapping text: every line is accepted (perhaps with warnings),
// counted as another platform's, or reported once with its line number; an accepted line, as
// handed to GLFW, is accepted again on its own with no warning and holds nothing GLFW would split,
// cut or refuse (no control characters, < 1024 bytes, no output modifier).
#include <e2d/input/gamepad_mappings.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

void check(bool condition) {
    if (!condition) {
        std::abort();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const e2d::input::MappingParseResult result = e2d::input::parseGamepadMappings(text, "fuzz");
    const auto lineCount = static_cast<int>(std::count(text.begin(), text.end(), '\n')) + 1;
    check(result.lines.size() + static_cast<std::size_t>(result.diagnostics.errorCount()) +
              static_cast<std::size_t>(result.otherPlatform) <=
          static_cast<std::size_t>(lineCount));
    int previous = 0;
    for (const e2d::core::Diagnostic& e : result.diagnostics.errors()) {
        check(e.line > previous && e.line <= lineCount);
        check(e.toString().starts_with("fuzz:" + std::to_string(e.line) + ": "));
        previous = e.line;
    }
    previous = 0;
    for (const e2d::core::Diagnostic& w : result.diagnostics.warnings()) {
        check(w.line >= previous && w.line <= lineCount);
        check(w.toString().starts_with("fuzz:" + std::to_string(w.line) + ": "));
        previous = w.line;
    }
    for (const std::string& line : result.lines) {
        check(line.size() < 1024);
        check(std::none_of(line.begin(), line.end(), [](char c) {
            return static_cast<unsigned char>(c) < 0x20 && c != '\t';
        }));
        // No field after the GUID and the name starts with an output modifier (a name may).
        const std::string_view fields =
            std::string_view(line).substr(line.find(',', line.find(',') + 1));
        check(fields.find(",+") == std::string_view::npos &&
              fields.find(",-") == std::string_view::npos);
        const e2d::input::MappingParseResult again = e2d::input::parseGamepadMappings(line);
        check(again.diagnostics.empty() && again.lines.size() == 1 && again.lines[0] == line);
    }
    return 0;
}
