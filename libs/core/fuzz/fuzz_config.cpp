// SPDX-License-Identifier: MIT
// Arbitrary bytes as a `key = value` configuration, read into settings of every type the
// reader binds: it never throws; every diagnostic names the source and a line (or none) and
// quotes nothing unprintable; numbers read are within their bounds; reading the same text
// again gives the same diagnostics.
#include <e2d/core/config.hpp>

#include <algorithm>
#include <cmath>
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

enum class Mode { First, Second, Third };

struct Settings {
    std::string title;
    int width = 1;
    std::int64_t frames = 0;
    std::uint64_t seed = 0;
    float gain = 0.5f;
    double step = 0.5;
    bool flag = true;
    Mode mode = Mode::First;
};

std::string readInto(Settings& s, std::string_view text) {
    using e2d::core::ConfigBounds;
    e2d::core::ConfigReader reader;
    reader.add("title", s.title);
    reader.add("width", s.width, ConfigBounds::atLeast(1.0));
    reader.add("frames", s.frames, ConfigBounds{-1e12, 1e12});
    reader.add("seed", s.seed);
    reader.add("gain", s.gain, ConfigBounds{0.0, 1.0});
    reader.add("step", s.step, ConfigBounds{0.0, 1.0, true});
    reader.add("flag", s.flag);
    reader.add("mode", s.mode,
               {{"first", Mode::First}, {"second", Mode::Second}, {"third", Mode::Third}});
    const e2d::core::ConfigReport report = reader.read(text, "fuzz");
    std::string all;
    for (const e2d::core::Diagnostic& d : report.diagnostics) {
        const std::string line = d.toString();
        check(line.starts_with("fuzz:"));
        check(d.line >= 1);
        check(std::none_of(line.begin(), line.end(), [](char c) {
            const auto byte = static_cast<unsigned char>(c);
            return byte < 0x20 || byte == 0x7F;
        }));
        all += line;
        all += '\n';
    }
    return all;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    Settings first;
    const std::string diagnostics = readInto(first, text);
    check(first.width >= 1);
    check(first.frames >= -1000000000000 && first.frames <= 1000000000000);
    check(first.gain >= 0.0f && first.gain <= 1.0f);
    check(first.step > 0.0 && first.step <= 1.0 && std::isfinite(first.step));
    Settings second;
    check(readInto(second, text) == diagnostics);
    check(second.title == first.title && second.width == first.width && second.seed == first.seed);
    return 0;
}
